// PatchTestMovementProjectiveConstraint: SOFA's corner search (quirks included), the
// bilinear / trilinear interpolation of the corner displacements (hand-computed), the time
// law shared with AffineMovementProjectiveConstraint, and SOFA's three example scenes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "badinput_helpers.h"
#include "core/mechanical_ops.h"
#include "core/node.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;

namespace {

// The 8 border points of a 3×3 grid on [0,1]² (x fastest), as a BoxROI/PairBoxROI gives them.
const char* kBorder2d = "0 1 2 3 5 6 7 8";
const char* kBorderPts2d = "0 0 0  0.5 0 0  1 0 0  0 0.5 0  1 0.5 0  0 1 0  0.5 1 0  1 1 0";

std::string square(const std::string& extra = "") {
  return std::string(R"(<Node name="root" dt="0.25" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-12" threshold="1e-20"/>
    <RegularGridTopology name="grid" n="3 3 1" min="0 0 0" max="1 1 0"/>
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="1"/>
    <PatchTestMovementProjectiveConstraint name="c" indices=")") +
         kBorder2d + "\" meshIndices=\"" + kBorder2d + "\" constrainedPoints=\"" + kBorderPts2d +
         "\" endConstraintTime=\"1\" cornerMovements=\"0.1 0 0  0 0.2 0  0 0 0.3  -0.1 -0.1 0\"" + extra +
         "/>\n</Node>";
}

std::vector<double> field_values(Component& c, const char* name) {
  std::vector<double> v;
  std::istringstream in(c.find_field(name)->text());
  for (double d; in >> d;) v.push_back(d);
  return v;
}

// Displacements of the 9 grid points at the end: d(α, β) = m0(1−α)(1−β) + m1 α(1−β) + m2 αβ + m3 (1−α)β
// with α = x, β = y; the interior point 4 is not constrained.
const double kFinal[9][3] = {
    {0.1, 0, 0},        {0.5 + 0.05, 0.1, 0}, {1, 0.2, 0},   {-0.05 + 0.05, 0.5 - 0.05, 0}, {0.5, 0.5, 0},
    {1, 0.5 + 0.1, 0.15}, {-0.1, 0.9, 0},     {0.5 - 0.05, 1 - 0.05, 0.15}, {1, 1, 0.3}};

TEST(PatchTestMovement, CornersOfASquareAndBilinearDisplacements) {
  auto s = test::load(square());
  auto* c = test::get<Component>(*s.root, "c");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(field_values(*c, "cornerPoints"), (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  const std::vector<double> x0 = mo->read(kPosition);
  // Two steps. As in SOFA, the projection reads the time before it advances (0.25 in the
  // second step): a quarter of the way from x0 to xf.
  animate(*s.root);
  animate(*s.root);
  const std::vector<double>& x = mo->read(kPosition);
  for (int i = 0; i < 9; ++i) {
    if (i == 4) continue;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[3 * i + k], 0.75 * x0[3 * i + k] + 0.25 * kFinal[i][k], 1e-15) << i << "," << k;
  }
  // After the end time: exactly xf; velocities of the constrained points stay zero.
  for (int step = 0; step < 4; ++step) animate(*s.root);
  for (int i = 0; i < 9; ++i) {
    if (i == 4) continue;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(x[3 * i + k], kFinal[i][k], 1e-15) << i << "," << k;
      EXPECT_EQ(mo->read(kVelocity)[3 * i + k], 0.0);
    }
  }
}

TEST(PatchTestMovement, SofaCornerSearchInThreeDimensions) {
  // Border points of a 3×3×3 grid on [0,1]³ in grid order: SOFA's comparisons take
  // (1,1,1) as corner 4 (only its z is used, so the interpolation is still right).
  std::string idx, pts;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x) {
        if (x == 1 && y == 1 && z == 1) continue;
        idx += std::to_string(x + 3 * y + 9 * z) + " ";
        pts += std::to_string(0.5 * x) + " " + std::to_string(0.5 * y) + " " + std::to_string(0.5 * z) + "  ";
      }
  auto s = test::load(R"(<Node name="root" dt="0.5" gravity="0 0 0"><DefaultAnimationLoop/>
    <RegularGridTopology n="3 3 3" min="0 0 0" max="1 1 1"/><MechanicalObject name="dofs"/>
    <PatchTestMovementProjectiveConstraint name="c" endConstraintTime="0.1" indices=")" +
                      idx + "\" constrainedPoints=\"" + pts +
                      "\" cornerMovements=\"1 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 2\"/></Node>");
  auto* c = test::get<Component>(*s.root, "c");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(field_values(*c, "cornerPoints"),
            (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}));
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  MechanicalOps ops(*s.root);
  s.root->time.set(1.0);  // after the end: x = xf
  ops.project_position(kPosition, 1.0);
  const std::vector<double>& x = mo->read(kPosition);
  // Point (0, 0.5, 0.5): α = 0, β = γ = ½ → m0·½·½ + m7·½·½ = (0.25, 0, 0.5).
  const int p = 0 + 3 * 1 + 9 * 1;
  EXPECT_NEAR(x[3 * p], 0.25, 1e-15);
  EXPECT_NEAR(x[3 * p + 1], 0.5, 1e-15);
  EXPECT_NEAR(x[3 * p + 2], 0.5 + 0.5, 1e-15);
  // Corner (0,0,0) moves by m0.
  EXPECT_NEAR(x[0], 1.0, 1e-15);
}

TEST(PatchTestMovement, MissingCornersOrMovementsAreReported) {
  auto s = test::load(R"(<Node gravity="0 0 0"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <PatchTestMovementProjectiveConstraint name="c" indices="0 1 7"/></Node>)");
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "index 7 is not valid")) << errors.size();
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "found 0 corner points"));
  auto t = test::load(square().replace(square().find("-0.1 -0.1 0"), 11, ""));
  EXPECT_TRUE(test::any_contains(test::messages(t.root->diagnostics(), Severity::warning),
                                 "cornerMovements has 3 displacements for 4 corners"));
}

class PatchTestExample : public ::testing::TestWithParam<const char*> {};

TEST_P(PatchTestExample, RunsAndMovesTheBorder) {
  std::vector<double> x, x0;
  const test::Outcome o = test::run_sofa_example(GetParam(), 20, [&](runner::Session& s) {
    std::vector<MechanicalState*> states;
    s.root().collect_down(states);
    x = states.at(0)->read(kPosition);
    x0 = states.at(0)->read(kRestPosition);
  });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  // At t = 1 the border has gone 1/20 of its way (the corners move by 0.1 or more).
  double moved = 0;
  for (std::size_t k = 0; k < x.size(); ++k) moved = std::max(moved, std::abs(x[k] - x0[k]));
  EXPECT_GT(moved, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PatchTestExample,
                         ::testing::Values("Component/Constraint/Projective/PatchTestConstraint.scn",
                                           "Component/Constraint/Projective/BilinearConstraint.scn",
                                           "Component/Constraint/Projective/BilinearConstraint3D.scn"));

}  // namespace
