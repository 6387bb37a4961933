// Rendering passes of a SOFA viewer (Sofa.GL.Component.Shader and
// Rendering2D): PostProcessManager (a full-screen shader after the scene),
// OrderIndependentTransparencyManager (weighted blending of translucent
// models) and OglViewport (an extra view in a corner of the window). Sinew's
// renderer draws one view with its own shading and sorted translucency
// (docs/render.md); these are accepted with their Data and validated.
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

class OglViewport final : public VisualComponent {
 public:
  Field<VecNi<2>> screen_position{this, "screenPosition", VecNi<2>::Zero(), "lower-left corner of the view in pixels",
                                  "Visualization"};
  Field<VecNi<2>> screen_size{this, "screenSize", VecNi<2>::Zero(), "size of the view in pixels", "Visualization"};
  Field<Vec3> camera_position{this, "cameraPosition", Vec3::Zero(), "camera position", "Visualization"};
  Field<VecN<4>> camera_orientation{this, "cameraOrientation", VecN<4>(0, 0, 0, 1),
                                    "camera orientation (quaternion x y z w)", "Visualization"};
  Field<VecN<7>> camera_rigid{this, "cameraRigid", (VecN<7>() << 0, 0, 0, 0, 0, 0, 1).finished(),
                              "camera position and orientation as one rigid coordinate", "Visualization"};
  Field<double> z_near{this, "zNear", 0.0, "near plane distance (0: from the scene)", "Visualization"};
  Field<double> z_far{this, "zFar", 0.0, "far plane distance (0: from the scene)", "Visualization"};
  Field<double> fovy{this, "fovy", 60.0, "vertical field of view (degrees)", "Visualization"};
  Field<bool> enabled{this, "enabled", true, "show the view", "Visualization"};
  Field<bool> advanced_rendering{this, "advancedRendering", false,
                                 "show the view only when the advancedRendering flag is on", "Visualization"};
  Field<bool> use_fbo{this, "useFBO", true, "render the view into a frame buffer object", "Visualization"};
  Field<bool> swap_main_view{this, "swapMainView", false, "swap this view with the main one", "Visualization"};
  Field<bool> draw_camera{this, "drawCamera", false, "draw the view's camera in the main view", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    const VecNi<2>& s = screen_size.value();
    if (s[0] < 0 || s[1] < 0)
      diag.error(where, describe() + ": screenSize must not be negative (" + std::to_string(s[0]) + " " +
                            std::to_string(s[1]) + ")");
    if (!(fovy.value() > 0.0 && fovy.value() < 180.0))
      diag.error(where, describe() + ": fovy must be in (0, 180) degrees");
  }
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
  add<OglViewport>(r, "OglViewport", "additional view drawn in a corner of the viewer");
}

}  // namespace sinew
