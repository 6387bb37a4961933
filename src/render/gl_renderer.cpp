#include "render/gl_renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "render/draw_shapes.h"
#include "render/draw_text.h"
#include "render/fluid_surface.h"
#include "render/gl_program.h"
#include "render/scene_shader.h"
#include "render/image_file.h"
#include "render/shadow_maps.h"

namespace sinew::render {

namespace {

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec2 a_texcoord;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_point_size;
uniform float u_splat_radius;  // > 0: points are discs of this world radius
uniform float u_half_height;   // half the viewport's height in pixels
uniform vec4 u_clip[8];  // ClipPlanes by id: kept where dot(u_clip[k], (p, 1)) >= 0 for every k
out float gl_ClipDistance[8];
out vec3 v_eye;
out vec3 v_normal;
out vec4 v_color;
out vec2 v_texcoord;
out vec3 v_world;
void main() {
  v_world = a_position;
  vec4 eye = u_view * vec4(a_position, 1.0);
  v_eye = eye.xyz;
  v_normal = mat3(u_view) * a_normal;  // the view is rigid: no inverse transpose needed
  v_color = a_color;
  gl_Position = u_proj * eye;
  if (u_splat_radius > 0.0) {
    // The disc's diameter in pixels: perspective divides by the depth, orthographic does not.
    float depth = u_proj[3][3] == 1.0 ? 1.0 : max(-eye.z, 1e-6);
    gl_PointSize = 2.0 * u_splat_radius * u_proj[1][1] * u_half_height / depth;
  } else {
    gl_PointSize = u_point_size;
  }
  v_texcoord = a_texcoord;
  for (int k = 0; k < 8; ++k) gl_ClipDistance[k] = dot(u_clip[k], vec4(a_position, 1.0));
}
)";

// Headlight: the light sits at the eye, so the light and view directions coincide.
// Two-sided: a back face is lit as if it faced the viewer (OglModel draws both sides).
const char* kFragmentShader = R"(#version 330 core
in vec3 v_eye;
in vec3 v_normal;
in vec4 v_color;
in vec2 v_texcoord;
uniform vec4 u_ambient;
uniform vec4 u_specular;
uniform vec4 u_emissive;
uniform float u_shininess;
uniform float u_color_ambient;
uniform bool u_lit;
uniform bool u_textured;
uniform bool u_translucent;
uniform int u_splat;  // 0: none, 1: soft disc (PointSplatModel)
// The scene's lights (LightManager), in eye space; without a LightManager, the headlight.
const int kMaxLights = 8;
uniform bool u_scene_lights;
uniform int u_nlights;
uniform vec3 u_global_ambient;
uniform vec4 u_light_pos[kMaxLights];     // w = 0: direction towards the light
uniform vec3 u_light_color[kMaxLights];   // ambient = diffuse = specular intensity
uniform vec3 u_light_spot[kMaxLights];    // spot direction
uniform float u_light_cos[kMaxLights];    // cos(cut-off); -2: no cone
uniform float u_light_exp[kMaxLights];
uniform float u_light_att[kMaxLights];    // linear attenuation (constant 1, quadratic 0)
uniform float u_splat_alpha;
uniform sampler2D u_texture;
in vec3 v_world;
// SOFA's shadow-mapping shaders (models under an OglShadowShader, docs/render.md): one-sided,
// ambient = the LightManager's ambient times the material's; a spot shines in a smoothstep of
// its cone (soft-shadow variant: to the spot's exponent) without attenuation; a directional
// light shines along its direction, without specular; a positional light gives nothing. A
// fragment in a light's shadow keeps (1 - shadowFactor) of that light.
uniform bool u_sofa_shadow;
uniform bool u_vsm;
uniform int u_light_type[kMaxLights];      // 0 directional, 1 positional, 2 spot
uniform vec3 u_light_dir_eye[kMaxLights];  // directional: the way the light travels (eye space)
uniform bool u_shadow_on[kMaxLights];
uniform mat4 u_light_vp[kMaxLights];
uniform bool u_light_persp[kMaxLights];
uniform float u_light_far[kMaxLights];
uniform float u_shadow_factor[kMaxLights];
uniform float u_vsm_bleeding[kMaxLights];
uniform float u_vsm_min_var[kMaxLights];
uniform float u_shadow_texel[kMaxLights];
uniform sampler2D u_shadow_map0;
uniform sampler2D u_shadow_map1;
uniform sampler2D u_shadow_map2;
uniform sampler2D u_shadow_map3;
uniform sampler2D u_shadow_map4;
uniform sampler2D u_shadow_map5;
uniform sampler2D u_shadow_map6;
uniform sampler2D u_shadow_map7;
// OrderIndependentTransparencyManager's accumulation (docs/render.md): the weighted
// premultiplied colour and alpha into target 0, alpha times the weight into target 1.
uniform bool u_oit;
uniform float u_oit_depth_scale;
layout(location = 0) out vec4 frag_color;
layout(location = 1) out float frag_oit_weight;
// GLSL 3.30 indexes sampler arrays by constants only.
vec2 shadow_moments(int i, vec2 uv) {
  if (i == 0) return texture(u_shadow_map0, uv).xy;
  if (i == 1) return texture(u_shadow_map1, uv).xy;
  if (i == 2) return texture(u_shadow_map2, uv).xy;
  if (i == 3) return texture(u_shadow_map3, uv).xy;
  if (i == 4) return texture(u_shadow_map4, uv).xy;
  if (i == 5) return texture(u_shadow_map5, uv).xy;
  if (i == 6) return texture(u_shadow_map6, uv).xy;
  return texture(u_shadow_map7, uv).xy;
}
// 1: lit by light i, 0: in its shadow (soft shadows: between).
float shadow_term(int i) {
  vec4 c = u_light_vp[i] * vec4(v_world, 1.0);
  if (c.w <= 0.0) return 1.0;
  vec3 p = c.xyz / c.w;
  vec2 uv = 0.5 * p.xy + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  float d = u_light_persp[i] ? c.w / u_light_far[i] : 0.5 * p.z + 0.5;
  if (!u_vsm) return d > shadow_moments(i, uv).x + 0.002 ? 0.0 : 1.0;
  // Variance shadow map: its moments averaged over 5 x 5 texels (SOFA blurs the map), then
  // Chebyshev's bound with the minimal variance and the light-bleeding reduction.
  vec2 m = vec2(0.0);
  for (int y = -2; y <= 2; ++y)
    for (int x = -2; x <= 2; ++x) m += shadow_moments(i, uv + vec2(x, y) * u_shadow_texel[i]);
  m /= 25.0;
  float lit = d <= m.x ? 1.0 : 0.0;
  float variance = max(m.y - m.x * m.x, u_vsm_min_var[i]);
  float dd = d - m.x;
  return smoothstep(u_vsm_bleeding[i], 1.0, max(lit, variance / (variance + dd * dd)));
}
vec3 sofa_shadow_shading(vec3 n, vec3 base, vec3 tex, out bool has_light) {
  vec3 c = u_global_ambient * (u_ambient.rgb + u_color_ambient * base);
  has_light = false;
  for (int i = 0; i < u_nlights; ++i) {
    has_light = true;
    int t = u_light_type[i];
    if (t == 1) continue;
    vec3 L = t == 0 ? -u_light_dir_eye[i] : normalize(u_light_pos[i].xyz - v_eye);
    float ndl = max(dot(n, L), 0.0);
    if (ndl <= 0.0) continue;
    float shadow = u_shadow_on[i] ? shadow_term(i) : 1.0;
    vec3 light = u_light_color[i];
    if (t == 2) {
      float cosc = u_light_cos[i] < -1.5 ? -1.0 : u_light_cos[i];
      float se = dot(normalize(u_light_spot[i]), -L);
      if (se <= cosc) continue;
      se = smoothstep(cosc, 1.0, se);
      if (u_vsm) se = pow(se, u_light_exp[i]);
      float k = se;
      if (shadow < 1.0) k *= shadow + (1.0 - u_shadow_factor[i]);
      if (u_vsm) k = min(k, se);
      vec3 h = normalize(normalize(u_light_pos[i].xyz) + vec3(0.0, 0.0, 1.0));
      c += k * base * light * ndl * tex + k * u_specular.rgb * light * pow(max(dot(n, h), 0.0), u_shininess);
    } else {
      vec3 dl = base * light * ndl;
      if (shadow < 0.99) dl *= shadow + (1.0 - u_shadow_factor[i]);
      c += dl * tex;
    }
  }
  return c;
}
void main() {
  if (u_splat != 0) {
    vec2 q = gl_PointCoord * 2.0 - 1.0;
    float r2 = dot(q, q);
    if (r2 >= 1.0) discard;
    // SOFA's billboard texture: alpha·cos(π/2·r), the colour as is.
    frag_color = vec4(v_color.rgb, u_splat_alpha * cos(1.5707963 * sqrt(r2)));
    return;
  }
  if (u_oit) {
    // SOFA's accumulation shader: light 0 (the headlight without a LightManager) at
    // infinity, two-sided (|n·L|, |n·H|), no emissive term.
    vec3 n = normalize(v_normal);
    vec3 L = vec3(0.0, 0.0, 1.0), light = vec3(1.0), global_ambient = vec3(0.0);
    if (u_scene_lights) {
      global_ambient = u_global_ambient;
      if (u_nlights > 0) {
        L = normalize(u_light_pos[0].xyz);
        light = u_light_color[0];
      } else {
        light = vec3(0.0);
      }
    }
    vec3 H = normalize(L + vec3(0.0, 0.0, 1.0));
    vec3 tex = vec3(1.0);
    float alpha = v_color.a;
    if (u_textured) {
      vec4 t = texture(u_texture, v_texcoord);
      tex = t.rgb;
      alpha *= t.a;
    }
    vec3 c = u_ambient.rgb * light + global_ambient * u_ambient.rgb + v_color.rgb * tex * light * abs(dot(n, L)) +
             u_specular.rgb * light * pow(abs(dot(n, H)), u_shininess);
    c *= alpha;  // premultiplied
    float depth = abs(1.0 / gl_FragCoord.w) * u_oit_depth_scale;
    float w = clamp(0.03 / (1e-5 + pow(depth, 4.0)), 1e-2, 3e3);
    frag_color = vec4(c * w, alpha);
    frag_oit_weight = alpha * w;
    return;
  }
  if (!u_lit) { frag_color = vec4(v_color.rgb, 1.0); return; }
  if (u_sofa_shadow) {
    // Without a LightManager SOFA's shader has no light and draws the material's diffuse colour.
    vec3 tex = u_textured ? texture(u_texture, v_texcoord).rgb : vec3(1.0);
    bool has_light;
    vec3 c = sofa_shadow_shading(normalize(v_normal), v_color.rgb, tex, has_light);
    frag_color = vec4(min(has_light ? c : v_color.rgb, vec3(1.0)), u_translucent ? v_color.a : 1.0);
    return;
  }
  vec3 n = normalize(v_normal);
  vec3 to_eye = normalize(-v_eye);
  float d = dot(n, to_eye);
  if (d < 0.0) { n = -n; d = -d; }
  vec3 c;
  if (!u_scene_lights) {
    float s = d > 0.0 ? pow(d, u_shininess) : 0.0;
    c = u_emissive.rgb + u_ambient.rgb + u_color_ambient * v_color.rgb + v_color.rgb * d + u_specular.rgb * s;
  } else {
    // Fixed-function OpenGL lighting (viewer at infinity, two-sided): per light
    // attenuation · spot · (ambient + diffuse·max(n·L, 0) + specular·max(n·h, 0)^shininess).
    vec3 mat_ambient = u_ambient.rgb + u_color_ambient * v_color.rgb;
    c = u_emissive.rgb + u_global_ambient * mat_ambient;
    for (int i = 0; i < u_nlights; ++i) {
      vec3 L;
      float att = 1.0;
      if (u_light_pos[i].w == 0.0) {
        L = normalize(u_light_pos[i].xyz);
      } else {
        vec3 to_light = u_light_pos[i].xyz - v_eye;
        float dist = length(to_light);
        L = to_light / max(dist, 1e-12);
        att = 1.0 / (1.0 + u_light_att[i] * dist);
      }
      float spot = 1.0;
      if (u_light_cos[i] > -1.5) {
        float sd = dot(-L, u_light_spot[i]);
        spot = sd >= u_light_cos[i] ? pow(max(sd, 0.0), u_light_exp[i]) : 0.0;
      }
      float ndl = max(dot(n, L), 0.0);
      vec3 h = normalize(L + vec3(0.0, 0.0, 1.0));
      float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
      c += att * spot * u_light_color[i] * (mat_ambient + v_color.rgb * ndl + u_specular.rgb * spec);
    }
  }
  // A texture modulates the lit colour (OpenGL's default GL_MODULATE, as SOFA's OglModel).
  // The alpha of fixed-function lighting is the diffuse alpha (texture alpha modulating it);
  // it matters only to translucent models, opaque ones keep the picture opaque.
  float alpha = 1.0;
  if (u_textured) {
    vec4 t = texture(u_texture, v_texcoord);
    c *= t.rgb;
    alpha = v_color.a * t.a;
  } else {
    alpha = v_color.a;
  }
  frag_color = vec4(min(c, vec3(1.0)), u_translucent ? alpha : 1.0);
}
)";

// OrderIndependentTransparencyManager's composition: a triangle covering the viewport; the
// normalised weighted colour over the picture, covering 1 − Π(1 − alpha) of it (blended
// with ONE, ONE_MINUS_SRC_ALPHA).
const char* kOitFragmentShader = R"(#version 330 core
uniform sampler2D u_accumulation;
uniform sampler2D u_weight;
out vec4 frag_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 accumulation = texelFetch(u_accumulation, p, 0);
  float revealage = accumulation.a;
  vec3 color = accumulation.rgb / max(texelFetch(u_weight, p, 0).r, 0.00001);
  frag_color = vec4(color, 1.0) * (1.0 - revealage);
}
)";

// A light's shadow map (render/shadow_maps.h): the depth it sees and its square (the moments
// of SOFA's variance shadow maps; hard shadows read the first).
const char* kShadowVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_light_vp;
out vec4 v_clip;
void main() {
  v_clip = u_light_vp * vec4(a_position, 1.0);
  gl_Position = v_clip;
}
)";

const char* kShadowFragmentShader = R"(#version 330 core
in vec4 v_clip;
uniform bool u_persp;
uniform float u_far;
out vec4 frag_color;
void main() {
  float d = u_persp ? v_clip.w / u_far : 0.5 * v_clip.z / v_clip.w + 0.5;
  frag_color = vec4(d, d * d, 0.0, 1.0);
}
)";

// Text (render/draw_text.h): vertices already in clip space; the font texture's alpha modulates
// the colour, and fragments it leaves transparent are dropped (SOFA's alpha test, GL_GREATER 0).
const char* kTextVertexShader = R"(#version 330 core
layout(location = 0) in vec4 a_clip;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_color;
out vec2 v_uv;
out vec4 v_color;
void main() {
  gl_Position = a_clip;
  v_uv = a_uv;
  v_color = a_color;
}
)";

const char* kTextFragmentShader = R"(#version 330 core
in vec2 v_uv;
in vec4 v_color;
uniform sampler2D u_font;
out vec4 frag_color;
void main() {
  vec4 t = v_uv.x < 0.0 ? vec4(1.0) : texture(u_font, v_uv);  // u < 0: a plain rectangle
  float a = t.a * v_color.a;
  if (a <= 0.0) discard;
  frag_color = vec4(v_color.rgb * t.rgb, a);
}
)";

// BackgroundSetting's image as SofaGLFWWindow::drawBackgroundImage lays it: tiled at its own
// pixel size from the bottom-left, through glOrtho(-0.5, width, -0.5, height), repeated (drawn
// on the composition's triangle over the viewport, kFullViewVertexShader).
const char* kBackgroundFragmentShader = R"(#version 330 core
uniform sampler2D u_image;
uniform vec2 u_viewport;  // pixels
uniform vec2 u_origin;    // the viewport's bottom-left corner in the framebuffer
uniform vec2 u_size;      // the image's pixels
out vec4 frag_color;
void main() {
  vec2 at = -0.5 + (gl_FragCoord.xy - u_origin) * (u_viewport + 0.5) / u_viewport;
  frag_color = vec4(texture(u_image, at / u_size).rgb, 1.0);
}
)";

unsigned compile(GLenum type, const char* src, std::string* error) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    if (error) *error = std::string("shader compilation failed: ") + log;
    glDeleteShader(s);
    return 0;
  }
  return s;
}

// Uploads `bytes` into `buffer`, growing its storage only when it is too small.
void upload(GLenum target, unsigned buffer, const void* data, std::size_t bytes, std::size_t& capacity) {
  glBindBuffer(target, buffer);
  if (bytes > capacity) {
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_DRAW);
    capacity = bytes;
  } else if (bytes > 0) {
    glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data);
  }
}

// The vertex shader's eight clip distances (ClipPlane ids 0 to 7) on or off.
void clip_distances(bool on) {
  for (int k = 0; k < Batch::kClipPlanes; ++k) (on ? glEnable : glDisable)(GL_CLIP_DISTANCE0 + k);
}

// The scissor test's state and box, kept across passes that set their own.
struct Scissor {
  GLboolean on;
  GLint box[4];
};
Scissor save_scissor() {
  Scissor s{glIsEnabled(GL_SCISSOR_TEST), {}};
  glGetIntegerv(GL_SCISSOR_BOX, s.box);
  return s;
}
void restore_scissor(const Scissor& s) {
  glScissor(s.box[0], s.box[1], s.box[2], s.box[3]);
  (s.on ? glEnable : glDisable)(GL_SCISSOR_TEST);
}

// A linked program of the two shaders; 0 with *error.
unsigned link(const char* vertex, const char* fragment, std::string* error) {
  return link_program_stages({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, error);
}

}  // namespace

const char* const kFullViewVertexShader = R"(#version 330 core
out vec2 v_uv;
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

unsigned link_program(const char* vertex, const char* fragment, std::string* error) {
  return link(vertex, fragment, error);
}

unsigned link_program_stages(const std::vector<std::pair<unsigned, std::string>>& stages, std::string* error) {
  std::vector<GLuint> shaders;
  auto drop = [&] {
    for (GLuint sh : shaders) glDeleteShader(sh);
  };
  for (const auto& [type, source] : stages) {
    const unsigned sh = compile(static_cast<GLenum>(type), source.c_str(), error);
    if (!sh) {
      drop();
      return 0;
    }
    shaders.push_back(sh);
  }
  const unsigned p = glCreateProgram();
  for (GLuint sh : shaders) glAttachShader(p, sh);
  glLinkProgram(p);
  drop();
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    if (error) *error = std::string("shader link failed: ") + log;
    glDeleteProgram(p);
    return 0;
  }
  return p;
}

void upload_buffer(unsigned target, unsigned buffer, const void* data, std::size_t bytes, std::size_t& capacity) {
  upload(static_cast<GLenum>(target), buffer, data, bytes, capacity);
}

std::unique_ptr<GlRenderer> GlRenderer::create(int width, int height, int samples, std::string* error) {
  std::unique_ptr<GlRenderer> r(new GlRenderer);
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  r->samples_ = std::max(0, std::min(samples, static_cast<int>(max_samples)));

  if (!r->allocate(width, height, error)) return nullptr;

  r->program_ = link(kVertexShader, kFragmentShader, error);
  if (!r->program_) return nullptr;
  r->text_program_ = link(kTextVertexShader, kTextFragmentShader, error);
  if (!r->text_program_) return nullptr;
  r->shadow_program_ = link(kShadowVertexShader, kShadowFragmentShader, error);
  if (!r->shadow_program_) return nullptr;
  r->oit_program_ = link(kFullViewVertexShader, kOitFragmentShader, error);
  if (!r->oit_program_) return nullptr;
  glUseProgram(r->oit_program_);
  glUniform1i(glGetUniformLocation(r->oit_program_, "u_accumulation"), kOitUnit);
  glUniform1i(glGetUniformLocation(r->oit_program_, "u_weight"), kOitUnit + 1);
  glGenVertexArrays(1, &r->oit_vao_);
  glUseProgram(r->text_program_);
  glUniform1i(glGetUniformLocation(r->text_program_, "u_font"), 0);  // texture unit 0
  const unsigned p = r->program_;
  r->u_view_ = glGetUniformLocation(p, "u_view");
  r->u_proj_ = glGetUniformLocation(p, "u_proj");
  r->u_ambient_ = glGetUniformLocation(p, "u_ambient");
  r->u_specular_ = glGetUniformLocation(p, "u_specular");
  r->u_emissive_ = glGetUniformLocation(p, "u_emissive");
  r->u_shininess_ = glGetUniformLocation(p, "u_shininess");
  r->u_lit_ = glGetUniformLocation(p, "u_lit");
  r->u_color_ambient_ = glGetUniformLocation(p, "u_color_ambient");
  r->u_point_size_ = glGetUniformLocation(p, "u_point_size");
  r->u_clip_ = glGetUniformLocation(p, "u_clip");
  r->u_textured_ = glGetUniformLocation(p, "u_textured");
  r->u_translucent_ = glGetUniformLocation(p, "u_translucent");
  r->u_splat_ = glGetUniformLocation(p, "u_splat");
  r->u_splat_alpha_ = glGetUniformLocation(p, "u_splat_alpha");
  r->u_splat_radius_ = glGetUniformLocation(p, "u_splat_radius");
  r->u_half_height_ = glGetUniformLocation(p, "u_half_height");
  r->u_nlights_ = glGetUniformLocation(p, "u_nlights");
  r->u_scene_lights_ = glGetUniformLocation(p, "u_scene_lights");
  r->u_global_ambient_ = glGetUniformLocation(p, "u_global_ambient");
  r->u_light_pos_ = glGetUniformLocation(p, "u_light_pos");
  r->u_light_color_ = glGetUniformLocation(p, "u_light_color");
  r->u_light_spot_ = glGetUniformLocation(p, "u_light_spot");
  r->u_light_cos_ = glGetUniformLocation(p, "u_light_cos");
  r->u_light_exp_ = glGetUniformLocation(p, "u_light_exp");
  r->u_light_att_ = glGetUniformLocation(p, "u_light_att");
  r->u_sofa_shadow_ = glGetUniformLocation(p, "u_sofa_shadow");
  r->u_oit_ = glGetUniformLocation(p, "u_oit");
  r->u_oit_depth_scale_ = glGetUniformLocation(p, "u_oit_depth_scale");
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "u_texture"), 0);  // texture unit 0
  for (int i = 0; i < static_cast<int>(LightManager::kMaxLights); ++i)  // units 1 to 8
    glUniform1i(glGetUniformLocation(p, ("u_shadow_map" + std::to_string(i)).c_str()), 1 + i);
  return r;
}

bool GlRenderer::allocate(int width, int height, std::string* error) {
  release_framebuffers();
  width_ = width, height_ = height;
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &color_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_rb_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  glGenRenderbuffers(1, &depth_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    if (error) *error = "the off-screen framebuffer is incomplete (size " + std::to_string(width) + "x" +
                        std::to_string(height) + ")";
    return false;
  }
  if (samples_ > 0) {  // single-sample target the multisampled picture is resolved into
    glGenFramebuffers(1, &resolve_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    glGenRenderbuffers(1, &resolve_rb_);
    glBindRenderbuffer(GL_RENDERBUFFER, resolve_rb_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_rb_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      if (error) *error = "the off-screen resolve framebuffer is incomplete";
      return false;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return true;
}

void GlRenderer::release_framebuffers() {
  const unsigned rbs[] = {color_rb_, depth_rb_, resolve_rb_, oit_depth_rb_};
  glDeleteRenderbuffers(4, rbs);
  const unsigned fbos[] = {fbo_, resolve_fbo_, oit_fbo_, post_fbo_};
  glDeleteFramebuffers(4, fbos);
  glDeleteTextures(2, oit_textures_);
  glDeleteTextures(2, post_textures_);
  color_rb_ = depth_rb_ = resolve_rb_ = fbo_ = resolve_fbo_ = 0;
  oit_fbo_ = oit_depth_rb_ = oit_textures_[0] = oit_textures_[1] = 0;
  post_fbo_ = post_textures_[0] = post_textures_[1] = 0;
  pass_fbo_ = 0;
}

bool GlRenderer::post_buffers() {
  if (post_fbo_) return true;
  if (post_failed_) return false;
  glGenFramebuffers(1, &post_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, post_fbo_);
  glGenTextures(2, post_textures_);
  for (int k = 0; k < 2; ++k) {
    glBindTexture(GL_TEXTURE_2D, post_textures_[k]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (k == 0) glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    else glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width_, height_, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, post_textures_[0], 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, post_textures_[1], 0);
  const bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  if (!ok) {
    std::fprintf(stderr, "sinew: PostProcessManager's pass not applied: its %dx%d picture is incomplete\n", width_,
                 height_);
    post_failed_ = true;
    const unsigned fbo = post_fbo_;
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(2, post_textures_);
    post_fbo_ = post_textures_[0] = post_textures_[1] = 0;
  }
  return ok;
}

Eigen::Matrix4f GlRenderer::post_projection(const PostProcess& p) {
  // gluPerspective(60, 1, zNear, zFar), as PostProcessManager::preDrawScene loads it.
  const float f = 1.f / std::tan(static_cast<float>(M_PI) / 6.f), n = p.z_near, far = p.z_far;
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = f;
  m(1, 1) = f;
  m(2, 2) = (far + n) / (n - far);
  m(2, 3) = 2.f * far * n / (n - far);
  m(3, 2) = -1.f;
  return m;
}

void GlRenderer::draw_post(const DrawList& list) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!post_vao_) {
    // The quad of PostProcessManager::drawScene: (±1, ±1, 0) with texture coordinates (0/1, 0/1).
    const float data[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0, 0, 0, 1, 0, 0, 1, 1, 1};
    glGenVertexArrays(1, &post_vao_);
    glGenBuffers(1, &post_vbo_);
    glBindVertexArray(post_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, post_vbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(12 * sizeof(float)));
    glEnableVertexAttribArray(3);
  }
  glBindVertexArray(post_vao_);
  if (!scene_shaders_) scene_shaders_ = std::make_unique<SceneShaders>();
  // Identity modelview and projection, as drawScene loads them for its quad.
  std::vector<unsigned> no_buffers;
  std::vector<std::size_t> no_capacity;
  const Batch quad;
  const bool bound = scene_shaders_->bind(list.shaders[static_cast<std::size_t>(list.post.shader)], quad, View{},
                                          list.lighting, no_buffers, no_capacity);
  if (!bound) {  // the shader does not run here (said once): the picture as drawn
    glBindFramebuffer(GL_READ_FRAMEBUFFER, post_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  } else {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    const unsigned p = static_cast<unsigned>(program);
    if (const int loc = glGetUniformLocation(p, "colorTexture"); loc >= 0) glUniform1i(loc, kPostUnit);
    if (const int loc = glGetUniformLocation(p, "depthTexture"); loc >= 0) glUniform1i(loc, kPostUnit + 1);
    if (const int loc = glGetUniformLocation(p, "pixelSize"); loc >= 0)
      glUniform2f(loc, 1.f / static_cast<float>(width_), 1.f / static_cast<float>(height_));
    for (int k = 0; k < 2; ++k) {
      glActiveTexture(GL_TEXTURE0 + kPostUnit + k);
      glBindTexture(GL_TEXTURE_2D, post_textures_[k]);
    }
    glDisable(GL_DEPTH_TEST);
    clip_distances(false);  // SOFA's shaders write no gl_ClipDistance
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    clip_distances(true);
    glEnable(GL_DEPTH_TEST);
    for (int k = 0; k < 2; ++k) {
      glActiveTexture(GL_TEXTURE0 + kPostUnit + k);
      glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(program_);
  }
  glBindVertexArray(0);
  pass_fbo_ = fbo_;
}

bool GlRenderer::oit_buffers() {
  if (oit_fbo_) return true;
  glGenFramebuffers(1, &oit_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, oit_fbo_);
  glGenTextures(2, oit_textures_);
  const GLint formats[2] = {GL_RGBA16F, GL_R16F};
  const GLenum layouts[2] = {GL_RGBA, GL_RED};
  for (int k = 0; k < 2; ++k) {
    glBindTexture(GL_TEXTURE_2D, oit_textures_[k]);
    glTexImage2D(GL_TEXTURE_2D, 0, formats[k], width_, height_, 0, layouts[k], GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + k, GL_TEXTURE_2D, oit_textures_[k], 0);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenRenderbuffers(1, &oit_depth_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, oit_depth_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);  // the picture's format: blitted
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, oit_depth_rb_);
  const bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  if (!ok) {
    if (!oit_warned_)
      std::fprintf(stderr, "sinew: order-independent transparency unavailable (float render targets): translucent "
                           "models are blended in drawing order\n");
    oit_warned_ = true;
    const unsigned fbo = oit_fbo_;
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(2, oit_textures_);
    glDeleteRenderbuffers(1, &oit_depth_rb_);
    oit_fbo_ = oit_depth_rb_ = oit_textures_[0] = oit_textures_[1] = 0;
  }
  return ok;
}

bool GlRenderer::oit_batch(const Batch& b) {
  return b.translucent && b.kind == Batch::Kind::triangles && b.splat == Batch::Splat::none;
}

void GlRenderer::draw_oit(const DrawList& list, int x, int y, int width, int height) {
  bool any = false;
  for (std::size_t i = 0; i < list.used && !any; ++i) any = oit_batch(list.batches[i]);
  if (!any) return;
  // The opaque models' depth, so that they hide what is behind them.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, pass_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, oit_fbo_);
  glBlitFramebuffer(x, y, x + width, y + height, x, y, x + width, y + height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, oit_fbo_);
  const GLenum targets[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, targets);
  const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, width, height);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float accumulation_clear[4] = {0.f, 0.f, 0.f, 1.f}, weight_clear[4] = {0.f, 0.f, 0.f, 0.f};
  glClearBufferfv(GL_COLOR, 0, accumulation_clear);
  glClearBufferfv(GL_COLOR, 1, weight_clear);
  // Colours and weights add up; the alpha channel keeps the product of (1 − alpha).
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  glUniform1i(u_oit_, 1);
  glUniform1f(u_oit_depth_scale_, list.oit.depth_scale);
  for (std::size_t i = 0; i < list.used; ++i)
    if (oit_batch(list.batches[i])) draw_batch(list.batches[i], gpu_[i]);
  glUniform1i(u_oit_, 0);
  glDepthMask(GL_TRUE);
  // Composition over the picture (its alpha kept).
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_DEPTH_TEST);
  clip_distances(false);  // the composition's triangle writes none
  glUseProgram(oit_program_);
  for (int k = 0; k < 2; ++k) {
    glActiveTexture(GL_TEXTURE0 + kOitUnit + k);
    glBindTexture(GL_TEXTURE_2D, oit_textures_[k]);
  }
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(oit_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(program_);
  clip_distances(true);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  if (!scissor) glDisable(GL_SCISSOR_TEST);
}

bool GlRenderer::resize(int width, int height, std::string* error) {
  if (width == width_ && height == height_) return true;
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    if (error) *error = "invalid picture size " + std::to_string(width) + "x" + std::to_string(height);
    return false;
  }
  return allocate(width, height, error);
}

void GlRenderer::present(int width, int height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 0 ? resolve_fbo_ : fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

GlRenderer::~GlRenderer() {
  if (frame_gpu_) {
    glDeleteVertexArrays(1, &frame_gpu_->vao);
    glDeleteBuffers(4, frame_gpu_->vbo);
    glDeleteBuffers(1, &frame_gpu_->ebo);
  }
  for (GpuBatch& g : gpu_) {
    glDeleteVertexArrays(1, &g.vao);
    glDeleteBuffers(4, g.vbo);
    glDeleteBuffers(1, &g.ebo);
    if (!g.attribute_vbo.empty()) glDeleteBuffers(static_cast<GLsizei>(g.attribute_vbo.size()), g.attribute_vbo.data());
    if (g.quad_ebo) glDeleteBuffers(1, &g.quad_ebo);
  }
  scene_shaders_.reset();
  fluids_.clear();
  for (const auto& t : textures_)
    if (t.second) glDeleteTextures(1, &t.second);
  if (program_) glDeleteProgram(program_);
  if (text_program_) glDeleteProgram(text_program_);
  if (shadow_program_) glDeleteProgram(shadow_program_);
  if (oit_program_) glDeleteProgram(oit_program_);
  if (oit_vao_) glDeleteVertexArrays(1, &oit_vao_);
  if (background_program_) glDeleteProgram(background_program_);
  if (post_vao_) glDeleteVertexArrays(1, &post_vao_);
  if (post_vbo_) glDeleteBuffers(1, &post_vbo_);
  for (ShadowMap& m : shadow_maps_) {
    if (m.fbo) glDeleteFramebuffers(1, &m.fbo);
    if (m.texture) glDeleteTextures(1, &m.texture);
    if (m.depth) glDeleteRenderbuffers(1, &m.depth);
  }
  if (text_vao_) glDeleteVertexArrays(1, &text_vao_);
  if (text_vbo_) glDeleteBuffers(1, &text_vbo_);
  release_framebuffers();
}

void GlRenderer::draw(const DrawList& list, const View& view, const std::array<float, 4>& background) {
  // PostProcessManager: the scene goes into the pass's picture first (its own projection).
  const bool post = list.post.on && post_buffers();
  pass_fbo_ = post ? post_fbo_ : fbo_;
  View scene_view = view;
  if (post) scene_view.projection = post_projection(list.post);
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  glViewport(0, 0, width_, height_);
  glClearColor(background[0], background[1], background[2], background[3]);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!list.background_image.empty()) draw_background_image(list.background_image, 0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glEnable(GL_PROGRAM_POINT_SIZE);
  clip_distances(true);
  while (gpu_.size() < list.used) {
    GpuBatch g;
    glGenVertexArrays(1, &g.vao);
    glGenBuffers(4, g.vbo);
    glGenBuffers(1, &g.ebo);
    gpu_.push_back(g);
  }
  pass_fluids_ = 0;
  // OglViewport's swapMainView: the picture from its camera, its rectangle from the main view.
  const ExtraViewport* swapped = nullptr;
  for (const ExtraViewport& e : list.viewports)
    if (e.swap) swapped = &e;
  const double aspect = static_cast<double>(width_) / std::max(height_, 1);
  // The lights' shadow maps do not depend on the view: drawn by the first pass only.
  if (swapped) draw_pass(list, viewport_view(*swapped, list.min, list.max, aspect), 0, 0, width_, height_, true);
  else draw_pass(list, scene_view, 0, 0, width_, height_, true);
  if (post) draw_post(list);
  // OglViewports, over the picture (SOFA's postDrawScene), each cleared to the background.
  for (const ExtraViewport& e : list.viewports) {
    const int x = e.x >= 0 ? e.x : width_ + e.x, y = e.y >= 0 ? e.y : height_ + e.y;
    const double ratio = static_cast<double>(e.width) / e.height;
    View v;
    if (&e == swapped) {
      v = view;  // the main view, its projection widened by the aspects' ratio
      const float scale = static_cast<float>(aspect / ratio);
      v.projection.row(0) *= scale;
    } else {
      v = viewport_view(e, list.min, list.max, ratio);
    }
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, e.width, e.height);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_pass(list, v, x, y, e.width, e.height, false);
    glDisable(GL_SCISSOR_TEST);
  }
  glViewport(0, 0, width_, height_);
  view_ = view.view;
  // The picture's alpha stays that of the opaque pass.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  if (list.texts_used > 0 || !list.overlay_rects.empty()) draw_texts(list, view);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (list.frame.on) draw_scene_frame(list.frame, view);
  glBindVertexArray(0);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  clip_distances(false);  // the viewer draws its overlays after this
  if (samples_ > 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
}

void GlRenderer::draw_pass(const DrawList& list, const View& view, int x, int y, int width, int height,
                           bool shadow_maps) {
  glUseProgram(program_);
  pass_list_ = &list;
  pass_view_ = view;
  glUniformMatrix4fv(u_view_, 1, GL_FALSE, view.view.data());  // Eigen is column-major, as GL
  glUniformMatrix4fv(u_proj_, 1, GL_FALSE, view.projection.data());
  glUniform1f(u_half_height_, 0.5f * static_cast<float>(height));
  view_ = view.view;
  set_lights(list.lighting, view);
  set_shadows(list, view, shadow_maps);  // may draw the lights' maps: the picture's framebuffer is bound after
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  glViewport(x, y, width, height);
  // SOFA's two visual passes: opaque models in graph order, then translucent ones.
  std::size_t fluids = pass_fluids_;
  for (std::size_t i = 0; i < list.used; ++i)
    if (list.batches[i].splat == Batch::Splat::fluid) {
      draw_fluid(list.batches[i], gpu_[i], fluids++, view, x, y, width, height);
    } else if (!list.batches[i].translucent) {
      begin_model_state(list.batches[i]);
      draw_batch(list.batches[i], gpu_[i]);
      end_model_state(list.batches[i]);
    }
  glUniform1i(u_translucent_, 1);
  // The picture's alpha stays that of the opaque pass (a PNG of a translucent model is not
  // itself translucent).
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  // Without float targets the manager's models are blended in drawing order (one message).
  const bool oit = list.oit.on && oit_buffers();
  fluids = pass_fluids_;
  for (std::size_t i = 0; i < list.used; ++i) {
    const Batch& b = list.batches[i];
    if (b.splat == Batch::Splat::fluid) {  // OglFluidModel::drawTransparent: its surface over the picture
      FluidSurface& f = *fluids_[fluids++];
      if (b.fluid.debug > 7) {
        clip_distances(false);
        const Scissor scissor = save_scissor();
        f.composite(x, y);
        restore_scissor(scissor);
        glUseProgram(program_);
        clip_distances(true);
      }
      continue;
    }
    if (!b.translucent || (oit && oit_batch(b))) continue;
    if (b.splat == Batch::Splat::soft) {  // PointSplatModel::drawTransparent: "over", back to front
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      draw_batch(b, gpu_[i]);
      glDisable(GL_BLEND);
      continue;
    }
    if (!b.blend) {  // blendTranslucency off: drawn opaque, after the opaque models
      begin_model_state(b);
      draw_batch(b, gpu_[i]);
      end_model_state(b);
      continue;
    }
    // OglModel::internalDraw: the background is first darkened by (1 - alpha), then the
    // colour is added weighted by alpha (or as is when premultiplied): the usual "over",
    // written without depth unless writeZTransparent.
    glEnable(GL_BLEND);
    glDepthMask(b.write_depth ? GL_TRUE : GL_FALSE);
    glBlendFunc(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
    draw_batch(b, gpu_[i]);
    glBlendFunc(b.premultiplied ? GL_ONE : GL_SRC_ALPHA, GL_ONE);
    begin_model_state(b);  // alphaBlend's factors replace these, as in internalDraw
    draw_batch(b, gpu_[i], /*upload=*/false);
    end_model_state(b);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
  if (oit) draw_oit(list, x, y, width, height);  // OrderIndependentTransparencyManager's models
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUniform1i(u_translucent_, 0);
  pass_fluids_ = fluids;
}

void GlRenderer::draw_fluid(const Batch& b, GpuBatch& g, std::size_t k, const View& view, int x, int y, int width,
                            int height) {
  while (fluids_.size() <= k) fluids_.push_back(std::make_unique<FluidSurface>());
  glBindVertexArray(g.vao);
  upload(GL_ARRAY_BUFFER, g.vbo[0], b.positions.data(), b.positions.size() * sizeof(float), g.capacity[0]);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(0);
  // The passes change the framebuffer, viewport, scissor, clear colour and program.
  const Scissor scissor = save_scissor();
  float clear[4];
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  clip_distances(false);  // the passes' shaders write no gl_ClipDistance
  FluidSurface& f = *fluids_[k];
  const bool drawn =
      f.render(g.vao, b.positions.data(), static_cast<int>(b.vertex_count()), b.fluid, view, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  glViewport(x, y, width, height);
  restore_scissor(scissor);
  glClearColor(clear[0], clear[1], clear[2], clear[3]);
  if (drawn) f.draw_debug(b.fluid.debug);  // OglFluidModel::doDrawVisual's debugFBO 0 to 6
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program_);
  clip_distances(true);
}

void GlRenderer::draw_background_image(const std::string& file, int x, int y, int width, int height) {
  const unsigned texture = texture_for(file);
  if (!texture) return;  // unreadable (said once): the colour stays
  if (!background_program_) {
    std::string err;
    background_program_ = link(kFullViewVertexShader, kBackgroundFragmentShader, &err);
    if (!background_program_) {
      std::fprintf(stderr, "sinew: the background image cannot be drawn: %s\n", err.c_str());
      return;
    }
  }
  GLint w = 0, h = 0;
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  if (w <= 0 || h <= 0) return;
  glUseProgram(background_program_);
  glUniform1i(glGetUniformLocation(background_program_, "u_image"), 0);
  glUniform2f(glGetUniformLocation(background_program_, "u_viewport"), static_cast<float>(width),
              static_cast<float>(height));
  glUniform2f(glGetUniformLocation(background_program_, "u_origin"), static_cast<float>(x), static_cast<float>(y));
  glUniform2f(glGetUniformLocation(background_program_, "u_size"), static_cast<float>(w), static_cast<float>(h));
  glDisable(GL_DEPTH_TEST);  // under everything, writing no depth
  clip_distances(false);
  glBindVertexArray(oit_vao_);  // an empty vertex array: the triangle comes from gl_VertexID
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  clip_distances(true);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program_);
}

void GlRenderer::begin_model_state(const Batch& b) {
  if (b.alpha_blend) {
    static const GLenum kEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_MIN, GL_MAX};
    static const GLenum kFactors[] = {GL_ZERO, GL_ONE, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
    glDepthMask(GL_FALSE);
    glBlendEquation(kEquations[b.blend_equation & 3]);
    glBlendFunc(kFactors[b.source_factor & 3], kFactors[b.dest_factor & 3]);
    glEnable(GL_BLEND);
  }
  if (!b.depth_test) glDisable(GL_DEPTH_TEST);
  if (b.cull == 1 || b.cull == 2) {
    glCullFace(b.cull == 1 ? GL_BACK : GL_FRONT);
    glEnable(GL_CULL_FACE);
  }
}

void GlRenderer::end_model_state(const Batch& b) {
  if (b.cull == 1 || b.cull == 2) glDisable(GL_CULL_FACE);
  if (!b.depth_test) glEnable(GL_DEPTH_TEST);
  if (b.alpha_blend) {  // internalDraw's restore
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
}

// Wide lines: core-profile contexts without the forward-compatible flag keep them (Mesa draws
// each as a screen-aligned quad, as SOFA's fixed-function glLineWidth); the width is clamped
// to the implementation's range.
void GlRenderer::set_line_width(float w) {
  if (line_width_range_[1] <= 0.f) glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, line_width_range_);
  if (!(w >= 1.f)) w = 1.f;  // also NaN
  glLineWidth(std::min(w, std::max(1.f, line_width_range_[1])));
}

void GlRenderer::draw_batch(const Batch& b, GpuBatch& g, bool upload_data) {
  glBindVertexArray(g.vao);
  if (upload_data) {
    upload(GL_ARRAY_BUFFER, g.vbo[0], b.positions.data(), b.positions.size() * sizeof(float), g.capacity[0]);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    if (!b.normals.empty()) {
      upload(GL_ARRAY_BUFFER, g.vbo[1], b.normals.data(), b.normals.size() * sizeof(float), g.capacity[1]);
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(1);
    } else {
      glDisableVertexAttribArray(1);
      glVertexAttrib3f(1, 0.f, 0.f, 1.f);
    }
    if (!b.colors.empty()) {
      upload(GL_ARRAY_BUFFER, g.vbo[2], b.colors.data(), b.colors.size() * sizeof(float), g.capacity[2]);
      glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(2);
    } else {  // one colour for the whole batch: the attribute's current value
      glDisableVertexAttribArray(2);
      glVertexAttrib4fv(2, b.shading.diffuse.data());
    }
    glUniform4fv(u_ambient_, 1, b.shading.ambient.data());
    glUniform4fv(u_specular_, 1, b.shading.specular.data());
    glUniform4fv(u_emissive_, 1, b.shading.emissive.data());
    glUniform1f(u_shininess_, b.shading.shininess);
    glUniform1f(u_color_ambient_, b.color_ambient);
    glUniform1f(u_point_size_, b.point_size);
    glUniform4fv(u_clip_, Batch::kClipPlanes, b.clip[0].data());
    glUniform1i(u_sofa_shadow_, b.shadow_shader ? 1 : 0);
    const unsigned texture = b.texture.empty() ? 0 : texture_for(b.texture);
    if (texture && b.texcoords.size() == b.vertex_count() * 2) {
      upload(GL_ARRAY_BUFFER, g.vbo[3], b.texcoords.data(), b.texcoords.size() * sizeof(float), g.capacity[4]);
      glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(3);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, texture);
      glUniform1i(u_textured_, 1);
    } else {
      glDisableVertexAttribArray(3);
      glUniform1i(u_textured_, 0);
    }
    if (!b.quad_indices.empty()) {  // patches or lines with adjacency of four: their own buffer
      if (!g.quad_ebo) glGenBuffers(1, &g.quad_ebo);
      upload(GL_ELEMENT_ARRAY_BUFFER, g.quad_ebo, b.quad_indices.data(), b.quad_indices.size() * sizeof(unsigned),
             g.quad_capacity);
    }
    if (b.kind == Batch::Kind::triangles && !b.indices.empty())
      upload(GL_ELEMENT_ARRAY_BUFFER, g.ebo, b.indices.data(), b.indices.size() * sizeof(unsigned), g.capacity[3]);
  }
  // Without upload, the vertex array object, the uniforms and the texture are still those
  // set by the previous call for this batch.
  const GLsizei n = static_cast<GLsizei>(b.vertex_count());
  if (b.kind == Batch::Kind::points) {
    glUniform1i(u_lit_, 0);
    glUniform1i(u_splat_, static_cast<int>(b.splat));
    glUniform1f(u_splat_radius_, b.splat == Batch::Splat::none ? 0.f : b.splat_radius);
    glUniform1f(u_splat_alpha_, b.splat_alpha);
    if (b.splat == Batch::Splat::soft) {
      // Back to front along the view (SOFA sorts by the distance along its view direction).
      sort_back_to_front(b);
      upload(GL_ELEMENT_ARRAY_BUFFER, g.ebo, order_.data(), order_.size() * sizeof(unsigned), g.capacity[3]);
      glDrawElements(GL_POINTS, n, GL_UNSIGNED_INT, nullptr);
    } else {
      glDrawArrays(GL_POINTS, 0, n);
    }
    glUniform1i(u_splat_, 0);
    glUniform1f(u_splat_radius_, 0.f);
  } else if (b.kind == Batch::Kind::lines) {
    glUniform1i(u_lit_, 0);
    set_line_width(b.line_width);
    glDrawArrays(GL_LINES, 0, n);
    set_line_width(1.f);
  } else {
    glUniform1i(u_lit_, b.lit ? 1 : 0);
    glPolygonMode(GL_FRONT_AND_BACK, b.wireframe ? GL_LINE : GL_FILL);
    if (b.wireframe) set_line_width(b.line_width);
    if (b.shader >= 0 && pass_list_ && static_cast<std::size_t>(b.shader) < pass_list_->shaders_used) {
      if (!scene_shaders_) scene_shaders_ = std::make_unique<SceneShaders>();
      if (scene_shaders_->bind(pass_list_->shaders[static_cast<std::size_t>(b.shader)], b, pass_view_,
                               pass_list_->lighting, g.attribute_vbo, g.attribute_capacity)) {
        clip_distances(false);  // SOFA's shaders write no gl_ClipDistance
        draw_shaded_elements(b, g);
        clip_distances(true);
        glUseProgram(program_);
        if (b.wireframe) set_line_width(1.f);
        return;
      }
    }
    if (b.primitive == Batch::Primitive::points) {  // OglModel's POINTS: every vertex, shaded or not
      glDrawArrays(GL_POINTS, 0, n);
    } else if (!b.indices.empty()) {
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(b.indices.size()), GL_UNSIGNED_INT, nullptr);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, n);
    }
    if (b.wireframe) set_line_width(1.f);
  }
}

void GlRenderer::draw_shaded_elements(const Batch& b, GpuBatch& g) {
  const GLsizei n = static_cast<GLsizei>(b.vertex_count());
  const GLsizei triangles = static_cast<GLsizei>(b.triangle_count * 3);
  switch (b.primitive) {
    case Batch::Primitive::points:
      glDrawArrays(GL_POINTS, 0, n);
      return;
    case Batch::Primitive::triangles:
      if (!b.indices.empty()) glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(b.indices.size()), GL_UNSIGNED_INT, nullptr);
      else glDrawArrays(GL_TRIANGLES, 0, n);
      return;
    case Batch::Primitive::patches:
      // OglModel::internalDraw: triangles as patches of 3, quads as patches of 4.
      if (triangles > 0) {
        glPatchParameteri(GL_PATCH_VERTICES, 3);
        glDrawElements(GL_PATCHES, triangles, GL_UNSIGNED_INT, nullptr);
      }
      break;
    case Batch::Primitive::lines_adjacency:
      // Triangles cannot be lines with adjacency: drawn as triangles (SOFA warns so).
      if (triangles > 0) glDrawElements(GL_TRIANGLES, triangles, GL_UNSIGNED_INT, nullptr);
      break;
  }
  if (b.quad_indices.empty() || !g.quad_ebo) return;
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.quad_ebo);
  const GLsizei quads = static_cast<GLsizei>(b.quad_indices.size());
  if (b.primitive == Batch::Primitive::patches) {
    glPatchParameteri(GL_PATCH_VERTICES, 4);
    glDrawElements(GL_PATCHES, quads, GL_UNSIGNED_INT, nullptr);
  } else {
    glDrawElements(GL_LINES_ADJACENCY, quads, GL_UNSIGNED_INT, nullptr);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ebo);  // the vertex array's own element buffer again
}

void GlRenderer::draw_scene_frame(const SceneFrame& f, const View& view) {
  if (frame_style_ != f.style) {
    frame_batch_ = Batch{};
    append_scene_frame(frame_batch_, f.style);
    frame_batch_.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    frame_batch_.lit = false;  // SOFA disables lighting for the frame
    frame_style_ = f.style;
    frame_gpu_.reset();
  }
  if (!frame_gpu_) {
    frame_gpu_ = std::make_unique<GpuBatch>();
    glGenVertexArrays(1, &frame_gpu_->vao);
    glGenBuffers(4, frame_gpu_->vbo);
    glGenBuffers(1, &frame_gpu_->ebo);
  }
  // OglSceneFrame::doDrawVisual: a square viewport in the corner, its depth cleared, a 60°
  // perspective (near 0.5, far 10) and the camera's rotation with the frame 3 in front.
  const int s = std::max(1, std::min(f.size, std::min(width_, height_)));
  const int x = (f.corner == 1 || f.corner == 2) ? width_ - s : 0;
  const int y = (f.corner == 2 || f.corner == 3) ? height_ - s : 0;
  glViewport(x, y, s, s);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x, y, s, s);
  glClear(GL_DEPTH_BUFFER_BIT);
  Eigen::Matrix4f v = view.view;
  v(0, 3) = 0.f, v(1, 3) = 0.f, v(2, 3) = -3.f;
  const float near = 0.5f, far = 10.f, t = 1.f / std::tan(static_cast<float>(M_PI) / 6.f);
  Eigen::Matrix4f p = Eigen::Matrix4f::Zero();
  p(0, 0) = t, p(1, 1) = t, p(2, 2) = (far + near) / (near - far), p(2, 3) = 2 * far * near / (near - far);
  p(3, 2) = -1.f;
  glUniformMatrix4fv(u_view_, 1, GL_FALSE, v.data());
  glUniformMatrix4fv(u_proj_, 1, GL_FALSE, p.data());
  draw_batch(frame_batch_, *frame_gpu_);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, width_, height_);
  glUniformMatrix4fv(u_view_, 1, GL_FALSE, view.view.data());
  glUniformMatrix4fv(u_proj_, 1, GL_FALSE, view.projection.data());
}

void GlRenderer::set_lights(const Lighting& l, const View& view) {
  const int n = l.from_scene ? static_cast<int>(std::min<std::size_t>(l.lights.size(), LightManager::kMaxLights)) : 0;
  // A LightManager without lights leaves only its global ambient, as in SOFA.
  glUniform1i(u_scene_lights_, l.from_scene ? 1 : 0);
  glUniform1i(u_nlights_, n);
  float pos[4 * LightManager::kMaxLights] = {}, col[3 * LightManager::kMaxLights] = {},
        spot[3 * LightManager::kMaxLights] = {}, cosc[LightManager::kMaxLights] = {},
        expo[LightManager::kMaxLights] = {}, att[LightManager::kMaxLights] = {};
  const Eigen::Matrix4d v = view.view.cast<double>();
  for (int i = 0; i < n; ++i) {
    const LightSource& s = l.lights[i];
    // OpenGL transforms a light's position (w = 1) or direction (w = 0), and its spot direction,
    // by the modelview matrix current when it is set: the camera's, so they are world values.
    const Eigen::Vector4d p = v * Eigen::Vector4d(s.position[0], s.position[1], s.position[2], s.position[3]);
    const Eigen::Vector3d d = v.topLeftCorner<3, 3>() * Eigen::Vector3d(s.spot_direction[0], s.spot_direction[1],
                                                                        s.spot_direction[2]);
    for (int k = 0; k < 4; ++k) pos[4 * i + k] = static_cast<float>(p[k]);
    for (int k = 0; k < 3; ++k) col[3 * i + k] = s.color[k], spot[3 * i + k] = static_cast<float>(d[k]);
    cosc[i] = s.cutoff >= 180.f ? -2.f : static_cast<float>(std::cos(s.cutoff * M_PI / 180.0));
    expo[i] = s.exponent;
    att[i] = s.linear_attenuation;
  }
  glUniform3f(u_global_ambient_, l.ambient[0], l.ambient[1], l.ambient[2]);
  if (n > 0) {
    glUniform4fv(u_light_pos_, n, pos);
    glUniform3fv(u_light_color_, n, col);
    glUniform3fv(u_light_spot_, n, spot);
    glUniform1fv(u_light_cos_, n, cosc);
    glUniform1fv(u_light_exp_, n, expo);
    glUniform1fv(u_light_att_, n, att);
  }
}

void GlRenderer::sort_back_to_front(const Batch& b) {
  const std::size_t n = b.vertex_count();
  depth_.resize(n);
  order_.resize(n);
  // Eye-space z of each point (the row of the view matrix giving z): larger is nearer.
  for (std::size_t i = 0; i < n; ++i) {
    const float* p = &b.positions[i * 3];
    depth_[i] = view_(2, 0) * p[0] + view_(2, 1) * p[1] + view_(2, 2) * p[2];
    order_[i] = static_cast<unsigned>(i);
  }
  // Equal depths keep the points' order, as SOFA's multimap; std::sort with the index as tie-break
  // does so without stable_sort's temporary buffer (no allocation per frame).
  std::sort(order_.begin(), order_.end(), [&](unsigned a, unsigned c) {
    return depth_[a] < depth_[c] || (depth_[a] == depth_[c] && a < c);
  });
}

void GlRenderer::set_shadows(const DrawList& list, const View& view, bool render_maps) {
  const Lighting& l = list.lighting;
  const int n = l.from_scene ? static_cast<int>(std::min<std::size_t>(l.lights.size(), LightManager::kMaxLights)) : 0;
  bool shaded = false;
  for (std::size_t i = 0; i < list.used; ++i) shaded |= list.batches[i].shadow_shader;
  if (!shaded) return;  // nothing drawn with SOFA's shadow shader: no uniform read
  constexpr int kMax = static_cast<int>(LightManager::kMaxLights);
  int type[kMax] = {}, on[kMax] = {}, persp[kMax] = {};
  float dir[3 * kMax] = {}, far[kMax] = {}, factor[kMax] = {}, bleed[kMax] = {}, minvar[kMax] = {},
        texel[kMax] = {}, vp[16 * kMax] = {};
  const Eigen::Matrix3f rot = view.view.topLeftCorner<3, 3>();
  for (int i = 0; i < n; ++i) {
    const LightSource& s = l.lights[i];
    type[i] = static_cast<int>(s.type);
    const Eigen::Vector3f d = (rot * Eigen::Vector3f(static_cast<float>(s.position[0]), static_cast<float>(s.position[1]),
                                                      static_cast<float>(s.position[2])))
                                  .normalized();
    for (int k = 0; k < 3; ++k) dir[3 * i + k] = d[k];
    factor[i] = s.shadow_factor, bleed[i] = s.vsm_light_bleeding, minvar[i] = s.vsm_min_variance;
    if (!s.shadows) continue;
    const std::optional<LightView> lv = light_view(s, list.min, list.max);
    if (!lv) continue;
    const int size = shadow_map_size(s.texture_size, width_, height_);
    if (!shadow_map(i, size)) continue;
    if (render_maps) render_shadow_map(list, *lv, shadow_maps_[i]);
    on[i] = 1, persp[i] = lv->perspective ? 1 : 0, far[i] = lv->far, texel[i] = 1.f / static_cast<float>(size);
    std::copy(lv->view_projection.data(), lv->view_projection.data() + 16, vp + 16 * i);
  }
  // Back to the picture.
  glBindFramebuffer(GL_FRAMEBUFFER, pass_fbo_);
  glViewport(0, 0, width_, height_);
  glUseProgram(program_);
  const auto loc = [this](const char* name) { return glGetUniformLocation(program_, name); };
  glUniform1i(loc("u_vsm"), l.soft_shadows ? 1 : 0);
  if (n > 0) {
    glUniform1iv(loc("u_light_type"), n, type);
    glUniform3fv(loc("u_light_dir_eye"), n, dir);
    glUniform1iv(loc("u_shadow_on"), n, on);
    glUniformMatrix4fv(loc("u_light_vp"), n, GL_FALSE, vp);
    glUniform1iv(loc("u_light_persp"), n, persp);
    glUniform1fv(loc("u_light_far"), n, far);
    glUniform1fv(loc("u_shadow_factor"), n, factor);
    glUniform1fv(loc("u_vsm_bleeding"), n, bleed);
    glUniform1fv(loc("u_vsm_min_var"), n, minvar);
    glUniform1fv(loc("u_shadow_texel"), n, texel);
  }
  for (int i = 0; i < n; ++i)
    if (on[i]) {
      glActiveTexture(GL_TEXTURE1 + i);
      glBindTexture(GL_TEXTURE_2D, shadow_maps_[i].texture);
    }
  glActiveTexture(GL_TEXTURE0);
}

bool GlRenderer::shadow_map(int i, int size) {
  ShadowMap& m = shadow_maps_[i];
  if (m.fbo && m.size == size) return true;
  if (!m.fbo) {
    glGenFramebuffers(1, &m.fbo);
    glGenTextures(1, &m.texture);
    glGenRenderbuffers(1, &m.depth);
  }
  glBindTexture(GL_TEXTURE_2D, m.texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindRenderbuffer(GL_RENDERBUFFER, m.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m.texture, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m.depth);
  m.size = size;
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    if (!shadow_warned_) std::fprintf(stderr, "sinew: shadows not drawn: no %dx%d shadow map framebuffer\n", size, size);
    shadow_warned_ = true;
    m.size = 0;
    return false;
  }
  return true;
}

void GlRenderer::render_shadow_map(const DrawList& list, const LightView& lv, ShadowMap& m) {
  glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
  glViewport(0, 0, m.size, m.size);
  glClearColor(1.f, 1.f, 0.f, 0.f);  // nothing seen: as far as can be
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(shadow_program_);
  glUniformMatrix4fv(glGetUniformLocation(shadow_program_, "u_light_vp"), 1, GL_FALSE, lv.view_projection.data());
  glUniform1i(glGetUniformLocation(shadow_program_, "u_persp"), lv.perspective ? 1 : 0);
  glUniform1f(glGetUniformLocation(shadow_program_, "u_far"), lv.far);
  clip_distances(false);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // Every visual model casts a shadow (SOFA draws them all in its shadow pass).
  for (std::size_t i = 0; i < list.used; ++i) {
    const Batch& b = list.batches[i];
    if (b.kind != Batch::Kind::triangles || b.positions.empty()) continue;
    GpuBatch& g = gpu_[i];
    glBindVertexArray(g.vao);
    upload(GL_ARRAY_BUFFER, g.vbo[0], b.positions.data(), b.positions.size() * sizeof(float), g.capacity[0]);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    if (!b.indices.empty()) {
      upload(GL_ELEMENT_ARRAY_BUFFER, g.ebo, b.indices.data(), b.indices.size() * sizeof(unsigned), g.capacity[3]);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(b.indices.size()), GL_UNSIGNED_INT, nullptr);
    } else {
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(b.vertex_count()));
    }
  }
  clip_distances(true);
}

void GlRenderer::draw_texts(const DrawList& list, const View& view) {
  unsigned font = 0;
  if (list.texts_used > 0) {
    if (font_.empty()) {
      if (!font_warned_)
        std::fprintf(stderr,
                     "sinew: text not drawn: SOFA's font textures/texture_ascii_smooth.png is in none of the data "
                     "folders (--data-path)\n");
      font_warned_ = true;
    } else {
      font = texture_for(font_);  // 0: texture_for said why
    }
  }
  text_vertices_.clear();
  // Depth-tested texts first, then the overlay rectangles and the texts drawn over everything;
  // each group in graph order.
  std::size_t tested_floats = 0;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) rect_vertices(list, width_, height_, text_vertices_);
    if (font)
      for (std::size_t i = 0; i < list.texts_used; ++i)
        if (list.texts[i].depth_test == (pass == 0)) text_vertices(list.texts[i], view, width_, height_, text_vertices_);
    if (pass == 0) tested_floats = text_vertices_.size();
  }
  if (text_vertices_.empty()) return;
  if (!text_vao_) {
    glGenVertexArrays(1, &text_vao_);
    glGenBuffers(1, &text_vbo_);
  }
  glBindVertexArray(text_vao_);
  upload(GL_ARRAY_BUFFER, text_vbo_, text_vertices_.data(), text_vertices_.size() * sizeof(float), text_capacity_);
  constexpr GLsizei stride = 10 * sizeof(float);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(4 * sizeof(float)));
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(6 * sizeof(float)));
  for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
  glUseProgram(text_program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, font);
  // The cells touch each other: no wrapping from one edge of the texture to the other.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  clip_distances(false);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  const auto count = [](std::size_t floats) { return static_cast<GLsizei>(floats / 10); };
  if (tested_floats > 0) glDrawArrays(GL_TRIANGLES, 0, count(tested_floats));
  glDisable(GL_DEPTH_TEST);
  if (text_vertices_.size() > tested_floats)
    glDrawArrays(GL_TRIANGLES, count(tested_floats), count(text_vertices_.size() - tested_floats));
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  clip_distances(true);
  glUseProgram(program_);
}

unsigned GlRenderer::texture_for(const std::string& path) {
  for (const auto& [file, id] : textures_)
    if (file == path) return id;
  std::string err;
  unsigned id = 0;
  if (auto img = read_image(path, &err)) {
    // OpenGL's first row is the bottom one (v = 0): the picture's last row goes first.
    const std::size_t row = static_cast<std::size_t>(img->width) * 4;
    std::vector<std::uint8_t> flipped(img->rgba.size());
    for (int y = 0; y < img->height; ++y)
      std::memcpy(&flipped[y * row], &img->rgba[(img->height - 1 - y) * row], row);
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img->width, img->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, flipped.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  } else {
    std::fprintf(stderr, "sinew: texture not drawn: %s\n", err.c_str());  // once per file
  }
  textures_.emplace_back(path, id);
  return id;
}

void GlRenderer::read(Image& out) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, samples_ > 0 ? resolve_fbo_ : fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  rows_.resize(row * height_);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rows_.data());
  out.width = width_, out.height = height_;
  out.rgba.resize(rows_.size());
  for (int y = 0; y < height_; ++y)  // GL's first row is the bottom one
    std::memcpy(&out.rgba[y * row], &rows_[(height_ - 1 - y) * row], row);
}

}  // namespace sinew::render
