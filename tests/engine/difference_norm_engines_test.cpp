// DifferenceEngine (SOFA's Engine/Transform) and NormEngine (Engine/Generate),
// chained as in examples/Demos/rigidifiedSectionsInBeam.scn.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/difference_engine.h"
#include "engine/norm_engine.h"
#include "engine/values_from_indices.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using D = std::vector<double>;
}  // namespace

TEST(DifferenceEngine, SubtractsComponentWise) {
  auto s = load(R"(<Node>
    <DifferenceEngine name="d" input="1 2 3  4 5 6" substractor="0.5 2 -1  4 0 6"/>
    <DifferenceEngine name="d1" template="Vec1" input="3 1" substractor="1 3"/>
  </Node>)");
  auto* d = get<DifferenceEngine>(*s.root, "d");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->output.get().data, (D{0.5, 0, 4, 0, 5, 0}));
  EXPECT_EQ(d->output.get().width, 3);
  d->substractor.set(FlatVec{3, {1, 1, 1, 1, 1, 1}});
  EXPECT_EQ(d->output.get().data, (D{0, 1, 2, 3, 4, 5}));
  auto* d1 = get<DifferenceEngine>(*s.root, "d1");
  ASSERT_TRUE(d1);
  EXPECT_EQ(d1->output.get().data, (D{2, -2}));
}

TEST(DifferenceEngine, SizeMismatchWarnsAndKeepsTheOutput) {
  auto s = load(R"(<Node><DifferenceEngine name="d" input="1 2 3  4 5 6" substractor="1 1 1"/></Node>)");
  auto* d = get<DifferenceEngine>(*s.root, "d");
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->output.get().data.empty());
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "differ in size"));
}

TEST(NormEngine, EveryNormType) {
  auto s = load(R"(<Node>
    <NormEngine name="n2" input="3 -4 0  1 2 2  0 0 0"/>
    <NormEngine name="n1" input="3 -4 0" normType="1"/>
    <NormEngine name="n0" input="3 -4 0" normType="0"/>
    <NormEngine name="ninf" input="3 -4 0" normType="-1"/>
    <NormEngine name="n3" input="1 -2 2" normType="3"/>
  </Node>)");
  EXPECT_EQ(get<NormEngine>(*s.root, "n2")->output.get(), (D{5, 3, 0}));
  EXPECT_EQ(get<NormEngine>(*s.root, "n1")->output.get(), (D{7}));
  EXPECT_EQ(get<NormEngine>(*s.root, "n0")->output.get(), (D{2}));
  EXPECT_EQ(get<NormEngine>(*s.root, "ninf")->output.get(), (D{4}));
  EXPECT_NEAR(get<NormEngine>(*s.root, "n3")->output.get().at(0), std::cbrt(17.0), 1e-14);
}

// The chain of rigidifiedSectionsInBeam.scn: distances between selected points.
TEST(NormEngine, DistancesFromValuesFromIndicesAndDifference) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  3 4 0  0 0 2"/>
    <ValuesFromIndices name="a" template="Vec3" in="@dofs.position" indices="0 0 1"/>
    <ValuesFromIndices name="b" template="Vec3" in="@dofs.position" indices="1 2 2"/>
    <DifferenceEngine name="diff" input="@b.out" substractor="@a.out"/>
    <NormEngine name="norm" input="@diff.output"/>
  </Node>)");
  auto* n = get<NormEngine>(*s.root, "norm");
  ASSERT_TRUE(n);
  const D& out = n->output.get();
  ASSERT_EQ(out.size(), 3u);
  EXPECT_DOUBLE_EQ(out[0], 5.0);
  EXPECT_DOUBLE_EQ(out[1], 2.0);
  EXPECT_DOUBLE_EQ(out[2], std::sqrt(29.0));
}
