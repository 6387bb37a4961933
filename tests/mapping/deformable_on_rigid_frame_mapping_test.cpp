// DeformableOnRigidFrameMapping: local points in a rigid frame, on numbers
// worked by hand (frame at (1, 2, 0) turned 90° about z: local x → world y,
// local y → world −x), SOFA's unnormalised quaternion, velocities, forces,
// constraint rows with the frame's scale factors, repartition over two
// frames, and bad input. (Adjoint, finite differences and the Jacobian are
// in the conformance battery.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/node.h"
#include "mapping/linear/deformable_on_rigid_frame_mapping.h"
#include "test_scene.h"

using namespace sinew;

namespace {

constexpr double kS = 0.70710678118654752;  // sin 45° = cos 45°

std::string frame_scene(const std::string& frames, const std::string& map_attrs,
                        const std::string& local = "1 0 0  0 1 0.5") {
  return "<Node name='root' gravity='0 0 0'>"
         "<MechanicalObject name='frames' template='Rigid3d' position='" + frames + "'/>"
         "<Node name='local'><MechanicalObject name='pts' position='" + local + "'/></Node>"
         "<Node name='child'><MechanicalObject name='out'/>"
         "<DeformableOnRigidFrameMapping name='map' input1='@../local/pts' input2='@../frames' output='@out' " +
         map_attrs + "/></Node></Node>";
}

struct Parts {
  scene::LoadedScene s;
  DeformableOnRigidFrameMapping* map = nullptr;
  MechanicalState *frames = nullptr, *pts = nullptr, *out = nullptr;
};

Parts load_parts(const std::string& xml) {
  Parts p;
  p.s = test::load(xml);
  if (!p.s.root) return p;
  p.map = test::get<DeformableOnRigidFrameMapping>(*p.s.root->find_child_named("child"), "map");
  p.frames = p.s.root->get_mechanical_state();
  p.pts = p.s.root->find_child_named("local")->get_mechanical_state();
  p.out = p.s.root->find_child_named("child")->get_mechanical_state();
  return p;
}

void expect_vec(const std::vector<double>& v, const std::vector<double>& want, double tol, const char* what) {
  ASSERT_EQ(v.size(), want.size()) << what;
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_NEAR(v[k], want[k], tol) << what << "[" << k << "]";
}

const std::string kTurned = "1 2 0  0 0 " + std::to_string(kS) + " " + std::to_string(kS);

}  // namespace

TEST(DeformableOnRigidFrameMapping, ApplyPutsLocalPointsInTheFrame) {
  Parts p = load_parts(frame_scene("1 2 0 0 0 0.70710678118654752 0.70710678118654752", ""));
  ASSERT_NE(p.map, nullptr);
  ASSERT_EQ(p.map->state(), ComponentState::valid);
  ASSERT_EQ(p.out->size(), 2u);  // sized as input1
  // (1, 0, 0) → (1, 2, 0) + (0, 1, 0); (0, 1, 0.5) → (1, 2, 0) + (−1, 0, 0.5).
  expect_vec(p.out->read(kPosition), {1, 3, 0, 0, 2, 0.5}, 1e-15, "out");
}

// SOFA reads the scene's quaternion as given (0 0 0.7 0.7 has norm² 0.98)
// and builds the matrix of a unit quaternion from it: x ↦ (0.02, 0.98, 0).
TEST(DeformableOnRigidFrameMapping, UnnormalisedQuaternionAsSofa) {
  Parts p = load_parts(frame_scene("1 2 0 0 0 0.7 0.7", ""));
  ASSERT_NE(p.map, nullptr);
  expect_vec(p.out->read(kPosition), {1.02, 2.98, 0, 1 - 0.98, 2 + 0.02, 0.5}, 1e-15, "out");
}

// v_out = ω × (R·p) + R·ṗ + v: frame velocity (0.1, 0, 0), ω = (0, 0, 1);
// point 0: R·p = (0, 1, 0), ω × it = (−1, 0, 0); ṗ = (0, 0, 2) stays (0, 0, 2).
TEST(DeformableOnRigidFrameMapping, VelocitiesAndForces) {
  Parts p = load_parts(frame_scene("1 2 0 0 0 0.70710678118654752 0.70710678118654752", ""));
  ASSERT_NE(p.map, nullptr);
  p.frames->write(kVelocity) = {0.1, 0, 0, 0, 0, 1};
  p.pts->write(kVelocity) = {0, 0, 2, 1, 0, 0};
  p.map->apply_j(kVelocity, kVelocity);
  // point 1: R·p = (−1, 0, 0.5), ω × it = (0, −1, 0); R·(1, 0, 0) = (0, 1, 0).
  expect_vec(p.out->read(kVelocity), {-0.9, 0, 2, 0.1, 0, 0}, 1e-15, "v_out");

  // Forces f0 = (1, 0, 0), f1 = (0, 0, 2): the frame gets (Σ f, Σ r × f).
  p.out->write(kForce) = {1, 0, 0, 0, 0, 2};
  p.frames->write(kForce) = {0, 0, 0, 0, 0, 0};
  p.pts->write(kForce) = {0, 0, 0, 0, 0, 0};
  p.map->apply_jt(kForce, kForce);
  // r0 × f0 = (0, 1, 0) × (1, 0, 0) = (0, 0, −1); r1 × f1 = (−1, 0, 0.5) × (0, 0, 2) = (0, 2, 0).
  expect_vec(p.frames->read(kForce), {1, 0, 2, 0, 2, -1}, 1e-15, "frame force");
  // Rᵀ(1, 0, 0) = (0, −1, 0); Rᵀ(0, 0, 2) = (0, 0, 2).
  expect_vec(p.pts->read(kForce), {0, -1, 0, 0, 0, 2}, 1e-15, "point forces");
}

// A constraint row on output point 0 along x: input1 gets Rᵀ·n = (0, −1, 0),
// the frame (2·n, 3·(r × n)) = (2, 0, 0, 0, 0, −3) with the scale factors.
TEST(DeformableOnRigidFrameMapping, ConstraintRowsWithScaleFactors) {
  Parts p = load_parts(frame_scene("1 2 0 0 0 0.70710678118654752 0.70710678118654752",
                       "rootLinearForceScaleFactor='2' rootAngularForceScaleFactor='3'"));
  ASSERT_NE(p.map, nullptr);
  for (MechanicalState* s : {p.frames, p.pts, p.out}) s->constraint_jacobian().clear(s->info().deriv_width);
  const double n[3] = {1, 0, 0};
  p.out->constraint_jacobian().add(7, 0, n);
  ASSERT_TRUE(p.map->apply_jt_constraints());
  ConstraintMatrix& j1 = p.pts->constraint_jacobian();
  ConstraintMatrix& j2 = p.frames->constraint_jacobian();
  j1.compress();
  j2.compress();
  ASSERT_EQ(j1.rows().size(), 1u);
  ASSERT_EQ(j2.rows().size(), 1u);
  EXPECT_EQ(j1.rows()[0].id, 7);
  EXPECT_EQ(j1.entries()[0].dof, 0);
  const double* a = j1.value(0);
  EXPECT_NEAR(a[0], 0, 1e-15);
  EXPECT_NEAR(a[1], -1, 1e-15);
  EXPECT_NEAR(a[2], 0, 1e-15);
  const double* b = j2.value(0);
  const double want[6] = {2, 0, 0, 0, 0, -3};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(b[k], want[k], 1e-15) << k;
}

// repartition="1 1": point 0 on frame 0 (identity at the origin), point 1 on
// frame 1; velocities and forces still use frame `index` only (SOFA).
TEST(DeformableOnRigidFrameMapping, RepartitionOverTwoFrames) {
  Parts p = load_parts(frame_scene("0 0 0 0 0 0 1  " + kTurned, "repartition='1 1'"));
  ASSERT_NE(p.map, nullptr);
  expect_vec(p.out->read(kPosition), {1, 0, 0, 0, 2, 0.5}, 1e-6, "out");
  // One value: the same count on every frame (here 1 each).
  Parts q = load_parts(frame_scene("0 0 0 0 0 0 1  " + kTurned, "repartition='1'"));
  ASSERT_NE(q.map, nullptr);
  expect_vec(q.out->read(kPosition), {1, 0, 0, 0, 2, 0.5}, 1e-6, "out");
}

// Without input2 the output copies input1 (one warning); an index past the
// frames and a repartition of the wrong length are errors, never a crash.
TEST(DeformableOnRigidFrameMapping, BadInput) {
  {
    scene::LoadedScene s = test::load(
        "<Node name='root'><Node name='local'><MechanicalObject name='pts' position='1 2 3'/></Node>"
        "<Node name='child'><MechanicalObject name='out'/>"
        "<DeformableOnRigidFrameMapping name='map' input1='@../local/pts' output='@out'/></Node></Node>");
    ASSERT_TRUE(s.root);
    auto* out = s.root->find_child_named("child")->get_mechanical_state();
    expect_vec(out->read(kPosition), {1, 2, 3}, 0, "copy");
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "input2"));
  }
  for (const std::string& attrs : {std::string("index='5'"), std::string("repartition='1 1 1'")}) {
    scene::LoadedScene s = test::build(frame_scene(kTurned, attrs));
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    EXPECT_FALSE(test::messages(s.root->diagnostics(), Severity::error).empty()) << attrs;
    auto* map = test::get<DeformableOnRigidFrameMapping>(*s.root->find_child_named("child"), "map");
    ASSERT_NE(map, nullptr);
    map->apply(kPosition);
    map->apply_j(kVelocity, kVelocity);
    map->apply_jt(kForce, kForce);
  }
  {
    scene::LoadedScene s = test::build(
        "<Node name='root'><MechanicalObject name='frames' template='Rigid3d' position='0 0 0 0 0 0 1'/>"
        "<Node name='child'><MechanicalObject name='out'/>"
        "<DeformableOnRigidFrameMapping name='map' input1='@../frames' input2='@../frames' output='@out'/></Node>"
        "</Node>");
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    auto* map = test::get<DeformableOnRigidFrameMapping>(*s.root->find_child_named("child"), "map");
    ASSERT_NE(map, nullptr);
    EXPECT_EQ(map->state(), ComponentState::invalid);
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "input1 is Rigid3d"));
  }
}
