// The view of a picture: the scene's camera (InteractiveCamera, Camera, RecordedCamera:
// position, orientation, fieldOfView, zNear/zFar or SOFA's computeZ), else SOFA's default
// view (BaseCamera::setDefaultView): looking at the centre of the bounding box, up = −gravity
// (y when there is none), from 3 half-diagonals away along the frame's z (runSofa's front
// view, along −z for a gravity along −y), 45° vertical field of view.
#pragma once

#include <Eigen/Core>

#include "core/roles.h"

namespace sinew {
class Node;
}

namespace sinew::render {

struct View {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();        // world → eye
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();  // eye → clip
  Vec3 eye = Vec3::Zero();
  bool from_scene_camera = false;
};

// `min`/`max`: the scene's bounding box (the root's `bbox` when set, else what is drawn).
View view_for(const Node& root, const Vec3& min, const Vec3& max, int width, int height);

}  // namespace sinew::render
