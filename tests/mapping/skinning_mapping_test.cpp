// SkinningMapping (Rigid3d → Vec3d): SOFA's 1/d² weights over the nbRef
// nearest frames, the points reproduced at init, blended motion, the forces
// carried back to the frames, and the refusal of explicit weight lists.
#include <gtest/gtest.h>

#include <cmath>

#include "mapping/linear/skinning_mapping.h"
#include "math/quat.h"
#include "test_scene.h"

using namespace sinew;

namespace {

const char* kScene = R"(<Node gravity="0 0 0">
  <MechanicalObject name="frames" template="Rigid3" position="0 0 0 0 0 0 1  2 0 0 0 0 0 1  10 0 0 0 0 0 1"/>
  <Node name="skin"><MechanicalObject name="pts" position="0.5 0 0  2 1 0"/>
    <SkinningMapping name="map" nbRef="2"/></Node></Node>)";

}  // namespace

TEST(SkinningMapping, WeightsAreInverseSquareDistancesOfTheNearestFrames) {
  auto s = test::load(kScene);
  auto* m = dynamic_cast<SkinningMapping*>(s.root->find_child_named("skin")->find_object_named("map"));
  ASSERT_NE(m, nullptr);
  ASSERT_EQ(m->state(), ComponentState::valid);
  // Point 0 at 0.5 from frame 0, 1.5 from frame 1: weights 4 and 4/9, normalised, nearest first.
  EXPECT_EQ(m->frame_index()[0], 0u);
  EXPECT_EQ(m->frame_index()[1], 1u);
  EXPECT_NEAR(m->weights()[0], 4.0 / (4.0 + 4.0 / 9), 1e-15);
  EXPECT_NEAR(m->weights()[1], (4.0 / 9) / (4.0 + 4.0 / 9), 1e-15);
  // Point 1: 1 from frame 1, √5 from frame 0.
  EXPECT_EQ(m->frame_index()[2], 1u);
  EXPECT_EQ(m->frame_index()[3], 0u);
  EXPECT_NEAR(m->weights()[2], 1.0 / 1.2, 1e-15);
}

TEST(SkinningMapping, ReproducesThePointsThenBlendsTheFrameMotions) {
  auto s = test::load(kScene);
  Node* skin = s.root->find_child_named("skin");
  auto* m = dynamic_cast<SkinningMapping*>(skin->find_object_named("map"));
  MechanicalState& out = *skin->mechanical_state;
  MechanicalState& in = *s.root->mechanical_state;
  m->apply(kPosition);
  const auto& p = out.read(kPosition);
  EXPECT_NEAR(p[0], 0.5, 1e-15);
  EXPECT_NEAR(p[4], 1.0, 1e-15);
  // Frame 1 turned 90° about z: point 1 (local (0, 1, 0) from it) goes to (1, 0, 0) from it.
  auto& x = in.write(kPosition);
  const double h = std::sqrt(0.5);
  x[7 + 5] = h, x[7 + 6] = h;
  m->apply(kPosition);
  const double w1 = 1.0 / 1.2, w0 = 0.2 / 1.2;
  EXPECT_NEAR(p[3], w1 * (2 - 1) + w0 * 2, 1e-12);
  EXPECT_NEAR(p[4], w0 * 1, 1e-12);
  // Forces: Σ over the frames of f·w, torques r × f with r = w·R·l.
  auto& f = out.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  f[3] = 0, f[4] = 1, f[5] = 0;
  auto& F = in.write(kForce);
  std::fill(F.begin(), F.end(), 0.0);
  m->apply_jt(kForce, kForce);
  EXPECT_NEAR(F[6 + 1], w1, 1e-15);
  EXPECT_NEAR(F[1], w0, 1e-15);
  EXPECT_NEAR(F[6 + 5], w1 * -1 * 1, 1e-12);  // r = w1·(−1, 0, 0): (r × f)_z = −w1
}

TEST(SkinningMapping, ExplicitWeightListsAreRefused) {
  auto s = test::build(R"(<Node gravity="0 0 0">
    <MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1"/>
    <Node name="skin"><MechanicalObject position="0.5 0 0"/>
    <SkinningMapping name="map" weight="1" indices="0"/></Node></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto* m = dynamic_cast<SkinningMapping*>(s.root->find_child_named("skin")->find_object_named("map"));
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "not supported"));
}
