// SOFA's SubsetMultiMapping example: two Vec3d grids and two Rigid3d grids, two points of
// each concatenated into one Vec3d state carrying the mass, the spheres and a constant force
// on its point 0. Only that force acts (the spheres never touch), so the first input's
// point 0 (its centre, for the frames) moves along +x and nothing else moves.
#include <gtest/gtest.h>

#include "badinput_helpers.h"
#include "test_paths.h"

namespace sinew {
namespace {

const MechanicalState& state_at(runner::Session& s, std::initializer_list<const char*> path, const char* name) {
  Node* n = &s.root();
  for (const char* p : path) n = n ? n->find_child_named(p) : nullptr;
  if (!n) throw std::runtime_error("node not found");
  const auto* st = test::get<MechanicalState>(*n, name);
  if (!st) throw std::runtime_error("state not found");
  return *st;
}

TEST(SubsetMultiMappingExample, ConcatenatedPointsCarryTheForceBackToTheirInputs) {
  std::vector<double> vec1, vec2, all, rig1, rig2;
  const test::Outcome o = test::run_sofa_example("Component/Mapping/Linear/SubsetMultiMapping.scn", 20,
                                                 [&](runner::Session& s) {
                                                   vec1 = state_at(s, {"object1"}, "dof1").read(kPosition);
                                                   vec2 = state_at(s, {"object1", "object2"}, "dof2").read(kPosition);
                                                   all = state_at(s, {"object1", "object2", "concatenation"}, "dofall")
                                                             .read(kPosition);
                                                   rig1 = state_at(s, {"rigid1"}, "dof1").read(kPosition);
                                                   rig2 = state_at(s, {"rigid1", "origid2"}, "dof2").read(kPosition);
                                                 });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  // Grid 2×2 on [0,1]² (translated): point 0 of the first input moved along +x only.
  ASSERT_EQ(vec1.size(), 12u);
  ASSERT_EQ(all.size(), 12u);
  EXPECT_GT(vec1[0], 0.01);
  EXPECT_EQ(vec1[1], 0.0);
  EXPECT_EQ(vec1[2], 0.0);
  for (std::size_t i = 3; i < 12; ++i) EXPECT_EQ(vec1[i], (std::vector<double>{1, 0, 0, 0, 1, 0, 1, 1, 0})[i - 3]);
  EXPECT_EQ(vec2[0], 2.0);  // the second input's mapped points feel no force
  // The concatenation is (dof1[0], dof1[1], dof2[0], dof2[1]).
  EXPECT_EQ(all[0], vec1[0]);
  EXPECT_EQ(all[3], vec1[3]);
  EXPECT_EQ(all[6], vec2[0]);
  EXPECT_EQ(all[9], vec2[3]);
  // Rigid3d → Vec3d: the frames' centres, the same motion as the Vec3d part.
  ASSERT_EQ(rig1.size(), 28u);
  EXPECT_EQ(rig1[0], vec1[0]);
  EXPECT_EQ(rig1[1], 2.0);
  EXPECT_EQ(rig1[6], 1.0);  // orientation untouched
  EXPECT_EQ(rig2[0], 2.0);
}

TEST(IdentityMultiMappingExample, RunsAndMovesTheForcedPoint) {
  std::vector<double> vec1, all;
  const test::Outcome o = test::run_sofa_example("Component/Mapping/Linear/IdentityMultiMapping.scn", 20,
                                                 [&](runner::Session& s) {
                                                   vec1 = state_at(s, {"object1"}, "dof1").read(kPosition);
                                                   all = state_at(s, {"object1", "object2", "concatenation"}, "dofall")
                                                             .read(kPosition);
                                                 });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  ASSERT_EQ(all.size(), 24u);  // both 2×2 grids
  EXPECT_GT(vec1[0], 0.01);
  EXPECT_EQ(all[0], vec1[0]);
}

}  // namespace
}  // namespace sinew
