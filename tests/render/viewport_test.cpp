// OglViewport (visual/ogl_viewport.h): its view as SOFA computes it, and pictures with the scene
// drawn again in a rectangle (skipped without off-screen OpenGL).
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera_view.h"
#include "render/offscreen.h"
#include "gl_skip.h"
#include "test_scene.h"

namespace sinew {
namespace {

using render::Image;

// Identity orientation: the camera at its position looking along −z; near and far from the
// box's corners: depths 4 and 6 from z = 5 → 0.8·4 and 1.2·6.
TEST(OglViewportView, FromItsCameraWithSofasClipPlanes) {
  render::ExtraViewport e;
  e.position = Vec3(0, 0, 5);
  e.fovy = 60;
  const render::View v = render::viewport_view(e, Vec3(-1, -1, -1), Vec3(1, 1, 1), 2.0);
  const Eigen::Vector4f eye = v.view * Eigen::Vector4f(0, 0, 0, 1);
  EXPECT_FLOAT_EQ(eye.z(), -5.f);
  const float f = 1.f / std::tan(static_cast<float>(M_PI) / 6);
  EXPECT_NEAR(v.projection(1, 1), f, 1e-6);
  EXPECT_NEAR(v.projection(0, 0), f / 2, 1e-6);
  const double n = 3.2, far = 7.2;
  EXPECT_NEAR(v.projection(2, 2), -(far + n) / (far - n), 1e-6);
  EXPECT_NEAR(v.projection(2, 3), -2 * far * n / (far - n), 1e-5);
  // Given planes; a box behind the camera: near 1.
  e.z_near = 0.5, e.z_far = 50;
  EXPECT_NEAR(render::viewport_view(e, Vec3(-1, -1, -1), Vec3(1, 1, 1), 1.0).projection(2, 2), -50.5 / 49.5, 1e-6);
  // A quarter turn about y (world → camera): the world's +x comes in front of the camera.
  e.z_near = e.z_far = 0;
  e.position = Vec3::Zero();
  e.orientation = VecN<4>(0, std::sin(M_PI / 4), 0, std::cos(M_PI / 4));
  const Eigen::Vector4f front = render::viewport_view(e, Vec3(-1, -1, -1), Vec3(1, 1, 1), 1.0).view *
                                Eigen::Vector4f(3, 0, 0, 1);
  EXPECT_NEAR(front.z(), -3, 1e-6);
}

class ViewportPictureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string err;
    render::RenderOptions o;
    o.width = 200, o.height = 200;
    o.samples = 0;
    renderer_ = render::OffscreenRenderer::create(o, &err);
    if (!renderer_) {
    ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
    GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
  }
  }
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

bool red(const std::array<int, 3>& c) { return c[0] > 100 && c[1] < 20 && c[2] < 20; }

// A red square [-0.5, 0.5]² at z = 0 seen from z = 20 by the main camera (small, at the
// centre; the rectangle hides a quarter of it) and, in a 100 × 100 rectangle at the
// bottom-left corner, from z = 2 with a 60° field of view: there its side is
// 100·1/(2·2·tan 30°) = 43.3 px, centred on (50, 150) from the top.
TEST_F(ViewportPictureTest, SceneDrawnAgainInItsRectangle) {
  auto s = test::load(
      "<Node name=\"root\"><InteractiveCamera position=\"0 0 20\" lookAt=\"0 0 0\"/>"
      "<OglViewport screenPosition=\"0 0\" screenSize=\"100 100\" cameraPosition=\"0 0 2\"/>"
      "<Node name=\"sq\"><OglModel color=\"1 0 0\" position=\"-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0\" "
      "quads=\"0 1 2 3\"/></Node></Node>");
  Image img;
  std::string err;
  ASSERT_TRUE(renderer_->render(*s.root, img, &err)) << err;
  long in_rect = 0, main_view = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      if (red(img.rgb(x, y))) (x < 100 && y >= 100 ? in_rect : main_view)++;
  const double side = 100.0 / (2.0 * 2.0 * std::tan(M_PI / 6));
  RecordProperty("rect_pixels", static_cast<int>(in_rect));
  EXPECT_NEAR(in_rect, side * side, 0.04 * side * side);
  const double small = 100.0 / (20.0 * std::tan(M_PI / 8));  // 12 px in the main view
  EXPECT_NEAR(main_view, 0.75 * small * small, 0.1 * small * small);
  EXPECT_TRUE(red(img.rgb(50, 150)));
  EXPECT_FALSE(red(img.rgb(3, 197)));
  // Disabled, or with advancedRendering without the flag: not drawn.
  for (const char* attrs : {"enabled=\"0\"", "advancedRendering=\"1\""}) {
    auto t = test::load(std::string("<Node name=\"root\"><InteractiveCamera position=\"0 0 20\" lookAt=\"0 0 0\"/>"
                                    "<OglViewport screenPosition=\"0 0\" screenSize=\"100 100\" cameraPosition=\"0 0 2\" ") +
                        attrs +
                        "/><Node name=\"sq\"><OglModel color=\"1 0 0\" position=\"-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  "
                        "-0.5 0.5 0\" quads=\"0 1 2 3\"/></Node></Node>");
    ASSERT_TRUE(renderer_->render(*t.root, img, &err)) << err;
    EXPECT_FALSE(red(img.rgb(50, 150))) << attrs;
  }
}

// drawCamera (OglViewport::draw): the view's camera as SOFA's frame of size 0.1, drawn even
// when the view is disabled. Seen from z = 2 (120.7 px per unit), the red x shaft ends about
// 12 px right of the centre, the green y shaft 12 px above; without drawCamera nothing
// (a blue square in a corner, so that the picture has a visual model).
// An OglFluidModel seen by the main view and by a 100 × 100 OglViewport, each pass with a
// surface of its own (targets of its size, kept from picture to picture): outside the rectangle
// the picture is the one drawn without the viewport, the rectangle shows the fluid too, and a
// second picture by the same renderer is the same.
TEST_F(ViewportPictureTest, FluidSurfaceInTheMainViewAndAViewport) {
  auto scene = [](const std::string& viewport) {
    return test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" + viewport +
                      "<Node name=\"f\"><OglFluidModel position=\"0 0 0\" spriteRadius=\"0.5\" "
                      "spriteThickness=\"1\" spriteBlurRadius=\"2\"/></Node></Node>");
  };
  auto alone = scene("");
  auto both = scene("<OglViewport screenPosition=\"0 0\" screenSize=\"100 100\" cameraPosition=\"0 0 3\"/>");
  Image a, b, again;
  std::string err;
  ASSERT_TRUE(renderer_->render(*alone.root, a, &err)) << err;
  ASSERT_TRUE(renderer_->render(*both.root, b, &err)) << err;
  ASSERT_TRUE(renderer_->render(*both.root, again, &err)) << err;
  EXPECT_EQ(b.rgba, again.rgba);
  long differ = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      if (!(x < 100 && y >= 100) && a.rgb(x, y) != b.rgb(x, y)) ++differ;
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(b.rgb(100, 100)[2], 255);  // the fluid's blue in the main view
  EXPECT_EQ(b.rgb(50, 150)[2], 255);   // and in the rectangle, centred on (50, 150)
}

TEST_F(ViewportPictureTest, DrawCameraShowsItsFrame) {
  auto picture = [&](const char* draw) {
    auto s = test::load(std::string("<Node name=\"root\"><InteractiveCamera position=\"0 0 2\" lookAt=\"0 0 0\"/>"
                                    "<OglViewport enabled=\"0\" screenSize=\"100 100\" cameraPosition=\"0 0 0\" "
                                    "drawCamera=\"") +
                        draw +
                        "\"/><Node name=\"sq\"><OglModel color=\"0 0 1\" position=\"-0.7 -0.7 0  -0.6 -0.7 0  -0.6 -0.6 0  "
                        "-0.7 -0.6 0\" quads=\"0 1 2 3\"/></Node></Node>");
    Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(*s.root, img, &err)) << err;
    return img;
  };
  const auto green = [](const std::array<int, 3>& c) { return c[1] > 100 && c[0] < 20 && c[2] < 20; };
  const Image on = picture("1");
  EXPECT_TRUE(red(on.rgb(106, 100)));
  EXPECT_TRUE(green(on.rgb(100, 94)));
  EXPECT_FALSE(red(on.rgb(120, 100)));  // beyond the 0.12-long arrow (14.5 px)
  const Image off = picture("0");
  EXPECT_FALSE(red(off.rgb(106, 100)));
  EXPECT_FALSE(green(off.rgb(100, 94)));
}

}  // namespace
}  // namespace sinew
