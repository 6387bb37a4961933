// TransformPosition (SOFA's Engine/Transform): every method, fixedIndices, files, lazy updates.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/transform_position.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using D = std::vector<double>;
void expect_near(const D& a, const D& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << "at " << i;
}
}  // namespace

TEST(TransformPosition, Methods) {
  auto s = load(R"(<Node>
    <TransformPosition name="plane" origin="0 0 1" normal="0 0 2" input_position="1 2 3  4 5 -1"/>
    <TransformPosition name="tr" method="translation" translation="1 2 3" input_position="1 1 1" fixedIndices=""/>
    <TransformPosition name="rot" method="rotation" rotation="0 0 90" input_position="1 0 0"/>
    <TransformPosition name="sc" method="scale" origin="1 1 1" scale="2 3 4" input_position="2 2 2"/>
    <TransformPosition name="st" method="scaleTranslation" scale="2 3 4" translation="1 1 1" input_position="1 1 1"/>
    <TransformPosition name="srt" method="scaleRotationTranslation" scale="2 1 1" rotation="0 0 90"
                       translation="0 0 1" input_position="1 0 0"/>
    <TransformPosition name="aff" method="affine" matrix="2 0 0 1  0 1 0 0  0 0 1 0  0 0 0 2"
                       input_position="1 2 3" fixedIndices=""/>
  </Node>)");
  auto out = [&](const char* n) { return get<TransformPosition>(*s.root, n)->output_position.get().data; };
  expect_near(out("plane"), D{1, 2, 1, 4, 5, 1});  // normal normalised at init
  EXPECT_EQ(get<TransformPosition>(*s.root, "plane")->normal.get(), Vec3(0, 0, 1));
  expect_near(out("tr"), D{2, 3, 4});
  expect_near(out("rot"), D{0, 1, 0});
  expect_near(out("sc"), D{3, 4, 5});
  expect_near(out("st"), D{3, 4, 5});
  expect_near(out("srt"), D{0, 2, 1});
  expect_near(out("aff"), D{1.5, 1, 1.5});  // (2+1, 2, 3, 2) / 2
}

TEST(TransformPosition, FixedIndicesAndLazyUpdate) {
  auto s = load(R"(<Node><TransformPosition name="t" method="translation" translation="1 0 0"
      input_position="0 0 0  1 1 1  2 2 2" fixedIndices="1"/></Node>)");
  auto* t = get<TransformPosition>(*s.root, "t");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->output_position.get().data, (D{1, 0, 0, 1, 1, 1, 3, 2, 2}));
  t->translation.set(Vec3(0, 0, 5));
  EXPECT_EQ(t->output_position.get().data, (D{0, 0, 5, 1, 1, 1, 2, 2, 7}));
  t->input_position.set(FlatVec{3, {9, 9, 9}});
  t->fixed_indices.set({});
  EXPECT_EQ(t->output_position.get().data, (D{9, 9, 14}));
  t->method.set("scale");
  t->scale.set(Vec3(2, 2, 2));
  EXPECT_EQ(t->output_position.get().data, (D{18, 18, 18}));
}

TEST(TransformPosition, EmptyInputAndBadInput) {
  auto s = test::build(R"(<Node>
    <TransformPosition name="e" method="translation" translation="1 0 0"/>
    <TransformPosition name="u" method="shear" translation="1 0 0" input_position="0 0 0"/>
    <TransformPosition name="f" method="translation" input_position="0 0 0" fixedIndices="3"/>
    <TransformPosition name="r" method="random" input_position="1 2 3"/>
    <TransformPosition name="nf" method="fromFile" input_position="1 2 3"/>
  </Node>)");
  init_root(*s.root);
  const auto errs = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(get<TransformPosition>(*s.root, "e")->output_position.get().data.empty());
  EXPECT_EQ(get<TransformPosition>(*s.root, "u")->output_position.get().data, (D{1, 0, 0}));
  EXPECT_TRUE(test::any_contains(errs, "unknown method 'shear'"));
  EXPECT_TRUE(test::any_contains(errs, "fixedIndices: 3 is beyond the 1 input points"));
  EXPECT_EQ(get<TransformPosition>(*s.root, "r")->output_position.get().data, (D{1, 2, 3}));
  EXPECT_TRUE(test::any_contains(errs, "random method"));
  EXPECT_EQ(get<TransformPosition>(*s.root, "nf")->output_position.get().data, (D{1, 2, 3}));
  EXPECT_TRUE(test::any_contains(errs, "without 'filename'"));
}

TEST(TransformPosition, FromFiles) {
  test::TempDir dir;
  const std::string tfm = dir.write("a.tfm",
                                    "#Insight Transform File V1.0\nTransform: AffineTransform_double_3_3\n"
                                    "Parameters: 1 0 0 0 0 -1 0 1 0 0 2 0\nFixedParameters: 0 0 0\n");
  const std::string trm = dir.write("b.trm", "1 2 3\n0 1 0\n1 0 0\n0 0 1\n");
  const std::string xfm = dir.write("c.xfm", "1 0 0 1\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  auto s = load("<Node><TransformPosition name=\"a\" method=\"fromFile\" filename=\"" + tfm +
                "\" input_position=\"1 2 3\"/><TransformPosition name=\"b\" method=\"fromFile\" filename=\"" + trm +
                "\" input_position=\"1 2 3\"/><TransformPosition name=\"c\" method=\"fromFile\" filename=\"" + xfm +
                "\" input_position=\"1 2 3\"/></Node>");
  // .tfm: rows (1 0 0), (0 0 -1), (0 1 0); translation read backwards: (0, 2, 0).
  EXPECT_EQ(get<TransformPosition>(*s.root, "a")->output_position.get().data, (D{1, -1, 2}));
  auto* b = get<TransformPosition>(*s.root, "b");
  EXPECT_EQ(b->output_position.get().data, (D{3, 3, 6}));  // (2+1, 1+2, 3+3)
  EXPECT_EQ(b->translation.get(), Vec3(1, 2, 3));
  EXPECT_EQ(get<TransformPosition>(*s.root, "c")->output_position.get().data, (D{2, 2, 3}));
}
