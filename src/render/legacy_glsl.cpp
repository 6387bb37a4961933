#include "render/legacy_glsl.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::render {

namespace {

// The fixed-function state both stages may read, as uniforms of the same names in both.
constexpr const char* kCommon = R"(
struct sinew_LightSourceParameters {
  vec4 ambient; vec4 diffuse; vec4 specular; vec4 position; vec4 halfVector; vec3 spotDirection;
  float spotExponent; float spotCutoff; float spotCosCutoff;
  float constantAttenuation; float linearAttenuation; float quadraticAttenuation;
};
struct sinew_MaterialParameters { vec4 emission; vec4 ambient; vec4 diffuse; vec4 specular; float shininess; };
struct sinew_LightProducts { vec4 ambient; vec4 diffuse; vec4 specular; };
struct sinew_LightModelParameters { vec4 ambient; };
struct sinew_LightModelProducts { vec4 sceneColor; };
uniform sinew_LightSourceParameters sinew_LightSource[8];
uniform sinew_MaterialParameters sinew_FrontMaterial;
uniform sinew_LightProducts sinew_FrontLightProduct[8];
uniform sinew_LightModelParameters sinew_LightModel;
uniform sinew_LightModelProducts sinew_FrontLightModelProduct;
uniform mat4 sinew_ModelViewMatrix;
uniform mat4 sinew_ProjectionMatrix;
uniform mat4 sinew_ModelViewProjectionMatrix;
uniform mat4 sinew_ModelViewMatrixInverse;
uniform mat4 sinew_ModelViewMatrixTranspose;
uniform mat4 sinew_ModelViewMatrixInverseTranspose;
uniform mat4 sinew_ProjectionMatrixInverse;
uniform mat3 sinew_NormalMatrix;
uniform mat4 sinew_TextureMatrix[4];
)";

constexpr const char* kVertex = R"(
layout(location = 0) in vec4 sinew_Vertex;
layout(location = 1) in vec3 sinew_Normal;
layout(location = 2) in vec4 sinew_Color;
layout(location = 3) in vec4 sinew_MultiTexCoord0;
out vec4 sinew_FrontColor;
out vec4 sinew_BackColor;
out vec4 sinew_TexCoord[4];
vec4 sinew_ftransform() { return sinew_ModelViewProjectionMatrix * sinew_Vertex; }
)";

constexpr const char* kFragment = R"(
in vec4 sinew_FrontColor;
in vec4 sinew_TexCoord[4];
layout(location = 0) out vec4 sinew_FragColor;
)";

// Built-in name → its replacement, both stages (stage-specific ones below).
struct Rename {
  std::string_view from, to;
};
constexpr Rename kBoth[] = {
    {"gl_ModelViewMatrix", "sinew_ModelViewMatrix"},
    {"gl_ProjectionMatrix", "sinew_ProjectionMatrix"},
    {"gl_ModelViewProjectionMatrix", "sinew_ModelViewProjectionMatrix"},
    {"gl_ModelViewMatrixInverse", "sinew_ModelViewMatrixInverse"},
    {"gl_ModelViewMatrixTranspose", "sinew_ModelViewMatrixTranspose"},
    {"gl_ModelViewMatrixInverseTranspose", "sinew_ModelViewMatrixInverseTranspose"},
    {"gl_ProjectionMatrixInverse", "sinew_ProjectionMatrixInverse"},
    {"gl_NormalMatrix", "sinew_NormalMatrix"},
    {"gl_LightSource", "sinew_LightSource"},
    {"gl_FrontMaterial", "sinew_FrontMaterial"},
    {"gl_BackMaterial", "sinew_FrontMaterial"},
    {"gl_FrontLightProduct", "sinew_FrontLightProduct"},
    {"gl_BackLightProduct", "sinew_FrontLightProduct"},
    {"gl_LightModel", "sinew_LightModel"},
    {"gl_FrontLightModelProduct", "sinew_FrontLightModelProduct"},
    {"gl_BackLightModelProduct", "sinew_FrontLightModelProduct"},
    {"gl_TexCoord", "sinew_TexCoord"},
    {"gl_TextureMatrix", "sinew_TextureMatrix"},
    {"texture2D", "texture"},
    {"texture3D", "texture"},
    {"textureCube", "texture"},
    {"texture2DLod", "textureLod"},
    {"texture2DProj", "textureProj"},
};
constexpr Rename kVertexOnly[] = {
    {"attribute", "in"},
    {"varying", "out"},
    {"gl_Vertex", "sinew_Vertex"},
    {"gl_Normal", "sinew_Normal"},
    {"gl_Color", "sinew_Color"},
    {"gl_MultiTexCoord0", "sinew_MultiTexCoord0"},
    {"gl_FrontColor", "sinew_FrontColor"},
    {"gl_BackColor", "sinew_BackColor"},
    {"ftransform", "sinew_ftransform"},
};
// Mesa's llvmpipe (22.x) drops a patch whose tessellation levels are written through a
// dynamic index (gl_TessLevelOuter[gl_InvocationID], as SOFA's PN-triangle shader does):
// the control stage writes them into arrays of its own, copied to the built-ins with
// constant indices at the end of main (with_tess_level_copies).
constexpr Rename kTessControlOnly[] = {
    {"gl_TessLevelOuter", "sinew_TessLevelOuter"},
    {"gl_TessLevelInner", "sinew_TessLevelInner"},
};
constexpr const char* kTessControl = R"(
float sinew_TessLevelOuter[4];
float sinew_TessLevelInner[2];
)";
constexpr const char* kTessLevelsUnset = " for (int sinew_k = 0; sinew_k < 4; ++sinew_k) sinew_TessLevelOuter[sinew_k] = -3.0e38;"
                                         " sinew_TessLevelInner[0] = sinew_TessLevelInner[1] = -3.0e38; ";
constexpr const char* kTessLevelsCopied =
    "\n  if (sinew_TessLevelOuter[0] != -3.0e38) gl_TessLevelOuter[0] = sinew_TessLevelOuter[0];"
    " if (sinew_TessLevelOuter[1] != -3.0e38) gl_TessLevelOuter[1] = sinew_TessLevelOuter[1];"
    " if (sinew_TessLevelOuter[2] != -3.0e38) gl_TessLevelOuter[2] = sinew_TessLevelOuter[2];"
    " if (sinew_TessLevelOuter[3] != -3.0e38) gl_TessLevelOuter[3] = sinew_TessLevelOuter[3];"
    " if (sinew_TessLevelInner[0] != -3.0e38) gl_TessLevelInner[0] = sinew_TessLevelInner[0];"
    " if (sinew_TessLevelInner[1] != -3.0e38) gl_TessLevelInner[1] = sinew_TessLevelInner[1];\n";

constexpr Rename kFragmentOnly[] = {
    {"varying", "in"},
    {"gl_Color", "sinew_FrontColor"},
    {"gl_FragColor", "sinew_FragColor"},
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string_view renamed(std::string_view word, GlslStage stage) {
  for (const Rename& r : kBoth)
    if (r.from == word) return r.to;
  if (stage == GlslStage::vertex) {
    for (const Rename& r : kVertexOnly)
      if (r.from == word) return r.to;
  } else if (stage == GlslStage::fragment) {
    for (const Rename& r : kFragmentOnly)
      if (r.from == word) return r.to;
  } else if (stage == GlslStage::tess_control) {
    for (const Rename& r : kTessControlOnly)
      if (r.from == word) return r.to;
  }
  return word;
}

// Where main's body opens and closes in `text` (a whole translated stage), reading only what
// the preprocessor keeps: #define/#undef/#ifdef/#ifndef/#else/#endif are followed; any other
// conditional (#if, #elif) gives up, as do comments hiding nothing else. False when not found.
bool main_body(const std::string& text, std::size_t& open, std::size_t& close) {
  std::vector<std::string> defined;
  std::vector<std::pair<bool, bool>> stack;  // (active, condition) per open conditional
  auto active = [&] { return stack.empty() || stack.back().first; };
  auto word_at = [&](std::size_t& j) {
    while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
    const std::size_t b = j;
    while (j < text.size() && ident_char(text[j])) ++j;
    return text.substr(b, j - b);
  };
  // Characters kept by the preprocessor, comments blanked.
  std::string kept(text.size(), ' ');
  bool block = false;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    std::size_t j = at;
    while (j < end && (text[j] == ' ' || text[j] == '\t')) ++j;
    if (!block && j < end && text[j] == '#') {
      ++j;
      const std::string directive = word_at(j);
      const std::string name = word_at(j);
      const bool known = std::find(defined.begin(), defined.end(), name) != defined.end();
      if (directive == "define" && active()) defined.push_back(name);
      else if (directive == "undef" && active()) std::erase(defined, name);
      else if (directive == "ifdef" || directive == "ifndef") {
        const bool cond = directive == "ifdef" ? known : !known;
        stack.emplace_back(active() && cond, cond);
      } else if (directive == "else") {
        if (stack.empty()) return false;
        const bool parent = stack.size() < 2 || stack[stack.size() - 2].first;
        stack.back() = {parent && !stack.back().second, !stack.back().second};
      } else if (directive == "endif") {
        if (stack.empty()) return false;
        stack.pop_back();
      } else if (directive == "if" || directive == "elif") {
        return false;
      }
      at = end + 1;
      continue;
    }
    for (std::size_t k = at; k < end; ++k) {
      if (block) {
        if (text.compare(k, 2, "*/") == 0) block = false, ++k;
        continue;
      }
      if (text.compare(k, 2, "/*") == 0) {
        block = true;
        ++k;
        continue;
      }
      if (text.compare(k, 2, "//") == 0) break;
      if (active()) kept[k] = text[k];
    }
    at = end + 1;
  }
  for (std::size_t k = kept.find("main"); k != std::string::npos; k = kept.find("main", k + 1)) {
    if ((k > 0 && ident_char(kept[k - 1])) || (k + 4 < kept.size() && ident_char(kept[k + 4]))) continue;
    std::size_t j = k + 4;
    while (j < kept.size() && std::isspace(static_cast<unsigned char>(kept[j]))) ++j;
    if (j >= kept.size() || kept[j] != '(') continue;
    j = kept.find(')', j);
    if (j == std::string::npos) return false;
    ++j;
    while (j < kept.size() && std::isspace(static_cast<unsigned char>(kept[j]))) ++j;
    if (j >= kept.size() || kept[j] != '{') continue;  // a declaration
    open = j;
    int depth = 0;
    for (; j < kept.size(); ++j) {
      if (kept[j] == '{') ++depth;
      if (kept[j] == '}' && --depth == 0) {
        close = j;
        return true;
      }
    }
    return false;
  }
  return false;
}

// SOFA's GLSLShader::GetShaderStageName + "Shader".
const char* stage_define(GlslStage stage) {
  switch (stage) {
    case GlslStage::vertex: return "VertexShader";
    case GlslStage::tess_control: return "TessellationControlShader";
    case GlslStage::tess_eval: return "TessellationEvaluationShader";
    case GlslStage::geometry: return "GeometryShader";
    case GlslStage::fragment: return "FragmentShader";
  }
  return "";
}

}  // namespace

int glsl_version(const std::string& source) {
  for (std::size_t at = 0; at < source.size();) {
    const std::size_t end = std::min(source.find('\n', at), source.size());
    std::size_t j = at;
    while (j < end && (source[j] == ' ' || source[j] == '\t')) ++j;
    if (source.compare(j, 8, "#version") == 0) {
      j += 8;
      while (j < end && (source[j] == ' ' || source[j] == '\t')) ++j;
      int v = 0;
      while (j < end && std::isdigit(static_cast<unsigned char>(source[j])) && v < 10000) v = v * 10 + (source[j++] - '0');
      return v > 0 ? v : 110;
    }
    at = end + 1;
  }
  return 110;
}

int glsl_program_version(const std::vector<std::string>& sources, bool tessellation) {
  int v = tessellation ? 400 : 330;
  for (const std::string& s : sources) v = std::max(v, glsl_version(s));
  return v;
}

std::string translate_glsl(const std::string& source, GlslStage stage,
                           const std::vector<std::pair<std::string, std::string>>& defines, int version) {
  std::string out = "#version " + std::to_string(std::max(version, 330)) + " core\n";
  // `#extension` lines must come before anything else: moved up (kept as empty lines).
  std::string body = source;
  for (std::size_t at = 0; at < body.size();) {
    const std::size_t end = std::min(body.find('\n', at), body.size());
    std::size_t j = at;
    while (j < end && (body[j] == ' ' || body[j] == '\t')) ++j;
    if (body.compare(j, 10, "#extension") == 0) {
      out.append(body, j, end - j);
      out += '\n';
      body.erase(at, end - at);
      ++at;  // past the line's newline
    } else {
      at = end + 1;
    }
  }
  for (const auto& [name, value] : defines) out += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
  out += std::string("#define ") + stage_define(stage) + "\n";
  out += kCommon;
  if (stage == GlslStage::vertex) out += kVertex;
  if (stage == GlslStage::fragment) out += kFragment;
  if (stage == GlslStage::tess_control) out += kTessControl;
  out += "#line 1\n";
  std::size_t i = 0;
  const std::size_t n = body.size();
  bool line_start = true;
  while (i < n) {
    const char c = body[i];
    if (line_start) {
      // A `#version` line of the source: dropped (kept as an empty line, so line numbers hold).
      std::size_t j = i;
      while (j < n && (body[j] == ' ' || body[j] == '\t')) ++j;
      if (body.compare(j, 8, "#version") == 0) {
        while (i < n && body[i] != '\n') ++i;
        continue;
      }
    }
    line_start = c == '\n';
    if (ident_start(c) && (i == 0 || !ident_char(body[i - 1]))) {
      std::size_t j = i;
      while (j < n && ident_char(body[j])) ++j;
      out += renamed(std::string_view(body).substr(i, j - i), stage);
      i = j;
      continue;
    }
    out += c;
    ++i;
  }
  if (stage == GlslStage::tess_control) {
    std::size_t open = 0, close = 0;
    if (main_body(out, open, close)) {
      out.insert(close, kTessLevelsCopied);
      out.insert(open + 1, kTessLevelsUnset);
    } else {
      // No main found for sure: the levels go to the built-ins directly, as written.
      for (const char* name : {"Outer", "Inner"}) {
        const std::string from = std::string("sinew_TessLevel") + name, to = std::string("gl_TessLevel") + name;
        for (std::size_t k = out.find(from); k != std::string::npos; k = out.find(from, k + to.size()))
          out.replace(k, from.size(), to);
      }
      const std::size_t decl = out.find(kTessControl);
      if (decl != std::string::npos) out.erase(decl, std::string(kTessControl).size());
    }
  }
  return out;
}

}  // namespace sinew::render
