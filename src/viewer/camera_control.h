// The viewer's camera under the mouse (SOFA's InteractiveCamera): left-drag turns a
// virtual trackball around the pivot, right-drag pans, middle-drag and the wheel zoom
// towards the point looked at (spec/user-interfaces.md §3.4).
//
// Pure geometry, no OpenGL: positions in pixels from the window's top-left corner.
#pragma once

#include "render/camera_view.h"

namespace sinew::viewer {

class CameraControl {
 public:
  // Starts from `frame` (the scene's camera or SOFA's default view); `pivot` is the point
  // the trackball turns around (SOFA's default pivot: the scene's centre).
  void reset(const render::CameraFrame& frame, const Vec3& pivot);

  // Trackball from pixel (x0, y0) to (x1, y1) in a width × height window.
  void rotate(double x0, double y0, double x1, double y1, int width, int height);
  // Moves the camera so that the plane through the pivot follows the cursor.
  void pan(double dx, double dy, int width, int height);
  // Towards the point looked at by a factor 0.9 per step (negative: away).
  void zoom(double steps);

  const render::CameraFrame& frame() const { return frame_; }
  const Vec3& pivot() const { return pivot_; }

 private:
  render::CameraFrame frame_;
  Vec3 pivot_ = Vec3::Zero();
};

// A ray in the world: origin on the near plane, unit direction.
struct Ray {
  Vec3 origin = Vec3::Zero();
  Vec3 dir = Vec3(0, 0, -1);
};

// The ray under pixel (x, y) of a width × height window drawn with `view`.
Ray ray_through(const render::View& view, double x, double y, int width, int height);

// Pixel position of world point `p` (false when behind the camera).
bool project(const render::View& view, const Vec3& p, int width, int height, double& x, double& y);

}  // namespace sinew::viewer
