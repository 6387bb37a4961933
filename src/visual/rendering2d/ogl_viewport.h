// OglViewport (SOFA's Sofa.GL.Component.Rendering2D): the scene drawn again from a fixed camera
// in a rectangle of the picture (src/render: render/camera_view.h viewport_view). The camera is
// `cameraRigid` when given (or linked), else `cameraPosition` and `cameraOrientation`; as in
// SOFA, the orientation is the rotation applied to the scene (world to camera), and a zero zNear
// or zFar fits both to the scene's box.
#pragma once

#include "core/roles.h"

namespace sinew {

class OglViewport final : public VisualComponent {
 public:
  Field<VecNi<2>> screen_position{this, "screenPosition", VecNi<2>::Zero(),
                                  "lower-left corner of the view in pixels (negative: from the right or top)",
                                  "Visualization"};
  Field<VecNi<2>> screen_size{this, "screenSize", VecNi<2>::Zero(), "size of the view in pixels", "Visualization"};
  Field<Vec3> camera_position{this, "cameraPosition", Vec3::Zero(), "camera position", "Visualization", "length"};
  Field<VecN<4>> camera_orientation{this, "cameraOrientation", VecN<4>(0, 0, 0, 1),
                                    "rotation from the world to the camera (quaternion x y z w)", "Visualization"};
  Field<VecN<7>> camera_rigid{this, "cameraRigid", (VecN<7>() << 0, 0, 0, 0, 0, 0, 1).finished(),
                              "camera position and orientation as one rigid coordinate", "Visualization"};
  Field<double> z_near{this, "zNear", 0.0, "near plane distance (0: from the scene)", "Visualization", "length"};
  Field<double> z_far{this, "zFar", 0.0, "far plane distance (0: from the scene)", "Visualization", "length"};
  Field<double> fovy{this, "fovy", 60.0, "vertical field of view (degrees)", "Visualization"};
  Field<bool> enabled{this, "enabled", true, "show the view", "Visualization"};
  Field<bool> advanced_rendering{this, "advancedRendering", false,
                                 "show the view only when the advancedRendering flag is on", "Visualization"};
  Field<bool> use_fbo{this, "useFBO", true, "render the view into a frame buffer object (same picture)",
                      "Visualization"};
  Field<bool> swap_main_view{this, "swapMainView", false, "swap this view with the main one", "Visualization"};
  Field<bool> draw_camera{this, "drawCamera", false, "draw the view's camera as a frame of size 0.1",
                          "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  // The camera used: cameraRigid when set or linked, else cameraPosition and cameraOrientation.
  void camera(Vec3& position, VecN<4>& orientation) const;
};

}  // namespace sinew
