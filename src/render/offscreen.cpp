#include "render/offscreen.h"

#include "core/node.h"
#include "render/material.h"
#include "visual/background_setting.h"
#include "render/gl_context.h"
#include "render/gl_renderer.h"

namespace sinew::render {

std::unique_ptr<OffscreenRenderer> OffscreenRenderer::create(const RenderOptions& options, std::string* error) {
  if (options.width <= 0 || options.height <= 0 || options.width > 16384 || options.height > 16384) {
    if (error) *error = "invalid picture size " + std::to_string(options.width) + "x" + std::to_string(options.height);
    return nullptr;
  }
  std::unique_ptr<OffscreenRenderer> r(new OffscreenRenderer);
  r->options_ = options;
  r->context_ = GlContext::create(error);
  if (!r->context_) return nullptr;
  r->gl_ = GlRenderer::create(options.width, options.height, options.samples, error);
  if (!r->gl_) return nullptr;
  return r;
}

OffscreenRenderer::~OffscreenRenderer() {
  // GL objects go while their context is current, then the context.
  if (context_) context_->make_current();
  gl_.reset();
  context_.reset();
}

void OffscreenRenderer::set_font(const std::string& path) { gl_->set_font(path); }

const std::string& OffscreenRenderer::gl_description() const { return context_->description(); }

namespace {
bool nothing_visible(const DrawList& list, std::string* error) {
  if (list.used > 0 && list.has_bounds) return false;
  if (error)
    *error = "nothing is visible: the scene has no visual model (OglModel) and its VisualStyle shows no "
             "behaviour model or force field";
  return true;
}
}  // namespace

bool OffscreenRenderer::frame(Node& root, std::string* error) {
  gather(root, list_);
  if (nothing_visible(list_, error)) return false;
  framed_ = true;
  framed_min_ = list_.min, framed_max_ = list_.max;
  return true;
}

bool OffscreenRenderer::render(Node& root, Image& out, std::string* error) {
  gather(root, list_);
  if (nothing_visible(list_, error)) return false;
  Vec3 min = framed_ ? framed_min_ : list_.min, max = framed_ ? framed_max_ : list_.max;
  // The root's bbox (SOFA's fixed bounding box), when given as min then max.
  if (const auto& b = root.bbox.get(); b.size() == 6 && b[0] <= b[3] && b[1] <= b[4] && b[2] <= b[5])
    min = Vec3(b[0], b[1], b[2]), max = Vec3(b[3], b[4], b[5]);
  if (min == max) {  // a single point: frame a unit box around it
    min -= Vec3::Constant(0.5);
    max += Vec3::Constant(0.5);
  }
  view_ = view_for(root, min, max, options_.width, options_.height);
  if (!context_->make_current()) {
    if (error) *error = "the off-screen OpenGL context cannot be made current";
    return false;
  }
  // The scene's BackgroundSetting colour, else the options' background.
  std::array<float, 4> background = options_.background;
  if (const auto* bg = root.find_down<BackgroundSetting>())
    if (auto c = parse_color(bg->color.get())) background = {(*c)[0], (*c)[1], (*c)[2], 1.f};
  gl_->draw(list_, view_, background);
  gl_->read(out);
  return true;
}

}  // namespace sinew::render
