#include "render/legacy_glsl.h"

#include <algorithm>
#include <cctype>
#include <string_view>

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
  } else {
    for (const Rename& r : kFragmentOnly)
      if (r.from == word) return r.to;
  }
  return word;
}

}  // namespace

std::string translate_glsl(const std::string& source, GlslStage stage,
                           const std::vector<std::pair<std::string, std::string>>& defines) {
  std::string out = "#version 330 core\n";
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
  out += kCommon;
  out += stage == GlslStage::vertex ? kVertex : kFragment;
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
  return out;
}

}  // namespace sinew::render
