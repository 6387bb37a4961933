// Textures: the picture readers (BMP, JPEG, PNG by their first bytes), OglModel's texture
// coordinates (scaleTex, translationTex as SOFA applies them), and a textured quad drawn.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "render/bmp_io.h"
#include "render/image_file.h"
#include "render/offscreen.h"
#include "render/png_io.h"
#include "gl_skip.h"
#include "test_scene.h"
#include "visual/ogl_model.h"
#include "test_paths.h"

namespace sinew {
namespace {

std::string temp(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("sinew_texture_test_" + name)).string();
}

void put32(std::vector<unsigned char>& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back((v >> (8 * i)) & 0xFF);
}

// A BMP of `bits` (24 or 8 with a 2-colour palette), 3 × 2 pixels, rows bottom-up unless `top_down`.
std::string write_bmp(int bits, bool top_down) {
  const int w = 3, h = 2;
  const int row = (w * bits / 8 + 3) & ~3;
  const int palette = bits == 8 ? 2 * 4 : 0;
  std::vector<unsigned char> b = {'B', 'M'};
  put32(b, 54 + palette + row * h);
  put32(b, 0);
  put32(b, 54 + palette);
  put32(b, 40);
  put32(b, w);
  put32(b, top_down ? static_cast<std::uint32_t>(-h) : h);
  b.push_back(1), b.push_back(0), b.push_back(bits), b.push_back(0);
  for (int i = 0; i < 6; ++i) put32(b, 0);
  if (bits == 8) {
    for (unsigned char c : {0, 0, 255, 0}) b.push_back(c);    // index 0: red (stored B G R x)
    for (unsigned char c : {255, 0, 0, 0}) b.push_back(c);    // index 1: blue
  }
  // Top row of the picture: red red blue; bottom row: blue blue red.
  auto pixel = [&](bool red) {
    if (bits == 8) b.push_back(red ? 0 : 1);
    else if (red) b.push_back(0), b.push_back(0), b.push_back(255);
    else b.push_back(255), b.push_back(0), b.push_back(0);
  };
  auto top = [&] { pixel(true), pixel(true), pixel(false); };
  auto bottom = [&] { pixel(false), pixel(false), pixel(true); };
  auto pad = [&] { while ((b.size() - 54 - palette) % row) b.push_back(0); };
  if (top_down) top(), pad(), bottom(), pad();
  else bottom(), pad(), top(), pad();
  const std::string path = temp("p" + std::to_string(bits) + (top_down ? "t" : "b") + ".bmp");
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), b.size());
  return path;
}

TEST(ReadBmp, TwentyFourAndEightBitRowsEitherWay) {
  for (int bits : {24, 8})
    for (bool top_down : {false, true}) {
      std::string err;
      const auto img = render::read_image(write_bmp(bits, top_down), &err);
      ASSERT_TRUE(img) << err;
      ASSERT_EQ(img->width, 3);
      ASSERT_EQ(img->height, 2);
      EXPECT_EQ(img->rgb(0, 0), (std::array<int, 3>{255, 0, 0})) << bits << top_down;
      EXPECT_EQ(img->rgb(2, 0), (std::array<int, 3>{0, 0, 255}));
      EXPECT_EQ(img->rgb(0, 1), (std::array<int, 3>{0, 0, 255}));
      EXPECT_EQ(img->rgb(2, 1), (std::array<int, 3>{255, 0, 0}));
      EXPECT_EQ(img->rgba[3], 255);
    }
}

TEST(ReadImage, BadFilesAreErrorsNotCrashes) {
  std::string err;
  EXPECT_FALSE(render::read_image("/nonexistent/x.png", &err));
  EXPECT_NE(err.find("cannot open"), std::string::npos);
  const std::string text = temp("text.bmp");
  std::ofstream(text) << "hello, not a picture";
  EXPECT_FALSE(render::read_image(text, &err));
  EXPECT_NE(err.find("not a PNG, JPEG or BMP"), std::string::npos) << err;
  const std::string cut = temp("cut.bmp");
  std::ofstream(cut, std::ios::binary) << "BM" << std::string(60, '\1');
  EXPECT_FALSE(render::read_image(cut, &err));
  const std::string jpeg = temp("cut.jpg");
  std::ofstream(jpeg, std::ios::binary) << "\xFF\xD8\xFF\xE0 truncated";
  EXPECT_FALSE(render::read_image(jpeg, &err));
  EXPECT_NE(err.find("not a readable JPEG"), std::string::npos) << err;
}

TEST(ReadImage, SofaJpegTexture) {
  const std::string path = std::string(SINEW_DATA_DIR) + "/share/textures/Sofa_Default.jpg";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  std::string err;
  const auto img = render::read_image(path, &err);
  ASSERT_TRUE(img) << err;
  EXPECT_EQ(img->width, 512);
  EXPECT_EQ(img->height, 512);
}

TEST(OglModelTexture, ScaleThenTranslationAppliedOnceAsSofa) {
  auto s = test::load(R"(<Node name="root">
      <OglModel name="m" position="0 0 0 1 0 0 1 1 0" triangles="0 1 2" texcoords="0 0 1 0 1 1"
                scaleTex="2 3" translationTex="0.5 -1"/></Node>)");
  auto* m = test::get<OglModel>(*s.root, "m");
  ASSERT_NE(m, nullptr);
  const auto& uv = m->texcoords.get();
  ASSERT_EQ(uv.size(), 3u);
  EXPECT_EQ(uv[1], Vec2(2.5, -1));
  EXPECT_EQ(uv[2], Vec2(2.5, 2));
  EXPECT_EQ(m->scale_tex.get(), Vec2(1, 1));  // reset, as SOFA does, so a reinit does not apply it twice
  EXPECT_EQ(m->translation_tex.get(), Vec2(0, 0));
}

TEST(OglModelTexture, MissingTextureIsAWarningAndTheModelStaysDrawn) {
  auto s = test::build(R"(<Node name="root">
      <OglModel name="m" position="0 0 0 1 0 0 1 1 0" triangles="0 1 2" texturename="no/such/texture.png"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_FALSE(s.root->diagnostics().has_errors());
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  bool said = false;
  for (const auto& w : warnings) said |= w.find("texture") != std::string::npos && w.find("not found") != std::string::npos;
  EXPECT_TRUE(said);
}

// A quad facing the camera with a 2 × 2 texture (red, green / blue, white from the top):
// each quarter of the quad shows its texel, modulating SOFA's default material lit head-on
// (ambient 0.2 + diffuse 0.75 = 0.95).
TEST(TexturedQuad, EachQuarterShowsItsTexel) {
  std::string err;
  render::RenderOptions o;
  o.width = 200, o.height = 200, o.samples = 0;
  auto r = render::OffscreenRenderer::create(o, &err);
  if (!r) {
    ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
    GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
  }
  render::Image tex;
  tex.width = tex.height = 2;
  tex.rgba = {255, 0, 0, 255, 0, 255, 0, 255,  // top row: red, green
              0, 0, 255, 255, 255, 255, 255, 255};  // bottom row: blue, white
  const std::string path = temp("checker.png");
  ASSERT_TRUE(render::write_png(path, tex, &err)) << err;
  auto s = test::load(R"(<Node name="root"><InteractiveCamera position="0 0 3" lookAt="0 0 0"/>
      <OglModel name="m" position="-1 -1 0  1 -1 0  1 1 0  -1 1 0" quads="0 1 2 3"
                texcoords="0 0  1 0  1 1  0 1" texturename=")" + path + R"("/></Node>)");
  render::Image img;
  ASSERT_TRUE(r->render(*s.root, img, &err)) << err;
  // The quad spans ±1 at distance 3: 100/(3 tan 22.5°) = 80.5 pixels each side of the centre.
  // A quarter's centre; bilinear filtering there mixes in a few % of the neighbouring texels.
  const int q = 40;
  auto near = [](std::array<int, 3> c, std::array<int, 3> want) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(c[k] - static_cast<int>(std::lround(want[k] * 0.95))) > 8) return false;
    return true;
  };
  auto show = [&](int x, int y) {
    const auto c = img.rgb(x, y);
    return std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
  };
  EXPECT_TRUE(near(img.rgb(100 - q, 100 - q), {255, 0, 0})) << show(100 - q, 100 - q) << " | " << show(100 + q, 100 - q)
                                                             << " | " << show(100 - q, 100 + q) << " | "
                                                             << show(100 + q, 100 + q);  // top left: red
  EXPECT_TRUE(near(img.rgb(100 + q, 100 - q), {0, 255, 0}));    // top right: green
  EXPECT_TRUE(near(img.rgb(100 - q, 100 + q), {0, 0, 255}));    // bottom left: blue
  EXPECT_TRUE(near(img.rgb(100 + q, 100 + q), {255, 255, 255})); // bottom right: white
}

}  // namespace
}  // namespace sinew
