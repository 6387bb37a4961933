// FixedRotationProjectiveConstraint: the swing–twist projection of SOFA's
// component (rotations about the flagged world axes go back to their initial
// values, the other rotations are kept), applied to positions only.
#include <gtest/gtest.h>

#include <cmath>

#include "math/quat.h"
#include "projective/fixed_rotation_projective_constraint.h"
#include "test_scene.h"

using namespace sinew;

namespace {

Quat rot(double ax, double ay, double az, double angle) {
  const double n = std::sqrt(ax * ax + ay * ay + az * az), s = std::sin(angle / 2) / n;
  return {ax * s, ay * s, az * s, std::cos(angle / 2)};
}

void expect_quat(const Quat& a, const Quat& b, double tol = 1e-14) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
  EXPECT_NEAR(a.w, b.w, tol);
}

}  // namespace

TEST(FixedRotation, TwistAboutAFixedAxisGoesBackToItsInitialValue) {
  // Pure rotation about z: replaced by the initial one.
  expect_quat(fix_rotation(rot(0, 0, 1, 0.7), rot(0, 0, 1, 0.2), false, false, true), rot(0, 0, 1, 0.2));
  // Swing about x then twist about z (q = swing·twist): the swing stays, the twist goes.
  const Quat q = quat_mul(rot(1, 0, 0, 0.3), rot(0, 0, 1, 0.4));
  expect_quat(fix_rotation(q, Quat{}, false, false, true), rot(1, 0, 0, 0.3));
  // No axis fixed: unchanged.
  expect_quat(fix_rotation(q, rot(0, 1, 0, 1.0), false, false, false), q);
  // All three fixed, a rotation about y: back to the initial rotation about y.
  expect_quat(fix_rotation(rot(0, 1, 0, 0.9), rot(0, 1, 0, 0.5), true, true, true), rot(0, 1, 0, 0.5));
  // A half turn about an axis perpendicular to z has no twist about z: kept as is.
  expect_quat(fix_rotation(rot(1, 0, 0, M_PI), Quat{}, false, false, true), quat_normalized(rot(1, 0, 0, M_PI)));
}

TEST(FixedRotation, ProjectsPositionsOnly) {
  auto s = test::load(R"(<Node gravity="0 0 0">
    <MechanicalObject template="Rigid3" name="dofs" position="1 2 3 0 0 0 1"/>
    <FixedRotationProjectiveConstraint name="c" template="Rigid3" FixedZRotation="1"/></Node>)");
  auto* c = test::get<FixedRotationProjectiveConstraint>(*s.root, "c");
  ASSERT_NE(c, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  const Quat q = quat_mul(rot(1, 0, 0, 0.3), rot(0, 0, 1, 0.4));
  auto& x = st.write(kPosition);
  q.store(&x[3]);
  c->project_position(kPosition, 0);
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(x[2], 3.0);
  expect_quat(Quat::from(&x[3]), rot(1, 0, 0, 0.3));
  auto& v = st.write(kVelocity);
  v = {1, 2, 3, 4, 5, 6};
  c->project_velocity(kVelocity, 0);
  EXPECT_EQ(v, (std::vector<double>{1, 2, 3, 4, 5, 6}));
}
