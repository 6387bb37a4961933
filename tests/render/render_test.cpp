// Off-screen pictures of small scenes written here (EGL + Mesa). Every test skips,
// saying why, when this machine cannot create an off-screen OpenGL context;
// scripts/setup installs Mesa so that CI runs them.
//
// Expected pictures live in tests/render/expected/ (small PNGs, looked at by a person
// when they were made); SINEW_UPDATE_EXPECTED=1 rewrites them from this build.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "alloc_counter.h"
#include "render/offscreen.h"
#include "render/png_io.h"
#include "runner/session.h"
#include "gl_skip.h"
#include "test_scene.h"
#include "visual/clip_plane.h"
#include "visual/ogl_model.h"
#include "test_paths.h"

namespace sinew {
namespace {

using render::Image;

// A cube [-0.5, 0.5]³ as six outward quads.
std::string cube(const std::string& name, const std::string& color, double dx) {
  std::string pos;
  for (int i = 0; i < 8; ++i) {
    const double x = (i & 1 ? 0.5 : -0.5) + dx, y = i & 2 ? 0.5 : -0.5, z = i & 4 ? 0.5 : -0.5;
    pos += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + " ";
  }
  return "<Node name=\"" + name + "\"><OglModel name=\"" + name + "\" color=\"" + color + "\" position=\"" + pos +
         "\" quads=\"0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2  1 3 7 5\"/></Node>";
}

class RenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string err;
    render::RenderOptions o;
    o.width = 200, o.height = 200;
    o.samples = 0;  // exact pixel counts
    renderer_ = render::OffscreenRenderer::create(o, &err);
    if (!renderer_) {
    ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
    GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
  }
  }
  Image render(Node& root) {
    Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(root, img, &err)) << err;
    return img;
  }
  // Pictures of SOFA's example `scene` (under examples/) when loaded and after 100 steps, the
  // view framed at loading as a viewer does; false when the SOFA data are absent.
  bool pictures_at_0_and_100(const std::string& scene, Image& first, Image& last) {
    const std::string root_dir = SINEW_DATA_DIR;
    const std::string path = root_dir + "/examples/" + scene;
    if (!std::filesystem::exists(path)) return false;
    runner::SessionOptions so;
    so.data_paths = runner::sofa_data_paths(root_dir);
    runner::Session session(path, so);
    if (!session.ok()) {
      ADD_FAILURE() << scene << " does not load";
      return true;
    }
    std::string err;
    EXPECT_TRUE(renderer_->frame(session.root(), &err)) << err;
    first = render(session.root());
    for (int i = 0; i < 100; ++i) EXPECT_TRUE(session.step());
    last = render(session.root());
    return true;
  }
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

bool is_background(const std::array<int, 3>& c) { return c[0] + c[1] + c[2] == 0; }

long count_if(const Image& img, const std::function<bool(const std::array<int, 3>&)>& f, int x0 = 0, int x1 = -1) {
  if (x1 < 0) x1 = img.width;
  long n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) n += f(img.rgb(x, y));
  return n;
}

// A unit cube 4.5 in front of the camera: its front face covers (100·0.5/(4.5·tan 22.5°))²·4
// pixels of a 200×200 picture with a 45° field of view, in the model's colour at the centre.
TEST_F(RenderTest, UnitCubeFromTheFrontAreaAndColour) {
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                      cube("cube", "red", 0) + "</Node>");
  const Image img = render(*s.root);
  const double half = 100.0 * 0.5 / (4.5 * std::tan(M_PI / 8));
  const double expected = 4 * half * half;  // 2877 pixels
  const long area = count_if(img, [](auto c) { return !is_background(c); });
  RecordProperty("area", static_cast<int>(area));
  EXPECT_NEAR(area, expected, 0.03 * expected);
  const auto centre = img.rgb(100, 100);
  // Facing the headlight: diffuse 1 + ambient 0.2 on red, clamped.
  EXPECT_EQ(centre[0], 255);
  EXPECT_LE(centre[1], 2);
  EXPECT_LE(centre[2], 2);
  // Corners stay background.
  EXPECT_TRUE(is_background(img.rgb(5, 5)));
}

// ClipPlane (normal +x through the origin, in the root) removes the right half of the cube
// of a child node: the left half of the front face stays, nothing right of the centre.
TEST_F(RenderTest, ClipPlaneRemovesHalfTheCube) {
  const double half = 100.0 * 0.5 / (4.5 * std::tan(M_PI / 8));
  const double full = 4 * half * half;  // 2877 pixels, as above
  auto lit = [](auto c) { return !is_background(c); };
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<ClipPlane name=\"clip\" normal=\"1 0 0\"/>" +
                      cube("cube", "red", 0) + "</Node>");
  Image img = render(*s.root);
  const long left = count_if(img, lit, 0, 100), right = count_if(img, lit, 101, 200);
  RecordProperty("left", static_cast<int>(left));
  EXPECT_NEAR(left, full / 2, 0.03 * full);
  EXPECT_EQ(right, 0);
  const auto kept = img.rgb(80, 100);  // still the red front face (headlight slightly off-axis)
  EXPECT_GT(kept[0], 200);
  EXPECT_LE(kept[1], 2);
  // Inactive: the whole cube again.
  test::get<ClipPlane>(*s.root, "clip")->active.set(false);
  img = render(*s.root);
  EXPECT_NEAR(count_if(img, lit), full, 0.03 * full);
  // Normal -x keeps the right half instead.
  auto t = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<ClipPlane normal=\"-1 0 0\" position=\"0.25 0 0\"/>" +
                      cube("cube", "red", 0) + "</Node>");
  img = render(*t.root);
  EXPECT_EQ(count_if(img, lit, 0, 100), 0);
  // The camera (x = 0) looks into the cut box [0.25, 0.5] × [-0.5, 0.5]²: its silhouette is the
  // front face's quarter (x from a to b pixels, height 2b) plus the strip of the inside seen
  // through the cut, between the back edge (x = c, height 2·back) and the front one.
  const double f = 100.0 / std::tan(M_PI / 8);
  const double a = f * 0.25 / 4.5, b = f * 0.5 / 4.5, c = f * 0.25 / 5.5, back = f * 0.5 / 5.5;
  const double expected = (b - a) * 2 * b + (a - c) * (b + back);  // 838 pixels
  EXPECT_NEAR(count_if(img, lit, 100, 200), expected, 0.03 * expected);
}

// Several ClipPlanes (SOFA's fwdDraw sets OpenGL plane `id`): the root's id 0 (normal +x) and a
// child node's id 1 (normal +y) both apply, leaving the bottom-left quarter of the front face;
// an inactive plane of id 0 in the child switches the root's off (only the top half goes); a
// second plane of the same id in a node replaces the first; an id beyond 7 is an error.
TEST_F(RenderTest, ClipPlanesOfDifferentIdsCombine) {
  const double half = 100.0 * 0.5 / (4.5 * std::tan(M_PI / 8));
  const double quarter = half * half;  // one quadrant of the front face, in pixels
  auto lit_in = [](const Image& img, bool left, bool top) {
    long n = 0;
    for (int y = top ? 0 : 100; y < (top ? 100 : 200); ++y)
      for (int x = left ? 0 : 100; x < (left ? 100 : 200); ++x) n += is_background(img.rgb(x, y)) ? 0 : 1;
    return n;
  };
  auto scene = [&](const std::string& inner_planes) {
    return test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<ClipPlane normal=\"1 0 0\"/><Node name=\"inner\">" +
                      inner_planes + cube("cube", "red", 0) + "</Node></Node>");
  };
  auto both = scene("<ClipPlane id=\"1\" normal=\"0 1 0\"/>");
  Image img = render(*both.root);
  EXPECT_NEAR(lit_in(img, true, false), quarter, 0.05 * quarter);
  EXPECT_EQ(lit_in(img, true, true), 0);
  EXPECT_EQ(lit_in(img, false, false), 0);
  EXPECT_EQ(lit_in(img, false, true), 0);
  auto off = scene("<ClipPlane id=\"1\" normal=\"0 1 0\"/><ClipPlane active=\"0\"/>");
  img = render(*off.root);
  EXPECT_NEAR(lit_in(img, true, false) + lit_in(img, false, false), 2 * quarter, 0.05 * quarter);
  EXPECT_EQ(lit_in(img, true, true) + lit_in(img, false, true), 0);
  auto replaced = scene("<ClipPlane normal=\"-1 0 0\"/>");  // id 0 again: keeps the right half
  img = render(*replaced.root);
  EXPECT_EQ(lit_in(img, true, false) + lit_in(img, true, true), 0);
  EXPECT_NEAR(lit_in(img, false, false) + lit_in(img, false, true), 2 * quarter, 0.05 * quarter);
  auto bad = test::load("<Node name=\"root\"><ClipPlane id=\"8\"/>" + cube("cube", "red", 0) + "</Node>");
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::error), "beyond OpenGL's eight"));
}

// VisualBoundingBox of [-0.5, 0.5]³ seen from z = 5: one-pixel green lines along the front
// square (half side b pixels), the back square (half side c) and four short joins; the inside
// stays background.
TEST_F(RenderTest, VisualBoundingBoxDrawsTwelveEdges) {
  auto s = test::load(
      "<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
      "<VisualBoundingBox color=\"green\" bbox=\"-0.5 -0.5 -0.5 0.5 0.5 0.5\"/></Node>");
  const Image img = render(*s.root);
  auto green = [](auto c) { return c[1] > 200 && c[0] < 30 && c[2] < 30; };
  const double f = 100.0 / std::tan(M_PI / 8), b = f * 0.5 / 4.5, c = f * 0.5 / 5.5;
  const double expected = 8 * b + 8 * c + 4 * (b - c);  // rasterised lines: one pixel per major step
  const long n = count_if(img, green);
  RecordProperty("green", static_cast<int>(n));
  EXPECT_NEAR(n, expected, 0.1 * expected);
  EXPECT_EQ(count_if(img, green), count_if(img, [](auto c) { return !is_background(c); }));
  EXPECT_TRUE(is_background(img.rgb(100, 100)));
  EXPECT_EQ(count_if(img, green, 0, static_cast<int>(100 - b) - 1), 0);  // nothing left of the front square
}

// `thickness` widens the lines as SOFA's glLineWidth: five-pixel lines cover about five times
// the pixels of one-pixel lines (less where the twelve edges overlap near the corners).
TEST_F(RenderTest, VisualBoundingBoxThicknessWidensItsLines) {
  auto box = [&](const std::string& thickness) {
    auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                        "<VisualBoundingBox color=\"green\" bbox=\"-0.5 -0.5 -0.5 0.5 0.5 0.5\" thickness=\"" +
                        thickness + "\"/></Node>");
    return count_if(render(*s.root), [](auto c) { return c[1] > 200 && c[0] < 30 && c[2] < 30; });
  };
  const long thin = box("1"), wide = box("5");
  RecordProperty("thin", static_cast<int>(thin));
  RecordProperty("wide", static_cast<int>(wide));
  EXPECT_GT(wide, 4.2 * thin);
  EXPECT_LT(wide, 5.0 * thin);
}

// BaseROI::draw under showBehaviorModels: BoxROI's box in cyan (drawBoxes), the selected
// points in (1, 0.4, 0.4) as squares of drawSize pixels (drawPoints); nothing without the flag.
TEST_F(RenderTest, BoxRoiDrawsItsBoxAndSelectedPoints) {
  auto scene = [](const std::string& flags) {
    return "<Node name=\"root\"><VisualStyle displayFlags=\"" + flags +
           "\"/><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" + cube("side", "blue", 1.5) +
           "<RegularGridTopology name=\"grid\" n=\"3 3 3\" min=\"-0.5 -0.5 -0.5\" max=\"0.5 0.5 0.5\"/>"
           "<MechanicalObject name=\"dofs\"/>"
           "<BoxROI box=\"-0.6 -0.6 -0.6 -0.25 0.6 0.6\" drawBoxes=\"1\" drawPoints=\"1\" drawSize=\"4\"/></Node>";
  };
  auto s = test::load(scene("showBehaviorModels"));
  const Image img = render(*s.root);
  auto cyan = [](auto c) { return c[0] < 30 && c[1] > 200 && c[2] > 200; };
  auto salmon = [](auto c) { return c[0] > 200 && c[1] > 80 && c[1] < 125 && c[2] > 80 && c[2] < 125; };
  const long n_cyan = count_if(img, cyan), n_salmon = count_if(img, salmon);
  RecordProperty("cyan", static_cast<int>(n_cyan));
  RecordProperty("salmon", static_cast<int>(n_salmon));
  // The box's front face is 0.35 × 1.2 at distance 4.4 (f = 100 / tan 22.5° px per unit at 1):
  // its outline alone is 2·(0.35 + 1.2)·f / 4.4 ≈ 170 pixels, four wide.
  EXPECT_GT(n_cyan, 4 * 150);
  // The nine points of the column x = −0.5, 4 × 4 pixels each (some hidden behind others or
  // under the box's lines), and none right of the box.
  EXPECT_GT(n_salmon, 3 * 16);
  EXPECT_LE(n_salmon, 9 * 16);
  const double f = 100.0 / std::tan(M_PI / 8);
  const int right_of_box = static_cast<int>(100 + (-0.25 * f / 4.4)) + 3;
  EXPECT_EQ(count_if(img, salmon, right_of_box), 0);
  EXPECT_EQ(count_if(img, cyan, right_of_box + 3, 130), 0);  // up to the blue cube's edge
  auto hidden = test::load(scene("hideBehaviorModels showVisual"));
  const Image none = render(*hidden.root);
  EXPECT_EQ(count_if(none, cyan) + count_if(none, salmon), 0);
}

// Pixels of a lit cyan wireframe (not a salmon point) inside and outside the disc of `radius_px`
// (plus 1.5) about the picture's centre.
std::pair<long, long> bluish_in_disc(const Image& img, double radius_px) {
  long inside = 0, outside = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const auto c = img.rgb(x, y);
      if (!(c[2] > 40 && c[2] >= c[0] + 20)) continue;
      (std::hypot(x + 0.5 - 100, y + 0.5 - 100) <= radius_px + 1.5 ? inside : outside)++;
    }
  return {inside, outside};
}

// SphereROI's drawSphere: its sphere in wireframe cyan (lit), inside the disc it covers.
TEST_F(RenderTest, SphereRoiDrawsItsSphereInWireframe) {
  auto s = test::load(
      "<Node name=\"root\"><VisualStyle displayFlags=\"showBehaviorModels\"/>"
      "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
      "<MechanicalObject name=\"dofs\" position=\"0 0 0  1.5 0 0\"/>"
      "<SphereROI centers=\"0 0 0\" radii=\"0.5\" drawSphere=\"1\"/></Node>");
  const Image img = render(*s.root);
  const double f = 100.0 / std::tan(M_PI / 8), radius_px = 0.5 * f / std::sqrt(25 - 0.25);
  const auto [inside, outside] = bluish_in_disc(img, radius_px);
  RecordProperty("inside", static_cast<int>(inside));
  EXPECT_GT(inside, 100);   // the wire mesh's lines
  EXPECT_EQ(outside, 0);    // nothing beyond the disc
  EXPECT_LT(inside, static_cast<long>(0.8 * M_PI * radius_px * radius_px));  // lines, not a filled disc
}

// PlaneROI::draw: triangles in the slab filled in cyan; the slab's box only while drawSize is 0
// (drawBoxes is not read, as in SOFA).
TEST_F(RenderTest, PlaneRoiFillsItsTrianglesAndDrawsItsSlabOnlyAtDrawSizeZero) {
  auto scene = [](const std::string& extra) {
    return "<Node name=\"root\"><VisualStyle displayFlags=\"showBehaviorModels\"/>"
           "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
           "<MechanicalObject name=\"dofs\" position=\"-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0\"/>"
           "<PlaneROI plane=\"-0.6 -0.6 0  0.6 -0.6 0  0.6 0.6 0  0.2\" position=\"@dofs.position\" "
           "triangles=\"0 1 2  0 2 3\" drawBoxes=\"1\" " + extra + "/></Node>";
  };
  auto cyan = [](auto c) { return c[0] < 30 && c[1] > 200 && c[2] > 200; };
  const double side = 100.0 / std::tan(M_PI / 8) / 5;  // the unit square's side in pixels
  auto filled = test::load(scene("drawTriangles=\"1\""));
  const long n_filled = count_if(render(*filled.root), cyan);
  RecordProperty("filled", static_cast<int>(n_filled));
  EXPECT_GT(n_filled, static_cast<long>(0.9 * side * side));
  EXPECT_LT(n_filled, static_cast<long>(1.1 * side * side));
  auto boxes_off = test::load(scene(""));
  EXPECT_EQ(count_if(render(*boxes_off.root), cyan), 0);
  auto slab = test::load(scene("drawSize=\"0\""));
  const long n_slab = count_if(render(*slab.root), cyan);
  RecordProperty("slab", static_cast<int>(n_slab));
  // The slab's two 1.2-wide squares at z = ±0.1, one pixel wide: about 2 × 4 × 1.2 × side.
  EXPECT_GT(n_slab, static_cast<long>(1.5 * 4 * 1.2 * side));
  EXPECT_LT(n_slab, static_cast<long>(2.5 * 4 * 1.2 * side));
}

// ProximityROI::draw: its spheres at half their radii, in wireframe cyan, and the selected
// points as 5-pixel squares.
TEST_F(RenderTest, ProximityRoiDrawsHalfRadiusSpheresAndItsPoints) {
  auto s = test::load(
      "<Node name=\"root\"><VisualStyle displayFlags=\"showBehaviorModels\"/>"
      "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
      "<MechanicalObject name=\"dofs\" position=\"0 0 0  1.5 0 0\"/>"
      "<ProximityROI centers=\"0 0 0\" radii=\"1\" N=\"5\" position=\"@dofs.position\" drawSphere=\"1\"/></Node>");
  const Image img = render(*s.root);
  const double f = 100.0 / std::tan(M_PI / 8), radius_px = 0.5 * f / std::sqrt(25 - 0.25);
  const auto [inside, outside] = bluish_in_disc(img, radius_px);
  RecordProperty("inside", static_cast<int>(inside));
  EXPECT_GT(inside, 100);
  EXPECT_EQ(outside, 0);  // the radius is halved: nothing out to the full radius's disc
  auto points = test::load(
      "<Node name=\"root\"><VisualStyle displayFlags=\"showBehaviorModels\"/>"
      "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
      "<MechanicalObject name=\"dofs\" position=\"0 0 0  0.5 0 0  3 0 0\"/>"
      "<ProximityROI centers=\"0 0 0\" radii=\"1\" N=\"5\" position=\"@dofs.position\" drawPoints=\"1\"/></Node>");
  auto cyan = [](auto c) { return c[0] < 30 && c[1] > 200 && c[2] > 200; };
  EXPECT_EQ(count_if(render(*points.root), cyan), 2 * 25);  // two points in the sphere, 5 × 5 each
}

// PairBoxROI::draw: its boxes in (1, 0.4, 0.4), drawn also without showBehaviorModels when
// drawSize is not 0, and not at all otherwise.
TEST_F(RenderTest, PairBoxRoiDrawsItsBoxesWithADrawSizeEvenWithoutBehaviorModels) {
  auto scene = [](const std::string& flags, const std::string& size) {
    return "<Node name=\"root\"><VisualStyle displayFlags=\"" + flags + "\"/>"
           "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
           "<MechanicalObject name=\"dofs\" position=\"0 0 0  0.8 0 0\"/>"
           "<PairBoxROI inclusiveBox=\"-1 -1 0  1 1 0\" includedBox=\"-0.5 -0.5 0  0.5 0.5 0\" "
           "drawInclusiveBox=\"1\" drawIncludedBox=\"1\" drawSize=\"" + size + "\"/></Node>";
  };
  auto salmon = [](auto c) { return c[0] > 240 && c[1] > 90 && c[1] < 115 && c[2] > 90 && c[2] < 115; };
  const double side = 100.0 / std::tan(M_PI / 8) / 5;
  auto hidden_sized = test::load(scene("hideBehaviorModels", "2"));
  const long n = count_if(render(*hidden_sized.root), salmon);
  RecordProperty("boxes", static_cast<int>(n));
  // Two square outlines of sides 2 and 1 (× side pixels), two pixels wide.
  EXPECT_GT(n, static_cast<long>(0.8 * 2 * 4 * 3 * side));
  EXPECT_LT(n, static_cast<long>(1.2 * 2 * 4 * 3 * side));
  auto hidden = test::load(scene("hideBehaviorModels", "0"));
  Image none;
  std::string err;
  EXPECT_FALSE(renderer_->render(*hidden.root, none, &err));  // nothing drawn at all
  EXPECT_NE(err.find("nothing is visible"), std::string::npos) << err;
  auto shown = test::load(scene("showBehaviorModels", "0"));
  EXPECT_GT(count_if(render(*shown.root), salmon), static_cast<long>(0.8 * 4 * 3 * side));
}

// MeshROI's drawROI: its mesh's points in (0.4, 0.4, 1) and, with drawBox, its bounding box in
// (1, 0.4, 0.4); without drawROI, neither.
TEST_F(RenderTest, MeshRoiDrawsItsMeshPointsAndBox) {
  auto scene = [](const std::string& draw_roi) {
    return "<Node name=\"root\"><VisualStyle displayFlags=\"showBehaviorModels\"/>"
           "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" + cube("side", "blue", 2.5) +
           "<MechanicalObject name=\"dofs\" position=\"3 3 3\"/>"
           "<MeshROI ROIposition=\"-0.5 -0.5 0  0.5 -0.5 0  0 0.5 0\" ROItriangles=\"0 1 2\" drawROI=\"" +
           draw_roi + "\" drawPoints=\"1\" drawBox=\"1\" drawSize=\"4\"/></Node>";
  };
  auto blue_points = [](auto c) { return c[0] > 90 && c[0] < 115 && c[1] > 90 && c[1] < 115 && c[2] > 240; };
  auto salmon = [](auto c) { return c[0] > 240 && c[1] > 90 && c[1] < 115 && c[2] > 90 && c[2] < 115; };
  auto on = test::load(scene("1"));
  const Image img = render(*on.root);
  EXPECT_GE(count_if(img, blue_points), 3 * 12);  // three 4 × 4 squares, partly under the box's lines
  // The box [-0.5, 0.5] × [-0.5, 0.5] × [0, 0]: a square of side f / 5 pixels, four wide.
  const double side = 100.0 / std::tan(M_PI / 8) / 5;
  EXPECT_GT(count_if(img, salmon), static_cast<long>(4 * 3 * side));
  auto off = test::load(scene("0"));
  const Image none = render(*off.root);
  EXPECT_EQ(count_if(none, blue_points) + count_if(none, salmon), 0);
}

// Without a camera, SOFA's default view frames the cube: 3 half-diagonals from its centre.
TEST_F(RenderTest, DefaultViewFramesTheBoundingBox) {
  auto s = test::load("<Node name=\"root\">" + cube("cube", "0 1 0", 0) + "</Node>");
  const Image img = render(*s.root);
  const double d = 3 * std::sqrt(0.75) - 0.5;  // eye to front face
  const double half = 100.0 * 0.5 / (d * std::tan(M_PI / 8));
  const double expected = 4 * half * half;
  const long area = count_if(img, [](auto c) { return !is_background(c); });
  RecordProperty("area", static_cast<int>(area));
  EXPECT_NEAR(area, expected, 0.03 * expected);
  EXPECT_EQ(img.rgb(100, 100)[1], 255);
}

// A red and a blue model side by side: red on the left half only, blue on the right.
TEST_F(RenderTest, RedLeftBlueRight) {
  auto s = test::load("<Node name=\"root\">" + cube("left", "red", -1) + cube("right", "blue", 1) + "</Node>");
  const Image img = render(*s.root);
  auto red = [](auto c) { return c[0] > 100 && c[2] < 30; };
  auto blue = [](auto c) { return c[2] > 100 && c[0] < 30; };
  EXPECT_GT(count_if(img, red, 0, 100), 1000);
  EXPECT_EQ(count_if(img, red, 100, 200), 0);
  EXPECT_GT(count_if(img, blue, 100, 200), 1000);
  EXPECT_EQ(count_if(img, blue, 0, 100), 0);

  // Against the stored picture: mean difference below 1 level, no pixel off by more than 8
  // outside 0.5 % of the picture (rasterisation may differ on edges between Mesa versions).
  const std::string expected_path = std::string(SINEW_SOURCE_DIR) + "/tests/render/expected/red_left_blue_right.png";
  if (std::getenv("SINEW_UPDATE_EXPECTED")) {
    std::string err;
    ASSERT_TRUE(render::write_png(expected_path, img, &err)) << err;
  }
  std::string err;
  auto ref = render::read_png(expected_path, &err);
  ASSERT_TRUE(ref) << err;
  ASSERT_EQ(ref->width, img.width);
  ASSERT_EQ(ref->height, img.height);
  double total = 0;
  long off = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const auto a = img.rgb(x, y), b = ref->rgb(x, y);
      int worst = 0;
      for (int c = 0; c < 3; ++c) {
        total += std::abs(a[c] - b[c]);
        worst = std::max(worst, std::abs(a[c] - b[c]));
      }
      off += worst > 8;
    }
  RecordProperty("mean_difference_x1000", static_cast<int>(1000 * total / (img.width * img.height * 3.0)));
  RecordProperty("pixels_off", static_cast<int>(off));
  EXPECT_LT(total / (img.width * img.height * 3.0), 1.0);
  EXPECT_LT(off, img.width * img.height / 200);
}

// A model moved between two renders (fixed camera): the picture changes, the cube's pixels
// move right, and the second frame allocates nothing on Sinew's side.
TEST_F(RenderTest, MovedModelChangesThePicture) {
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                      cube("cube", "white", 0) + "</Node>");
  const Image before = render(*s.root);
  auto* m = dynamic_cast<OglModel*>(s.root->find_child_named("cube")->find_object_named("cube"));
  ASSERT_TRUE(m);
  auto centroid_x = [](const Image& img) {
    double sx = 0;
    long n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (!is_background(img.rgb(x, y))) sx += x, ++n;
    return n ? sx / n : -1.0;
  };
  std::vector<double>& x = m->position.edit().data;
  for (std::size_t i = 0; i < x.size(); i += 3) x[i] += 0.5;
  Image after;
  std::string err;
#if SINEW_COUNT_ALLOCATIONS
  ASSERT_TRUE(renderer_->render(*s.root, after, &err)) << err;  // sizes settle (the image buffer)
  const long allocs = test::g_allocations.load();
  ASSERT_TRUE(renderer_->render(*s.root, after, &err)) << err;
  // Mesa may allocate inside the driver; Sinew's own part (gather, view, read-back) does not.
  const long used = test::g_allocations.load() - allocs;
  RecordProperty("allocations_in_second_frame", static_cast<int>(used));
#else
  ASSERT_TRUE(renderer_->render(*s.root, after, &err)) << err;
#endif
  long changed = 0;
  for (std::size_t i = 0; i < before.rgba.size(); ++i) changed += before.rgba[i] != after.rgba[i];
  RecordProperty("changed_bytes", static_cast<int>(changed));
  RecordProperty("centroid_shift_x100", static_cast<int>(100 * (centroid_x(after) - centroid_x(before))));
  EXPECT_GT(changed, 1000);
  const double shift_px = 100.0 * 0.5 / (4.5 * std::tan(M_PI / 8));  // 0.5 at the front face's depth
  EXPECT_NEAR(centroid_x(after) - centroid_x(before), shift_px, 3.0);
}

// frame(): the default view keeps the box of the loaded scene, so a moved model moves in the
// picture (without it, each picture frames its own content and the cube stays centred).
TEST_F(RenderTest, FramedDefaultViewStaysPut) {
  auto s = test::load("<Node name=\"root\">" + cube("cube", "white", 0) + "</Node>");
  std::string err;
  ASSERT_TRUE(renderer_->frame(*s.root, &err)) << err;
  const Image before = render(*s.root);
  auto* m = dynamic_cast<OglModel*>(s.root->find_child_named("cube")->find_object_named("cube"));
  std::vector<double>& x = m->position.edit().data;
  for (std::size_t i = 1; i < x.size(); i += 3) x[i] += 0.3;  // up
  const Image after = render(*s.root);
  auto top_row = [](const Image& img) {
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (!is_background(img.rgb(x, y))) return y;
    return -1;
  };
  EXPECT_LT(top_row(after), top_row(before) - 10);
}

// BackgroundSetting's colour clears the picture; showWireframe draws the edges only.
TEST_F(RenderTest, BackgroundSettingAndWireframe) {
  auto filled = test::load("<Node name=\"root\"><BackgroundSetting color=\"0 0 1\"/>" + cube("c", "white", 0) +
                           "</Node>");
  const Image a = render(*filled.root);
  EXPECT_EQ(a.rgb(2, 2), (std::array<int, 3>{0, 0, 255}));
  auto lit = [](const Image& img) {
    return count_if(img, [](auto c) { return c[0] > 0; });  // white model on blue
  };
  auto wire = test::load("<Node name=\"root\"><BackgroundSetting color=\"0 0 1\"/>"
                         "<VisualStyle displayFlags=\"showWireframe\"/>" +
                         cube("c", "white", 0) + "</Node>");
  const Image b = render(*wire.root);
  RecordProperty("filled", static_cast<int>(lit(a)));
  RecordProperty("wireframe", static_cast<int>(lit(b)));
  EXPECT_GT(lit(b), 100);
  EXPECT_LT(lit(b), lit(a) / 4);
}

// An OBJ with a .mtl: the loader's defaultMaterial is the first material a usemtl names
// (SOFA's MeshOBJLoader), the OglModel takes it through src=@loader and draws its Kd.
TEST_F(RenderTest, ObjMaterialGivesTheColour) {
  test::TempDir dir;
  dir.write("quad.mtl", "newmtl unused\nKd 0 1 0\nnewmtl tissue\nNs 10\nKa 0 0 0\nKd 0.8 0.2 0.1\nd 1\n");
  const std::string obj = dir.write("quad.obj",
                                    "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                    "usemtl tissue\nf 1 2 3 4\n");
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<MeshOBJLoader name=\"l\" filename=\"" + obj + "\"/><OglModel name=\"m\" src=\"@l\"/></Node>");
  auto* m = test::get<OglModel>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->material.get().rfind("tissue Diffuse 1 0.8 0.2 0.1 1 Ambient 1 0 0 0 1", 0), 0u) << m->material.get();
  const Image img = render(*s.root);
  const auto c = img.rgb(100, 100);  // facing the light: Kd (no ambient)
  EXPECT_NEAR(c[0], 204, 2);
  EXPECT_NEAR(c[1], 51, 2);
  EXPECT_NEAR(c[2], 26, 2);
}

// A unit square facing the camera at depth z, as one OglModel (quads are split in two).
std::string square(const std::string& name, const std::string& attrs, double z) {
  const std::string zs = std::to_string(z);
  return "<Node name=\"" + name + "\"><OglModel name=\"" + name + "\" " + attrs + " position=\"-0.5 -0.5 " + zs +
         "  0.5 -0.5 " + zs + "  0.5 0.5 " + zs + "  -0.5 0.5 " + zs + "\" quads=\"0 1 2 3\"/></Node>";
}

// SOFA's transparent pass (OglModel::internalDraw): a translucent model is drawn after the
// opaque ones whatever its place in the graph, the background darkened by (1 - a) then its
// lit colour added times a, without writing depth. Red at a = 0.5 in front of blue: half of
// each; behind it: hidden; blendTranslucency off: opaque red. The picture stays opaque.
TEST_F(RenderTest, TranslucentModelBlendsOverTheOpaqueOnes) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  const std::string blue = square("blue", "color=\"0 0 1 1\"", 0.0);
  auto centre = [&](const std::string& xml, int* alpha = nullptr) {
    auto s = test::load("<Node name=\"root\">" + camera + xml + "</Node>");
    const Image img = render(*s.root);
    if (alpha) *alpha = img.rgba[(100 * img.width + 100) * 4 + 3];
    return img.rgb(100, 100);
  };
  int alpha = 0;
  // Lit red facing the headlight: ambient 0.2 + diffuse 1, clamped to 1.
  const auto over = centre(square("red", "color=\"1 0 0 0.5\"", 1.0) + blue, &alpha);
  EXPECT_NEAR(over[0], 128, 2);
  EXPECT_EQ(over[1], 0);
  EXPECT_NEAR(over[2], 128, 2);
  EXPECT_EQ(alpha, 255);
  // A quarter of red over blue.
  const auto quarter = centre(blue + square("red", "color=\"1 0 0 0.25\"", 1.0));
  EXPECT_NEAR(quarter[0], 64, 2);
  EXPECT_NEAR(quarter[2], 191, 2);
  // Behind the opaque square: the depth test hides it.
  EXPECT_EQ(centre(square("red", "color=\"1 0 0 0.5\"", -1.0) + blue), (std::array<int, 3>{0, 0, 255}));
  // Not blended: drawn as an opaque model (after the others). Rendered right after the scene
  // above with the same renderer, this red model took the address of the blue one freed with
  // that scene, and was drawn blue while the renderer keyed its material cache on the
  // material field's version (now on the material's text).
  EXPECT_EQ(centre(square("red", "color=\"1 0 0 0.5\" blendTranslucency=\"0\"", 1.0) + blue),
            (std::array<int, 3>{255, 0, 0}));
  // Two translucent squares: each blends over what was drawn before it, in graph order.
  const auto two = centre(blue + square("red", "color=\"1 0 0 0.5\"", 1.0) + square("green", "color=\"0 1 0 0.5\"", 2.0));
  EXPECT_NEAR(two[0], 64, 2);
  EXPECT_NEAR(two[1], 128, 2);
  EXPECT_NEAR(two[2], 64, 2);
}

// OglModel's own GL state (internalDraw): alphaBlend draws it with blendEquation, sfactor and
// dfactor; depthTest="0" draws it over what is in front; cullFace 1 drops back faces, 2 front
// faces (the square faces the camera). Red drawn after blue, at the centre of the picture.
TEST_F(RenderTest, OglModelBlendDepthAndCullOptions) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  const std::string blue = square("blue", "color=\"0 0 1 1\"", 0.0);
  auto centre = [&](const std::string& red_attrs, double z) {
    auto s = test::load("<Node name=\"root\">" + camera + blue + square("red", "color=\"1 0 0 1\" " + red_attrs, z) +
                        "</Node>");
    return render(*s.root).rgb(100, 100);
  };
  using C = std::array<int, 3>;
  EXPECT_EQ(centre("", 1.0), (C{255, 0, 0}));
  EXPECT_EQ(centre("alphaBlend=\"1\"", 1.0), (C{255, 0, 0}));  // source alpha 1: the default factors replace
  EXPECT_EQ(centre("alphaBlend=\"1\" sfactor=\"GL_ONE\" dfactor=\"GL_ONE\"", 1.0), (C{255, 0, 255}));
  EXPECT_EQ(centre("alphaBlend=\"1\" blendEquation=\"GL_MIN\"", 1.0), (C{0, 0, 0}));
  EXPECT_EQ(centre("", -1.0), (C{0, 0, 255}));
  EXPECT_EQ(centre("depthTest=\"0\"", -1.0), (C{255, 0, 0}));
  EXPECT_EQ(centre("cullFace=\"1\"", 1.0), (C{255, 0, 0}));
  EXPECT_EQ(centre("cullFace=\"2\"", 1.0), (C{0, 0, 255}));
  auto bad = test::load("<Node name=\"root\">" + camera + square("red", "sfactor=\"GL_DST_COLOR\"", 0.0) + "</Node>");
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::warning),
                                 "sfactor 'GL_DST_COLOR' is not one of"));
}

// OrderIndependentTransparencyManager in the root node: translucent models are
// accumulated with SOFA's weights w = clamp(0.03 / (1e-5 + (depth·0.01)⁴), 1e-2, 3e3) and
// composed as Σ c·a·w / Σ a·w covering 1 − Π(1 − a) of the picture. Red (a = 0.5) at eye
// depth 4 (w = 2388.5) and green (a = 0.5) at depth 3 (w = 2775.2) over opaque blue:
// (0.4625, 0.5375, 0)·0.75 + (0, 0, 1)·0.25 = (88.5, 102.8, 63.75)/255, whatever their order;
// blended in drawing order they give (64, 128, 64). A translucent model behind an opaque one
// stays hidden; a manager outside the root node does nothing, as in SOFA's visual loop.
TEST_F(RenderTest, OrderIndependentTransparencyWeighsByDepthNotOrder) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  const std::string plain = "Ambient 0 0 0 0 1 Specular 0 0 0 0 1 Emissive 0 0 0 0 1 Shininess 0 45\"";
  const std::string red = square("red", "material=\"m Diffuse 1 1 0 0 0.5 " + plain, 1.0);
  const std::string green = square("green", "material=\"m Diffuse 1 0 1 0 0.5 " + plain, 2.0);
  const std::string blue = square("blue", "material=\"m Diffuse 1 0 0 1 1 " + plain, 0.0);
  const std::string manager = "<OrderIndependentTransparencyManager/>";
  auto centre = [&](const std::string& xml) {
    auto s = test::load("<Node name=\"root\">" + camera + xml + "</Node>");
    const Image img = render(*s.root);
    EXPECT_EQ(img.rgba[(100 * img.width + 100) * 4 + 3], 255) << "the picture stays opaque";
    return img.rgb(100, 100);
  };
  for (const std::string& xml : {manager + blue + red + green, manager + green + red + blue}) {
    const auto c = centre(xml);
    EXPECT_NEAR(c[0], 88.5, 1.5);
    EXPECT_NEAR(c[1], 102.8, 1.5);
    EXPECT_NEAR(c[2], 63.75, 1.5);
  }
  const auto ordered = centre(blue + red + green);
  EXPECT_NEAR(ordered[0], 64, 2);
  EXPECT_NEAR(ordered[1], 128, 2);
  EXPECT_EQ(centre(manager + blue + square("red", "material=\"m Diffuse 1 1 0 0 0.5 " + plain, -1.0)),
            (std::array<int, 3>{0, 0, 255}));
  auto nested = test::load("<Node name=\"root\">" + camera + "<Node name=\"inner\">" + manager + "</Node>" + blue +
                           red + green + "</Node>");
  ASSERT_TRUE(nested.root);
  EXPECT_TRUE(test::any_contains(test::messages(nested.root->diagnostics(), Severity::warning), "not in the root node"));
  const auto c = render(*nested.root).rgb(100, 100);
  EXPECT_NEAR(c[0], 64, 2);
  EXPECT_NEAR(c[1], 128, 2);
}

// Pixels of `img` with exactly the colour `c` (±2 per channel).
long count_color(const Image& img, const std::array<int, 3>& c) {
  return count_if(img, [&](auto p) {
    return std::abs(p[0] - c[0]) <= 2 && std::abs(p[1] - c[1]) <= 2 && std::abs(p[2] - c[2]) <= 2;
  });
}

// VisualPointCloud as SOFA's doDrawVisual: Point mode draws unlit squares of pointSize pixels;
// Sphere mode lit spheres whose radii pad with the last one; Frame mode (Rigid3d) red, green and
// blue axes of length pointSize along the frame's rotated axes.
TEST_F(RenderTest, VisualPointCloudPointsSpheresAndFrames) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  auto points = test::load("<Node name=\"root\">" + camera +
                           "<VisualPointCloud position=\"0 0 0  1 0 0\" pointSize=\"10\" color=\"navy\"/></Node>");
  const Image a = render(*points.root);
  EXPECT_EQ(count_color(a, {0, 0, 128}), 200);  // two squares of 10 × 10 pixels, unlit navy
  // Radii 0.5 then padded with 0.5: two discs of radius 0.5·48.3 px (the unit is 100 / (4.5 tan 22.5°)
  // px at the spheres' front, a bit more than at their centre).
  auto spheres = test::load("<Node name=\"root\">" + camera +
                            "<VisualPointCloud position=\"-1 0 0  1 0 0\" drawMode=\"Sphere\" sphereRadius=\"0.5\" "
                            "color=\"red\"/></Node>");
  const Image b = render(*spheres.root);
  const double r_px = 0.5 * 100.0 / (5 * std::tan(M_PI / 8));
  const long lit = count_if(b, [](auto c) { return c[0] > 0; });
  EXPECT_NEAR(lit, 2 * M_PI * r_px * r_px, 0.12 * 2 * M_PI * r_px * r_px);
  EXPECT_EQ(b.rgb(100 + static_cast<int>(r_px * 2), 100)[0], 255);  // the centre of the right one, facing the light
  // A frame turned 90° about z: its x axis (red) points up, its y axis (green) to the left.
  auto frame = test::load("<Node name=\"root\">" + camera +
                          "<VisualPointCloud template=\"Rigid3d\" position=\"0 0 0  0 0 0.7071067811865476 "
                          "0.7071067811865476\" drawMode=\"Frame\" pointSize=\"1\"/></Node>");
  const Image c = render(*frame.root);
  auto reddish = [](auto p) { return p[0] > 100 && p[1] < 60 && p[2] < 60; };
  auto greenish = [](auto p) { return p[1] > 100 && p[0] < 60 && p[2] < 60; };
  EXPECT_GT(count_if(c, reddish), 50);
  EXPECT_GT(count_if(c, greenish), 50);
  // Red above the centre, none below; green left of it, none right.
  EXPECT_TRUE(reddish(c.rgb(100, 100 - 30)));
  EXPECT_FALSE(reddish(c.rgb(100, 100 + 30)));
  EXPECT_TRUE(greenish(c.rgb(100 - 30, 100)));
  EXPECT_FALSE(greenish(c.rgb(100 + 30, 100)));
}

// CylinderVisualModel: a lit cylinder per edge: from (-1, 0, 0) to (1, 0, 0), radius 0.25, seen
// from 5 away: a 2 × 0.5 rectangle of about 96 × 24 pixels, yellow where it faces the light.
TEST_F(RenderTest, CylinderVisualModelDrawsACylinderPerEdge) {
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<CylinderVisualModel position=\"-1 0 0  1 0 0\" edges=\"0 1\" radius=\"0.25\" "
                      "color=\"yellow\"/></Node>");
  const Image img = render(*s.root);
  const double px = 100.0 / (5 * std::tan(M_PI / 8));
  const long area = count_if(img, [](auto c) { return !is_background(c); });
  EXPECT_NEAR(area, 2 * px * 0.5 * px, 0.1 * px * px);
  const auto centre = img.rgb(100, 100);
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[1], 255);
  EXPECT_LE(centre[2], 2);
  EXPECT_TRUE(is_background(img.rgb(100, 100 - static_cast<int>(0.4 * px))));
}

// VisualMesh as SOFA's DrawMesh: one hexahedron shrunk by elementSpace 0.15, its +z face (SOFA's
// face 1, colour (0.7, 0, 0)) towards the camera, lit: (0.84, 0, 0); unlit: (0.7, 0, 0); its
// width 0.85 of the cube's. A surface of triangles only: green, teal, blue by index.
TEST_F(RenderTest, VisualMeshDrawsShrunkElementsInSofasColours) {
  const std::string cube_points =
      "-0.5 -0.5 -0.5  0.5 -0.5 -0.5  0.5 0.5 -0.5  -0.5 0.5 -0.5  "
      "-0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5";
  auto mesh = [&](const std::string& extra) {
    return test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<MeshTopology name=\"t\" hexahedra=\"0 1 2 3 4 5 6 7\"/>"
                      "<VisualMesh position=\"" + cube_points + "\" topology=\"@t\" " + extra + "/></Node>");
  };
  auto lit = mesh("");
  const Image a = render(*lit.root);
  EXPECT_EQ(a.rgb(100, 100), (std::array<int, 3>{214, 0, 0}));
  // The front face spans 0.85 of the unit cube, at distance 4.5 − 0.075.
  const double half = 100.0 * 0.5 * 0.85 / ((4.5 + 0.075) * std::tan(M_PI / 8));
  const long front = count_if(a, [](auto c) { return c[0] > 150 && c[1] < 5; });
  EXPECT_NEAR(front, 4 * half * half, 0.05 * 4 * half * half);
  auto flat = mesh("lighting=\"0\"");
  EXPECT_EQ(render(*flat.root).rgb(100, 100), (std::array<int, 3>{178, 0, 0}));
  // Three triangles side by side, facing the camera: green, teal, blue, unlit.
  auto tris = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                         "<MeshTopology name=\"t\" triangles=\"0 1 2  3 4 5  6 7 8\"/>"
                         "<VisualMesh position=\"-1.6 -0.4 0  -0.8 -0.4 0  -1.2 0.4 0  -0.4 -0.4 0  0.4 -0.4 0  0 0.4 0 "
                         " 0.8 -0.4 0  1.6 -0.4 0  1.2 0.4 0\" topology=\"@t\" lighting=\"0\"/></Node>");
  const Image t = render(*tris.root);
  const int third = static_cast<int>(1.2 * 100.0 / (5 * std::tan(M_PI / 8)));
  EXPECT_EQ(t.rgb(100 - third, 100), (std::array<int, 3>{0, 255, 0}));
  EXPECT_EQ(t.rgb(100, 100), (std::array<int, 3>{0, 128, 128}));
  EXPECT_EQ(t.rgb(100 + third, 100), (std::array<int, 3>{0, 0, 255}));
}

// PointSplatModel: each point a disc facing the camera whose opacity is alpha·cos(π/2·r/R), blended
// "over" from the farthest point to the nearest (SOFA sorts them), after the opaque models.
TEST_F(RenderTest, PointSplatModelBlendsSoftDiscsBackToFront) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  auto one = test::load("<Node name=\"root\">" + camera +
                        "<MechanicalObject position=\"0 0 0\"/><PointSplatModel radius=\"0.5\" color=\"red\"/></Node>");
  const Image a = render(*one.root);
  const double r_px = 0.5 * 100.0 / (5 * std::tan(M_PI / 8));  // 24.1 px
  EXPECT_NEAR(a.rgb(100, 100)[0], 255, 3);
  EXPECT_NEAR(a.rgb(100 + static_cast<int>(0.5 * r_px), 100)[0], 255 * std::cos(M_PI / 4), 8);
  EXPECT_GT(a.rgb(100 + static_cast<int>(0.8 * r_px), 100)[0], 0);
  EXPECT_TRUE(is_background(a.rgb(100 + static_cast<int>(1.2 * r_px), 100)));
  // Green in front of red (listed first), both at alpha 0.5: red is drawn first, then green over it.
  auto two = test::load("<Node name=\"root\">" + camera +
                        "<Node name=\"g\"><MechanicalObject position=\"0 0 1\"/>"
                        "<PointSplatModel radius=\"0.5\" alpha=\"0.5\" color=\"lime\"/></Node>"
                        "<Node name=\"r\"><MechanicalObject position=\"0 0 -1\"/>"
                        "<PointSplatModel radius=\"0.5\" alpha=\"0.5\" color=\"red\"/></Node></Node>");
  const auto c = render(*two.root).rgb(100, 100);
  EXPECT_NEAR(c[0], 64, 3);   // red 0.5, then · (1 − 0.5)
  EXPECT_NEAR(c[1], 128, 3);  // lime's green 1 · 0.5
}

// OglFluidModel's screen-space surface (render/fluid_surface.h). One particle 5 in front of the
// camera (45°, 200 px high): SOFA's sprite is spriteRadius · 200 / tan(32.5°) / |(eye, 1)| = 30.8 px
// across whatever the field of view. Blur radius 0 (one sample: no blur) keeps the thickness
// exact. Over black, red = thickness · (1 − thickness) for a blue fluid (its white part), away
// from the centre's highlight; two particles at one place add their thicknesses.
TEST_F(RenderTest, OglFluidModelDrawsSofasScreenSpaceSurface) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  auto fluid = [&](const std::string& points, const std::string& more = "spriteThickness=\"0.2\"") {
    return "<Node name=\"f\"><OglFluidModel position=\"" + points + "\" spriteRadius=\"0.5\" spriteBlurRadius=\"0\" " +
           more + "/></Node>";
  };
  auto one = test::load("<Node name=\"root\">" + camera + fluid("0 0 0", "spriteThickness=\"1\"") + "</Node>");
  const Image img = render(*one.root);
  const double r_px = 0.5 * 0.5 * 200.0 / std::tan(65.0 * M_PI / 360.0) / std::sqrt(26.0);  // 15.4 px
  const long area = count_if(img, [](auto c) { return !is_background(c); });
  EXPECT_NEAR(area, M_PI * r_px * r_px, 0.1 * M_PI * r_px * r_px);
  EXPECT_EQ(img.rgb(100, 100)[2], 255);  // thick: the fluid's blue, lit head-on
  EXPECT_TRUE(is_background(img.rgb(100 + static_cast<int>(1.2 * r_px), 100)));

  const int off = 100 + static_cast<int>(0.5 * r_px);
  auto thin = test::load("<Node name=\"root\">" + camera + fluid("0 0 0") + "</Node>");
  EXPECT_NEAR(render(*thin.root).rgb(off, 100)[0], 255 * 0.2 * 0.8, 2);
  auto two = test::load("<Node name=\"root\">" + camera + fluid("0 0 0  0 0 0") + "</Node>");
  EXPECT_NEAR(render(*two.root).rgb(off, 100)[0], 255 * 0.4 * 0.6, 2);

  // Depth-tested against the scene: an opaque square in front hides it, one behind shows through
  // (alpha = thickness 0.2: 0.8 of the square plus 0.2 of the fluid's 0.8 white in red and green).
  const std::string red = "color=\"1 0 0 1\"";
  auto alone = test::load("<Node name=\"root\">" + camera + square("sq", red, 1.0) + "</Node>");
  auto front = test::load("<Node name=\"root\">" + camera + fluid("0 0 0") + square("sq", red, 1.0) + "</Node>");
  EXPECT_EQ(render(*front.root).rgb(off, 100), render(*alone.root).rgb(off, 100));
  auto under = test::load("<Node name=\"root\">" + camera + square("sq", red, -1.0) + "</Node>");
  auto back = test::load("<Node name=\"root\">" + camera + fluid("0 0 0") + square("sq", red, -1.0) + "</Node>");
  const auto square_only = render(*under.root).rgb(off, 100), behind = render(*back.root).rgb(off, 100);
  for (int c : {0, 1}) EXPECT_NEAR(behind[c], 0.8 * square_only[c] + 255 * 0.2 * 0.8, 3) << c;

  // enable="0" (VisualModel's): not drawn.
  auto disabled = test::load("<Node name=\"root\">" + camera + fluid("0 0 0", "spriteThickness=\"1\" enable=\"0\"") + "</Node>");
  render::DrawList list;
  render::gather(*disabled.root, list);
  EXPECT_EQ(list.used, 0u);

  // debugFBO 0: the thickness target over the whole view (cleared to (0, 1, 1) where empty).
  auto debug = test::load("<Node name=\"root\">" + camera + fluid("0 0 0", "spriteThickness=\"0.2\" debugFBO=\"0\"") + "</Node>");
  const Image d = render(*debug.root);
  EXPECT_EQ(d.rgb(5, 5), (std::array<int, 3>{0, 255, 255}));
  EXPECT_EQ(d.rgb(100, 100), (std::array<int, 3>{51, 255, 255}));
}

// The fluid's passes cover only its sprites' pixels (render/fluid_surface.h): one drawn after
// another elsewhere by the same renderer leaves nothing of the first (the picture is the one a
// fresh renderer makes), and debugFBO 6 still shows the thickness spread by the blur's reach
// (10 px, SOFA's default spriteBlurRadius) beyond the sprite, and 0 farther away.
TEST_F(RenderTest, OglFluidModelPassesCoverOnlyItsSprites) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  auto fluid = [&](const std::string& point, const std::string& more = "") {
    return test::load("<Node name=\"root\">" + camera + "<Node name=\"f\"><OglFluidModel position=\"" + point +
                      "\" spriteRadius=\"0.5\" spriteThickness=\"0.2\" " + more + "/></Node></Node>");
  };
  auto left = fluid("-1 0 0"), right = fluid("1 0 0");
  const Image fresh = render(*right.root);
  const Image other = render(*left.root);
  const int centre = 100 + static_cast<int>(std::lround(0.2 / std::tan(M_PI / 8) * 100));  // 148
  EXPECT_FALSE(is_background(other.rgb(200 - centre, 100)));
  EXPECT_TRUE(is_background(other.rgb(centre, 100)));
  const Image again = render(*right.root);
  EXPECT_TRUE(is_background(again.rgb(200 - centre, 100)));
  EXPECT_EQ(again.rgba, fresh.rgba);

  const double r_px = 0.5 * 0.5 * 200.0 / std::tan(65.0 * M_PI / 360.0) / std::sqrt(26.0);  // 15.4 px
  auto debug = fluid("1 0 0", "debugFBO=\"6\"");
  const Image d = render(*debug.root);
  const int edge = centre + static_cast<int>(std::ceil(r_px));
  EXPECT_GT(d.rgb(edge + 5, 100)[0], 0);
  EXPECT_GT(d.rgb(centre, 100 - static_cast<int>(std::ceil(r_px)) - 5)[0], 0);
  EXPECT_EQ(d.rgb(edge + 14, 100), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(d.rgb(5, 5), (std::array<int, 3>{0, 0, 0}));
}

// PostProcessManager with SOFA's depth-of-field shader: the scene is drawn through the manager's
// gluPerspective(60°, 1, zNear, zFar) (a unit square 5 ahead: 0.1 · cot 30° · 100 = 17.3 px half
// width instead of the camera's 45°: 24.1 px), and the shader reads that picture's depth
// (showDepthMap: the square's window depth 0.808 with near 1, far 100; 1 around it) and colour
// (no blur when blurIntensity is 0: the square's own colour).
TEST_F(RenderTest, PostProcessManagerRunsItsShaderOverTheScenesPicture) {
  const std::string shaders = std::string(SINEW_DATA_DIR) + "/share/shaders/";
  if (!std::filesystem::exists(shaders + "depthOfField.frag"))
    GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  auto scene = [&](const std::string& variables) {
    return "<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
           square("sq", "color=\"0 1 0 1\"", 0.0) + "<OglShader passive=\"true\" fileVertexShaders=\"['" + shaders +
           "depthOfField.vert']\" fileFragmentShaders=\"['" + shaders + "depthOfField.frag']\"/>" + variables +
           "<PostProcessManager zNear=\"1\" zFar=\"100\"/></Node>";
  };
  auto width_of = [](const Image& img, auto is_square) {
    int n = 0;
    for (int x = 0; x < 200; ++x) n += is_square(img.rgb(x, 100)) ? 1 : 0;
    return n;
  };
  auto depth = test::load(scene("<OglIntVariable id=\"showDepthMap\" value=\"1\"/>"));
  const Image d = render(*depth.root);
  const double window_depth = 0.5 * ((101.0 / -99.0 * -5.0 + 200.0 / -99.0) / 5.0 + 1.0);  // 0.808
  EXPECT_NEAR(d.rgb(100, 100)[0], 255 * window_depth, 1);
  EXPECT_EQ(d.rgb(100, 100)[1], d.rgb(100, 100)[0]);
  EXPECT_EQ(d.rgb(3, 3)[0], 255);
  EXPECT_NEAR(width_of(d, [](auto c) { return c[0] < 250; }), 2 * 17.3, 2);

  auto sharp = test::load(scene("<OglFloatVariable id=\"blurIntensity\" value=\"0\"/>"));
  const Image c = render(*sharp.root);
  EXPECT_GT(c.rgb(100, 100)[1], 100);
  EXPECT_EQ(c.rgb(100, 100)[0], 0);
  EXPECT_TRUE(is_background(c.rgb(3, 3)));
  EXPECT_NEAR(width_of(c, [](auto p) { return !is_background(p); }), 2 * 17.3, 2);
  // Without the manager, the camera's own 45°.
  auto plain = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                          square("sq", "color=\"0 1 0 1\"", 0.0) + "</Node>");
  EXPECT_NEAR(width_of(render(*plain.root), [](auto p) { return !is_background(p); }), 2 * 24.1, 2);
}

// OglModel primitiveType POINTS: its vertices as points of pointSize pixels, not its triangles.
TEST_F(RenderTest, OglModelPrimitiveTypePointsDrawsItsVertices) {
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                      square("sq", "color=\"1 1 1 1\" primitiveType=\"POINTS\" pointSize=\"5\"", 0.0) + "</Node>");
  const Image img = render(*s.root);
  const long lit = count_if(img, [](auto c) { return !is_background(c); });
  EXPECT_NEAR(lit, 4 * 25, 12);  // four 5 × 5 points (a corner may fall between pixels)
  EXPECT_TRUE(is_background(img.rgb(100, 100)));  // no face between them
  auto bad = test::load("<Node name=\"root\">" + square("sq", "primitiveType=\"QUADS\"", 0.0) + "</Node>");
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::warning), "primitiveType 'QUADS'"));
}

// BackgroundSetting's image, tiled at its own size from the bottom-left under the scene (as
// SofaGLFW): a 4 × 4 picture, two red columns then two blue ones, repeats every 4 pixels; a
// missing image warns and leaves the colour.
TEST_F(RenderTest, BackgroundImageIsTiledUnderTheScene) {
  Image tile;
  tile.width = tile.height = 4;
  tile.rgba.assign(4 * 4 * 4, 255);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      std::uint8_t* p = &tile.rgba[static_cast<std::size_t>((y * 4 + x) * 4)];
      p[0] = x < 2 ? 255 : 0, p[1] = 0, p[2] = x < 2 ? 0 : 255;
    }
  const std::string file = (std::filesystem::temp_directory_path() / "sinew_background_tile.png").string();
  std::string err;
  ASSERT_TRUE(render::write_png(file, tile, &err)) << err;
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                      "<BackgroundSetting color=\"0 1 0\" image=\"" + file + "\"/>" +
                      square("sq", "color=\"1 1 1 1\"", 0.0) + "</Node>");
  const Image img = render(*s.root);
  for (int x : {1, 5, 101, 197}) EXPECT_EQ(img.rgb(x, 198), (std::array<int, 3>{255, 0, 0})) << x;
  for (int x : {3, 7, 103}) EXPECT_EQ(img.rgb(x, 198), (std::array<int, 3>{0, 0, 255})) << x;
  EXPECT_EQ(img.rgb(100, 100)[1], img.rgb(100, 100)[0]);  // the white square over it (lit grey)
  EXPECT_GT(img.rgb(100, 100)[1], 100);
  auto missing = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                            "<BackgroundSetting color=\"0 1 0\" image=\"no/such/sky.png\"/>" +
                            square("sq", "color=\"1 1 1 1\"", 0.0) + "</Node>");
  EXPECT_TRUE(test::any_contains(test::messages(missing.root->diagnostics(), Severity::warning), "no/such/sky.png"));
  EXPECT_EQ(render(*missing.root).rgb(1, 198), (std::array<int, 3>{0, 255, 0}));
}

// A LightManager's lights replace the headlight with fixed-function OpenGL lighting: per light
// attenuation · spot · colour · (ambient + diffuse·max(n·L, 0)), plus the manager's ambient. A
// square facing the camera, colour 0.5 red (ambient 0.1, diffuse 0.5, no specular).
TEST_F(RenderTest, SceneLightsAsFixedFunctionOpenGL) {
  auto centre_red = [&](const std::string& lights, int dx = 0) {
    auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" + lights +
                        square("sq", "color=\"0.5 0 0 1\"", 0.0) + "</Node>");
    return render(*s.root).rgb(100 + dx, 100)[0];
  };
  // Light from the camera's side: 0.1 + 0.5.
  EXPECT_NEAR(centre_red("<LightManager/><DirectionalLight direction=\"0 0 1\"/>"), 153, 2);
  // From behind the square: its ambient only.
  EXPECT_NEAR(centre_red("<LightManager/><DirectionalLight direction=\"0 0 -1\"/>"), 26, 2);
  // 60° from the normal: 0.1 + 0.5 cos 60°.
  EXPECT_NEAR(centre_red("<LightManager/><DirectionalLight direction=\"0.8660254 0 0.5\"/>"), 89, 2);
  // No light: the manager's ambient times the material's.
  EXPECT_NEAR(centre_red("<LightManager ambient=\"1 1 1 1\"/>"), 26, 2);
  EXPECT_EQ(centre_red("<LightManager/>"), 0);
  // A point light 2 above the centre, linear attenuation 1: (0.1 + 0.5) / (1 + 2).
  EXPECT_NEAR(centre_red("<LightManager/><PositionalLight position=\"0 0 2\" attenuation=\"1\"/>"), 51, 2);
  // A spot 2 above, cut-off 10°: the centre lit, a point 0.45 aside (12.7° off axis) dark.
  const std::string spot = "<LightManager/><SpotLight position=\"0 0 2\" direction=\"0 0 -1\" cutoff=\"10\"/>";
  EXPECT_NEAR(centre_red(spot), 153, 2);
  EXPECT_EQ(centre_red(spot, static_cast<int>(0.45 * 100.0 / (5 * std::tan(M_PI / 8)))), 0);
  // A light outside any LightManager's subtree is not used (a warning); the scene keeps the headlight.
  auto lonely = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>"
                           "<DirectionalLight direction=\"0 0 -1\"/>" + square("sq", "color=\"0.5 0 0 1\"", 0.0) +
                           "</Node>");
  EXPECT_TRUE(test::any_contains(test::messages(lonely.root->diagnostics(), Severity::warning), "no LightManager"));
  EXPECT_NEAR(render(*lonely.root).rgb(100, 100)[0], 153, 2);
}

// VisualGrid (plane z, side 2, two subdivisions): unlit lines at x, y = −1, 0, 1 in its grey;
// LineAxis: x red horizontal, y green vertical, of `size`, only the axes named.
TEST_F(RenderTest, VisualGridAndLineAxis) {
  const std::string camera = "<InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>";
  const int unit = static_cast<int>(std::lround(100.0 / (5 * std::tan(M_PI / 8))));  // 48 px
  auto grid = test::load("<Node name=\"root\">" + camera + "<VisualGrid size=\"2\" nbSubdiv=\"2\"/></Node>");
  const Image g = render(*grid.root);
  // A one-pixel line through a pixel boundary lands on one of the two pixels: look at ±1.
  auto near = [](const Image& img, int x, int y, const std::array<int, 3>& c) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (img.rgb(x + dx, y + dy) == c) return true;
    return false;
  };
  const std::array<int, 3> grey{87, 87, 87};
  EXPECT_TRUE(near(g, 100, 100 + unit / 2, grey));         // the line x = 0
  EXPECT_TRUE(near(g, 100 + unit / 2, 100, grey));         // the line y = 0
  EXPECT_TRUE(is_background(g.rgb(100 + unit / 2, 100 + unit / 2)));  // inside a cell
  EXPECT_TRUE(is_background(g.rgb(100 + 2 * unit, 100)));             // beyond the grid
  auto axes = test::load("<Node name=\"root\">" + camera + "<LineAxis size=\"2\"/></Node>");
  const Image a = render(*axes.root);
  EXPECT_TRUE(near(a, 100 + unit / 2, 100, {255, 0, 0}));
  EXPECT_TRUE(near(a, 100, 100 - unit / 2, {0, 255, 0}));
  EXPECT_TRUE(is_background(a.rgb(100 + 2 * unit, 100)));  // ends at size / 2
  auto x_only = test::load("<Node name=\"root\">" + camera + "<LineAxis size=\"2\" axis=\"X\"/></Node>");
  const Image x = render(*x_only.root);
  EXPECT_TRUE(near(x, 100 + unit / 2, 100, {255, 0, 0}));
  EXPECT_FALSE(near(x, 100, 100 - unit / 2, {0, 255, 0}));
}

// OglSceneFrame: the axes in a corner viewport of viewportSize pixels over the scene, turned as
// the camera sees the world: x red to the right, y green upwards for a camera on +z.
TEST_F(RenderTest, OglSceneFrameDrawsTheAxesInItsCorner) {
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                      cube("c", "white", 0) + "<OglSceneFrame style=\"Arrows\" viewportSize=\"60\"/></Node>");
  const Image img = render(*s.root);
  auto red = [](auto c) { return c[0] > 200 && c[1] < 50 && c[2] < 50; };
  auto green = [](auto c) { return c[1] > 200 && c[0] < 50 && c[2] < 50; };
  // The bottom-right 60 × 60 pixels, centred on (170, 170) in picture rows from the top.
  EXPECT_TRUE(red(img.rgb(170 + 15, 170)));
  EXPECT_TRUE(green(img.rgb(170, 170 - 15)));
  EXPECT_FALSE(red(img.rgb(170 - 15, 170)));
  EXPECT_FALSE(green(img.rgb(170, 170 + 15)));
  // Nothing of it outside its corner.
  long outside = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if ((x < 140 || y < 140) && (red(img.rgb(x, y)) || green(img.rgb(x, y)))) ++outside;
  EXPECT_EQ(outside, 0);
  // Top-left with cylinders.
  auto t = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" +
                      cube("c", "white", 0) + "<OglSceneFrame alignment=\"TopLeft\" viewportSize=\"60\"/></Node>");
  const Image tl = render(*t.root);
  EXPECT_TRUE(red(tl.rgb(30 + 15, 30)));
  EXPECT_TRUE(green(tl.rgb(30, 30 - 15)));
}

TEST_F(RenderTest, NothingVisibleIsAnError) {
  auto s = test::load(R"(<Node name="root"><VisualStyle displayFlags="hideVisualModels"/>
      <OglModel position="0 0 0 1 0 0 1 1 0" triangles="0 1 2"/></Node>)");
  Image img;
  std::string err;
  EXPECT_FALSE(renderer_->render(*s.root, img, &err));
  EXPECT_NE(err.find("nothing is visible"), std::string::npos) << err;
}

// The issue's check: SOFA's TetrahedronFEMForceField.scn (no visual model: its VisualStyle shows
// behaviour models and force fields) at steps 0 and 100 gives two different, non-blank pictures.
TEST_F(RenderTest, TetrahedronFEMForceFieldSceneBendsBetweenSteps0And100) {
  Image first, last;
  if (!pictures_at_0_and_100("Component/SolidMechanics/FEM/TetrahedronFEMForceField.scn", first, last))
    GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  const long lit0 = count_if(first, [](auto c) { return !is_background(c); });
  const long lit1 = count_if(last, [](auto c) { return !is_background(c); });
  RecordProperty("lit0", static_cast<int>(lit0));
  RecordProperty("lit100", static_cast<int>(lit1));
  EXPECT_GT(lit0, 2000);
  EXPECT_GT(lit1, 2000);
  long changed = 0;
  for (std::size_t i = 0; i < std::min(first.rgba.size(), last.rgba.size()); i += 4)
    changed += first.rgba[i + 2] != last.rgba[i + 2];
  EXPECT_GT(changed, 500);
  // The free ends (towards the camera) sag under gravity: the lowest lit row moves down.
  auto lowest = [](const Image& img) {
    for (int y = img.height - 1; y >= 0; --y)
      for (int x = 0; x < img.width; ++x)
        if (!is_background(img.rgb(x, y))) return y;
    return -1;
  };
  RecordProperty("changed_pixels", static_cast<int>(changed));
  RecordProperty("lowest_row_0", lowest(first));
  RecordProperty("lowest_row_100", lowest(last));
  EXPECT_GT(lowest(last), lowest(first) + 3);
}

// The issue's other check: SOFA's liver.scn (a red OglModel mapped from a tetrahedral FEM body,
// with collision) at steps 0 and 100: two different, non-blank pictures of a red liver.
TEST_F(RenderTest, LiverSceneIsRedAndMovesBetweenSteps0And100) {
  Image first, last;
  if (!pictures_at_0_and_100("Demos/liver.scn", first, last))
    GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  // Red dominant (the specular highlights are pink, the grazing edges dark red).
  auto reddish = [](auto c) { return c[0] > 20 && c[0] > c[1] + 10 && c[0] > c[2] + 10; };
  const long red0 = count_if(first, reddish), red1 = count_if(last, reddish);
  const long lit0 = count_if(first, [](auto c) { return !is_background(c); });
  RecordProperty("red0", static_cast<int>(red0));
  RecordProperty("red100", static_cast<int>(red1));
  EXPECT_GT(red0, 2000);
  EXPECT_GT(red1, 2000);
  EXPECT_GT(red0, 0.97 * lit0);  // the liver is all there is, and it is red
  long changed = 0;
  for (std::size_t i = 0; i < std::min(first.rgba.size(), last.rgba.size()); i += 4)
    changed += first.rgba[i] != last.rgba[i];
  RecordProperty("changed_pixels", static_cast<int>(changed));
  EXPECT_GT(changed, 500);
}

}  // namespace
}  // namespace sinew
