// Shadows of SOFA's shadow-mapping shaders (render/shadow_maps.h): the lights' views, the map
// sizes, and pictures of a square casting its shadow on a wall under a spot and a directional
// light (skipped without off-screen OpenGL).
#include <gtest/gtest.h>

#include <cmath>

#include "render/offscreen.h"
#include "render/shadow_maps.h"
#include "gl_skip.h"
#include "test_scene.h"

namespace sinew {
namespace {

using render::Image;

Eigen::Vector3f project(const render::LightView& v, const Vec3& p) {
  const Eigen::Vector4f c = v.view_projection * Eigen::Vector4f(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                                                static_cast<float>(p.z()), 1.f);
  return {c.x() / c.w(), c.y() / c.w(), v.perspective ? c.w() / v.far : 0.5f * c.z() / c.w() + 0.5f};
}

// A spot at (0, 5, 0) looking down with a 30° cut-off: the axis maps to the map's centre at
// depth distance / far, a point 30° off the axis to the frustum's edge; far fits the box.
TEST(ShadowMaps, SpotViewIsItsConeAndDepthAlongTheAxis) {
  LightSource s;
  s.type = LightSource::Type::spot;
  s.position[0] = 0, s.position[1] = 5, s.position[2] = 0, s.position[3] = 1;
  s.spot_direction[0] = 0, s.spot_direction[1] = -1, s.spot_direction[2] = 0;
  s.cutoff = 30.f;
  const auto v = render::light_view(s, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  ASSERT_TRUE(v);
  EXPECT_TRUE(v->perspective);
  EXPECT_NEAR(v->far, 6 * 1.01, 1e-5);
  const Eigen::Vector3f axis = project(*v, Vec3(0, 0, 0));
  EXPECT_NEAR(axis.x(), 0, 1e-6);
  EXPECT_NEAR(axis.y(), 0, 1e-6);
  EXPECT_NEAR(axis.z(), 5 / (6 * 1.01), 1e-5);
  const Eigen::Vector3f edge = project(*v, Vec3(5 * std::tan(M_PI / 6), 0, 0));
  EXPECT_NEAR(std::max(std::abs(edge.x()), std::abs(edge.y())), 1, 1e-5);
  // Given planes are used as they are.
  s.z_near = 0.5, s.z_far = 20;
  EXPECT_FLOAT_EQ(render::light_view(s, Vec3(-1, -1, -1), Vec3(1, 1, 1))->far, 20.f);
  // A scene wholly behind the spot, a positional light: no shadow map.
  s.z_near = s.z_far = 0;
  s.spot_direction[1] = 1;
  EXPECT_FALSE(render::light_view(s, Vec3(-1, -1, -1), Vec3(1, 1, 1)));
  s.type = LightSource::Type::positional;
  EXPECT_FALSE(render::light_view(s, Vec3(-1, -1, -1), Vec3(1, 1, 1)));
}

// A directional light's box holds the whole scene box, depth growing along its direction.
TEST(ShadowMaps, DirectionalViewHoldsTheSceneBox) {
  LightSource s;
  s.type = LightSource::Type::directional;
  s.position[0] = -0.5, s.position[1] = -0.5, s.position[2] = -0.5, s.position[3] = 0;
  const Vec3 min(-2, -1, -3), max(2, 1, 0);
  const auto v = render::light_view(s, min, max);
  ASSERT_TRUE(v);
  EXPECT_FALSE(v->perspective);
  for (int i = 0; i < 8; ++i) {
    const Vec3 c(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(), i & 4 ? max.z() : min.z());
    const Eigen::Vector3f p = project(*v, c);
    EXPECT_LT(p.head<2>().cwiseAbs().maxCoeff(), 1.f);
    EXPECT_GT(p.z(), 0.f);
    EXPECT_LT(p.z(), 1.f);
  }
  // Farther along the light's way, deeper.
  EXPECT_LT(project(*v, Vec3(1, 0.5, -1)).z(), project(*v, Vec3(0.5, 0, -1.5)).z());
}

TEST(ShadowMaps, MapSizeAsSofa) {
  EXPECT_EQ(render::shadow_map_size(2048, 100, 100), 2048);
  EXPECT_EQ(render::shadow_map_size(0, 1280, 1024), 1024);
  EXPECT_EQ(render::shadow_map_size(0, 800, 600), 512);
  EXPECT_EQ(render::shadow_map_size(0, 300, 256), 256);
  EXPECT_EQ(render::shadow_map_size(0, 200, 200), 128);
}

class ShadowPictureTest : public ::testing::Test {
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
  // A white wall z = 0 over [-2, 2]², a square of side 0.5 at z = 1 in front of it, the camera
  // at z = 5 (48.3 px per unit on the wall), the lights and manager given.
  Image picture(const std::string& lights, bool shader = true) {
    auto s = test::load(
        "<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/>" + lights +
        (shader ? "<OglShadowShader/>" : "") +
        "<Node name=\"wall\"><OglModel color=\"1 1 1\" position=\"-2 -2 0  2 -2 0  2 2 0  -2 2 0\" quads=\"0 1 2 3\"/></Node>"
        "<Node name=\"square\"><OglModel color=\"1 1 1\" position=\"-0.25 -0.25 1  0.25 -0.25 1  0.25 0.25 1  "
        "-0.25 0.25 1\" quads=\"0 1 2 3\"/></Node></Node>");
    Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(*s.root, img, &err)) << err;
    return img;
  }
  // Red level of the wall at x (world, y = 0).
  static int wall(const Image& img, double x) {
    const double px = 100.0 / (5.0 * std::tan(M_PI / 8));
    return img.rgb(static_cast<int>(std::lround(100 + x * px)), 100)[0];
  }
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

// A spot at (1.5, 0, 4) aimed at the origin: the square's shadow falls on the wall around
// x = -0.5 (from -0.83 to -0.17); x = -0.7 is in it, x = 0.7 is not. shadowFactor 1 and no
// ambient: the shadow is black. Without shadows, or without the OglShadowShader, it is lit.
TEST_F(ShadowPictureTest, SpotShadowFallsWhereTheSquareHidesTheLight) {
  const std::string spot = "<SpotLight position=\"1.5 0 4\" direction=\"-1.5 0 -4\" cutoff=\"45\"/>";
  const Image shadowed = picture("<LightManager shadows=\"1\"/>" + spot);
  RecordProperty("in_shadow", wall(shadowed, -0.7));
  RecordProperty("lit", wall(shadowed, 0.7));
  EXPECT_LE(wall(shadowed, -0.7), 5);
  EXPECT_GT(wall(shadowed, 0.7), 60);
  EXPECT_GT(wall(shadowed, -1.2), 40);  // past the shadow's edge: lit again
  const Image without = picture("<LightManager shadows=\"0\"/>" + spot);
  EXPECT_GT(wall(without, -0.7), 40);
  EXPECT_EQ(wall(without, 0.7), wall(shadowed, 0.7));
  // shadowFactor 0.5: half of the light stays in the shadow.
  const Image half = picture("<LightManager shadows=\"1\"/><SpotLight position=\"1.5 0 4\" direction=\"-1.5 0 -4\" "
                             "cutoff=\"45\" shadowFactor=\"0.5\"/>");
  EXPECT_NEAR(wall(half, -0.7), 0.5 * wall(without, -0.7), 3);
  // Soft shadows (variance shadow map): dark inside, lit away from it.
  const Image soft = picture("<LightManager shadows=\"1\" softShadows=\"1\"/>" + spot);
  EXPECT_LT(wall(soft, -0.5), 0.3 * wall(without, -0.5));
  EXPECT_GT(wall(soft, 0.7), 60);
}

// A directional light travelling along (-1, 0, -2) (SOFA's shadow shader reads `direction`
// as the way the light goes): the shadow of the square is shifted by -0.5 in x on the wall.
TEST_F(ShadowPictureTest, DirectionalShadowShiftedAlongTheLight) {
  const Image img = picture("<LightManager shadows=\"1\"/><DirectionalLight direction=\"-1 0 -2\"/>");
  EXPECT_LE(wall(img, -0.6), 5);
  EXPECT_GT(wall(img, 0.6), 60);
  EXPECT_GT(wall(img, -1.0), 60);
  // Lit as SOFA's shader lights it: diffuse · n·L, no specular: n·L = 2/√5 on the wall.
  EXPECT_NEAR(wall(img, 0.6), 255 * 2 / std::sqrt(5.0), 3);
}

// No OglShadowShader: fixed-function lighting, no shadow; no LightManager under the shader:
// SOFA's shader has no light and shows the material's diffuse colour.
TEST_F(ShadowPictureTest, WithoutShaderOrManager) {
  const std::string spot = "<SpotLight position=\"1.5 0 4\" direction=\"-1.5 0 -4\" cutoff=\"45\"/>";
  EXPECT_GT(wall(picture("<LightManager shadows=\"1\"/>" + spot, false), -0.7), 40);
  EXPECT_EQ(wall(picture(""), -0.7), 255);
}

// Light::drawSource: a PositionalLight at (1, 1, 1) is a sphere in its colour of 1 % of the
// scene box's diagonal around its projection (the box [-2, 2]² × [0, 1] of two small squares:
// radius 0.057, 3.5 px at depth 4); a SpotLight's cone and sphere are drawn as lines in its
// colour; nothing without drawSource.
TEST_F(ShadowPictureTest, LightSourcesDrawn) {
  const auto draw = [this](const std::string& light) {
    auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 5\" lookAt=\"0 0 0\"/><LightManager/>" +
                        light +
                        "<Node name=\"a\"><OglModel color=\"0.2 0.2 0.2\" position=\"-2 -2 0  -1.9 -2 0  -1.9 -1.9 0  "
                        "-2 -1.9 0\" quads=\"0 1 2 3\"/></Node><Node name=\"b\"><OglModel color=\"0.2 0.2 0.2\" "
                        "position=\"1.9 1.9 1  2 1.9 1  2 2 1  1.9 2 1\" quads=\"0 1 2 3\"/></Node></Node>");
    Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(*s.root, img, &err)) << err;
    return img;
  };
  const auto green = [](const std::array<int, 3>& c) { return c[1] > 200 && c[0] < 30 && c[2] < 30; };
  const double px = 100.0 / (4.0 * std::tan(M_PI / 8));
  const int x = static_cast<int>(std::lround(100 + px)), y = static_cast<int>(std::lround(100 - px));
  const Image shown = draw("<PositionalLight color=\"0 1 0\" position=\"1 1 1\" drawSource=\"1\"/>");
  EXPECT_TRUE(green(shown.rgb(x, y)));
  EXPECT_FALSE(green(shown.rgb(x + 6, y)));
  const Image hidden = draw("<PositionalLight color=\"0 1 0\" position=\"1 1 1\"/>");
  EXPECT_FALSE(green(hidden.rgb(x, y)));
  // A spot at the top looking down: lines of its colour along the middle of the picture.
  const Image spot = draw("<SpotLight color=\"0 1 0\" position=\"0 1.8 0.5\" direction=\"0 -1 0\" cutoff=\"10\" "
                          "drawSource=\"1\"/>");
  long lines = 0;
  for (int yy = 0; yy < 200; ++yy)
    for (int xx = 80; xx < 120; ++xx) lines += green(spot.rgb(xx, yy));
  RecordProperty("spot_pixels", static_cast<int>(lines));
  EXPECT_GT(lines, 50);
}

}  // namespace
}  // namespace sinew
