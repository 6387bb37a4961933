#include "render/scene_shader.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <Eigen/LU>

#include "render/gl_program.h"
#include "render/image_file.h"
#include "render/legacy_glsl.h"

namespace sinew::render {

namespace {

bool read_text(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

int location(unsigned program, const std::string& name) { return glGetUniformLocation(program, name.c_str()); }

void set4(int loc, const float* v) {
  if (loc >= 0) glUniform4fv(loc, 1, v);
}

// FNV-1a, fed piece by piece: the identity of a program or texture without building a key.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void text(const std::string& s) {
    bytes(s.data(), s.size());
    const char end = '\0';  // "ab" + "c" differs from "a" + "bc"
    bytes(&end, 1);
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
};

// The uniforms and samplers the scene sets are part of a program's identity: one it does not
// set keeps the value the program was linked with (its GLSL initialiser or 0), never one set
// for another scene drawn by this renderer before.
std::uint64_t program_key(const SceneShader& s) {
  Hash k;
  for (const std::string* f : {&s.vertex_file, &s.tess_control_file, &s.tess_eval_file, &s.geometry_file,
                               &s.fragment_file})
    k.text(*f);
  for (const auto& [name, value] : s.defines) k.text(name), k.text(value);
  k.value('u');
  for (const SceneShader::Input& u : s.uniforms) k.text(u.name), k.value(u.value.array);
  k.value('s');
  for (const SceneShader::Input& t : s.textures) k.text(t.name);
  return k.h;
}

std::uint64_t texture_key(const ShaderInput& t) {
  Hash k;
  k.text(t.text);
  if (t.text.empty()) {  // procedural: its size and texels
    k.value(t.texture_width), k.value(t.texture_height);
    k.bytes(t.values.data(), t.values.size() * sizeof(float));
  }
  k.value(t.repeat), k.value(t.linear);
  return k.h;
}

// The fixed-function lights as OpenGL holds them, in eye space.
struct GlLight {
  float ambient[4] = {0, 0, 0, 1}, diffuse[4] = {0, 0, 0, 1}, specular[4] = {0, 0, 0, 1};
  float position[4] = {0, 0, 1, 0}, spot[3] = {0, 0, -1};
  float exponent = 0, cutoff = 180, constant = 1, linear = 0, quadratic = 0;
};

}  // namespace

SceneShaders::~SceneShaders() {
  for (const Program& p : programs_)
    if (p.id) glDeleteProgram(p.id);
  for (const auto& t : textures_)
    if (t.second) glDeleteTextures(1, &t.second);
}

SceneShaders::Program* SceneShaders::program_for(const SceneShader& s) {
  const std::uint64_t key = program_key(s);
  for (Program& p : programs_)
    if (p.key == key) return p.id ? &p : nullptr;
  Program& p = programs_.emplace_back();
  p.key = key;
  const std::string who = s.source ? s.source->describe() : std::string("OglShader");
  struct Stage {
    const std::string* file;
    GlslStage stage;
    unsigned type;
    std::string source;
  };
  Stage stages[] = {{&s.vertex_file, GlslStage::vertex, GL_VERTEX_SHADER, {}},
                    {&s.tess_control_file, GlslStage::tess_control, GL_TESS_CONTROL_SHADER, {}},
                    {&s.tess_eval_file, GlslStage::tess_eval, GL_TESS_EVALUATION_SHADER, {}},
                    {&s.geometry_file, GlslStage::geometry, GL_GEOMETRY_SHADER, {}},
                    {&s.fragment_file, GlslStage::fragment, GL_FRAGMENT_SHADER, {}}};
  std::vector<std::string> sources;
  bool tessellation = false;
  for (Stage& st : stages) {
    if (st.file->empty()) continue;
    if (!read_text(*st.file, st.source)) {
      std::fprintf(stderr, "sinew: %s: cannot read %s: its models are drawn with Sinew's shading\n", who.c_str(),
                   st.file->c_str());
      return nullptr;
    }
    sources.push_back(st.source);
    tessellation |= st.stage == GlslStage::tess_control || st.stage == GlslStage::tess_eval;
  }
  const int version = glsl_program_version(sources, tessellation);
  std::vector<std::pair<unsigned, std::string>> translated;
  for (const Stage& st : stages)
    if (!st.file->empty()) translated.emplace_back(st.type, translate_glsl(st.source, st.stage, s.defines, version));
  std::string err;
  p.id = link_program_stages(translated, &err);
  if (!p.id) {
    std::fprintf(stderr, "sinew: %s (%s, %s) does not run here: %s; its models are drawn with Sinew's shading\n",
                 who.c_str(), s.vertex_file.c_str(), s.fragment_file.c_str(), err.c_str());
    return nullptr;
  }
  locate(p, s);
  return &p;
}

void SceneShaders::locate(Program& p, const SceneShader& s) {
  const unsigned id = p.id;
  const char* const matrices[7] = {"sinew_ModelViewMatrix",          "sinew_ProjectionMatrix",
                                   "sinew_ModelViewProjectionMatrix", "sinew_ModelViewMatrixInverse",
                                   "sinew_ModelViewMatrixTranspose",  "sinew_ModelViewMatrixInverseTranspose",
                                   "sinew_ProjectionMatrixInverse"};
  for (int k = 0; k < 7; ++k) p.matrices[k] = glGetUniformLocation(id, matrices[k]);
  p.normal_matrix = glGetUniformLocation(id, "sinew_NormalMatrix");
  p.texture_matrix = glGetUniformLocation(id, "sinew_TextureMatrix[0]");
  for (int i = 0; i < kGlslMaxLights; ++i) {
    Light& l = p.lights[i];
    const std::string at = "sinew_LightSource[" + std::to_string(i) + "].";
    l.ambient = location(id, at + "ambient");
    l.diffuse = location(id, at + "diffuse");
    l.specular = location(id, at + "specular");
    l.position = location(id, at + "position");
    l.half = location(id, at + "halfVector");
    l.spot_direction = location(id, at + "spotDirection");
    const char* const scalars[6] = {"spotExponent",        "spotCutoff",        "spotCosCutoff",
                                    "constantAttenuation", "linearAttenuation", "quadraticAttenuation"};
    for (int k = 0; k < 6; ++k) l.scalars[k] = location(id, at + scalars[k]);
    const std::string pp = "sinew_FrontLightProduct[" + std::to_string(i) + "].";
    l.products[0] = location(id, pp + "ambient");
    l.products[1] = location(id, pp + "diffuse");
    l.products[2] = location(id, pp + "specular");
  }
  const char* const material[5] = {"emission", "ambient", "diffuse", "specular", "shininess"};
  for (int k = 0; k < 5; ++k) p.material[k] = location(id, std::string("sinew_FrontMaterial.") + material[k]);
  p.model_ambient = glGetUniformLocation(id, "sinew_LightModel.ambient");
  p.scene_color = glGetUniformLocation(id, "sinew_FrontLightModelProduct.sceneColor");
  // The scene's uniforms and samplers: a name that is not in the program gets -1 (skipped, as by OpenGL).
  for (const SceneShader::Input& u : s.uniforms)
    p.uniforms.push_back(location(id, u.value.array ? u.name + "[0]" : u.name));
  for (const SceneShader::Input& t : s.textures) p.samplers.push_back(location(id, t.name));
  p.textures.assign(s.textures.size(), {0, 0});
}

unsigned SceneShaders::texture_for(const ShaderInput& t, std::uint64_t key) {
  for (const auto& [k, id] : textures_)
    if (k == key) return id;
  unsigned id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  bool ok = false;
  if (!t.text.empty()) {
    std::string err;
    if (auto img = read_image(t.text, &err)) {
      // OpenGL's first row is the bottom one: the picture's last row goes first.
      const std::size_t row = static_cast<std::size_t>(img->width) * 4;
      std::vector<std::uint8_t> flipped(img->rgba.size());
      for (int y = 0; y < img->height; ++y)
        std::memcpy(&flipped[y * row], &img->rgba[(img->height - 1 - y) * row], row);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img->width, img->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
      ok = true;
    } else {
      std::fprintf(stderr, "sinew: shader texture not bound: %s\n", err.c_str());
    }
  } else if (t.texture_width > 0 && t.texture_height > 0 &&
             t.values.size() == static_cast<std::size_t>(t.texture_width) * t.texture_height) {
    // One channel, read as luminance (r = g = b, a = 1), as SOFA's procedural images.
    std::vector<std::uint8_t> texels(t.values.size());
    for (std::size_t i = 0; i < texels.size(); ++i)
      texels[i] = static_cast<std::uint8_t>(std::clamp(t.values[i], 0.f, 255.f));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, t.texture_width, t.texture_height, 0, GL_RED, GL_UNSIGNED_BYTE,
                 texels.data());
    const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    ok = true;
  } else {
    std::fprintf(stderr, "sinew: procedural shader texture not bound: %d x %d texels expected, %zu given\n",
                 t.texture_width, t.texture_height, t.values.size());
  }
  if (ok) {
    if (t.linear) glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, t.linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, t.linear ? GL_LINEAR : GL_NEAREST);
    const GLint wrap = t.repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  } else {
    glDeleteTextures(1, &id);
    id = 0;
  }
  textures_.emplace_back(key, id);
  return id;
}

bool SceneShaders::bind(const SceneShader& s, const Batch& b, const View& view, const Lighting& lighting,
                        std::vector<unsigned>& buffers, std::vector<std::size_t>& capacity) {
  Program* found = program_for(s);  // valid until the next program is made
  if (!found) return false;
  Program& prog = *found;
  const unsigned p = prog.id;
  glUseProgram(p);

  // Matrices: the modelview is the camera's (visual models are in world coordinates).
  const Eigen::Matrix4f& mv = view.view;
  const Eigen::Matrix4f& pr = view.projection;
  const Eigen::Matrix4f mv_inv = mv.inverse();
  const Eigen::Matrix4f matrices[7] = {mv, pr, pr * mv, mv_inv, mv.transpose(), mv_inv.transpose(), pr.inverse()};
  for (int k = 0; k < 7; ++k)
    if (prog.matrices[k] >= 0) glUniformMatrix4fv(prog.matrices[k], 1, GL_FALSE, matrices[k].data());
  if (prog.normal_matrix >= 0) {
    const Eigen::Matrix3f normal = mv.topLeftCorner<3, 3>().inverse().transpose();
    glUniformMatrix3fv(prog.normal_matrix, 1, GL_FALSE, normal.data());
  }
  if (prog.texture_matrix >= 0) {
    Eigen::Matrix4f id[4];
    for (auto& m : id) m.setIdentity();
    glUniformMatrix4fv(prog.texture_matrix, 4, GL_FALSE, id[0].data());
  }

  // Lights, in eye space as OpenGL stores them.
  GlLight lights[kGlslMaxLights];
  float model_ambient[4] = {0, 0, 0, 1};
  int n = 0;
  if (lighting.from_scene) {
    const Eigen::Matrix4d v = mv.cast<double>();
    n = static_cast<int>(std::min<std::size_t>(lighting.lights.size(), kGlslMaxLights));
    for (int i = 0; i < n; ++i) {
      const LightSource& src = lighting.lights[static_cast<std::size_t>(i)];
      GlLight& l = lights[i];
      const Eigen::Vector4d pos = v * Eigen::Vector4d(src.position[0], src.position[1], src.position[2], src.position[3]);
      const Eigen::Vector3d dir =
          v.topLeftCorner<3, 3>() * Eigen::Vector3d(src.spot_direction[0], src.spot_direction[1], src.spot_direction[2]);
      for (int k = 0; k < 4; ++k) l.position[k] = static_cast<float>(pos[k]);
      for (int k = 0; k < 3; ++k) l.diffuse[k] = l.specular[k] = src.color[k], l.spot[k] = static_cast<float>(dir[k]);
      l.cutoff = src.cutoff, l.exponent = src.exponent, l.linear = src.linear_attenuation;
    }
    for (int k = 0; k < 4; ++k) model_ambient[k] = lighting.ambient[k];
  } else {
    n = 1;
    GlLight& l = lights[0];
    const float ambient[4] = {0.5f, 0.5f, 0.5f, 1}, diffuse[4] = {0.9f, 0.9f, 0.9f, 1}, position[4] = {-0.7f, 0.3f, 0, 1};
    std::memcpy(l.ambient, ambient, sizeof ambient);
    std::memcpy(l.diffuse, diffuse, sizeof diffuse);
    for (float& c : l.specular) c = 1;
    std::memcpy(l.position, position, sizeof position);
    model_ambient[3] = 0;
  }
  const Shading& m = b.shading;
  for (int i = 0; i < n; ++i) {
    const GlLight& l = lights[i];
    const Light& at = prog.lights[i];
    set4(at.ambient, l.ambient);
    set4(at.diffuse, l.diffuse);
    set4(at.specular, l.specular);
    set4(at.position, l.position);
    // OpenGL's half vector: between the light's direction and the eye's (0, 0, 1).
    Eigen::Vector3f half = Eigen::Vector3f(l.position[0], l.position[1], l.position[2]);
    if (half.norm() > 0) half.normalize();
    half += Eigen::Vector3f(0, 0, 1);
    if (half.norm() > 0) half.normalize();
    const float h[4] = {half[0], half[1], half[2], 1};
    set4(at.half, h);
    if (at.spot_direction >= 0) glUniform3fv(at.spot_direction, 1, l.spot);
    const float cos_cutoff = l.cutoff >= 180 ? -1.f : std::cos(l.cutoff * static_cast<float>(M_PI) / 180.f);
    const float scalars[6] = {l.exponent, l.cutoff, cos_cutoff, l.constant, l.linear, l.quadratic};
    for (int k = 0; k < 6; ++k)
      if (at.scalars[k] >= 0) glUniform1f(at.scalars[k], scalars[k]);
    float prod[3][4];
    for (int k = 0; k < 4; ++k) {
      prod[0][k] = l.ambient[k] * m.ambient[k];
      prod[1][k] = l.diffuse[k] * m.diffuse[k];
      prod[2][k] = l.specular[k] * m.specular[k];
    }
    for (int k = 0; k < 3; ++k) set4(at.products[k], prod[k]);
  }
  set4(prog.material[0], m.emissive.data());
  set4(prog.material[1], m.ambient.data());
  set4(prog.material[2], m.diffuse.data());
  set4(prog.material[3], m.specular.data());
  if (prog.material[4] >= 0) glUniform1f(prog.material[4], m.shininess);
  set4(prog.model_ambient, model_ambient);
  float scene_color[4];
  for (int k = 0; k < 3; ++k) scene_color[k] = m.emissive[k] + m.ambient[k] * model_ambient[k];
  scene_color[3] = m.diffuse[3];  // OpenGL: the alpha of the material's diffuse colour
  set4(prog.scene_color, scene_color);

  // The scene's uniforms (their names are part of the program's identity: same order here).
  thread_local std::vector<int> ints;
  for (std::size_t k = 0; k < s.uniforms.size() && k < prog.uniforms.size(); ++k) {
    const ShaderInput& in = s.uniforms[k].value;
    const int loc = prog.uniforms[k];
    if (loc < 0 || in.values.empty() || in.width < 1) continue;
    const GLsizei count = static_cast<GLsizei>(in.values.size() / static_cast<std::size_t>(in.width));
    if (count == 0) continue;
    if (in.kind == ShaderInput::Kind::matrix_uniform) {
      // Given row by row, and passed to OpenGL (which reads column by column) with `transpose`
      // as its flag, as SOFA's setMatrix4: without it the shader sees each matrix transposed.
      glUniformMatrix4fv(loc, count, in.transpose ? GL_TRUE : GL_FALSE, in.values.data());
    } else if (in.kind == ShaderInput::Kind::int_uniform) {
      ints.assign(in.values.begin(), in.values.end());
      static void (*const kSet[])(GLint, GLsizei, const GLint*) = {glUniform1iv, glUniform2iv, glUniform3iv, glUniform4iv};
      if (in.width <= 4) kSet[in.width - 1](loc, count, ints.data());
    } else {
      static void (*const kSet[])(GLint, GLsizei, const GLfloat*) = {glUniform1fv, glUniform2fv, glUniform3fv,
                                                                      glUniform4fv};
      if (in.width <= 4) kSet[in.width - 1](loc, count, in.values.data());
    }
  }
  for (std::size_t k = 0; k < s.textures.size() && k < prog.samplers.size(); ++k) {
    const ShaderInput& t = s.textures[k].value;
    const int loc = prog.samplers[k];
    if (loc < 0 || t.unit >= static_cast<unsigned>(kUnits)) continue;
    // The texture of this sampler, looked up again only when its input changed.
    auto& [key, id] = prog.textures[k];
    const std::uint64_t now = texture_key(t);
    if (key != now || !id) key = now, id = texture_for(t, now);
    if (!id) continue;
    glActiveTexture(GL_TEXTURE0 + kFirstUnit + t.unit);
    glBindTexture(GL_TEXTURE_2D, id);
    glUniform1i(loc, kFirstUnit + static_cast<int>(t.unit));
  }
  glActiveTexture(GL_TEXTURE0);

  // Per-vertex attributes, into the batch's vertex array (bound by the caller).
  if (buffers.size() < b.attributes.size()) {
    const std::size_t old = buffers.size();
    buffers.resize(b.attributes.size());
    capacity.resize(b.attributes.size(), 0);
    glGenBuffers(static_cast<GLsizei>(buffers.size() - old), buffers.data() + old);
  }
  for (std::size_t k = 0; k < b.attributes.size(); ++k) {
    const Batch::Attribute& a = b.attributes[k];
    const int loc = glGetAttribLocation(p, a.name.c_str());
    if (loc < 0 || a.width < 1 || a.width > 4) continue;
    upload_buffer(GL_ARRAY_BUFFER, buffers[k], a.values.data(), a.values.size() * sizeof(float), capacity[k]);
    glVertexAttribPointer(static_cast<GLuint>(loc), a.width, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(static_cast<GLuint>(loc));
  }
  return true;
}

}  // namespace sinew::render
