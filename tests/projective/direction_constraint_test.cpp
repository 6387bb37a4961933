// DirectionProjectiveConstraint: the direction normalised and written back,
// responses and velocities projected on it (parallel to it, hand-computed),
// positions put back on the line through the first positions, SOFA's
// projection-matrix fill (a repeated index stops it), Vec2d, whole steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "projective/direction_projective_constraint.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
std::string make_scene(const std::string& constraint, const char* positions = "0 0 0  1 2 3  4 5 6",
                  const char* tmpl = "Vec3d") {
  return std::string(R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <MechanicalObject name="dofs" template=")") + tmpl + "\" position=\"" + positions + "\"/>\n" + constraint +
         "\n</Node>";
}
}  // namespace

TEST(DirectionConstraint, ProjectedDisplacementsAreParallelToTheDirection) {
  auto s = load(make_scene(R"(<DirectionProjectiveConstraint name="dc" indices="1 2" direction="3 4 0"/>)"));
  ASSERT_TRUE(s.root);
  auto* dc = get<DirectionProjectiveConstraint>(*s.root, "dc");
  ASSERT_EQ(dc->direction.get().size(), 3u);  // written back normalised
  EXPECT_NEAR(dc->direction.get()[0], 0.6, 1e-15);
  EXPECT_NEAR(dc->direction.get()[1], 0.8, 1e-15);
  MechanicalState& st = *s.root->mechanical_state;
  st.write(kForce).assign({1, 2, 3, 1, 2, 3, -5, 0, 7});
  MechanicalOps ops(*s.root);
  ops.project_response(kForce);
  const auto& d = st.read(kForce);
  EXPECT_EQ(d[0], 1.0);  // DoF 0 free
  // (1, 2, 3)·n = 2.2 → 2.2·n = (1.32, 1.76, 0); (−5, 0, 7)·n = −3 → (−1.8, −2.4, 0).
  EXPECT_NEAR(d[3], 1.32, 1e-15);
  EXPECT_NEAR(d[4], 1.76, 1e-15);
  EXPECT_EQ(d[5], 0.0);
  EXPECT_NEAR(d[6], -1.8, 1e-15);
  EXPECT_NEAR(d[7], -2.4, 1e-15);
  for (int i : {1, 2}) {  // parallel: the cross product with the direction vanishes
    const double* v = &d[3 * i];
    EXPECT_NEAR(v[0] * 0.8 - v[1] * 0.6, 0.0, 1e-15);
    EXPECT_EQ(v[2], 0.0);
  }
  // Velocities the same way.
  st.write(kVelocity).assign({1, 1, 1, 0, 5, 0, 0, 0, 0});
  ops.project_velocity(kVelocity, 0);
  EXPECT_NEAR(st.read(kVelocity)[3], 2.4, 1e-15);
  EXPECT_NEAR(st.read(kVelocity)[4], 3.2, 1e-15);
}

TEST(DirectionConstraint, PositionsGoBackOnTheLineThroughTheFirstPositions) {
  auto s = load(make_scene(R"(<DirectionProjectiveConstraint name="dc" indices="1" direction="0 0 2"/>)"));
  ASSERT_TRUE(s.root);
  MechanicalState& st = *s.root->mechanical_state;
  st.write(kPosition).assign({7, 7, 7, 3, -1, 10, 4, 5, 6});
  MechanicalOps ops(*s.root);
  ops.project_position(kPosition, 0);
  EXPECT_EQ(st.read(kPosition), (std::vector<double>{7, 7, 7, 1, 2, 10, 4, 5, 6}));
}

TEST(DirectionConstraint, ARepeatedIndexStopsTheMatrixFillAsInSofa) {
  auto s = load(make_scene(R"(<DirectionProjectiveConstraint name="dc" indices="0 0 2" direction="1 0 0"/>)"));
  ASSERT_TRUE(s.root);
  auto* dc = get<DirectionProjectiveConstraint>(*s.root, "dc");
  EXPECT_EQ(dc->projected(), (std::vector<char>{1, 0, 0}));
}

TEST(DirectionConstraint, Vec2d) {
  auto s = load(make_scene(R"(<DirectionProjectiveConstraint name="dc" template="Vec2d" indices="1" direction="1 1"/>)",
                      "0 0  1 2", "Vec2d"));
  ASSERT_TRUE(s.root);
  MechanicalState& st = *s.root->mechanical_state;
  st.write(kForce).assign({1, 1, 2, 0});
  MechanicalOps ops(*s.root);
  ops.project_response(kForce);
  EXPECT_NEAR(st.read(kForce)[2], 1.0, 1e-15);
  EXPECT_NEAR(st.read(kForce)[3], 1.0, 1e-15);
}

TEST(DirectionConstraint, StepsMoveTheListedPointsOnlyAlongTheDirection) {
  auto s = load(R"(<Node name="root" dt="0.05" gravity="0 -9.81 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="40" tolerance="1e-12" threshold="1e-12"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0"/>
    <UniformMass totalMass="3"/>
    <DirectionProjectiveConstraint indices="0 2" direction="1 -1 0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  for (int i = 0; i < 20; ++i) animate(*s.root);
  const auto& x = s.root->mechanical_state->read(kPosition);
  // Constrained points slid down the line y = −(x − x0): gravity's component along it.
  for (int i : {0, 2}) {
    const double x0 = i == 0 ? 0.0 : 2.0;
    EXPECT_LT(x[3 * i + 1], -0.1);
    EXPECT_NEAR(x[3 * i + 1], -(x[3 * i] - x0), 1e-12);
    EXPECT_NEAR(x[3 * i + 2], 0.0, 1e-15);
  }
  // The free point fell twice as far (full gravity instead of half).
  EXPECT_NEAR(x[4] / x[1], 2.0, 1e-9);
}
