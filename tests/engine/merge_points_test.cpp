// MergePoints (SOFA's Engine/Generate): addition, injection, bad mapping, lazy update.
#include <gtest/gtest.h>

#include "engine/merge_points.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using D = std::vector<double>;
using Idx = std::vector<unsigned>;
}  // namespace

TEST(MergePoints, AppendsAndFollowsInputs) {
  auto s = load(R"(<Node><MergePoints name="m" position1="0 0 0  1 1 1" position2="5 5 5"/></Node>)");
  auto* m = get<MergePoints>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->points.get().data, (D{0, 0, 0, 1, 1, 1, 5, 5, 5}));
  EXPECT_EQ(m->indices1.get(), (Idx{0, 1}));
  EXPECT_EQ(m->indices2.get(), (Idx{2}));
  m->position1.set(FlatVec{3, {}});
  EXPECT_EQ(m->points.get().data, (D{5, 5, 5}));
  EXPECT_EQ(m->indices2.get(), (Idx{0}));
}

TEST(MergePoints, InjectsAtMappingAndReportsBadIndices) {
  auto s = test::build(R"(<Node>
    <MergePoints name="m" position1="0 0 0  1 1 1  2 2 2" position2="7 7 7  9 9 9" mappingX2="2 0"/>
    <MergePoints name="bad" position1="0 0 0" position2="7 7 7  8 8 8" mappingX2="4"/>
    <MergePoints name="once" noUpdate="1" position1="0 0 0" position2="1 1 1"/>
  </Node>)");
  init_root(*s.root);
  auto* m = get<MergePoints>(*s.root, "m");
  EXPECT_EQ(m->points.get().data, (D{9, 9, 9, 1, 1, 1, 7, 7, 7}));
  EXPECT_EQ(m->indices1.get(), (Idx{1}));
  EXPECT_EQ(m->indices2.get(), (Idx{0, 2}));
  auto* bad = get<MergePoints>(*s.root, "bad");
  EXPECT_EQ(bad->points.get().data, (D{0, 0, 0}));
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "mappingX2[0] = 4 is beyond the 1 points of position1"));
  auto* once = get<MergePoints>(*s.root, "once");
  EXPECT_EQ(once->points.get().data, (D{0, 0, 0, 1, 1, 1}));  // computed at the first read (lazy, as SOFA)
  once->position2.set(FlatVec{3, {}});
  EXPECT_EQ(once->points.get().data, (D{0, 0, 0, 1, 1, 1}));  // noUpdate: never again
}
