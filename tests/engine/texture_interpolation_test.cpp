// TextureInterpolation: u = (s − min)/(max − min), v = 0 from a field (its
// range, or min_value/max_value), the mean of the components with
// scalarField = 0, following a linked state; without a field, the planar
// mapping of the coordinates on their bounding box.
#include <gtest/gtest.h>

#include "core/roles.h"
#include "engine/texture_interpolation.h"
#include "test_scene.h"

namespace sinew::texture_interpolation_test {

using test::get;
using test::load;

TEST(TextureInterpolation, FieldValuesToTextureCoordinates) {
  auto s = load(R"(<Node>
    <Node name="f"><MechanicalObject template="Vec1d" name="u" position="2 4 7 12"/></Node>
    <TextureInterpolation template="Vec1d" name="auto" input_states="@f/u.position"/>
    <TextureInterpolation template="Vec1d" name="manual" input_states="@f/u.position" manual_scale="1"
                          min_value="0" max_value="20"/>
    <TextureInterpolation template="Vec2d" name="mean" scalarField="0" input_states="1 3  5 5  0 0"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  const auto& a = get<TextureInterpolation>(*s.root, "auto")->output_coordinates.get();
  ASSERT_EQ(a.size(), 4u);
  EXPECT_DOUBLE_EQ(a[0][0], 0.0);
  EXPECT_DOUBLE_EQ(a[1][0], 0.2);
  EXPECT_DOUBLE_EQ(a[2][0], 0.5);
  EXPECT_DOUBLE_EQ(a[3][0], 1.0);
  for (const auto& t : a) EXPECT_EQ(t[1], 0.0);
  const auto& m = get<TextureInterpolation>(*s.root, "manual")->output_coordinates.get();
  EXPECT_DOUBLE_EQ(m[3][0], 0.6);
  // Means 2, 5, 0: range [0, 5].
  const auto& mean = get<TextureInterpolation>(*s.root, "mean")->output_coordinates.get();
  ASSERT_EQ(mean.size(), 3u);
  EXPECT_DOUBLE_EQ(mean[0][0], 0.4);
  EXPECT_DOUBLE_EQ(mean[1][0], 1.0);
  EXPECT_DOUBLE_EQ(mean[2][0], 0.0);
  // The field changes: the coordinates follow at the next read.
  auto* u = s.root->find_child_named("f")->mechanical_state;
  u->write(kPosition)[3] = 22;
  get<Component>(*s.root->find_child_named("f"), "u")->find_field("position")->touch();
  EXPECT_DOUBLE_EQ(get<TextureInterpolation>(*s.root, "auto")->output_coordinates.get()[2][0], 0.25);
}

TEST(TextureInterpolation, PlanarMappingWithoutAField) {
  auto s = load(R"(<Node><TextureInterpolation template="Vec1d" name="t"
                   input_coordinates="0 1 5  2 1 5  0 1 9  1 1 7"/></Node>)");
  ASSERT_TRUE(s.root);
  // y is flat: u along z (from 5 to 9), v along x (from 0 to 2).
  const auto& t = get<TextureInterpolation>(*s.root, "t")->output_coordinates.get();
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0], Vec2(0, 0));
  EXPECT_EQ(t[1], Vec2(0, 1));
  EXPECT_EQ(t[2], Vec2(1, 0));
  EXPECT_EQ(t[3], Vec2(0.5, 0.5));
}

}  // namespace sinew::texture_interpolation_test
