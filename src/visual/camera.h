// Scene cameras: InteractiveCamera, Camera and RecordedCamera share SOFA's
// BaseCamera data (Sofa/Component/Visual/.../BaseCamera.cpp): position,
// orientation (quaternion x y z w), lookAt, distance, fieldOfView (vertical,
// degrees), zNear/zFar (or computed from the scene's bounding box), projection
// type. init() completes the missing ones as SOFA does; when too few are given
// the viewer frames the scene (SOFA's setDefaultView). No drawing here: the
// renderer (src/render) reads the resolved view.
#pragma once

#include "core/roles.h"

namespace sinew {

class BaseCamera : public VisualComponent {
 public:
  Field<Vec3> position{this, "position", Vec3::Zero(), "camera position", "Camera", "length"};
  Field<VecN<4>> orientation{this, "orientation", VecN<4>(0, 0, 0, 1), "camera orientation (quaternion x y z w)",
                             "Camera"};
  Field<Vec3> look_at{this, "lookAt", Vec3::Zero(), "point the camera looks at", "Camera", "length"};
  Field<double> distance{this, "distance", 0.0, "distance between the camera and lookAt", "Camera", "length"};
  Field<double> field_of_view{this, "fieldOfView", 45.0, "vertical field of view", "Camera", "degrees"};
  Field<double> z_near{this, "zNear", 0.01, "near clipping plane", "Camera", "length"};
  Field<double> z_far{this, "zFar", 100.0, "far clipping plane", "Camera", "length"};
  Field<bool> compute_z_clip{this, "computeZClip", true, "compute zNear and zFar from the bounding box", "Camera"};
  Field<Vec3> min_bbox{this, "minBBox", Vec3::Zero(), "scene bounding box (minimum)", "Camera", "length"};
  Field<Vec3> max_bbox{this, "maxBBox", Vec3::Ones(), "scene bounding box (maximum)", "Camera", "length"};
  Field<unsigned> width_viewport{this, "widthViewport", 800, "viewport width", "Camera"};
  Field<unsigned> height_viewport{this, "heightViewport", 600, "viewport height", "Camera"};
  Field<std::string> projection_type{this, "projectionType", "Perspective",
                                     "Perspective (0) or Orthographic (1)", "Camera"};
  Field<bool> activated{this, "activated", true, "camera in use", "Camera"};
  Field<bool> fixed_look_at{this, "fixedLookAt", false, "keep the lookAt point fixed", "Camera"};

  void init() override;
  // SOFA's b_setDefaultParameters: position/orientation/lookAt were not enough to place the
  // camera, so the viewer frames the scene along −gravity as up.
  bool wants_default_view() const { return default_view_; }
  bool orthographic() const;

 private:
  bool default_view_ = false;
};

class InteractiveCamera final : public BaseCamera {
 public:
  Field<double> zoom_speed{this, "zoomSpeed", 250.0, "zoom speed of the mouse", "Camera"};
  Field<double> pan_speed{this, "panSpeed", 0.1, "pan speed of the mouse", "Camera"};
  Field<int> pivot{this, "pivot", 2, "rotation pivot: 0 lookAt, 1 camera, 2 scene centre, 3 world centre", "Camera"};
};

// Quaternion (x y z w) whose rotation has columns x, y, z (SOFA's createQuaterFromFrame).
VecN<4> quat_from_frame(const Vec3& x, const Vec3& y, const Vec3& z);
// The rotation of a quaternion (x y z w), normalised.
Mat3 quat_matrix(const VecN<4>& q);

}  // namespace sinew
