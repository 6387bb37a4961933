// OglColorMap's palettes (SOFA's helper::ColorMap) and DataDisplay's range
// (what SOFA's drawVisual computes before drawing): hand-computed colours,
// SOFA's quirks (the "Red to Yellow" option gives the HSV palette), the size
// checks, userRange and the maximal range over time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_scene.h"
#include "visual/color_map.h"
#include "visual/drawing/data_display.h"
#include "visual/rendering2d/ogl_color_map.h"

namespace sinew {
namespace {

void expect_rgba(const Rgba& c, float r, float g, float b, float a, const char* what) {
  EXPECT_NEAR(c[0], r, 1e-6f) << what;
  EXPECT_NEAR(c[1], g, 1e-6f) << what;
  EXPECT_NEAR(c[2], b, 1e-6f) << what;
  EXPECT_NEAR(c[3], a, 1e-6f) << what;
}

TEST(ColorMap, PalettesAsSofaBuildsThem) {
  // HSV: hue i/(n−1)·360: red, then green at 120°, blue at 240°, red again at 360°.
  const auto hsv = build_palette(4, "HSV");
  ASSERT_EQ(hsv.size(), 4u);
  expect_rgba(hsv[0], 1, 0, 0, 1, "HSV 0");
  expect_rgba(hsv[1], 0, 1, 0, 1, "HSV 120");
  expect_rgba(hsv[2], 0, 0, 1, 1, "HSV 240");
  expect_rgba(hsv[3], 1, 0, 0, 1, "HSV 360");
  // Blue to Red: hue from 240° down to 0°.
  const auto b2r = build_palette(3, "Blue to Red");
  expect_rgba(b2r.front(), 0, 0, 1, 1, "blue end");
  expect_rgba(b2r[1], 0, 1, 0, 1, "middle, 120°");
  expect_rgba(b2r.back(), 1, 0, 0, 1, "red end");
  // Single-hue ramps: 0.3 + 1.4·i/n on the first half, then the others rise.
  const auto red = build_palette(4, "Red");
  expect_rgba(red[0], 0.3f, 0, 0, 1, "Red 0");
  expect_rgba(red[1], 0.65f, 0, 0, 1, "Red 1");
  expect_rgba(red[3], 1, 0.35f, 0.35f, 1, "Red 3");
  expect_rgba(build_palette(4, "Yellow to Red")[2], 1, 0.5f, 0, 1, "Yellow to Red 2");
  // SOFA's ColorMap knows this preset as "Red to Yello": the option falls back to HSV, as "Custom".
  EXPECT_EQ(build_palette(8, "Red to Yellow"), build_palette(8, "HSV"));
  EXPECT_EQ(build_palette(8, "Custom"), build_palette(8, "HSV"));
  EXPECT_EQ(build_palette(1, "Red").size(), 256u);  // below 2 colours: 256
}

TEST(ColorMap, EvaluatorInterpolatesBetweenNeighbours) {
  const std::vector<Rgba> p = {{0, 0, 0, 1}, {1, 0, 0, 1}, {1, 1, 0, 1}};
  expect_rgba(evaluate_palette(p, 0, 2, -1), 0, 0, 0, 1, "below");
  expect_rgba(evaluate_palette(p, 0, 2, 0.5), 0.5f, 0, 0, 1, "first interval");
  expect_rgba(evaluate_palette(p, 0, 2, 1.5), 1, 0.5f, 0, 1, "second interval");
  expect_rgba(evaluate_palette(p, 0, 2, 2), 1, 1, 0, 1, "top");
  expect_rgba(evaluate_palette(p, 1, 1, 5), 0, 0, 0, 1, "empty range: first colour");
}

TEST(DataDisplay, RangeChecksAndMaximalRange) {
  auto s = test::load(R"(<Node name="root">
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
      <MeshTopology name="mesh" triangles="0 1 2  1 3 2"/>
      <Node name="v">
        <DataDisplay name="dd" topology="@../mesh" triangleData="2 -1"/>
        <OglColorMap name="map" colorScheme="Blue to Red" min="@dd.currentMin" max="@dd.currentMax"/>
        <IdentityMapping input="@../dofs" output="@dd"/>
      </Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  Node& v = *s.root->find_child_named("v");
  auto* dd = test::get<DataDisplay>(v, "dd");
  auto* map = test::get<OglColorMap>(v, "map");
  ASSERT_TRUE(dd && map);
  EXPECT_EQ(dd->state(), ComponentState::valid);
  EXPECT_EQ(dd->position.get().size(), 4u);  // the mapping's output
  EXPECT_EQ(dd->current_min.get(), 0.0);     // nothing drawn yet
  DataDisplay::Range r = dd->update_range();
  EXPECT_TRUE(r.cell_data);
  EXPECT_FALSE(r.point_data);
  EXPECT_EQ(r.min, -1.0);
  EXPECT_EQ(r.max, 2.0);
  EXPECT_EQ(map->max.get(), 2.0);  // OglColorMap reads the range through its links
  // Blue to Red over [−1, 2]: −1 is blue, 2 red, NaN the colorNaN colour (black).
  expect_rgba(dd->color_of(-1, r.min, r.max), 0, 0, 1, 1, "min");
  expect_rgba(dd->color_of(2, r.min, r.max), 1, 0, 0, 1, "max");
  expect_rgba(dd->color_of(std::numeric_limits<double>::quiet_NaN(), r.min, r.max), 0, 0, 0, 1, "NaN");
  // maximalRange (default): a narrower range later keeps the widest one seen.
  dd->triangle_data.set({0.5, 0.25});
  r = dd->update_range();
  EXPECT_EQ(r.min, -1.0);
  EXPECT_EQ(r.max, 2.0);
  dd->maximal_range.set(false);
  r = dd->update_range();
  EXPECT_EQ(r.min, 0.25);
  EXPECT_EQ(r.max, 0.5);
  // userRange without maximalRange replaces the range.
  dd->user_range.set(Vec2(0, 10));
  r = dd->update_range();
  EXPECT_EQ(r.min, 0.0);
  EXPECT_EQ(r.max, 10.0);
  // A list that does not match the mesh: an error, nothing coloured.
  dd->triangle_data.set({1, 2, 3});
  r = dd->update_range();
  EXPECT_FALSE(r.cell_data);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "triangleData has 3 values for 2 triangles"));
}

TEST(DataDisplay, WithoutAColorMapUsesSofasDefaultPalette) {
  auto s = test::load(R"(<Node name="root">
      <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
      <Node name="v"><DataDisplay name="dd" pointData="0 1"/><IdentityMapping input="@../dofs" output="@dd"/></Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  auto* dd = test::get<DataDisplay>(*s.root->find_child_named("v"), "dd");
  ASSERT_TRUE(dd);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning),
                                 "an OglColorMap is required by DataDisplay"));
  const auto r = dd->update_range();
  EXPECT_TRUE(r.point_data);
  expect_rgba(dd->color_of(0, r.min, r.max), 1, 0, 0, 1, "HSV start");
}

TEST(OglColorMap, UnknownSchemeIsRefused) {
  auto s = test::build(R"(<Node name="root"><OglColorMap colorScheme="Rainbow"/></Node>)");
  ASSERT_TRUE(s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "colorScheme \"Rainbow\" is not one of OglColorMap's schemes"));
}

}  // namespace
}  // namespace sinew
