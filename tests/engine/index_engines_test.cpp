// PointsFromIndices, ValuesFromIndices, IndexValueMapper (SOFA's Engine/Select and Engine/Transform).
#include <gtest/gtest.h>

#include "engine/index_value_mapper.h"
#include "engine/points_from_indices.h"
#include "engine/values_from_indices.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using D = std::vector<double>;
std::vector<std::string> errors(const scene::LoadedScene& s) {
  return test::messages(s.root->diagnostics(), Severity::error);
}
}  // namespace

TEST(PointsFromIndices, SelectsDistinctPointsInIndexOrder) {
  auto s = load(R"(<Node><PointsFromIndices name="p" position="0 0 0  1 0 0  2 0 0  1 0 0" indices="2 0 2 3 1"/></Node>)");
  auto* p = get<PointsFromIndices>(*s.root, "p");
  ASSERT_TRUE(p);
  // Index 2 repeated and point 3 equal to point 1: each distinct point once, as SOFA.
  EXPECT_EQ(p->indices_position.get().data, (D{2, 0, 0, 0, 0, 0, 1, 0, 0}));
}

TEST(PointsFromIndices, DefaultsToTheContextStateAndFollowsIt) {
  auto s = load(R"(<Node><MechanicalObject name="mo" position="0 0 0  1 2 3  4 5 6"/>
    <Node name="c"><PointsFromIndices name="p" indices="1"/></Node></Node>)");
  auto* p = get<PointsFromIndices>(*s.root->children()[0], "p");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->indices_position.get().data, (D{1, 2, 3}));
  get<MechanicalObject>(*s.root, "mo")->position.edit().data[3] = 7;
  EXPECT_EQ(p->indices_position.get().data, (D{7, 2, 3}));
  p->indices.set({2});
  EXPECT_EQ(p->indices_position.get().data, (D{4, 5, 6}));
}

TEST(PointsFromIndices, OutOfRangeIndexIsAnError) {
  auto s = test::build(R"(<Node><PointsFromIndices name="p" position="0 0 0  1 0 0" indices="1 5"/></Node>)");
  init_root(*s.root);
  auto* p = get<PointsFromIndices>(*s.root, "p");
  EXPECT_EQ(p->indices_position.get().data, (D{1, 0, 0}));
  EXPECT_TRUE(test::any_contains(errors(s), "beyond the 2 points"));
}

TEST(PointsFromIndices, EmptyInputs) {
  auto s = load(R"(<Node><PointsFromIndices name="p" position="0 0 0" indices=""/></Node>)");
  EXPECT_TRUE(get<PointsFromIndices>(*s.root, "p")->indices_position.get().data.empty());
}

TEST(ValuesFromIndices, KeepsOrderAndRepeats) {
  auto s = load(R"(<Node>
    <ValuesFromIndices name="v" template="Vec3" in="0 0 0  1 1 1  2 2 2" indices="2 2 0"/>
    <ValuesFromIndices name="s" template="double" input="10 20 30" indices="1"/>
  </Node>)");
  auto* v = get<ValuesFromIndices>(*s.root, "v");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->out.get().data, (D{2, 2, 2, 2, 2, 2, 0, 0, 0}));
  EXPECT_EQ(v->out_str.get(), "2 2 2 2 2 2 0 0 0");
  v->indices.set({1});
  EXPECT_EQ(v->out.get().data, (D{1, 1, 1}));
  EXPECT_EQ(get<ValuesFromIndices>(*s.root, "s")->out.get().data, (D{20}));
  EXPECT_TRUE(v->find_field("output"));
}

TEST(ValuesFromIndices, OutOfRangeIndexIsAnErrorAndEmptyInputGivesEmptyOutput) {
  auto s = test::build(R"(<Node><ValuesFromIndices name="v" in="1 2 3" indices="0 1"/>
    <ValuesFromIndices name="e" indices=""/></Node>)");
  init_root(*s.root);
  EXPECT_EQ(get<ValuesFromIndices>(*s.root, "v")->out.get().data, (D{1, 2, 3}));
  EXPECT_TRUE(test::any_contains(errors(s), "invalid input index 1: 1 >= 1"));
  EXPECT_TRUE(get<ValuesFromIndices>(*s.root, "e")->out.get().data.empty());
}

TEST(IndexValueMapper, WritesValueAtIndicesAndFillsGaps) {
  auto s = load(R"(<Node>
    <IndexValueMapper name="a" indices="1 3" value="5"/>
    <IndexValueMapper name="b" indices="0 4" value="7" defaultValue="2" inputValues="@a.outputValues"/>
  </Node>)");
  auto* a = get<IndexValueMapper>(*s.root, "a");
  auto* b = get<IndexValueMapper>(*s.root, "b");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->output_values.get(), (D{1, 5, 1, 5}));
  EXPECT_EQ(b->output_values.get(), (D{7, 5, 1, 5, 7}));
  a->value.set(9);  // follows through the chain
  EXPECT_EQ(b->output_values.get(), (D{7, 9, 1, 9, 7}));
}

TEST(IndexValueMapper, EmptyIndicesCopyTheInput) {
  auto s = load(R"(<Node><IndexValueMapper name="a" inputValues="1 2" value="5"/></Node>)");
  EXPECT_EQ(get<IndexValueMapper>(*s.root, "a")->output_values.get(), (D{1, 2}));
}
