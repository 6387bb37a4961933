// Texts in pictures (render/draw_text.h): the glyph quads' geometry and texture cells as SOFA's
// GL draw tool makes them, then pictures of OglLabel, Visual3DText and showIndices drawn with
// SOFA's font texture (skipped without the SOFA data or without off-screen OpenGL).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "core/component.h"
#include "render/camera_view.h"
#include "render/draw_text.h"
#include "render/offscreen.h"
#include "render/png_io.h"
#include "runner/session.h"
#include "test_paths.h"
#include "gl_skip.h"
#include "test_scene.h"
#include "visual/rendering2d/ogl_label.h"

namespace sinew {
namespace {

using render::Image;
using render::Text;

constexpr int kFloats = 10;  // per vertex: clip x y z w, u v, r g b a

// A perspective view from the origin along −z, 45° vertical field of view.
render::View perspective_view() {
  render::View v;
  const float f = 1.f / std::tan(static_cast<float>(M_PI) / 8.f);
  v.projection.setZero();
  v.projection(0, 0) = f, v.projection(1, 1) = f;
  v.projection(2, 2) = -1.002f, v.projection(2, 3) = -0.2002f;
  v.projection(3, 2) = -1.f;
  return v;
}

// Pixel (x right, y down) of vertex k of `out` in a w × h picture.
std::array<float, 2> pixel(const std::vector<float>& out, std::size_t k, int w, int h) {
  const float* v = &out[k * kFloats];
  return {(v[0] / v[3] + 1.f) * 0.5f * static_cast<float>(w), (1.f - v[1] / v[3]) * 0.5f * static_cast<float>(h)};
}

// OglLabel "AB" at (10, 20), fontsize 14: glyphs 14 px wide and 28 px high from the top-left
// corner; 'A' (65) is cell 33 of SOFA's texture: column 1, row 2 from the top.
TEST(TextVertices, OverlayGlyphsArePlacedInPixelsWithTheirTextureCells) {
  Text t;
  t.kind = Text::Kind::overlay;
  t.text = "AB";
  t.anchor = Vec3(10, 20, 0);
  t.size = 14;
  t.color = {1, 0, 0, 1};
  std::vector<float> out;
  render::text_vertices(t, render::View{}, 200, 100, out);
  ASSERT_EQ(out.size(), 12u * kFloats);  // two triangles per glyph
  // Vertex order per glyph: top-left, bottom-left, top-right, top-right, bottom-left, bottom-right.
  EXPECT_NEAR(pixel(out, 0, 200, 100)[0], 10, 1e-4);
  EXPECT_NEAR(pixel(out, 0, 200, 100)[1], 20, 1e-4);
  EXPECT_NEAR(pixel(out, 11, 200, 100)[0], 10 + 2 * 14, 1e-4);
  EXPECT_NEAR(pixel(out, 11, 200, 100)[1], 20 + 28, 1e-4);
  EXPECT_FLOAT_EQ(out[4], 1.f / 16);           // u of A's left edge
  EXPECT_FLOAT_EQ(out[5], 1.f - 2.f / 16);     // v of its top (image uploaded bottom row first)
  EXPECT_FLOAT_EQ(out[kFloats + 5], 1.f - 3.f / 16);  // bottom-left: v of its bottom
  EXPECT_FLOAT_EQ(out[6 * kFloats + 4], 2.f / 16);    // 'B' is the next cell
  EXPECT_FLOAT_EQ(out[6], 1.f);                       // colour
  EXPECT_FLOAT_EQ(out[7], 0.f);
}

// UTF-8 is decoded to Latin-1 cells (é = 233: cell 201, column 9, row 12); a control character
// takes its place without a glyph; code points past 255 are drawn as '?'.
TEST(TextVertices, Utf8AndControlCharacters) {
  Text t;
  t.kind = Text::Kind::overlay;
  t.size = 10;
  t.text = "\xC3\xA9";
  std::vector<float> out;
  render::text_vertices(t, render::View{}, 100, 100, out);
  ASSERT_EQ(out.size(), 6u * kFloats);
  EXPECT_FLOAT_EQ(out[4], 9.f / 16);
  EXPECT_FLOAT_EQ(out[5], 1.f - 12.f / 16);
  out.clear();
  t.text = "a\tb";
  render::text_vertices(t, render::View{}, 100, 100, out);
  ASSERT_EQ(out.size(), 12u * kFloats);
  EXPECT_NEAR(pixel(out, 6, 100, 100)[0], 20, 1e-4);  // 'b' two cells to the right
  out.clear();
  t.text = "\xE2\x82\xAC";  // €, U+20AC
  render::text_vertices(t, render::View{}, 100, 100, out);
  ASSERT_EQ(out.size(), 6u * kFloats);
  EXPECT_FLOAT_EQ(out[4], static_cast<float>(('?' - 32) % 16) / 16);
  // A truncated sequence: its first byte alone, as Latin-1 (Ã = 195).
  out.clear();
  t.text = "\xC3";
  render::text_vertices(t, render::View{}, 100, 100, out);
  ASSERT_EQ(out.size(), 6u * kFloats);
  EXPECT_FLOAT_EQ(out[4], static_cast<float>((195 - 32) % 16) / 16);
}

// Indices keep 30·scale pixels of height at any depth, centred on their point, over a black
// shadow 1.5·scale px right and down (70 % of the colour's alpha).
TEST(TextVertices, IndicesKeepTheirPixelHeightCentredOnThePoint) {
  const render::View v = perspective_view();
  for (const float depth : {2.f, 5.f, 40.f}) {
    Text t;
    t.kind = Text::Kind::indices;
    t.points = {0.f, 0.f, -depth};
    t.size = 0.5f;
    t.color = {0, 1, 0, 0.8f};
    std::vector<float> out;
    render::text_vertices(t, v, 200, 200, out);
    ASSERT_EQ(out.size(), 12u * kFloats);  // "0": shadow, then the glyph
    const auto tl = pixel(out, 6, 200, 200), br = pixel(out, 11, 200, 200);
    EXPECT_NEAR(br[1] - tl[1], 15.f, 1e-3) << depth;
    EXPECT_NEAR(br[0] - tl[0], 7.5f, 1e-3) << depth;
    EXPECT_NEAR(0.5f * (tl[0] + br[0]), 100.f, 1e-3) << depth;
    EXPECT_NEAR(0.5f * (tl[1] + br[1]), 100.f, 1e-3) << depth;
    const auto stl = pixel(out, 0, 200, 200);
    EXPECT_NEAR(stl[0] - tl[0], 1.5f * 0.5f, 1e-3);  // 1.5 px at scale 1
    EXPECT_NEAR(stl[1] - tl[1], 1.5f * 0.5f, 1e-3);
    EXPECT_FLOAT_EQ(out[6], 0.f);  // shadow colour
    EXPECT_FLOAT_EQ(out[9], 0.7f * 0.8f);
    EXPECT_FLOAT_EQ(out[6 * kFloats + 7], 1.f);  // the label's green
  }
  // Point 12: two digits, still centred.
  Text t;
  t.kind = Text::Kind::indices;
  t.size = 1.f;
  for (int i = 0; i <= 12; ++i) t.points.insert(t.points.end(), {0.f, 0.f, -5.f});
  std::vector<float> out;
  render::text_vertices(t, v, 200, 200, out);
  ASSERT_EQ(out.size(), (10u * 12 + 3 * 24) * kFloats);  // 10 one-digit labels, 3 two-digit ones
  const std::size_t last = out.size() / kFloats - 12;  // the glyphs of "12"
  EXPECT_NEAR(0.5f * (pixel(out, last, 200, 200)[0] + pixel(out, last + 11, 200, 200)[0]), 100.f, 1e-3);
}

// Visual3DText: top-left corner at the point, glyphs `scale` high in eye units, half as wide.
TEST(TextVertices, WorldTextFacesTheCamera) {
  const render::View v = perspective_view();
  Text t;
  t.kind = Text::Kind::world;
  t.text = "ab";
  t.anchor = Vec3(1, 1, -5);
  t.size = 0.5f;
  std::vector<float> out;
  render::text_vertices(t, v, 200, 200, out);
  ASSERT_EQ(out.size(), 12u * kFloats);
  const float px = 100.f / (5.f * std::tan(static_cast<float>(M_PI) / 8));  // pixels per unit at depth 5
  const auto tl = pixel(out, 0, 200, 200), br = pixel(out, 11, 200, 200);
  EXPECT_NEAR(tl[0], 100 + px, 1e-3);
  EXPECT_NEAR(tl[1], 100 - px, 1e-3);
  EXPECT_NEAR(br[0] - tl[0], 0.5f * px, 1e-3);  // two glyphs of 0.25
  EXPECT_NEAR(br[1] - tl[1], 0.5f * px, 1e-3);
}

TEST(OglLabel, ContrastingColourFollowsTheBackground) {
  auto colour = [](const std::string& background) {
    auto s = test::load("<Node name=\"root\">" + background +
                        "<OglLabel name=\"l\" label=\"x\" selectContrastingColor=\"true\"/></Node>");
    return test::get<OglLabel>(*s.root, "l")->shown_color();
  };
  EXPECT_EQ(colour("<BackgroundSetting color=\"0.8 0.4 0.6\"/>"), (Rgba{0, 0, 0, 1}));  // luma 138
  EXPECT_EQ(colour("<BackgroundSetting color=\"0.2 0.6 0.1\"/>"), (Rgba{1, 1, 1, 1}));  // luma 116
  EXPECT_EQ(colour(""), (Rgba{1, 1, 1, 1}));
  auto s = test::load("<Node name=\"root\"><OglLabel name=\"l\" color=\"0 0 1\"/></Node>");
  EXPECT_EQ(test::get<OglLabel>(*s.root, "l")->shown_color(), (Rgba{0, 0, 1, 1}));
  // SOFA's old spelling: a deprecation warning, then the contrasting colour.
  auto d = test::build("<Node name=\"root\"><OglLabel name=\"l\" color=\"contrast\"/></Node>");
  auto* l = test::get<OglLabel>(*d.root, "l");
  EXPECT_TRUE(l->select_contrasting_color.get());
  EXPECT_TRUE(test::any_contains(test::messages(d.root->diagnostics(), Severity::warning), "deprecated"));
}

// updateLabelEveryNbSteps N: the label shown is read again once every N + 1 steps; without it,
// at every picture.
TEST(OglLabel, LabelUpdatedEveryNbSteps) {
  auto s = test::load("<Node name=\"root\"><OglLabel name=\"a\" prefix=\"[\" label=\"0\" suffix=\"]\" "
                      "updateLabelEveryNbSteps=\"2\"/><OglLabel name=\"b\" label=\"0\"/></Node>");
  auto* a = test::get<OglLabel>(*s.root, "a");
  auto* b = test::get<OglLabel>(*s.root, "b");
  Event begin{Event::Kind::animate_begin};
  std::vector<std::string> shown;
  for (int step = 1; step <= 6; ++step) {
    a->label.set(std::to_string(step));
    b->label.set(std::to_string(step));
    a->handle_event(begin);
    b->handle_event(begin);
    shown.push_back(a->text());
    EXPECT_EQ(b->text(), std::to_string(step));
  }
  EXPECT_EQ(shown, (std::vector<std::string>{"[0]", "[0]", "[3]", "[3]", "[3]", "[6]"}));
}

class TextPictureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    font_ = runner::find_data_file({std::string(SINEW_DATA_DIR) + "/share"}, render::kFontFile);
    if (font_.empty()) GTEST_SKIP() << "SOFA's font texture not found under " << SINEW_DATA_DIR << "/share";
    std::string err;
    render::RenderOptions o;
    o.width = 200, o.height = 200;
    o.samples = 0;
    renderer_ = render::OffscreenRenderer::create(o, &err);
    if (!renderer_) {
    ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
    GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
  }
    renderer_->set_font(font_);
  }
  // A 200×200 picture of `xml` (inside the root, camera at z = 5 looking at the origin: 48.3
  // pixels per unit at depth 5) with a small grey square at the centre giving the bounds.
  Image picture(const std::string& xml) {
    auto s = test::load(
        "<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
        "<Node name=\"sq\"><OglModel color=\"0.3 0.3 0.3\" position=\"-0.1 -0.1 0  0.1 -0.1 0  0.1 0.1 0  -0.1 0.1 0\" "
        "quads=\"0 1 2 3\"/></Node>" +
        xml + "</Node>");
    Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(*s.root, img, &err)) << err;
    if (const char* dump = std::getenv("SINEW_DUMP_TEXT_PICTURES")) {
      static int k = 0;
      render::write_png(std::string(dump) + "/text" + std::to_string(k++) + ".png", img, &err);
    }
    return img;
  }
  // Pixels matching `f`, and whether all of them lie in [x0, x1) × [y0, y1).
  static long count(const Image& img, const std::function<bool(const std::array<int, 3>&)>& f, int x0, int y0,
                    int x1, int y1, long* outside) {
    long in = 0;
    *outside = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (f(img.rgb(x, y))) (x >= x0 && x < x1 && y >= y0 && y < y1 ? in : *outside)++;
    return in;
  }
  std::string font_;
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

// Text pixels (blended at the glyphs' smooth edges): mostly the text's colour.
bool reddish(const std::array<int, 3>& c) { return c[0] > 80 && c[0] > 2 * c[2] && c[1] < 30; }
bool greenish(const std::array<int, 3>& c) { return c[1] > 80 && c[1] > 2 * c[2] && c[0] < 30; }

// OglLabel "HI" at (20, 30), fontsize 10: red pixels only in its box [20, 40) × [30, 50).
TEST_F(TextPictureTest, OglLabelInItsPixelBox) {
  const Image img = picture("<OglLabel label=\"HI\" x=\"20\" y=\"30\" fontsize=\"10\" color=\"red\"/>");
  long outside = 0;
  const long in = count(img, reddish, 20, 30, 40, 50, &outside);
  RecordProperty("pixels", static_cast<int>(in));
  EXPECT_GT(in, 30);
  EXPECT_EQ(outside, 0);
  // Hidden with the visual models.
  const Image hidden = picture("<Node name=\"n\"><VisualStyle displayFlags=\"hideVisual\"/><OglLabel label=\"HI\" "
                               "x=\"20\" y=\"30\" fontsize=\"10\" color=\"red\"/></Node>");
  EXPECT_EQ(count(hidden, reddish, 0, 0, 200, 200, &outside), 0);
}

// Visual3DText "HI" at (-1.8, 1.8, 0), scale 1: its box starts 1.8·48.3 px left of and above
// the centre and is 48.3 px high and as wide (two glyphs of half the height); drawn over a model
// in front of it (no depth test, as SOFA), blended with it at the glyphs' edges.
TEST_F(TextPictureTest, Visual3DTextAtItsPointOverTheModels) {
  const double px = 100.0 / (5.0 * std::tan(M_PI / 8));
  const int x0 = static_cast<int>(100 - 1.8 * px), s = static_cast<int>(std::ceil(px));
  const Image img = picture("<Visual3DText text=\"HI\" position=\"-1.8 1.8 0\" scale=\"1\" color=\"1 0 0 1\"/>"
                            "<Node name=\"front\"><OglModel color=\"0 0 1\" position=\"-2 0.8 1  -0.5 0.8 1  -0.5 2 1  "
                            "-2 2 1\" quads=\"0 1 2 3\"/></Node>");
  const auto red_over_blue = [](const std::array<int, 3>& c) { return c[0] > 80 && c[0] > c[2] && c[1] < 30; };
  long outside = 0;
  const long in = count(img, red_over_blue, x0, x0, x0 + s + 1, x0 + s + 1, &outside);
  RecordProperty("pixels", static_cast<int>(in));
  EXPECT_GT(in, 60);
  EXPECT_EQ(outside, 0);
}

// MechanicalObject showIndices: "0" and "1" centred on their points, 30 px high, in
// showColor; depth-tested: a model in front of point 0 hides its index.
TEST_F(TextPictureTest, ShowIndicesCentredOnThePointsAndHiddenBehindModels) {
  const double px = 100.0 / (5.0 * std::tan(M_PI / 8));
  const std::string points =
      "<Node name=\"pts\"><MechanicalObject position=\"-1 0 0  1 0 0\" showIndices=\"true\" "
      "showColor=\"0 1 0 1\"/></Node>";
  const Image img = picture(points);
  const int xa = static_cast<int>(std::lround(100 - px)), xb = static_cast<int>(std::lround(100 + px));
  long outside = 0, outside_a = 0, outside_b = 0;
  const long a = count(img, greenish, xa - 9, 84, xa + 9, 117, &outside_a);
  const long b = count(img, greenish, xb - 9, 84, xb + 9, 117, &outside_b);
  EXPECT_GT(a, 10);
  EXPECT_GT(b, 10);
  EXPECT_EQ(outside_a, b);  // every green pixel is in one of the two boxes
  const Image hidden = picture(points + "<Node name=\"front\"><OglModel color=\"0 0 1\" position=\"-1.5 -0.5 1  "
                                        "-0.5 -0.5 1  -0.5 0.5 1  -1.5 0.5 1\" quads=\"0 1 2 3\"/></Node>");
  EXPECT_EQ(count(hidden, greenish, xa - 9, 84, xa + 9, 117, &outside), 0);
  EXPECT_GT(count(hidden, greenish, xb - 9, 84, xb + 9, 117, &outside), 10);
}

// Without the font texture the texts are left out; the rest of the picture is drawn.
TEST_F(TextPictureTest, NoFontNoText) {
  renderer_->set_font("");
  const Image img = picture("<OglLabel label=\"HI\" x=\"20\" y=\"30\" fontsize=\"10\" color=\"red\"/>");
  long outside = 0;
  EXPECT_EQ(count(img, reddish, 0, 0, 200, 200, &outside), 0);
  EXPECT_GT(count(img, [](auto c) { return c[0] > 30 && c[0] == c[1]; }, 90, 90, 110, 110, &outside), 10);
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// OglColorMap's legend: a bar 10 px wide from y = 25 to 125 (legendOffset 10 5), the palette's
// last colour at the top (red for "Blue to Red"), its first at the bottom; max and min written
// beside its ends in white on black; a title moves everything down by 2·legendSize. The bar is
// drawn without the font too.
TEST_F(TextPictureTest, ColorMapLegend) {
  const std::string map = "<OglColorMap colorScheme=\"Blue to Red\" showLegend=\"true\" min=\"-1.5\" max=\"2\"/>";
  const Image img = picture(map);
  const auto top = img.rgb(25, 26), bottom = img.rgb(25, 123);
  EXPECT_GT(top[0], 200);
  EXPECT_LT(top[2], 40);
  EXPECT_GT(bottom[2], 200);
  EXPECT_LT(bottom[0], 40);
  EXPECT_TRUE(img.rgb(19, 70)[0] + img.rgb(19, 70)[1] + img.rgb(19, 70)[2] == 0);  // left of the bar
  const auto white = [](const std::array<int, 3>& c) { return c[0] > 90 && c[0] == c[1] && c[1] == c[2]; };
  long outside = 0;
  EXPECT_GT(count(img, white, 10, 5, 10 + 12, 5 + 24, &outside), 10);        // "2"
  EXPECT_GT(count(img, white, 10, 125, 10 + 4 * 12, 125 + 24, &outside), 10);  // "-1.5"
  const Image titled = picture("<OglColorMap colorScheme=\"Blue to Red\" showLegend=\"true\" legendTitle=\"T\" "
                               "legendSize=\"10\"/>");
  EXPECT_GT(titled.rgb(25, 46)[0], 200);  // the bar's top moved down by 20 px
  EXPECT_EQ(titled.rgb(25, 30), (std::array<int, 3>{0, 0, 0}));
  renderer_->set_font("");
  const Image no_font = picture(map);
  EXPECT_EQ(no_font.rgb(25, 26), top);
  EXPECT_EQ(count(no_font, white, 10, 5, 60, 29, &outside) + count(no_font, white, 10, 125, 60, 149, &outside), 0);
}

}  // namespace
}  // namespace sinew
