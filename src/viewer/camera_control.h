// The viewer's camera under the mouse, as the scene camera's own event handling moves it
// (SofaGLFW hands the mouse to the camera; spec/user-interfaces.md §3.4): left-drag turns
// SOFA's trackball around the pivot, right-drag pans, middle-drag and the wheel zoom along the
// view. InteractiveCamera's law (also the viewer's own camera when the scene has none) scales
// zooms and pans by the scene's radius, RecordedCamera's does not; a plain Camera ignores the
// mouse, as SOFA's does.
//
// Pure geometry, no OpenGL: positions in pixels from the window's top-left corner, truncated
// to whole pixels as SofaGLFW passes them.
#pragma once

#include "render/camera_view.h"

namespace sinew {
class Node;
}

namespace sinew::viewer {

// The camera Data the mouse reads.
struct Navigation {
  enum class Law { interactive, recorded, none };
  Law law = Law::interactive;
  double zoom_speed = 250.0;  // zoomSpeed
  double pan_speed = 0.1;     // panSpeed
  // InteractiveCamera: 0 the point looked at, 1 the camera, 2 the scene's centre, 3 the world's
  // origin; RecordedCamera: 1 the world's origin, else the scene's centre.
  int pivot = 2;
  bool fixed_look_at = false;  // fixedLookAt: the point looked at stays where it is
};

// The navigation of the scene's first active camera (the defaults without one).
Navigation navigation_of(const Node& root);

class CameraControl {
 public:
  enum class Mode { none, trackball, pan, zoom };

  // Starts from `frame` (the scene's camera or SOFA's default view).
  void reset(const render::CameraFrame& frame, const Navigation& navigation = {});
  // The scene's box (SofaGLFW gives it to the camera every frame): its centre is the scene
  // pivot, half its diagonal the scene radius that scales InteractiveCamera's zooms and pans.
  void set_scene_box(const Vec3& min, const Vec3& max);

  // A button pressed at pixel (x, y): `mode` until release.
  void press(Mode mode, double x, double y);
  // The cursor at (x, y) of a width × height window.
  void move(double x, double y, int width, int height);
  void release() { mode_ = Mode::none; }
  // The wheel turned by `offset` notches (GLFW's y offset; SofaGLFW sends int(10 · offset)).
  void wheel(double offset, int height);

  const render::CameraFrame& frame() const { return frame_; }
  const Navigation& navigation() const { return nav_; }
  // The point the trackball turns around now.
  Vec3 pivot() const { return pivot_of(frame_); }

 private:
  Vec3 pivot_of(const render::CameraFrame& f) const;
  void translate(const Vec3& t, bool look_at_too);
  void zoom_by(double distance, double step);
  render::CameraFrame frame_;
  Navigation nav_;
  Vec3 centre_ = Vec3::Zero();
  double radius_ = 1.0;
  Mode mode_ = Mode::none;
  int last_x_ = 0, last_y_ = 0;
  render::CameraFrame start_;  // the frame at the press (InteractiveCamera's trackball)
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
