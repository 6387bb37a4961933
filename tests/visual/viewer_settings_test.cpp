// Viewer-side components with SOFA's Data: VisualGrid's lines as SOFA builds them, LineAxis's
// letters, TrailRenderer's stored trail (capped at nbSteps, cleared by reset, colour map text),
// SOFA's fallback for a selectable item that is not in its list, and unknown attributes.
#include <gtest/gtest.h>

#include "core/component.h"
#include "core/node.h"
#include "test_scene.h"
#include "visual/color_map.h"
#include "visual/drawing/line_axis.h"
#include "visual/drawing/trail_renderer.h"
#include "visual/drawing/visual_grid.h"

namespace sinew {
namespace {

TEST(VisualGrid, LinesAsSofaBuildsThem) {
  auto s = test::load(R"(<Node name="root"><VisualGrid name="g" plane="x" size="4" nbSubdiv="2" nbLineSegments="2"/></Node>)");
  auto* g = test::get<VisualGrid>(*s.root, "g");
  ASSERT_TRUE(g);
  std::vector<Vec3> pts;
  g->lines(pts);
  // (nbSubdiv + 1) lines per family, nbLineSegments segments each, two families, two points per segment.
  ASSERT_EQ(pts.size(), 3u * 2 * 2 * 2);
  // Plane x: first the lines along z at y = −2, 0, 2, in two segments; then along y.
  EXPECT_EQ(pts[0], Vec3(0, -2, -2));
  EXPECT_EQ(pts[1], Vec3(0, -2, 0));
  EXPECT_EQ(pts[3], Vec3(0, -2, 2));
  EXPECT_EQ(pts[12], Vec3(0, -2, -2));
  EXPECT_EQ(pts[13], Vec3(0, 0, -2));
  for (const Vec3& p : pts) EXPECT_EQ(p.x(), 0.0);
}

TEST(LineAxis, LettersInEitherCase) {
  auto s = test::load(R"(<Node name="root"><LineAxis name="a" axis="xZ"/></Node>)");
  auto* a = test::get<LineAxis>(*s.root, "a");
  ASSERT_TRUE(a);
  EXPECT_TRUE(a->draws(0));
  EXPECT_FALSE(a->draws(1));
  EXPECT_TRUE(a->draws(2));
  EXPECT_EQ(a->size.get(), 10.0);
}

TEST(TrailRenderer, KeepsTheLastStepsAndClearsOnReset) {
  auto s = test::load(R"(<Node name="root"><TrailRenderer name="t" position="0 0 0  1 1 1" nbSteps="3"/></Node>)");
  auto* t = test::get<TrailRenderer>(*s.root, "t");
  ASSERT_TRUE(t);
  Event end{Event::Kind::animate_end};
  for (int k = 0; k < 5; ++k) {
    t->position.edit().data[0] = k;  // the first point moves along x
    t->handle_event(end);
  }
  ASSERT_EQ(t->trail().size(), 2u);
  ASSERT_EQ(t->trail()[0].size(), 3u);
  EXPECT_EQ(t->trail()[0].front().x(), 2.0);  // steps 2, 3, 4 kept
  EXPECT_EQ(t->trail()[0].back().x(), 4.0);
  EXPECT_EQ(t->trail()[1].back(), Vec3(1, 1, 1));
  t->reset();
  EXPECT_TRUE(t->trail().empty());
  // SOFA's default colour map is green alone; a scheme name gives its 256 colours.
  EXPECT_EQ(parse_color_map(t->color.get()), (std::vector<Rgba>{{0, 1, 0, 1}}));
  EXPECT_EQ(parse_color_map("HSV").size(), 256u);
  EXPECT_EQ(parse_color_map("red 0 0 1").size(), 2u);
  EXPECT_TRUE(parse_color_map("not a colour").empty());
}

TEST(ViewerComponents, SelectableItemFallsBackAndUnknownAttributeIsReported) {
  auto s = test::build(R"(<Node name="root"><OglSceneFrame name="f" style="1"/>
    <ViewerSetting name="v" resolution="640 480" cameraMode="Fisheye"/><VisualGrid sise="3"/></Node>)");
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "style \"1\" is not one of Arrows, Cylinders, CubeCones; falls back to Arrows"))
      << ::testing::PrintToString(warnings);
  EXPECT_TRUE(test::any_contains(warnings, "cameraMode \"Fisheye\""));
  const auto all = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(all, "sise") || test::any_contains(warnings, "sise"));
}

}  // namespace
}  // namespace sinew
