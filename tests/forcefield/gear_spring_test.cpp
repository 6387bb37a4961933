// GearSpringForceField (SOFA's GearSpring text and algorithm): the parser
// (defaults, carried-over values, bad input), the angle about a gear axis,
// the coupling torques of a known rotation, add_dforce against finite
// differences where SOFA's tangent is exact, the assembled matrix against
// add_dforce, and SOFA's example scene.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "badinput_helpers.h"
#include "forcefield/spring/gear_spring.h"
#include "forcefield/spring/gear_spring_force_field.h"
#include "math/rigid.h"
#include "spring_helpers.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace gear_spring_test {

using gears::GearSpring;

Quat about(const Vec3& axis, double angle) {
  const Vec3 a = axis.normalized();
  const double s = std::sin(angle / 2);
  return {a[0] * s, a[1] * s, a[2] * s, std::cos(angle / 2)};
}

TEST(GearSpringText, DefaultsCarriedOverValuesAndAxisReset) {
  std::vector<GearSpring> s;
  ASSERT_EQ(gears::parse_gear_springs(
                "BEGIN_SPRING 0 1 2 3 END_SPRING\n"
                "\tBEGIN_SPRING  4 0 6 2 AXIS 1 1 KS_T 2000000  KS_R 300 400 KD 1 RATIO 2 END_SPRING "
                "BEGIN_SPRING 4 0 5 1 RATIO -1.5385 END_SPRING",
                s),
            "");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].p1, 0u);
  EXPECT_EQ(s[0].m1, 1u);
  EXPECT_EQ(s[0].p2, 2u);
  EXPECT_EQ(s[0].m2, 3u);
  EXPECT_EQ(s[0].hard_trans, 10000);
  EXPECT_EQ(s[0].soft_rot, 10000);
  EXPECT_EQ(s[0].hard_rot, 10000);
  EXPECT_EQ(s[0].kd, 10000);  // SOFA's default damping
  EXPECT_EQ(s[0].ratio, 1);
  EXPECT_EQ(s[1].axis[0], 1u);
  EXPECT_EQ(s[1].axis[1], 1u);
  EXPECT_EQ(s[1].hard_trans, 2000000);
  EXPECT_EQ(s[1].soft_rot, 300);
  EXPECT_EQ(s[1].hard_rot, 400);
  // The third spring keeps the second's stiffnesses and damping, not its axes.
  EXPECT_EQ(s[2].axis[0], 0u);
  EXPECT_EQ(s[2].axis[1], 0u);
  EXPECT_EQ(s[2].hard_trans, 2000000);
  EXPECT_EQ(s[2].kd, 1);
  EXPECT_EQ(s[2].ratio, -1.5385);
}

TEST(GearSpringText, BadTextIsRefusedWithTheSpringAndTheToken) {
  std::vector<GearSpring> s;
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 END_SPRING", s).find("four frame indices"),
            std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 3 AXIS 3 0 END_SPRING", s).find("AXIS"), std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 3 RATIO 0 END_SPRING", s).find("RATIO"), std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 3 KS_T x END_SPRING", s).find("'x'"), std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 3 END_SPRING BEGIN_SPRING 0 1 2 3 FOO", s)
                .find("spring 1: unknown keyword 'FOO'"),
            std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("BEGIN_SPRING 0 1 2 3 KD 1", s).find("missing END_SPRING"), std::string::npos);
  EXPECT_NE(gears::parse_gear_springs("0 1 2 3", s).find("expected BEGIN_SPRING"), std::string::npos);
}

TEST(GearSpring, AngleAroundAnAxisIsTheRotationAboutIt) {
  const double a[7] = {1, 2, 3, 0, 0, 0, 1};
  for (double angle : {0.3, -0.7, 2.5}) {
    double b[7] = {1, 2, 3};
    about(Vec3(0, 0, 1), angle).store(b + 3);
    EXPECT_NEAR(gears::angle_around_axis(a, b, 2), angle, 1e-14);
    // About x, the rotation shows on y only: the mean of |θ| (about ±z, not x) and 0.
    EXPECT_NEAR(gears::angle_around_axis(a, b, 0), std::abs(angle) / 2, 1e-14);
  }
  // Relative to a rotated first frame, about its own axis.
  double r[7] = {0, 0, 0}, s[7] = {0, 0, 0};
  const Quat q = about(Vec3(1, 2, 3), 0.8);
  q.store(r + 3);
  quat_mul(q, about(Vec3(0, 1, 0), 0.25)).store(s + 3);
  EXPECT_NEAR(gears::angle_around_axis(r, s, 1), 0.25, 1e-14);
}

std::string frames(const std::vector<std::pair<Vec3, Quat>>& f) {
  std::ostringstream o;
  o.precision(17);
  for (const auto& [c, q] : f) o << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << q.x << ' ' << q.y << ' ' << q.z << ' ' << q.w << ' ';
  return o.str();
}

struct Gears {
  scene::LoadedScene s;
  GearSpringForceField* ff = nullptr;
  MechanicalObject* mo = nullptr;
};
Gears load_gears(const std::string& positions, const std::string& springs) {
  Gears g;
  g.s = test::load("<Node gravity='0 0 0'><MechanicalObject name='dofs' template='Rigid3d' position='" + positions +
                   "'/><GearSpringForceField name='ff' spring='" + springs + "'/></Node>");
  if (!g.s.root) return g;
  g.ff = test::get<GearSpringForceField>(*g.s.root, "ff");
  g.mo = test::get<MechanicalObject>(*g.s.root, "dofs");
  return g;
}

// Two gears on their own initial frames (pivot = gear), axes z, ratio 2:
// gear 1 turned by θ gives f = −ks·(2θ + 0), torque f about z on gear 1 and
// f/2 on gear 2; nothing else (the axes stay aligned, no translation, no velocity).
TEST(GearSpringForceField, TurningOneGearTorquesBothByTheRatio) {
  Gears g = load_gears(frames({{Vec3(0, 0, 0), Quat{}}, {Vec3(3, 0, 0), Quat{}}}),
                       "BEGIN_SPRING 0 0 1 1 AXIS 2 2 KS_T 500 KS_R 100 1000 KD 0 RATIO 2 END_SPRING");
  ASSERT_TRUE(g.ff && g.mo);
  std::vector<double> x = g.mo->read(kPosition);
  about(Vec3(0, 0, 1), 0.1).store(&x[3]);
  const std::vector<double> f = test::force_at(*g.ff, *g.mo, x);
  const double expected[12] = {0, 0, 0, 0, 0, -20, 0, 0, 0, 0, 0, -10};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(f[i], expected[i], 1e-12) << i;
  EXPECT_NEAR(g.ff->work()[0].angle1, 0.1, 1e-15);
  // Tilting gear 2 off its axis: held back by the hard rotational stiffness.
  x = g.mo->read(kPosition);
  about(Vec3(1, 0, 0), 0.05).store(&x[10]);
  const std::vector<double> f2 = test::force_at(*g.ff, *g.mo, x);
  EXPECT_NEAR(f2[9], -1000 * 0.05, 1e-9);
}

// Moves frame i by the rigid derivative d·h (centre + rotation vector).
std::vector<double> moved(const std::vector<double>& x, const std::vector<double>& d, double h) {
  std::vector<double> out(x.size());
  for (std::size_t i = 0; i < x.size() / 7; ++i) rigid3_add_deriv(&x[7 * i], &d[6 * i], h, &out[7 * i]);
  return out;
}

// Gears on distinct pivots at rest: SOFA's tangent is the derivative of the
// force there (central differences), and the assembled matrix is add_dforce.
TEST(GearSpringForceField, TangentAtRestAndMatrixEqualAddDforce) {
  const Quat q0 = about(Vec3(0.3, 1, 0.2), 0.4), q1 = about(Vec3(1, 0.1, 0.5), -0.9);
  Gears g = load_gears(frames({{Vec3(0, 0, 0), q0}, {Vec3(3, 1, 0), q1}, {Vec3(0, 0, 0), q0}, {Vec3(3, 1, 0), q1}}),
                       "BEGIN_SPRING 2 0 3 1 AXIS 2 1 KS_T 500 KS_R 100 1000 KD 0 RATIO -1.5 END_SPRING");
  ASSERT_TRUE(g.ff && g.mo);
  const std::vector<double> x0 = g.mo->read(kPosition);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> dx(24, 0.0);
  // The gears move: any translation, rotations about their gear axes only (the
  // angle about an axis, a mean of two angles between axes, has no derivative
  // at rest in the other directions; SOFA's coupling also ignores the pivots).
  const Vec3 a0 = quat_to_matrix(q0).col(2), a1 = quat_to_matrix(q1).col(1);
  for (int i : {0, 1, 2, 6, 7, 8}) dx[i] = u(rng);
  const double s0 = u(rng), s1 = u(rng);
  for (int c = 0; c < 3; ++c) dx[3 + c] = s0 * a0[c], dx[9 + c] = s1 * a1[c];
  const double h = 1e-6;
  const std::vector<double> fp = test::force_at(*g.ff, *g.mo, moved(x0, dx, h));
  const std::vector<double> fm = test::force_at(*g.ff, *g.mo, moved(x0, dx, -h));
  test::force_at(*g.ff, *g.mo, x0);
  const std::vector<double> df = test::dforce(*g.ff, *g.mo, dx);
  double scale = 0;
  for (double v : df) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 1.0);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(df[i], (fp[i] - fm[i]) / (2 * h), 1e-5 * scale) << i;
  // The assembled matrix reproduces add_dforce for any dx (pivots included), away from rest too.
  std::vector<double> x = x0;
  about(Vec3(0, 0, 1), 0.3).store(&x[3]);
  test::force_at(*g.ff, *g.mo, x);
  for (double& v : dx) v = u(rng);
  const std::vector<double> df2 = test::dforce(*g.ff, *g.mo, dx);
  const std::vector<double> K = test::dense_stiffness(*g.ff, *g.mo);
  for (int i = 0; i < 24; ++i) {
    double kx = 0;
    for (int j = 0; j < 24; ++j) kx += K[i * 24 + j] * dx[j];
    EXPECT_NEAR(kx, df2[i], 1e-9 * (1 + std::abs(df2[i]))) << i;
  }
}

TEST(GearSpringForceField, IndicesBeyondTheStateAreAnError) {
  test::TempDir dir;
  const test::Outcome o = test::run_xml(
      dir,
      "<Node><DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver/>"
      "<MechanicalObject template='Rigid3d' position='0 0 0 0 0 0 1'/><UniformMass template='Rigid3d'/>"
      "<GearSpringForceField spring='BEGIN_SPRING 0 0 5 5 END_SPRING'/></Node>");
  EXPECT_TRUE(test::any_contains(o.errors, "out of range")) << o.all();
}

// SOFA's example: the gears turn together; its rigidIndexPerPoint (5 entries
// for 8 frames, the old per-rigid counts) is ignored as SOFA ignores it, with a warning.
TEST(GearSpringForceField, SofaExampleRunsWithAWarningOnItsRigidIndexPerPoint) {
  const test::Outcome o = test::run_sofa_example("Component/SolidMechanics/Spring/GearSpringForceField.scn", 100);
  if (!o.loaded) GTEST_SKIP() << "SOFA data absent";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  EXPECT_TRUE(test::any_contains(o.warnings, "rigidIndexPerPoint has 5 entries for 8 mapped points")) << o.all();
}

}  // namespace gear_spring_test
}  // namespace sinew
