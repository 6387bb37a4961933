// Scene shaders (OglShader): SOFA's GLSL 1.x translated to 3.30 (render/legacy_glsl.h), and
// run for the models under the shader with the fixed-function state, the uniforms, textures
// and attributes of the scene (render/scene_shader.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#define SINEW_ALLOC_COUNTER_DECLARE_ONLY  // the counter is defined in render_test.cpp
#include "alloc_counter.h"
#include "render/draw_list.h"
#include "render/gl_program.h"
#include "render/legacy_glsl.h"
#include "render/offscreen.h"
#include "gl_skip.h"
#include "test_paths.h"
#include "test_scene.h"

namespace sinew {
namespace {

using render::GlslStage;
using render::translate_glsl;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(TranslateGlsl, RenamesTheFixedFunctionNamesPerStage) {
  const std::string vs = translate_glsl(
      "#version 120\nattribute vec4 w;\nvarying vec3 n;\nvoid main() { n = gl_NormalMatrix * gl_Normal;\n"
      "  gl_FrontColor = gl_Color; gl_Position = ftransform(); }\n",
      GlslStage::vertex, {});
  EXPECT_EQ(vs.rfind("#version 330 core\n", 0), 0u);
  EXPECT_FALSE(has(vs, "#version 120"));
  EXPECT_TRUE(has(vs, "in vec4 w;"));
  EXPECT_TRUE(has(vs, "out vec3 n;"));
  EXPECT_TRUE(has(vs, "n = sinew_NormalMatrix * sinew_Normal;"));
  EXPECT_TRUE(has(vs, "sinew_FrontColor = sinew_Color; gl_Position = sinew_ftransform();"));
  const std::string fs = translate_glsl(
      "varying vec3 n;\nuniform sampler2D t;\nvoid main() { gl_FragColor = gl_Color * texture2D(t, vec2(1e-3)); }\n",
      GlslStage::fragment, {});
  EXPECT_TRUE(has(fs, "in vec3 n;"));
  EXPECT_TRUE(has(fs, "sinew_FragColor = sinew_FrontColor * texture(t, vec2(1e-3));"));
}

TEST(TranslateGlsl, LeavesLongerNamesAloneAndPutsDefinesAndExtensionsFirst) {
  const std::string out = translate_glsl(
      "uniform float my_gl_Vertex;\nfloat gl_VertexCount2;\n#extension GL_EXT_gpu_shader4 : enable\nvoid main() {}\n",
      GlslStage::vertex, {{"PHONG", ""}, {"LEVEL", "3"}});
  EXPECT_TRUE(has(out, "uniform float my_gl_Vertex;"));
  EXPECT_TRUE(has(out, "float gl_VertexCount2;"));
  const std::size_t ext = out.find("#extension GL_EXT_gpu_shader4 : enable");
  const std::size_t phong = out.find("#define PHONG\n"), level = out.find("#define LEVEL 3\n");
  ASSERT_NE(ext, std::string::npos);
  ASSERT_NE(phong, std::string::npos);
  ASSERT_NE(level, std::string::npos);
  EXPECT_LT(ext, phong);  // extensions before anything else but #version
  EXPECT_LT(phong, out.find("uniform sinew_LightSourceParameters"));
  EXPECT_EQ(out.find("#extension", ext + 1), std::string::npos);  // moved, not copied
}

// Each stage gets SOFA's stage define; 4.x sources keep their version (core); tessellation
// asks for 4.00. In the control stage the levels go through arrays of its own, copied to the
// built-ins at the end of the main the preprocessor keeps (not the vertex stage's of one file).
TEST(TranslateGlsl, StagesVersionsAndTheTessellationLevelCopies) {
  EXPECT_EQ(render::glsl_version("// none\nvoid main() {}\n"), 110);
  EXPECT_EQ(render::glsl_version("  #version 420 compatibility\n"), 420);
  EXPECT_EQ(render::glsl_program_version({"#version 120\n"}, false), 330);
  EXPECT_EQ(render::glsl_program_version({"#version 120\n"}, true), 400);
  EXPECT_EQ(render::glsl_program_version({"#version 120\n", "#version 420 compatibility\n"}, true), 420);
  const std::string file =
      "#version 420 compatibility\n#ifdef VertexShader\nvoid main() { gl_Position = gl_Vertex; }\n#endif\n"
      "#ifdef TessellationControlShader\nlayout(vertices = 3) out;\n#define I gl_InvocationID\n"
      "void main() { /* } */ gl_TessLevelOuter[I] = 2.0; if (I == 0) { gl_TessLevelInner[0] = 2.0; } }\n#undef I\n#endif\n";
  const std::string tcs = translate_glsl(file, GlslStage::tess_control, {}, 420);
  EXPECT_EQ(tcs.rfind("#version 420 core\n", 0), 0u);
  EXPECT_TRUE(has(tcs, "#define TessellationControlShader\n"));
  EXPECT_TRUE(has(tcs, "sinew_TessLevelOuter[I] = 2.0;"));
  const std::size_t copy = tcs.find("gl_TessLevelOuter[0] = sinew_TessLevelOuter[0]");
  ASSERT_NE(copy, std::string::npos);
  EXPECT_GT(copy, tcs.find("sinew_TessLevelInner[0] = 2.0; }"));  // after the body, inside the tess main
  EXPECT_EQ(tcs.find("}", copy), tcs.rfind("}"));                  // before its closing brace
  EXPECT_LT(tcs.find("= -3.0e38"), tcs.find("sinew_TessLevelOuter[I]"));
  const std::string vs = translate_glsl(file, GlslStage::vertex, {}, 420);
  EXPECT_TRUE(has(vs, "#define VertexShader\n"));
  EXPECT_FALSE(has(vs, "sinew_TessLevel"));
}

std::string temp_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("sinew_scene_shader_" + name);
  std::ofstream(path) << text;
  return path.string();
}

class SceneShaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string err;
    render::RenderOptions o;
    o.width = 200, o.height = 200, o.samples = 0;
    renderer_ = render::OffscreenRenderer::create(o, &err);
    if (!renderer_) {
      ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
      GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
    }
  }
  // A 2 × 2 quad facing the camera at distance 3 (±80.5 pixels about the centre), under
  // `shader` (components written in its node).
  render::Image draw(const std::string& shader, const std::string& model_extra = "") {
    auto s = test::load(
        "<Node name=\"root\"><InteractiveCamera position=\"0 0 3\" lookAt=\"0 0 0\"/><Node name=\"n\">" + shader +
        "<OglModel name=\"m\" position=\"-1 -1 0  1 -1 0  1 1 0  -1 1 0\" quads=\"0 1 2 3\" "
        "material=\"Default Diffuse 1 0.5 0.4 0.2 1 Ambient 1 0 0 0 1 Specular 0 0 0 0 1 Emissive 0 0 0 0 1 "
        "Shininess 0 45\" " + model_extra + "/></Node></Node>");
    render::Image img;
    std::string err;
    EXPECT_TRUE(renderer_->render(*s.root, img, &err)) << err;
    return img;
  }
  std::string shader(const std::string& vertex, const std::string& fragment, const std::string& extra = "") {
    return "<OglShader fileVertexShaders=\"['" + temp_file("v.vert", vertex) + "']\" fileFragmentShaders=\"['" +
           temp_file("f.frag", fragment) + "']\" " + extra + "/>";
  }
  std::unique_ptr<render::OffscreenRenderer> renderer_;
};

const char* kPlainVertex = "void main() { gl_Position = ftransform(); }\n";

TEST_F(SceneShaderTest, AUniformOfTheSceneColoursTheModel) {
  const render::Image img =
      draw(shader(kPlainVertex, "uniform vec4 tint;\nvoid main() { gl_FragColor = tint; }\n") +
           "<OglFloat4Variable id=\"tint\" value=\"0 1 0.5 1\"/>");
  const auto c = img.rgb(100, 100);
  EXPECT_EQ(c[0], 0);
  EXPECT_EQ(c[1], 255);
  EXPECT_NEAR(c[2], 128, 1);
  EXPECT_EQ(img.rgb(5, 5)[1], 0);  // the background outside the quad
}

// gl_FrontLightProduct[0].diffuse: the material's diffuse times SOFA's viewer light 0 (0.9).
TEST_F(SceneShaderTest, TheFixedFunctionLightProductIsTheMaterialTimesSofasViewerLight) {
  const render::Image img = draw(shader(kPlainVertex, "void main() { gl_FragColor = gl_FrontLightProduct[0].diffuse; }\n"));
  const auto c = img.rgb(100, 100);
  EXPECT_NEAR(c[0], 0.9 * 0.5 * 255, 1.0);
  EXPECT_NEAR(c[1], 0.9 * 0.4 * 255, 1.0);
  EXPECT_NEAR(c[2], 0.9 * 0.2 * 255, 1.0);
}

// OglMatrix4VectorVariable, rows given, transpose="1" (SOFA's skinning scenes): the second
// matrix moves the quad −0.1 along x, 8 pixels (the quad stays inside the picture).
TEST_F(SceneShaderTest, AMatrixArrayUniformMovesTheModel) {
  const std::string vs =
      "uniform mat4 bones[2];\nvoid main() { gl_Position = gl_ModelViewProjectionMatrix * (bones[1] * gl_Vertex); }\n";
  const render::Image img = draw(shader(vs, "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n") +
                                 "<OglMatrix4VectorVariable id=\"bones\" transpose=\"1\" value=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1  "
                                 "1 0 0 -0.1 0 1 0 0 0 0 1 0 0 0 0 1\"/>");
  double sum = 0;
  long count = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      if (img.rgb(x, y)[1] > 200) sum += x + 0.5, ++count;
  ASSERT_GT(count, 100);
  const double f = 100.0 / std::tan(M_PI / 8) / 3;  // pixels per unit at distance 3
  EXPECT_NEAR(sum / count, 100 - 0.1 * f, 0.5);
}

// OglFloat3Attribute: one colour per vertex, left vertices red, right ones blue.
TEST_F(SceneShaderTest, AVertexAttributeReachesTheShaderPerVertex) {
  const std::string vs = "attribute vec3 col;\nvarying vec3 c;\nvoid main() { c = col; gl_Position = ftransform(); }\n";
  const std::string fs = "varying vec3 c;\nvoid main() { gl_FragColor = vec4(c, 1.0); }\n";
  const render::Image img = draw(shader(vs, fs) + "<OglFloat3Attribute id=\"col\" value=\"1 0 0  0 0 1  0 0 1  1 0 0\"/>");
  const auto left = img.rgb(30, 100), right = img.rgb(170, 100);
  EXPECT_GT(left[0], 200);
  EXPECT_LT(left[2], 60);
  EXPECT_GT(right[2], 200);
  EXPECT_LT(right[0], 60);
}

// A shader that does not compile, or a passive one: the model is drawn as without a shader.
TEST_F(SceneShaderTest, ABrokenOrPassiveShaderLeavesTheModelToSinewsShading) {
  const render::Image plain = draw("");
  const render::Image broken = draw(shader(kPlainVertex, "void main() { gl_FragColor = vec4(1.0 }\n"));
  const render::Image passive =
      draw(shader(kPlainVertex, "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }\n", "passive=\"1\""));
  EXPECT_EQ(broken.rgba, plain.rgba);
  EXPECT_EQ(passive.rgba, plain.rgba);
  EXPECT_NE(plain.rgb(100, 100)[0], 0);  // lit by Sinew's shading
}

// SOFA's own shaders of its example scenes translate, compile and link here.
TEST_F(SceneShaderTest, SofasExampleShadersCompileAndLink) {
  const std::filesystem::path dir = std::filesystem::path(SINEW_DATA_DIR) / "share/shaders";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "SOFA's data are absent: " << dir;
  struct Pair {
    const char* vertex;
    const char* fragment;
    std::vector<std::pair<std::string, std::string>> defines;
  };
  const Pair pairs[] = {{"toonShading.vert", "toonShading.frag", {}},
                        {"linearBlendSkinning.vert", "linearBlendSkinning.frag", {}},
                        {"skybox.vert", "skybox.frag", {}},
                        {"generalRenderingShader.vert", "generalRenderingShader.frag",
                         {{"PERLIN_NOISE_COLOR", ""}, {"PERLIN_NOISE_BUMP", ""}, {"PHONG", ""}}},
                        {"phong.vert", "phong.frag", {}}};
  auto read = [&](const char* name) {
    std::ifstream in(dir / name);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const Pair& p : pairs) {
    const std::string vs = translate_glsl(read(p.vertex), GlslStage::vertex, p.defines);
    const std::string fs = translate_glsl(read(p.fragment), GlslStage::fragment, p.defines);
    std::string err;
    const unsigned program = render::link_program(vs.c_str(), fs.c_str(), &err);
    EXPECT_NE(program, 0u) << p.vertex << ", " << p.fragment << ": " << err;
  }
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {
// A tessellation program in one file (SOFA defines the stage's name in each), the model's
// triangles sent as patches of 3 (primitiveType PATCHES): the evaluation stage places each
// generated vertex by its barycentric coordinates, the geometry stage passes triangles on.
TEST_F(SceneShaderTest, TessellationAndGeometryStagesRunOnPatches) {
  const std::string file = temp_file("tess.glsl", R"(#version 400 compatibility
#ifdef VertexShader
out vec3 p;
void main() { p = gl_Vertex.xyz; }
#endif
#ifdef TessellationControlShader
layout(vertices = 3) out;
uniform float level;
in vec3 p[];
out vec3 q[];
void main() {
  q[gl_InvocationID] = p[gl_InvocationID];
  gl_TessLevelOuter[gl_InvocationID] = level;
  if (gl_InvocationID == 0) gl_TessLevelInner[0] = level;
}
#endif
#ifdef TessellationEvaluationShader
layout(triangles, equal_spacing, cw) in;
in vec3 q[];
void main() {
  vec3 x = gl_TessCoord.x * q[0] + gl_TessCoord.y * q[1] + gl_TessCoord.z * q[2];
  gl_Position = gl_ModelViewProjectionMatrix * vec4(x, 1.0);
}
#endif
#ifdef GeometryShader
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
  for (int i = 0; i < 3; ++i) { gl_Position = gl_in[i].gl_Position; EmitVertex(); }
  EndPrimitive();
}
#endif
#ifdef FragmentShader
void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }
#endif
)");
  const std::string all = "['" + file + "']";
  const std::string sh = "<OglShader fileVertexShaders=\"" + all + "\" fileTessellationControlShaders=\"" + all +
                         "\" fileTessellationEvaluationShaders=\"" + all + "\" fileGeometryShaders=\"" + all +
                         "\" fileFragmentShaders=\"" + all + "\"/><OglFloatVariable name=\"level\" value=\"4\"/>";
  auto s = test::load("<Node name=\"root\"><InteractiveCamera position=\"0 0 3\" lookAt=\"0 0 0\"/><Node name=\"n\">" + sh +
                      "<OglModel position=\"-1 -1 0  1 -1 0  1 1 0  -1 1 0\" triangles=\"0 1 2  0 2 3\" "
                      "primitiveType=\"PATCHES\"/></Node></Node>");
  render::Image img;
  std::string err;
  ASSERT_TRUE(renderer_->render(*s.root, img, &err)) << err;
  long green = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) green += img.rgb(x, y)[1] == 255 && img.rgb(x, y)[0] == 0;
  EXPECT_NEAR(green, 161 * 161, 2 * 161 * 2);  // the 2 × 2 square, ±80.5 px
}

// Gathering a scene with an OglShader (uniforms, a macro, a texture, a per-vertex attribute) a
// second time allocates nothing: the list's shader entries and the batch's attributes keep
// their storage.
TEST(SceneShaderGather, ASecondFrameAllocatesNothing) {
#if SINEW_COUNT_ALLOCATIONS
  auto s = test::load(
      "<Node name=\"root\"><Node name=\"n\"><OglShader fileVertexShaders=\"['" + temp_file("a.vert", kPlainVertex) +
      "']\" fileFragmentShaders=\"['" + temp_file("a.frag", "void main() { gl_FragColor = vec4(1.0); }\n") + "']\"/>"
      "<OglFloat4Variable id=\"tint\" value=\"0 1 0.5 1\"/><OglMatrix4VectorVariable id=\"bones\" "
      "value=\"1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\"/><OglShaderDefineMacro id=\"LEVEL\" value=\"3\"/>"
      "<OglTexture id=\"pattern\" proceduralTextureWidth=\"2\" proceduralTextureHeight=\"2\" "
      "proceduralTextureData=\"0 255 255 0\"/><OglFloat3Attribute id=\"col\" value=\"1 0 0  1 0 0  0 0 1  0 0 1\"/>"
      "<OglModel name=\"m\" position=\"-1 -1 0  1 -1 0  1 1 0  -1 1 0\" quads=\"0 1 2 3\"/></Node></Node>");
  render::DrawList list;
  render::gather(*s.root, list);
  ASSERT_EQ(list.shaders_used, 1u);
  ASSERT_EQ(list.shaders[0].uniforms.size(), 2u);
  ASSERT_EQ(list.shaders[0].textures.size(), 1u);
  ASSERT_EQ(list.shaders[0].defines.size(), 1u);
  ASSERT_EQ(list.batches[0].attributes.size(), 1u);
  render::gather(*s.root, list);
  const long before = test::g_allocations.load();
  render::gather(*s.root, list);
  EXPECT_EQ(test::g_allocations.load() - before, 0);
  EXPECT_EQ(list.shaders[0].uniforms[1].value.values.size(), 16u);
  EXPECT_EQ(list.batches[0].attributes[0].values.size(), 12u);
#else
  GTEST_SKIP() << "allocations are not counted under AddressSanitizer";
#endif
}

}  // namespace
}  // namespace sinew
