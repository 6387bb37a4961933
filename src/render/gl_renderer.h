// Draws a DrawList into an off-screen framebuffer and reads the picture back.
//
// OpenGL 3.3 core profile (GLSL 3.30): one program, headlight Phong shading (a white
// light at the eye, two-sided, as OglModel's default lighting), per-batch vertex arrays.
// Buffers are kept between frames and only grown, so once the scene's sizes are
// stable a frame allocates nothing (glBufferSubData into the existing storage).
// Multisampled (4× by default) into a renderbuffer, resolved before reading.
// The GL context must be current.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/camera_view.h"
#include "render/draw_list.h"
#include "render/image.h"

namespace sinew::render {

struct LightView;
class SceneShaders;
class FluidSurface;

class GlRenderer {
 public:
  // nullptr and *error when the framebuffer or the program cannot be made.
  static std::unique_ptr<GlRenderer> create(int width, int height, int samples, std::string* error);
  ~GlRenderer();

  void draw(const DrawList& list, const View& view, const std::array<float, 4>& background);
  // The last drawn picture, top row first.
  void read(Image& out);
  // New picture size (the viewer's window was resized); buffers of the batches are kept.
  bool resize(int width, int height, std::string* error);
  // Copies the last drawn picture into the window's framebuffer (0), width × height pixels.
  void present(int width, int height);
  // SOFA's ASCII font texture (render/draw_text.h kFontFile); without it texts are not drawn
  // (one message on stderr).
  void set_font(const std::string& path) { font_ = path; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  GlRenderer() = default;
  bool allocate(int width, int height, std::string* error);
  void release_framebuffers();
  struct GpuBatch {
    unsigned vao = 0, vbo[4] = {0, 0, 0, 0}, ebo = 0;
    std::size_t capacity[5] = {0, 0, 0, 0, 0};  // bytes: positions, normals, colours, indices, texcoords
    std::vector<unsigned> attribute_vbo;  // a scene shader's per-vertex attributes
    std::vector<std::size_t> attribute_capacity;
    unsigned quad_ebo = 0;  // Batch::quad_indices (made at first use)
    std::size_t quad_capacity = 0;
  };
  int width_ = 0, height_ = 0, samples_ = 0;
  unsigned fbo_ = 0, color_rb_ = 0, depth_rb_ = 0, resolve_fbo_ = 0, resolve_rb_ = 0;
  unsigned program_ = 0;
  int u_view_ = -1, u_proj_ = -1, u_ambient_ = -1, u_specular_ = -1, u_emissive_ = -1, u_shininess_ = -1,
      u_lit_ = -1, u_color_ambient_ = -1, u_point_size_ = -1, u_clip_ = -1, u_textured_ = -1,
      u_translucent_ = -1, u_splat_ = -1, u_splat_alpha_ = -1, u_splat_radius_ = -1, u_half_height_ = -1,
      u_nlights_ = -1, u_scene_lights_ = -1, u_global_ambient_ = -1, u_light_pos_ = -1, u_light_color_ = -1, u_light_spot_ = -1,
      u_light_cos_ = -1, u_light_exp_ = -1, u_light_att_ = -1;
  std::vector<GpuBatch> gpu_;
  // The models seen through `view` in the rectangle (x, y, width, height) of the picture
  // (pixels from the bottom-left): opaque, then translucent.
  // `shadow_maps`: draw the lights' shadow maps first (once per picture).
  void draw_pass(const DrawList& list, const View& view, int x, int y, int width, int height, bool shadow_maps);
  // Uploads `b` into `g` and draws it (`upload` false: drawn again from what was uploaded,
  // the second pass of a translucent model).
  void draw_batch(const Batch& b, GpuBatch& g, bool upload = true);
  void set_line_width(float w);
  // A shaded model's elements as its primitiveType asks (Batch::Primitive); its vertex array
  // and program bound.
  static void draw_shaded_elements(const Batch& b, GpuBatch& g);
  float line_width_range_[2] = {0.f, 0.f};  // GL_ALIASED_LINE_WIDTH_RANGE, read once
  // OglModel's alphaBlend, depthTest and cullFace set before a draw of `b`, and undone after.
  static void begin_model_state(const Batch& b);
  static void end_model_state(const Batch& b);
  // order_: the points of `b` from the farthest to the nearest under view_.
  void sort_back_to_front(const Batch& b);
  // OglSceneFrame's axes in their corner viewport, over the scene.
  void draw_scene_frame(const SceneFrame& f, const View& view);
  Batch frame_batch_;
  int frame_style_ = -1;
  std::unique_ptr<GpuBatch> frame_gpu_;
  // Shadows of SOFA's shadow-mapping shaders (render/shadow_maps.h): each spot or directional
  // light's map rendered from the light when the LightManager asks for shadows, and the
  // uniforms of the shading; nothing when no model is under an OglShadowShader.
  struct ShadowMap {
    unsigned fbo = 0, texture = 0, depth = 0;
    int size = 0;
  };
  void set_shadows(const DrawList& list, const View& view, bool render_maps);
  bool shadow_map(int i, int size);  // map i made (or resized) to size × size
  void render_shadow_map(const DrawList& list, const LightView& lv, ShadowMap& m);
  unsigned shadow_program_ = 0;
  int u_sofa_shadow_ = -1;
  ShadowMap shadow_maps_[8];
  bool shadow_warned_ = false;
  // OrderIndependentTransparencyManager (list.oit): the translucent triangle batches
  // accumulated into float targets over the opaque depth, then composed over the picture
  // in the rectangle (x, y, width, height). Float targets made at first use, at the
  // picture's size (none: blended in drawing order, one message).
  static bool oit_batch(const Batch& b);
  void draw_oit(const DrawList& list, int x, int y, int width, int height);
  bool oit_buffers();
  static constexpr int kOitUnit = 9;  // texture units 9 and 10 (0: models, 1-8: shadow maps)
  unsigned oit_fbo_ = 0, oit_textures_[2] = {0, 0}, oit_depth_rb_ = 0, oit_program_ = 0, oit_vao_ = 0;
  int u_oit_ = -1, u_oit_depth_scale_ = -1;
  bool oit_warned_ = false;
  // PostProcessManager (list.post): the scene drawn into a picture of colour and depth
  // textures (post_fbo_, single-sampled, made at first use at the picture's size) through the
  // manager's projection, then the picture covered by the manager's shader reading them.
  bool post_buffers();
  static Eigen::Matrix4f post_projection(const PostProcess& p);
  void draw_post(const DrawList& list);
  static constexpr int kPostUnit = 26;  // units 26 and 27: colour and depth (past the scene shaders')
  unsigned post_fbo_ = 0, post_textures_[2] = {0, 0}, post_vao_ = 0, post_vbo_ = 0;
  bool post_failed_ = false;
  // The framebuffer a pass draws into: the picture's, or the post-process pass's.
  unsigned pass_fbo_ = 0;
  // OglFluidModel's surfaces (render/fluid_surface.h), one per fluid batch of each pass of a
  // picture (the main view, then each OglViewport: each keeps targets of its own size): the
  // k-th surface rendered for batch `b` into its targets, and its debugFBO view drawn, for the
  // rectangle (x, y, width, height); the translucent pass lays it over the picture.
  void draw_fluid(const Batch& b, GpuBatch& g, std::size_t k, const View& view, int x, int y, int width, int height);
  std::vector<std::unique_ptr<FluidSurface>> fluids_;
  std::size_t pass_fluids_ = 0;  // surfaces used by the picture's earlier passes
  // BackgroundSetting's image over the rectangle (x, y, width, height), under the scene.
  void draw_background_image(const std::string& file, int x, int y, int width, int height);
  unsigned background_program_ = 0;
  // The list's texts over the models (depth-tested ones first), blended, alpha kept.
  void draw_texts(const DrawList& list, const View& view);
  unsigned text_program_ = 0, text_vao_ = 0, text_vbo_ = 0;
  std::size_t text_capacity_ = 0;
  std::vector<float> text_vertices_;
  std::string font_;
  bool font_warned_ = false;
  // Scene shaders (OglShader, render/scene_shader.h) for the batches under one; the list and
  // view of the pass being drawn, which they read.
  std::unique_ptr<SceneShaders> scene_shaders_;
  const DrawList* pass_list_ = nullptr;
  View pass_view_;
  // The scene's lights as uniforms, in eye space (none: the shader's headlight).
  void set_lights(const Lighting& l, const View& view);
  Eigen::Matrix4f view_ = Eigen::Matrix4f::Identity();
  std::vector<float> depth_;
  std::vector<unsigned> order_;
  // Textures by file, loaded at first use (id 0: the file could not be read; drawn untextured).
  unsigned texture_for(const std::string& path);
  std::vector<std::pair<std::string, unsigned>> textures_;
  std::vector<std::uint8_t> rows_;  // read-back, bottom row first
};

}  // namespace sinew::render
