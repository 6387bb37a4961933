// Rendering passes of a SOFA viewer (Sofa.GL.Component.Shader): PostProcessManager (a
// full-screen shader over the scene's picture) and OrderIndependentTransparencyManager
// (weighted blending of translucent models); both drawn by src/render (docs/render.md).
#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"
#include "visual/shader/ogl_shader.h"
#include "visual/shader/order_independent_transparency.h"
#include "visual/shader/post_process_manager.h"

namespace sinew {

namespace {

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

void PostProcessManager::init() {
  if (!(z_near.value() > 0.0) || !(z_far.value() > z_near.value()))
    msg_warning("zNear and zFar should satisfy 0 < zNear < zFar (" + std::to_string(z_near.value()) + ", " +
                std::to_string(z_far.value()) + ")");
  // SOFA's getContext()->get<OglShader>(): the manager's node, then its ancestors.
  shader_ = node() ? node()->find_up<OglShader>() : nullptr;
  if (!shader_) msg_warning("no OglShader in this node or above: no post-process pass is applied");
  if (node() && !node()->parents().empty())
    msg_warning("not in the root node: SOFA's visual loop asks only the root node's managers to draw, so no "
                "post-process pass is applied");
}

void OrderIndependentTransparencyManager::init() {
  if (!(depth_scale.value() > 0.0))
    msg_warning("depthScale should be positive (got " + std::to_string(depth_scale.value()) + ")");
  if (node() && !node()->parents().empty())
    msg_warning("not in the root node: SOFA's visual loop asks only the root node's managers to draw, so "
                "translucent models are blended in drawing order");
}

void register_render_passes(Registry& r) {
  add<PostProcessManager>(r, "PostProcessManager", "full-screen shader pass over the scene's picture");
  ComponentInfo info;
  info.name = "OrderIndependentTransparencyManager";
  info.category = "Visual";
  info.description = "order-independent transparency of the translucent visual models (viewer only)";
  info.create = creator<OrderIndependentTransparencyManager>();
  r.add(std::move(info));
}

}  // namespace sinew
