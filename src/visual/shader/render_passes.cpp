// Rendering passes of a SOFA viewer (Sofa.GL.Component.Shader): PostProcessManager (a
// full-screen shader after the scene) and OrderIndependentTransparencyManager (weighted
// blending of translucent models). Sinew's renderer keeps its own shading and blends
// translucent models in drawing order (docs/render.md); these are accepted with their Data
// and validated.
#include "core/registry.h"
#include "core/roles.h"

namespace sinew {

namespace {

class PostProcessManager final : public VisualComponent {
 public:
  Field<double> z_near{this, "zNear", 1.0, "near distance used to read the depth buffer", "Visualization"};
  Field<double> z_far{this, "zFar", 100.0, "far distance used to read the depth buffer", "Visualization"};
  void init() override {
    if (!(z_near.value() > 0.0) || !(z_far.value() > z_near.value()))
      msg_warning("zNear and zFar should satisfy 0 < zNear < zFar (" + std::to_string(z_near.value()) + ", " +
                  std::to_string(z_far.value()) + ")");
  }
};

class OrderIndependentTransparencyManager final : public VisualComponent {
 public:
  Field<double> depth_scale{this, "depthScale", 0.01, "depth scale of the blending weights", "Visualization"};
};

template <class C>
void add(Registry& r, const char* name, const char* what) {
  ComponentInfo info;
  info.name = name;
  info.category = "Visual";
  info.description = std::string(what) + " (viewer only; no effect in batch runs)";
  info.create = creator<C>();
  r.add(std::move(info));
}

}  // namespace

void register_render_passes(Registry& r) {
  add<PostProcessManager>(r, "PostProcessManager", "full-screen shader pass after the scene");
  add<OrderIndependentTransparencyManager>(r, "OrderIndependentTransparencyManager",
                                           "order-independent transparency of translucent models");
}

}  // namespace sinew
