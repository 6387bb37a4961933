// The view of a picture: the scene's camera (InteractiveCamera, Camera, RecordedCamera:
// position, orientation, fieldOfView, zNear/zFar or SOFA's computeZ), else SOFA's default
// view (BaseCamera::setDefaultView): looking at the centre of the bounding box, up = −gravity
// (y when there is none), from 3 half-diagonals away along the frame's z (runSofa's front
// view, along −z for a gravity along −y), 45° vertical field of view.
#pragma once

#include <Eigen/Core>

#include "core/roles.h"
#include "render/draw_list.h"

namespace sinew {
class BaseCamera;
class Node;
}

namespace sinew::render {

struct View {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();        // world → eye
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();  // eye → clip
  Vec3 eye = Vec3::Zero();
  bool from_scene_camera = false;
};

// Where a camera is and how it projects: the rigid frame (it looks along −z of `rotation`),
// the vertical field of view, and the point it looks at.
struct CameraFrame {
  Vec3 position = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();  // columns: the camera's x, y, z in the world
  double fov_deg = 45.0;
  bool ortho = false;
  Vec3 look_at = Vec3::Zero();
};

// The scene's first active camera, depth-first (no allocation: called every frame); null
// without one.
const BaseCamera* find_camera(const Node& root);

// The frame of the scene's first active camera, else SOFA's default view of [min, max]
// (with the camera's field of view and projection type when it asks for the default view).
// *from_scene (optional) tells which.
CameraFrame camera_frame(const Node& root, const Vec3& min, const Vec3& max, bool* from_scene = nullptr);

// The view of `frame`: clip planes from the scene camera (or computed from [min, max]
// as BaseCamera::computeZ does), projection for a width × height picture.
View view_of(const CameraFrame& frame, const Node& root, const Vec3& min, const Vec3& max, int width, int height);

// The view of an OglViewport (OglViewport::renderToViewport): world → eye = R(orientation)·(p −
// position); with zNear or zFar 0, both from the scene box's corners at R·p − position (SOFA's
// Transformation; the same for an identity orientation): near ≤ 0 → 1, far ≥ 1000 → 1000, else
// ×0.8 and ×1.2, near ≥ far/100 and 0.1, far ≥ 2; perspective of `fovy` and the rectangle's aspect.
View viewport_view(const ExtraViewport& v, const Vec3& min, const Vec3& max, double aspect);

// `min`/`max`: the scene's bounding box (the root's `bbox` when set, else what is drawn).
View view_for(const Node& root, const Vec3& min, const Vec3& max, int width, int height);

}  // namespace sinew::render
