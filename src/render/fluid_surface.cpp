#include "render/fluid_surface.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/LU>

#include "render/gl_program.h"

namespace sinew::render {

namespace {

// Targets by pass (see the header).
enum : int { kThickness, kDepth, kBlurDepthAcross, kBlurDepthAlong, kNormals, kBlurThicknessAcross,
             kBlurThicknessAlong, kShade };

// Texture units of the passes' inputs: above those the renderer keeps bound during a pass
// (0 models, 1-8 shadow maps, 9-10 order-independent transparency, 11+ scene shaders).
constexpr int kUnit = 24;

// A particle as a sphere sprite: its size in pixels shrinks with the distance to the eye
// (SOFA measures it on the homogeneous eye position, w = 1 included).
const char* kSpriteVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;
uniform float u_scale;
out vec3 v_eye;
void main() {
  vec4 eye = u_view * vec4(a_position, 1.0);
  v_eye = eye.xyz;
  gl_PointSize = u_radius * (u_scale / length(eye));
  gl_Position = u_proj * eye;
}
)";
// The sphere's front surface: its depth; the colour is the sprite's thickness.
const char* kSpriteFragment = R"(#version 330 core
uniform mat4 u_proj;
uniform float u_radius;
uniform float u_thickness;
in vec3 v_eye;
out vec4 frag_color;
void main() {
  vec2 q = gl_PointCoord * vec2(2.0, -2.0) + vec2(-1.0, 1.0);
  float r2 = dot(q, q);
  if (r2 > 1.0) discard;
  vec3 n = vec3(q, sqrt(1.0 - r2));
  vec4 clip = u_proj * vec4(v_eye + n * u_radius, 1.0);
  gl_FragDepth = (gl_DepthRange.diff * (clip.z / clip.w) + gl_DepthRange.near + gl_DepthRange.far) / 2.0;
  frag_color = vec4(u_thickness, u_thickness, u_thickness, 1.0);
}
)";

// Bilateral blur along u_direction over ±u_taps texels (SOFA's spriteBlurRadius), one body for
// both inputs. DEPTH: the input is a depth texture, empty pixels (depth 1) are discarded, the
// blurred depth is the fragment's and its colour the linearised depth (what debugFBO 2 and 3
// show); else the input is the thickness, blurred everywhere. The taps are read with texelFetch
// at whole texels, clamped to the edges: SOFA's loop samples the texel centres of a linearly
// filtered texture, the same values, which a software renderer filters at four times the cost.
// Spatial weight exp(−(x·scale)²), x in texture units; range weight exp(−(Δ·falloff)²).
const char* kBlurFragment = R"(
uniform sampler2D u_input;
uniform ivec2 u_direction;
uniform int u_taps;
uniform float u_texel;
uniform float u_scale;
uniform float u_falloff;
uniform float u_near;
uniform float u_far;
out vec4 frag_color;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(u_input, 0) - 1;
  float centre = texelFetch(u_input, p, 0).x;
#ifdef DEPTH
  if (centre > 0.999) discard;
#endif
  float sum = 0.0, weights = 0.0;
  for (int k = -u_taps; k <= u_taps; ++k) {
    float s = texelFetch(u_input, clamp(p + k * u_direction, ivec2(0), last), 0).x;
    float spatial = float(k) * u_texel * u_scale, range = (s - centre) * u_falloff;
    float w = exp(-spatial * spatial) * exp(-range * range);
    sum += s * w;
    weights += w;
  }
  if (weights > 0.0) sum /= weights;
#ifdef DEPTH
  gl_FragDepth = sum;
  float linear = 2.0 * u_near / (u_far + u_near - sum * (u_far - u_near));
  frag_color = vec4(linear, linear, linear, 1.0);
#else
  frag_color = vec4(sum, sum, sum, 1.0);
#endif
}
)";
const std::string kBlurDepthFragment = std::string("#version 330 core\n#define DEPTH 1\n") + kBlurFragment;
const std::string kBlurThicknessFragment = std::string("#version 330 core\n") + kBlurFragment;

// Eye-space positions of the blurred depth (its [0, 1] value taken as NDC z, as SOFA) and the
// surface normal from the one-sided differences of smaller depth change.
const char* kNormalsFragment = R"(#version 330 core
uniform sampler2D u_input;
uniform vec2 u_size;
uniform mat4 u_inv_proj;
in vec2 v_uv;
out vec4 frag_color;
vec3 eye_at(vec2 uv, float depth) {
  vec4 e = u_inv_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return e.xyz / e.w;
}
vec3 eye_of(vec2 uv) { return eye_at(uv, texture(u_input, uv).x); }
void main() {
  float depth = texture(u_input, v_uv).x;
  if (depth > 0.99999) discard;
  vec2 texel = 1.0 / u_size;
  vec3 p = eye_at(v_uv, depth);
  vec3 dx = eye_of(v_uv + vec2(texel.x, 0.0)) - p;
  vec3 dx_back = p - eye_of(v_uv - vec2(texel.x, 0.0));
  if (abs(dx.z) > abs(dx_back.z)) dx = dx_back;
  vec3 dy = eye_of(v_uv + vec2(0.0, texel.y)) - p;
  vec3 dy_back = p - eye_of(v_uv - vec2(0.0, texel.y));
  if (abs(dy.z) > abs(dy_back.z)) dy = dy_back;
  frag_color = vec4(normalize(cross(dx, dy)), 1.0);
}
)";

// The surface's colour: half-Lambert from a light along +z, the fluid's colour where thick and
// white where thin, a sharp Blinn highlight; alpha the thickness.
const char* kShadeFragment = R"(#version 330 core
uniform sampler2D u_normals;
uniform sampler2D u_depth;
uniform sampler2D u_thickness;
uniform vec4 u_color;
uniform mat4 u_inv_proj;
in vec2 v_uv;
out vec4 frag_color;
void main() {
  float depth = texture(u_depth, v_uv).x;
  if (depth > 0.999) discard;
  const vec3 light = vec3(0.0, 0.0, 1.0);
  vec3 n = normalize(texture(u_normals, v_uv).xyz);
  vec4 e = u_inv_proj * vec4(v_uv * 2.0 - 1.0, depth, 1.0);
  vec3 to_eye = -e.xyz / e.w;
  vec4 diffuse = (max(dot(light, n), 0.0) * 0.5 + 0.5) * u_color;
  float highlight = pow(max(dot(n, normalize(light + to_eye)), 0.0), 1280.0);
  float thickness = texture(u_thickness, v_uv).x;
  diffuse = thickness * diffuse + (1.0 - thickness) * vec4(1.0);
  frag_color = vec4(diffuse.rgb + vec3(highlight), thickness);
  gl_FragDepth = depth;
}
)";

// The shaded surface over the picture, at its own depth.
const char* kCompositeFragment = R"(#version 330 core
uniform sampler2D u_color;
uniform sampler2D u_depth;
in vec2 v_uv;
out vec4 frag_color;
void main() {
  float depth = texture(u_depth, v_uv).x;
  if (depth > 0.999999) discard;
  gl_FragDepth = depth;
  frag_color = texture(u_color, v_uv);
}
)";

// A target shown as is (debugFBO); a depth texture as grey.
const char* kShowFragment = R"(#version 330 core
uniform sampler2D u_input;
uniform int u_depth;
in vec2 v_uv;
out vec4 frag_color;
void main() {
  vec4 t = texture(u_input, v_uv);
  frag_color = u_depth != 0 ? vec4(t.xxx, 1.0) : vec4(t.rgb, 1.0);
}
)";

void bind_input(int slot, unsigned texture) {
  glActiveTexture(GL_TEXTURE0 + kUnit + slot);
  glBindTexture(GL_TEXTURE_2D, texture);
}

int at(unsigned program, const char* name) { return glGetUniformLocation(program, name); }

using Rect = FluidSurface::Rect;

Rect unite(const Rect& a, const Rect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

// `r` grown by (dx, dy) pixels on each side, within the width × height picture.
Rect grow(const Rect& r, int dx, int dy, int width, int height) {
  if (r.empty()) return r;
  return {std::max(r.x0 - dx, 0), std::max(r.y0 - dy, 0), std::min(r.x1 + dx, width), std::min(r.y1 + dy, height)};
}

void scissor_to(const Rect& r) { glScissor(r.x0, r.y0, std::max(r.x1 - r.x0, 0), std::max(r.y1 - r.y0, 0)); }

// The pixels the sprite vertex shader's points cover, with two pixels to spare for the
// rasteriser's rounding: a point's size is radius · scale / |(eye, 1)| pixels (at least one, as
// GL clamps it) around its window position. Points with clip w ≤ 0 are clipped by GL and left
// out; anything not finite gives the whole picture.
Rect sprite_pixels(const float* p, int count, const View& view, float radius, float scale, int width, int height) {
  const Rect all{0, 0, width, height};
  float x0 = static_cast<float>(width), y0 = static_cast<float>(height), x1 = 0.f, y1 = 0.f;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector4f eye = view.view * Eigen::Vector4f(p[3 * i], p[3 * i + 1], p[3 * i + 2], 1.f);
    const Eigen::Vector4f clip = view.projection * eye;
    if (clip.w() <= 0.f) continue;
    const float half = 0.5f * std::max(radius * scale / eye.norm(), 1.f) + 2.f;
    const float cx = (0.5f * clip.x() / clip.w() + 0.5f) * static_cast<float>(width);
    const float cy = (0.5f * clip.y() / clip.w() + 0.5f) * static_cast<float>(height);
    if (!std::isfinite(half) || !std::isfinite(cx) || !std::isfinite(cy)) return all;
    x0 = std::min(x0, cx - half), x1 = std::max(x1, cx + half);
    y0 = std::min(y0, cy - half), y1 = std::max(y1, cy + half);
  }
  // Clamped as floats first: a point far outside must not overflow the conversion.
  auto clamp = [](float v, int hi) { return static_cast<int>(std::clamp(v, 0.f, static_cast<float>(hi))); };
  Rect r{clamp(std::floor(x0), width), clamp(std::floor(y0), height), clamp(std::ceil(x1), width),
         clamp(std::ceil(y1), height)};
  return r.empty() ? Rect{} : r;
}

}  // namespace

FluidSurface::~FluidSurface() {
  release();
  for (unsigned p : {sprite_, blur_depth_, normals_, blur_thickness_, shade_, over_, show_})
    if (p) glDeleteProgram(p);
  if (quad_vao_) glDeleteVertexArrays(1, &quad_vao_);
}

void FluidSurface::release() {
  for (Target& t : targets_) {
    if (t.fbo) glDeleteFramebuffers(1, &t.fbo);
    const unsigned textures[2] = {t.color, t.depth};
    glDeleteTextures(2, textures);
    t = Target{};
  }
  width_ = height_ = 0;
}

bool FluidSurface::make(int width, int height) {
  if (!sprite_) {
    std::string error;
    struct Source {
      unsigned* program;
      const char* vertex;
      const char* fragment;
    };
    const Source sources[] = {{&sprite_, kSpriteVertex, kSpriteFragment},
                              {&blur_depth_, kFullViewVertexShader, kBlurDepthFragment.c_str()},
                              {&normals_, kFullViewVertexShader, kNormalsFragment},
                              {&blur_thickness_, kFullViewVertexShader, kBlurThicknessFragment.c_str()},
                              {&shade_, kFullViewVertexShader, kShadeFragment},
                              {&over_, kFullViewVertexShader, kCompositeFragment},
                              {&show_, kFullViewVertexShader, kShowFragment}};
    for (const Source& s : sources) {
      *s.program = link_program(s.vertex, s.fragment, &error);
      if (!*s.program) {
        std::fprintf(stderr, "sinew: OglFluidModel's surface cannot be drawn: %s\n", error.c_str());
        return false;
      }
    }
    // Samplers by pass; the units do not change.
    for (unsigned p : {blur_depth_, normals_, blur_thickness_, show_}) {
      glUseProgram(p);
      glUniform1i(at(p, "u_input"), kUnit);
    }
    glUseProgram(shade_);
    glUniform1i(at(shade_, "u_normals"), kUnit);
    glUniform1i(at(shade_, "u_depth"), kUnit + 1);
    glUniform1i(at(shade_, "u_thickness"), kUnit + 2);
    glUseProgram(over_);
    glUniform1i(at(over_, "u_color"), kUnit);
    glUniform1i(at(over_, "u_depth"), kUnit + 1);
    glGenVertexArrays(1, &quad_vao_);
  }
  if (width == width_ && height == height_) return true;
  release();
  for (Target& t : targets_) {
    glGenFramebuffers(1, &t.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, t.fbo);
    glGenTextures(1, &t.color);
    glGenTextures(1, &t.depth);
    for (unsigned texture : {t.color, t.depth}) {
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      if (texture == t.color)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      else
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.color, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, t.depth, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      std::fprintf(stderr, "sinew: OglFluidModel's surface cannot be drawn: its %dx%d targets are incomplete\n", width,
                   height);
      release();
      return false;
    }
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  width_ = width, height_ = height;
  for (Rect& w : written_) w = Rect{0, 0, width, height};  // undefined until first cleared
  return true;
}

void FluidSurface::start(int target, float red, bool grey, Rect r) {
  glBindFramebuffer(GL_FRAMEBUFFER, targets_[target].fbo);
  const Rect dirty = unite(written_[target], r);
  if (!dirty.empty()) {
    scissor_to(dirty);
    const float other = grey ? red : 1.f;
    glClearColor(red, other, other, 1.f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  scissor_to(r);
  written_[target] = r;
}

void FluidSurface::full_screen(unsigned program) {
  glUseProgram(program);
  glBindVertexArray(quad_vao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

bool FluidSurface::render(unsigned vao, const float* positions, int count, const FluidLook& look, const View& view,
                          int width, int height) {
  if (failed_ || count <= 0 || width <= 0 || height <= 0) return false;
  if (!make(width, height)) {
    failed_ = true;
    return false;
  }
  const Eigen::Matrix4f& proj = view.projection;
  const Eigen::Matrix4f inv_proj = proj.inverse();
  // The projection's near and far planes (used by the linearised depth of debugFBO 2 and 3).
  const bool ortho = proj(3, 3) == 1.f;
  const float a = proj(2, 2), b = proj(2, 3);
  const float z_near = ortho ? (b + 1.f) / a : b / (a - 1.f);
  const float z_far = ortho ? (b - 1.f) / a : b / (a + 1.f);
  // SOFA's sprite scale: the picture's width over the tangent of half of 65°.
  const float scale = static_cast<float>(width) / std::tan(65.f * (static_cast<float>(M_PI_2) / 180.f));
  const float size[2] = {static_cast<float>(width), static_cast<float>(height)};

  // The sprites' pixels. The thickness blurs spread what they read by their taps, across then
  // along; their rectangles keep one texel to spare. Whole texels of the blur: the picture's
  // size at most (a hostile radius must not make the loop endless).
  sprites_ = sprite_pixels(positions, count, view, look.radius, scale, width, height);
  const float taps_f = std::clamp(std::floor(look.blur_radius), 0.f, static_cast<float>(std::max(width, height)));
  const int taps = std::isfinite(taps_f) ? static_cast<int>(taps_f) : 0;
  const int reach = taps + 1;
  const Rect across = grow(sprites_, reach, 2 * reach, width, height);
  const Rect along = grow(sprites_, reach, reach, width, height);

  glViewport(0, 0, width, height);
  glEnable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glUseProgram(sprite_);
  glUniformMatrix4fv(at(sprite_, "u_view"), 1, GL_FALSE, view.view.data());
  glUniformMatrix4fv(at(sprite_, "u_proj"), 1, GL_FALSE, proj.data());
  glUniform1f(at(sprite_, "u_radius"), look.radius);
  glUniform1f(at(sprite_, "u_thickness"), look.thickness);
  glUniform1f(at(sprite_, "u_scale"), scale);
  glBindVertexArray(vao);
  // 0: thicknesses added up, no depth test.
  start(kThickness, 0.f, false, sprites_);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_POINTS, 0, count);
  glDisable(GL_BLEND);
  // 1: the nearest sphere.
  start(kDepth, 1.f, false, sprites_);
  glEnable(GL_DEPTH_TEST);
  glDrawArrays(GL_POINTS, 0, count);

  auto blur = [&](unsigned program, int target, unsigned input, int dx, int dy, Rect r) {
    start(target, program == blur_thickness_ ? 0.f : 1.f, true, r);
    glUseProgram(program);
    glUniform2i(at(program, "u_direction"), dx, dy);
    glUniform1i(at(program, "u_taps"), taps);
    glUniform1f(at(program, "u_texel"), 1.f / size[dx ? 0 : 1]);
    glUniform1f(at(program, "u_scale"), look.blur_scale);
    glUniform1f(at(program, "u_falloff"), look.blur_falloff);
    glUniform1f(at(program, "u_near"), z_near);
    glUniform1f(at(program, "u_far"), z_far);
    bind_input(0, input);
    full_screen(program);
  };
  // 2, 3: depth blurred across then along.
  blur(blur_depth_, kBlurDepthAcross, targets_[kDepth].depth, 1, 0, sprites_);
  blur(blur_depth_, kBlurDepthAlong, targets_[kBlurDepthAcross].depth, 0, 1, sprites_);
  // 4: normals (the inverse projection as is).
  start(kNormals, 1.f, false, sprites_);
  glUseProgram(normals_);
  glUniform2fv(at(normals_, "u_size"), 1, size);
  glUniformMatrix4fv(at(normals_, "u_inv_proj"), 1, GL_FALSE, inv_proj.data());
  bind_input(0, targets_[kBlurDepthAlong].depth);
  full_screen(normals_);
  // 5, 6: thickness blurred across then along.
  blur(blur_thickness_, kBlurThicknessAcross, targets_[kThickness].color, 1, 0, across);
  blur(blur_thickness_, kBlurThicknessAlong, targets_[kBlurThicknessAcross].color, 0, 1, along);
  // 7: shading (SOFA hands this pass the inverse projection transposed).
  start(kShade, 1.f, false, sprites_);
  glUseProgram(shade_);
  glUniformMatrix4fv(at(shade_, "u_inv_proj"), 1, GL_TRUE, inv_proj.data());
  glUniform4fv(at(shade_, "u_color"), 1, look.color.data());
  bind_input(0, targets_[kNormals].color);
  bind_input(1, targets_[kBlurDepthAlong].depth);
  bind_input(2, targets_[kBlurThicknessAlong].color);
  full_screen(shade_);
  for (int slot = 0; slot < 3; ++slot) bind_input(slot, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(0);
  return true;
}

void FluidSurface::draw_debug(unsigned debug) {
  if (width_ == 0 || debug >= kShade) return;
  // What SOFA binds for each debugFBO: the depth pass shows its depth texture, the others their colour.
  const bool depth = debug == kDepth;
  const Target& t = targets_[debug];
  glDisable(GL_DEPTH_TEST);
  glUseProgram(show_);
  glUniform1i(at(show_, "u_depth"), depth ? 1 : 0);
  bind_input(0, depth ? t.depth : t.color);
  full_screen(show_);
  bind_input(0, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(0);
  glEnable(GL_DEPTH_TEST);
}

void FluidSurface::composite(int x, int y) {
  if (width_ == 0) return;
  glEnable(GL_SCISSOR_TEST);
  scissor_to(Rect{x + sprites_.x0, y + sprites_.y0, x + sprites_.x1, y + sprites_.y1});
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  bind_input(0, targets_[kShade].color);
  bind_input(1, targets_[kShade].depth);
  full_screen(over_);
  bind_input(0, 0);
  bind_input(1, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace sinew::render
