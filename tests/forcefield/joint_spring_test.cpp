// JointSpringForceField (SOFA's JointSpring text and algorithm): the parser
// (defaults, carried-over stiffnesses, round trip, bad input), forces from
// known stretches and rotations (clamped, hinge, angular limits), add_dforce
// against finite differences of add_force where SOFA's tangent is exact, the
// assembled matrix against add_dforce, and SOFA's example scenes run to the end.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "badinput_helpers.h"
#include "forcefield/spring/joint_spring.h"
#include "forcefield/spring/joint_spring_force_field.h"
#include "math/rigid.h"
#include "runner/session.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;
using sinew::joints::JointSpring;
using sinew::test::dense_stiffness;
using sinew::test::dforce;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;

namespace {

// Unit quaternion of a rotation by `angle` about `axis` (normalised here).
Quat axis_angle(Vec3 axis, double angle) {
  axis.normalize();
  const double s = std::sin(angle / 2);
  return {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(angle / 2)};
}

std::string rigid_text(const Vec3& c, const Quat& q) {
  std::ostringstream o;
  o.precision(17);
  o << c[0] << " " << c[1] << " " << c[2] << " " << q.x << " " << q.y << " " << q.z << " " << q.w;
  return o.str();
}

// Two frames in one state, one joint spring between them.
struct Pair {
  scene::LoadedScene s;
  JointSpringForceField* ff = nullptr;
  MechanicalState* st = nullptr;
  Pair(const Vec3& c1, const Quat& q1, const Vec3& c2, const Quat& q2, const std::string& spring) {
    s = load(R"(<Node gravity="0 0 0"><MechanicalObject template="Rigid3" name="dofs" position=")" + rigid_text(c1, q1) +
             "  " + rigid_text(c2, q2) + R"("/><JointSpringForceField name="ff" template="Rigid3" spring=")" + spring +
             R"("/></Node>)");
    ff = get<JointSpringForceField>(*s.root, "ff");
    st = s.root->mechanical_state;
  }
  std::vector<double> x() { return st->write(kPosition); }
  std::vector<double> force() { return force_at(*ff, *st, x()); }
};

void expect_vec(const std::vector<double>& f, std::size_t at, const Vec3& v, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[at + i], v[i], tol) << "component " << at + i;
}

// Moves every frame of x by h·d (d: 6 numbers per frame, world-frame ω).
std::vector<double> displaced(const std::vector<double>& x, const std::vector<double>& d, double h) {
  std::vector<double> out = x;
  for (std::size_t i = 0; i < x.size() / 7; ++i) rigid3_add_deriv(&x[7 * i], &d[6 * i], h, &out[7 * i]);
  return out;
}

// Central difference of add_force along d, with the tangent restored at x.
std::vector<double> fd(JointSpringForceField& ff, MechanicalState& st, const std::vector<double>& x,
                       const std::vector<double>& d, double h) {
  const auto fp = force_at(ff, st, displaced(x, d, h));
  const auto fm = force_at(ff, st, displaced(x, d, -h));
  std::vector<double> out(fp.size());
  for (std::size_t i = 0; i < fp.size(); ++i) out[i] = (fp[i] - fm[i]) / (2 * h);
  force_at(ff, st, x);
  return out;
}

}  // namespace

// ---------------------------------------------------------------- parser

TEST(JointSpringText, DefaultsAreABallJoint) {
  std::vector<JointSpring> v;
  ASSERT_EQ(joints::parse_joint_springs("BEGIN_SPRING 3 7 END_SPRING", v), "");
  ASSERT_EQ(v.size(), 1u);
  const JointSpring& s = v[0];
  EXPECT_EQ(s.m1, 3u);
  EXPECT_EQ(s.m2, 7u);
  EXPECT_EQ(s.free, (std::array<bool, 6>{false, false, false, true, true, true}));
  EXPECT_EQ(s.soft_trans, 0.0);
  EXPECT_EQ(s.hard_trans, 10000.0);
  EXPECT_EQ(s.soft_rot, 0.0);
  EXPECT_EQ(s.hard_rot, 10000.0);
  EXPECT_EQ(s.bloc_rot, 100.0);  // hard_rot / 100
  EXPECT_EQ(s.kd, 0.0);
  EXPECT_EQ(s.limits[0], -100000.0);
  EXPECT_EQ(s.limits[5], 100000.0);
  EXPECT_FALSE(s.init_from_positions);
  EXPECT_EQ(s.init_rot.w, 1.0);
}

TEST(JointSpringText, ReadsEveryKeywordAndHoldsAxesWithEqualLimits) {
  std::vector<JointSpring> v;
  ASSERT_EQ(joints::parse_joint_springs("  BEGIN_SPRING  0 1  FREE_AXIS 1 0 0 1 1 1  KS_T 10 30000  KS_R 5 200000 "
                                        "KS_B 77 KD 1e-1\n\t R_LIM_X -0.8 0.8  R_LIM_Y 0 0  R_LIM_Z -1.57 1.57 "
                                        "REST_T 1 2 3 REST_R 0 0 0.6 0.8 END_SPRING\n",
                                        v),
            "");
  ASSERT_EQ(v.size(), 1u);
  const JointSpring& s = v[0];
  EXPECT_EQ(s.free, (std::array<bool, 6>{true, false, false, true, false, true}));  // y: limits 0 0
  EXPECT_EQ(s.soft_trans, 10.0);
  EXPECT_EQ(s.hard_trans, 30000.0);
  EXPECT_EQ(s.soft_rot, 5.0);
  EXPECT_EQ(s.hard_rot, 200000.0);
  EXPECT_EQ(s.bloc_rot, 77.0);
  EXPECT_EQ(s.kd, 0.1);
  EXPECT_EQ(s.limits, (std::array<double, 6>{-0.8, 0.8, 0, 0, -1.57, 1.57}));
  EXPECT_EQ(s.init_trans, Vec3(1, 2, 3));
  EXPECT_EQ(s.init_rot.z, 0.6);
  EXPECT_EQ(s.init_rot.w, 0.8);
  EXPECT_TRUE(s.init_from_positions);
}

// SOFA reads every spring into the same object: KS_T, KS_R and KD carry over,
// the axes, limits, KS_B and rest offsets do not.
TEST(JointSpringText, StiffnessesCarryOverToTheNextSpring) {
  std::vector<JointSpring> v;
  ASSERT_EQ(joints::parse_joint_springs("BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 1 KS_T 1 2 KS_R 3 400 KS_B 9 KD 0.5 "
                                        "R_LIM_Z -1 1 END_SPRING BEGIN_SPRING 2 3 END_SPRING",
                                        v),
            "");
  ASSERT_EQ(v.size(), 2u);
  const JointSpring& s = v[1];
  EXPECT_EQ(s.soft_trans, 1.0);
  EXPECT_EQ(s.hard_trans, 2.0);
  EXPECT_EQ(s.soft_rot, 3.0);
  EXPECT_EQ(s.hard_rot, 400.0);
  EXPECT_EQ(s.kd, 0.5);
  EXPECT_EQ(s.bloc_rot, 4.0);  // reset, then hard_rot / 100
  EXPECT_EQ(s.free, (std::array<bool, 6>{false, false, false, true, true, true}));
  EXPECT_EQ(s.limits[5], 100000.0);
}

TEST(JointSpringText, RoundTrip) {
  const std::string text =
      "BEGIN_SPRING 4 9 FREE_AXIS 0 1 0 0 0 1 KS_T 10 100000 KS_R 1000 10000 KS_B 3 KD 0.1 R_LIM_Z -0.5 0.25 "
      "REST_R 0 0.6 0 0.8 END_SPRING";
  std::vector<JointSpring> a, b;
  ASSERT_EQ(joints::parse_joint_springs(text, a), "");
  const std::string written = joints::format_joint_spring(a[0]);
  EXPECT_EQ(written,
            "BEGIN_SPRING  4 9  FREE_AXIS 0 1 0 0 0 1  KS_T 10 100000  KS_R 1000 10000  KS_B 3  KD 0.1  "
            "R_LIM_Z -0.5 0.25  REST_R 0 0.6 0 0.8  END_SPRING\n");
  ASSERT_EQ(joints::parse_joint_springs(written, b), "");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(joints::format_joint_spring(b[0]), written);
  EXPECT_EQ(b[0].free, a[0].free);
  EXPECT_EQ(b[0].limits, a[0].limits);
  EXPECT_EQ(b[0].bloc_rot, a[0].bloc_rot);
  // Defaults are left out.
  ASSERT_EQ(joints::parse_joint_springs("BEGIN_SPRING 0 1 END_SPRING", a), "");
  EXPECT_EQ(joints::format_joint_spring(a[0]), "BEGIN_SPRING  0 1  END_SPRING\n");
  // Nothing, or only white space: no spring.
  EXPECT_EQ(joints::parse_joint_springs(" \n\t ", a), "");
  EXPECT_TRUE(a.empty());
}

TEST(JointSpringText, BadInputIsReportedWithTheSpringNumber) {
  std::vector<JointSpring> v;
  const auto err = [&](const char* t) { return joints::parse_joint_springs(t, v); };
  EXPECT_NE(err("BEGIN_SPRING 0 1 END_SPRING BEGIN_SPRING 0 1 KS_Q 1 END_SPRING").find("spring 1: unknown keyword 'KS_Q'"),
            std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING 0 1 KS_T 1 2").find("missing END_SPRING"), std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING 0 1 FREE_AXIS 0 0 2 0 0 0 END_SPRING").find("FREE_AXIS"), std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING -1 1 END_SPRING").find("two frame indices"), std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING 0 END_SPRING").find("two frame indices"), std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING 0 1 KS_T 1 x END_SPRING").find("KS_T expects numbers, found 'x'"), std::string::npos);
  EXPECT_NE(err("BEGIN_SPRING 0 1 REST_T 1 2").find("REST_T"), std::string::npos);
  EXPECT_NE(err("0 1 END_SPRING").find("expected BEGIN_SPRING"), std::string::npos);
}

TEST(JointSpringForceField, BadSpringTextOrIndexStopsTheComponentWithItsName) {
  test::TempDir dir;
  auto o = test::run_xml(dir, R"(<Node gravity="0 0 0"><DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver/>
    <MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/><UniformMass totalMass="1"/>
    <JointSpringForceField name="hinge" template="Rigid3" spring="BEGIN_SPRING 0 1 KS_X 1 END_SPRING"/></Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"hinge", "unknown keyword 'KS_X'"})) << o.all();
  o = test::run_xml(dir, R"(<Node gravity="0 0 0"><DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver/>
    <MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/><UniformMass totalMass="1"/>
    <JointSpringForceField name="hinge" template="Rigid3" spring="BEGIN_SPRING 0 5 END_SPRING"/></Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"hinge", "out of range"})) << o.all();
  o = test::run_xml(dir, R"(<Node gravity="0 0 0"><DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver/>
    <MechanicalObject template="Vec3" position="0 0 0  1 0 0"/><UniformMass totalMass="1"/>
    <JointSpringForceField name="hinge" spring="BEGIN_SPRING 0 1 END_SPRING"/></Node>)");
  EXPECT_FALSE(o.errors.empty()) << o.all();
  test::expect_no_silent_garbage(o);
}

// ---------------------------------------------------------------- forces

TEST(JointSpringForceField, HeldTranslationsPullWithTheHardStiffness) {
  // No REST_T: the rest offset is zero, the whole centre offset is the stretch.
  Pair p(Vec3(0, 0, 0), Quat{}, Vec3(1.5, 0.2, -0.3), Quat{}, "BEGIN_SPRING 0 1 KS_T 0 1000 END_SPRING");
  ASSERT_EQ(p.ff->state(), ComponentState::valid);
  const auto f = p.force();
  expect_vec(f, 0, Vec3(1500, 200, -300), 1e-9);
  expect_vec(f, 3, Vec3(0, 0, 0), 1e-12);
  expect_vec(f, 6, Vec3(-1500, -200, 300), 1e-9);
  expect_vec(f, 9, Vec3(0, 0, 0), 1e-12);
  EXPECT_FALSE(p.ff->potential_energy().has_value());  // SOFA computes none (reports 0)
}

TEST(JointSpringForceField, StiffnessPerAxisOfTheFirstFrame) {
  // First frame turned 90° about z: its x axis is the world y axis. Free
  // translation along local x (soft 10), held along y and z (hard 1000).
  const Quat q1 = axis_angle(Vec3(0, 0, 1), M_PI / 2);
  Pair p(Vec3(1, 1, 1), q1, Vec3(1.5, 3, 1), q1, "BEGIN_SPRING 0 1 FREE_AXIS 1 0 0 1 1 1 KS_T 10 1000 END_SPRING");
  // Offset (0.5, 2, 0) world = (2, −0.5, 0) local → local force (20, −500, 0) → world (500, 20, 0).
  const auto f = p.force();
  expect_vec(f, 0, Vec3(500, 20, 0), 1e-9);
  expect_vec(f, 6, Vec3(-500, -20, 0), 1e-9);
}

TEST(JointSpringForceField, VelocityDamping) {
  Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), Quat{}, "BEGIN_SPRING 0 1 KD 2 END_SPRING");
  std::vector<double> v = {0.5, 0, 0, 0, 0, 1, 1.5, -1, 0, 0, 0, 3};
  const auto f = force_at(*p.ff, *p.st, p.x(), &v);
  expect_vec(f, 0, Vec3(2, -2, 0), 1e-12);  // kd·(v2 − v1)
  expect_vec(f, 3, Vec3(0, 0, 4), 1e-12);   // kd·(ω2 − ω1)
  expect_vec(f, 6, Vec3(-2, 2, 0), 1e-12);
  expect_vec(f, 9, Vec3(0, 0, -4), 1e-12);
}

TEST(JointSpringForceField, ClampedRotationGivesKTimesTheRotationVector) {
  // Second frame turned by 0.1 rad about n relative to the first (itself turned):
  // torque on the first frame = R1·(kr·0.1·n), opposite on the second.
  const Vec3 n = Vec3(1, 2, 2) / 3;
  const Quat q1 = axis_angle(Vec3(0.3, -1, 0.5), 0.7);
  const Quat q2 = quat_mul(q1, axis_angle(n, 0.1));
  Pair p(Vec3(0, 0, 0), q1, Vec3(0, 0, 0), q2, "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 0 KS_R 0 2000 END_SPRING");
  const auto f = p.force();
  const Vec3 t = quat_rotate(q1, n * (2000 * 0.1));
  expect_vec(f, 3, t, 1e-9);
  expect_vec(f, 9, -t, 1e-9);
  expect_vec(f, 0, Vec3(0, 0, 0), 1e-12);
}

TEST(JointSpringForceField, HingeAboutZ) {
  // Free rotation about z (soft 1000), hard 10000 about x and y.
  const std::string spring = "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 1 KS_R 1000 10000 END_SPRING";
  {  // a twist about z: soft torque 1000·θ about z
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(0, 0, 1), 0.3), spring);
    const auto f = p.force();
    expect_vec(f, 3, Vec3(0, 0, 300), 1e-9);
  }
  {  // a tilt α about x: the z axis leaves its place; torque kr·α·sin α about x (SOFA's hinge law)
    const double a = 0.2;
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(1, 0, 0), a), spring);
    const auto f = p.force();
    expect_vec(f, 3, Vec3(10000 * a * std::sin(a), 0, 0), 1e-9);
  }
}

TEST(JointSpringForceField, AngularLimitsUseTheBlocStiffnessBeyondThem) {
  // Free about y within ±0.5 rad; held about x and z (KS_R 0 10000, so KS_B = 100).
  const std::string spring =
      "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 1 0 KS_R 0 10000 R_LIM_Y -0.5 0.5 END_SPRING";
  {  // inside the limits: the hinge law, zero soft stiffness → no torque
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(0, 1, 0), 0.3), spring);
    expect_vec(p.force(), 3, Vec3(0, 0, 0), 1e-9);
  }
  {  // 0.7 rad: 0.2 beyond the limit, pulled back with 100 → 20 about y
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(0, 1, 0), 0.7), spring);
    const auto f = p.force();
    expect_vec(f, 3, Vec3(0, 20, 0), 1e-9);
    EXPECT_NEAR(p.ff->work()[0].lawful[1], 0.5, 1e-15);
    EXPECT_EQ(p.ff->work()[0].kr[1], 100.0);  // the tangent uses the bloc stiffness too
  }
  {  // −0.9 rad: beyond the lower limit → +40 about y
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(0, 1, 0), -0.9), spring);
    expect_vec(p.force(), 3, Vec3(0, -40, 0), 1e-9);
  }
  {  // two free axes inside their limits (general case): soft torque 50·0.3 about y
    Pair p(Vec3(0, 0, 0), Quat{}, Vec3(0, 0, 0), axis_angle(Vec3(0, 1, 0), 0.3),
           "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 1 1 0 KS_R 50 10000 R_LIM_Y -0.5 0.5 END_SPRING");
    expect_vec(p.force(), 3, Vec3(0, 15, 0), 1e-9);
  }
}

// ---------------------------------------------------------------- tangent

// With isotropic stiffnesses and no relative rotation, SOFA's tangent (per-axis
// stiffness of the last force) is the exact derivative: check all 12 DoFs.
TEST(JointSpringForceField, DForceMatchesFiniteDifferencesWhereSofasTangentIsExact) {
  const Quat q = axis_angle(Vec3(1, -2, 0.5), 0.8);
  Pair p(Vec3(0.1, 0.2, 0.3), q, Vec3(1.1, -0.4, 0.9), q,
         "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 0 KS_T 0 700 KS_R 0 300 END_SPRING");
  const auto x = p.x();
  p.force();
  const std::vector<double> d = {0.3, -0.7, 0.2, 0.5, 0.1, -0.4, -0.6, 0.25, 0.9, -0.3, 0.8, 0.2};
  const auto df = dforce(*p.ff, *p.st, d);
  const auto num = fd(*p.ff, *p.st, x, d, 1e-6);
  for (std::size_t i = 0; i < df.size(); ++i) EXPECT_NEAR(df[i], num[i], 1e-4) << "dof " << i;
  // kfactor scales it.
  const auto df2 = dforce(*p.ff, *p.st, d, -0.25);
  for (std::size_t i = 0; i < df.size(); ++i) EXPECT_NEAR(df2[i], -0.25 * df[i], 1e-12);
}

// Anisotropic translation stiffness in a turned frame: exact for displacements
// of the centres (SOFA leaves out the frame-rotation terms).
TEST(JointSpringForceField, DForceMatchesFiniteDifferencesOnPositions) {
  const Quat q1 = axis_angle(Vec3(0.2, 1, -0.4), 1.1);
  const Quat q2 = quat_mul(q1, axis_angle(Vec3(1, 1, 0), 0.05));
  Pair p(Vec3(0, 0, 0), q1, Vec3(0.7, -0.2, 0.4), q2,
         "BEGIN_SPRING 0 1 FREE_AXIS 1 0 0 0 0 0 KS_T 15 900 KS_R 0 300 END_SPRING");
  const auto x = p.x();
  p.force();
  const std::vector<double> d = {0.3, -0.7, 0.2, 0, 0, 0, -0.6, 0.25, 0.9, 0, 0, 0};
  const auto df = dforce(*p.ff, *p.st, d);
  const auto num = fd(*p.ff, *p.st, x, d, 1e-6);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(df[i], num[i], 1e-5) << "dof " << i;
  for (std::size_t i = 6; i < 9; ++i) EXPECT_NEAR(df[i], num[i], 1e-5) << "dof " << i;
  // The rotation stiffness on a small rotation of the second frame: kr·R1·R1ᵀ·δθ to first order.
  const std::vector<double> r = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0.2, -0.5, 0.3};
  const auto dr = dforce(*p.ff, *p.st, r);
  const auto nr = fd(*p.ff, *p.st, x, r, 1e-6);
  for (std::size_t i = 9; i < 12; ++i) EXPECT_NEAR(dr[i], nr[i], 0.05 * 300 * 0.6) << "dof " << i;
}

TEST(JointSpringForceField, AssembledStiffnessEqualsDForce) {
  const Quat q1 = axis_angle(Vec3(0.2, 1, -0.4), 1.1);
  const Quat q2 = quat_mul(q1, axis_angle(Vec3(0, 0, 1), 0.9));
  Pair p(Vec3(0, 0, 0), q1, Vec3(0.7, -0.2, 0.4), q2,
         "BEGIN_SPRING 0 1 FREE_AXIS 0 1 0 1 0 1 KS_T 15 900 KS_R 40 300 R_LIM_Z -0.5 0.5 END_SPRING");
  p.force();
  const auto K = dense_stiffness(*p.ff, *p.st);
  const std::vector<double> d = {0.3, -0.7, 0.2, 0.5, 0.1, -0.4, -0.6, 0.25, 0.9, -0.3, 0.8, 0.2};
  const auto df = dforce(*p.ff, *p.st, d);
  for (std::size_t i = 0; i < 12; ++i) {
    double kd = 0;
    for (std::size_t j = 0; j < 12; ++j) kd += K[i * 12 + j] * d[j];
    EXPECT_NEAR(kd, df[i], 1e-9) << "row " << i;
  }
  // Symmetric.
  for (std::size_t i = 0; i < 12; ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_NEAR(K[i * 12 + j], K[j * 12 + i], 1e-9);
}

// ---------------------------------------------------------------- scenes

namespace {
namespace fs = std::filesystem;

// Runs SOFA's example scene for `steps` steps as `sinew run` does.
test::Outcome run_example(const std::string& rel, long steps) {
  const fs::path scene = fs::path(SINEW_DATA_DIR) / "examples" / rel;
  test::Outcome o;
  if (!fs::exists(scene)) return o;
  runner::SessionOptions opts;
  opts.data_paths = {(fs::path(SINEW_DATA_DIR) / "share").string(), (fs::path(SINEW_DATA_DIR) / "examples").string()};
  runner::Session session(scene.string(), opts);
  o.loaded = session.loaded();
  o.init_ok = session.ok();
  if (o.init_ok)
    for (long i = 0; i < steps; ++i)
      if (!session.step()) break;
  o.steps = session.steps_done();
  if (o.init_ok) o.finite = test::all_finite(session.root());
  o.errors = test::messages(session.diagnostics(), Severity::error);
  o.warnings = test::messages(session.diagnostics(), Severity::warning);
  return o;
}
}  // namespace

class JointSpringExample : public ::testing::TestWithParam<const char*> {};

TEST_P(JointSpringExample, RunsToTheEnd) {
  if (!fs::exists(fs::path(SINEW_DATA_DIR) / "examples" / GetParam())) GTEST_SKIP() << "SOFA data absent";
  const auto o = run_example(GetParam(), 100);
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
}

INSTANTIATE_TEST_SUITE_P(Scenes, JointSpringExample,
                         ::testing::Values("Component/SolidMechanics/Spring/JointSpringForceField.scn",
                                           "Component/Mapping/NonLinear/RigidRigidMapping.scn",
                                           "Component/Constraint/Projective/FixedRotationProjectiveConstraint.scn",
                                           "Component/Mapping/Linear/SkinningMapping.scn"));

// infile: one line of 6 numbers per spring and evaluation (first frame's axes),
// from the start again after the end; outfile: SOFA's text record of each spring.
TEST(JointSpringForceField, InfileForcesAndOutfileRecords) {
  test::TempDir dir;
  const std::string in = dir.write("forces.txt", "1 2 3 0 0 0.5\n-1 0 0 0 0 0\n");
  const std::string out = (std::filesystem::path(in).parent_path() / "out.txt").string();
  const Quat q1 = axis_angle(Vec3(0, 0, 1), M_PI / 2);
  auto s = load(R"(<Node gravity="0 0 0"><MechanicalObject template="Rigid3" name="dofs" position=")" +
                rigid_text(Vec3(0, 0, 0), q1) + "  " + rigid_text(Vec3(0, 0, 0), q1) +
                R"("/><JointSpringForceField name="ff" template="Rigid3" infile=")" + in + R"(" outfile=")" + out +
                R"(" spring="BEGIN_SPRING 0 1 END_SPRING"/></Node>)");
  auto* ff = get<JointSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  auto f = force_at(*ff, st, st.write(kPosition));
  expect_vec(f, 0, Vec3(-2, 1, 3), 1e-12);  // (1, 2, 3) in the frame turned 90° about z
  expect_vec(f, 3, Vec3(0, 0, 0.5), 1e-12);
  f = force_at(*ff, st, st.write(kPosition));
  expect_vec(f, 0, Vec3(0, -1, 0), 1e-12);
  // As std::getline in SOFA: the read after the last line gives an empty line (no
  // force) and sets eof; the next one starts again from the first line.
  f = force_at(*ff, st, st.write(kPosition));
  expect_vec(f, 0, Vec3(0, 0, 0), 1e-12);
  f = force_at(*ff, st, st.write(kPosition));
  expect_vec(f, 0, Vec3(-2, 1, 3), 1e-12);
  std::ifstream rec(out);
  std::string first, second;
  std::getline(rec, first);
  std::getline(rec, second);
  EXPECT_EQ(first, "T= 0");
  EXPECT_EQ(second.rfind("  Xrel= 0 0 0 0 0 0 1", 0), 0u) << second;
}

TEST(JointSpringForceField, AStateThatLosesASpringEndStopsTheForceField) {
  Pair p(Vec3(0, 0, 0), Quat{}, Vec3(1, 0, 0), Quat{}, "BEGIN_SPRING 0 1 KS_T 0 10 END_SPRING");
  p.force();
  p.st->resize(1);
  std::vector<double> x = {0, 0, 0, 0, 0, 0, 1};
  const auto f = force_at(*p.ff, *p.st, x);
  EXPECT_EQ(p.ff->state(), ComponentState::invalid);
  EXPECT_EQ(f, std::vector<double>(6, 0.0));
}

// A frame hanging from a fixed one by a joint spring held in translation
// (REST_T: rest offset from the initial positions): under gravity it settles
// m·g/k lower, without turning, with the iterative solver (add_dforce) and with
// a direct one (build_stiffness).
TEST(JointSpringForceField, HangingFrameSettlesAtMgOverK) {
  for (const char* linear : {"<CGLinearSolver iterations='100' tolerance='1e-16' threshold='1e-20'/>",
                             "<SparseLDLSolver/>"}) {
    auto s = load(std::string(R"(<Node gravity="0 -10 0" dt="0.02"><DefaultAnimationLoop/>
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="1"/>)") + linear + R"(
      <MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/>
      <UniformMass vertexMass="2 1 [1 0 0,0 1 0,0 0 1]"/>
      <FixedProjectiveConstraint indices="0"/>
      <JointSpringForceField name="ff" spring="BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 0 KS_T 0 1000 KS_R 0 500 REST_T 0 0 0 END_SPRING"/>
    </Node>)");
    for (int i = 0; i < 2000; ++i) animate(*s.root);
    const auto& x = s.root->mechanical_state->read(kPosition);
    EXPECT_NEAR(x[7], 1.0, 1e-9) << linear;
    EXPECT_NEAR(x[8], -2 * 10.0 / 1000, 1e-9) << linear;
    EXPECT_NEAR(x[9], 0.0, 1e-9) << linear;
    EXPECT_NEAR(x[13], 1.0, 1e-9) << linear;  // no rotation
    for (const Message& m : s.root->diagnostics().messages()) EXPECT_NE(m.severity, Severity::error) << Diagnostics::format(m);
  }
}
