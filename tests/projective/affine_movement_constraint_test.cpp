// AffineMovementProjectiveConstraint: the rotation Data in SOFA's bracketed
// syntax, x0/xf taken at the first projection, positions between the begin and
// end times on the line from x0 to R·x0 + t (hand-computed), xf after the end,
// velocities and responses zeroed, the Rigid3d quaternion, whole steps, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/simulation.h"
#include "projective/affine_movement_projective_constraint.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

std::string make_scene(const std::string& constraint, const char* positions = "0 0 0  1 2 3  4 5 6",
                  const char* tmpl = "Vec3d") {
  return std::string(R"(<Node name="root" dt="0.1" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <MechanicalObject name="dofs" template=")") + tmpl + "\" position=\"" + positions + "\"/>\n" + constraint +
         "\n</Node>";
}

void project_at(Node& root, double t) {
  root.time.set(t);
  MechanicalOps ops(root);
  ops.project_position(kPosition, t);
}

}  // namespace

TEST(AffineMovementConstraint, RotationReadsSofasBracketedRows) {
  Mat3 m = Mat3::Zero();
  EXPECT_TRUE(parse::read("[0.7 -0.7 0,0.7 0.7 0,0 0 1]", m));
  EXPECT_EQ(m(0, 0), 0.7);
  EXPECT_EQ(m(0, 1), -0.7);
  EXPECT_EQ(m(1, 0), 0.7);
  EXPECT_EQ(m(1, 1), 0.7);
  EXPECT_EQ(m(2, 2), 1.0);
  EXPECT_EQ(m(2, 0), 0.0);
  EXPECT_TRUE(parse::read("1 2 3 4 5 6 7 8 9", m));
  EXPECT_EQ(m(1, 2), 6.0);
  EXPECT_EQ(parse::to_text(m), "[1 2 3,4 5 6,7 8 9]");
  EXPECT_FALSE(parse::read("[1 0 0,0 1", m));  // too short: what was read is kept
  EXPECT_EQ(m(1, 1), 1.0);
  EXPECT_EQ(m(1, 2), 6.0);
}

TEST(AffineMovementConstraint, InterpolatesFromTheFirstPositionsToTheirAffineImage) {
  auto s = load(make_scene(R"(<AffineMovementProjectiveConstraint name="am" indices="1 2" beginConstraintTime="1"
      endConstraintTime="3" translation="0.5 -1 2" rotation="[0 -1 0,1 0 0,0 0 1]"/>)"));
  ASSERT_TRUE(s.root);
  auto* am = get<AffineMovementProjectiveConstraint>(*s.root, "am");
  ASSERT_NE(am, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> start = st.read(kPosition);

  // First projection (t = 0.5, before the begin time): x0 and xf taken, nothing moves.
  project_at(*s.root, 0.5);
  EXPECT_EQ(st.read(kPosition), start);
  // R·(1, 2, 3) + t = (−2, 1, 3) + (0.5, −1, 2) = (−1.5, 0, 5); R·(4, 5, 6) + t = (−4.5, 3, 8).
  const std::vector<double>& xf = am->final_positions();
  ASSERT_EQ(xf.size(), 9u);
  EXPECT_EQ(xf[3], -1.5);
  EXPECT_EQ(xf[4], 0.0);
  EXPECT_EQ(xf[5], 5.0);
  EXPECT_EQ(xf[6], -4.5);
  EXPECT_EQ(xf[7], 3.0);
  EXPECT_EQ(xf[8], 8.0);

  // Moving the points does not change x0: it was taken at the first projection.
  st.write(kPosition).assign({9, 9, 9, 7, 7, 7, 8, 8, 8});
  for (double t : {1.5, 2.0, 2.75, 3.0}) {
    project_at(*s.root, t);
    const double a = (t - 1) / 2;  // fraction of the way from x0 to xf
    const auto& x = st.read(kPosition);
    EXPECT_EQ(x[0], 9.0) << "not constrained";
    const double x0[6] = {1, 2, 3, 4, 5, 6};
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(x[3 + c], x0[c] + a * (xf[3 + c] - x0[c]), 1e-14) << "t " << t << " c " << c;
  }
  // After the end the points sit at xf.
  project_at(*s.root, 10);
  for (int c = 3; c < 9; ++c) EXPECT_EQ(st.read(kPosition)[c], xf[c]);

  // Velocities and responses of the listed DoFs are zeroed, always (even while moving).
  s.root->time.set(2);
  st.write(kVelocity).assign(9, 4.0);
  st.write(kForce).assign(9, 3.0);
  MechanicalOps ops(*s.root);
  ops.project_velocity(kVelocity, 2);
  ops.project_response(kForce);
  EXPECT_EQ(st.read(kVelocity), (std::vector<double>{4, 4, 4, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(st.read(kForce), (std::vector<double>{3, 3, 3, 0, 0, 0, 0, 0, 0}));
}

TEST(AffineMovementConstraint, DefaultRotationIsZeroAndTimesAreZeroAndTwenty) {
  auto s = load(make_scene(R"(<AffineMovementProjectiveConstraint name="am" indices="1" translation="1 2 3"/>)"));
  ASSERT_TRUE(s.root);
  auto* am = get<AffineMovementProjectiveConstraint>(*s.root, "am");
  EXPECT_EQ(am->begin_time.get(), 0.0);
  EXPECT_EQ(am->end_time.get(), 20.0);
  project_at(*s.root, 0);  // t = 0 is not after the begin time: untouched
  EXPECT_EQ(am->final_positions()[3], 1.0);  // SOFA's default matrix is zero: xf = translation
  EXPECT_EQ(am->final_positions()[5], 3.0);
  project_at(*s.root, 10);
  EXPECT_DOUBLE_EQ(s.root->mechanical_state->read(kPosition)[3], 1.0);  // halfway from (1, 2, 3) to (1, 2, 3)
  EXPECT_DOUBLE_EQ(s.root->mechanical_state->read(kPosition)[4], 2.0);
}

TEST(AffineMovementConstraint, Rigid3dTurnsCentresAndComposesOrientations) {
  // A quarter turn about z: q = (0, 0, sin 45°, cos 45°).
  const double h = std::sqrt(0.5);
  auto s = load(make_scene("<AffineMovementProjectiveConstraint name=\"am\" template=\"Rigid3d\" indices=\"0\" "
                      "quaternion=\"0 0 " + parse::format_double(h) + " " + parse::format_double(h) +
                      "\" translation=\"0 0 1\" endConstraintTime=\"1\"/>",
                      "1 0 0 0 0 0 1  5 5 5 0 0 0 1", "Rigid3d"));
  ASSERT_TRUE(s.root);
  auto* am = get<AffineMovementProjectiveConstraint>(*s.root, "am");
  project_at(*s.root, 2);  // after the end: the whole coordinate is xf
  const auto& x = s.root->mechanical_state->read(kPosition);
  EXPECT_NEAR(x[0], 0.0, 1e-6);
  EXPECT_NEAR(x[1], 1.0, 1e-6);
  EXPECT_NEAR(x[2], 1.0, 1e-12);
  EXPECT_NEAR(x[5], h, 1e-6);
  EXPECT_NEAR(x[6], h, 1e-6);
  EXPECT_EQ(x[7], 5.0);  // DoF 1 not listed
  EXPECT_EQ(am->final_positions().size(), 14u);
}

TEST(AffineMovementConstraint, StepsOfTheExampleSceneMoveTheBorderTowardsItsImage) {
  auto s = load(R"(<Node name="root" dt="0.5" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <CGLinearSolver iterations="40" tolerance="1e-10" threshold="1e-10"/>
    <MechanicalObject name="dofs"/>
    <RegularGridTopology nx="3" ny="3" nz="1" xmin="0" xmax="1" ymin="0" ymax="1" zmin="0" zmax="0"/>
    <UniformMass totalMass="1"/>
    <MeshSpringForceField linesStiffness="10"/>
    <AffineMovementProjectiveConstraint name="am" indices="0 1 2 3 5 6 7 8" endConstraintTime="2"
        translation="0.1 0 0" rotation="[0.7 -0.7 0,0.7 0.7 0,0 0 1]"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* am = get<AffineMovementProjectiveConstraint>(*s.root, "am");
  MechanicalState& st = *s.root->mechanical_state;
  for (int i = 0; i < 8; ++i) sinew::animate(*s.root);
  const auto& x = st.read(kPosition);
  const auto& xf = am->final_positions();
  for (unsigned i : {0u, 1u, 2u, 3u, 5u, 6u, 7u, 8u})
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(x[3 * i + c], xf[3 * i + c], 1e-12) << "dof " << i;
  // The free centre point followed the border (pulled by the springs towards the turned square).
  EXPECT_GT(x[3 * 4 + 1], 0.5);
  for (double v : x) EXPECT_TRUE(std::isfinite(v));
}

TEST(AffineMovementConstraint, BadInputIsReported) {
  auto s = sinew::test::build(make_scene(R"(<AffineMovementProjectiveConstraint name="am" indices="1 7"/>)"));
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "index 7 is not valid"));
  EXPECT_EQ(get<AffineMovementProjectiveConstraint>(*s.root, "am")->indices.get(), std::vector<unsigned>{1});
  project_at(*s.root, 1);
}
