// Off-screen pictures of a scene: `sinew render` and the render tests.
//
//   std::string err;
//   auto r = render::OffscreenRenderer::create(800, 600, &err);  // nullptr: no GL here
//   render::Image img;
//   if (r && r->render(root, img, &err)) render::write_png("out.png", img, &err);
//
// One renderer keeps its context, framebuffer, buffers and draw list between
// pictures: rendering the same scene again allocates nothing.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "render/camera_view.h"
#include "render/draw_list.h"
#include "render/image.h"

namespace sinew {
class Node;
}

namespace sinew::render {

class GlContext;
class GlRenderer;

struct RenderOptions {
  int width = 800, height = 600;
  int samples = 4;  // multisampling (0: none)
  std::array<float, 4> background{0.f, 0.f, 0.f, 1.f};  // SofaGLFW's default: black
};

class OffscreenRenderer {
 public:
  static std::unique_ptr<OffscreenRenderer> create(const RenderOptions& options, std::string* error);
  ~OffscreenRenderer();

  // Draws what `root` shows into `out`. False with *error when nothing is visible
  // (no visual model, and no behaviour or force field shown by the display flags).
  bool render(Node& root, Image& out, std::string* error);

  // Fixes the bounding box the default view frames to what `root` shows now (a viewer frames
  // the scene once, when it is loaded, so a moving body moves in the picture); without it,
  // every picture frames what it shows. No effect on a scene camera's view, except its clip planes.
  bool frame(Node& root, std::string* error);

  // SOFA's ASCII font texture for the scene's texts (render/draw_text.h kFontFile).
  void set_font(const std::string& path);
  const DrawList& draw_list() const { return list_; }
  const View& view() const { return view_; }
  // "OpenGL <version> on <renderer>".
  const std::string& gl_description() const;

 private:
  OffscreenRenderer() = default;
  RenderOptions options_;
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<GlRenderer> gl_;
  DrawList list_;
  View view_;
  bool framed_ = false;
  Vec3 framed_min_ = Vec3::Zero(), framed_max_ = Vec3::Zero();
};

}  // namespace sinew::render
