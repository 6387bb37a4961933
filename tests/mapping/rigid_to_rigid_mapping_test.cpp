// RigidMapping Rigid3d → Rigid3d: frames attached to a frame, on a hand-made
// case (the conformance battery checks J, Jᵀ and the geometric stiffness).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(RigidMappingRigid3dToRigid3d, FrameFollowsItsParentFrame) {
  // Parent at (1, 2, 3) turned 90° about z; child frame at local (1, 0, 0), turned 90° about x.
  auto s = test::load(R"(<Node name="root">
    <MechanicalObject name="in" template="Rigid3d" position="1 2 3 0 0 0.7071067811865476 0.7071067811865476"/>
    <Node name="child">
      <MechanicalObject name="out" template="Rigid3d" position="1 0 0 0.7071067811865476 0 0 0.7071067811865476"/>
      <RigidMapping name="map" template="Rigid3d,Rigid3d"/>
    </Node>
  </Node>)");
  auto* out = test::get<MechanicalState>(*s.root->find_child_named("child"), "out");
  auto* in = test::get<MechanicalState>(*s.root, "in");
  ASSERT_TRUE(out && in);
  const std::vector<double>& x = out->read(kPosition);
  ASSERT_EQ(x.size(), 7u);
  // centre = c + R_z(90°)·(1, 0, 0) = (1, 3, 3); orientation q_z·q_x = (½, ½, ½, ½)
  const std::vector<double> want = {1, 3, 3, 0.5, 0.5, 0.5, 0.5};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(x[k], want[k], 1e-15) << k;

  // Velocity: v_out = v + ω × (R·local) = (0,0,0) + (0,0,1) × (0,1,0) = (−1, 0, 0); ω_out = ω.
  in->write(kVelocity) = {0, 0, 0, 0, 0, 1};
  auto* map = test::get<Mapping>(*s.root->find_child_named("child"), "map");
  map->apply_j(kVelocity, kVelocity);
  const std::vector<double>& v = out->read(kVelocity);
  const std::vector<double> vw = {-1, 0, 0, 0, 0, 1};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(v[k], vw[k], 1e-15) << k;

  // Forces: F = f, τ = τ_out + (R·local) × f = (0,0,2) + (0,1,0) × (1,0,0) = (0, 0, 1).
  out->write(kForce) = {1, 0, 0, 0, 0, 2};
  in->write(kForce) = {0, 0, 0, 0, 0, 0};
  map->apply_jt(kForce, kForce);
  const std::vector<double>& f = in->read(kForce);
  const std::vector<double> fw = {1, 0, 0, 0, 0, 1};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(f[k], fw[k], 1e-15) << k;
}

}  // namespace
}  // namespace sinew
