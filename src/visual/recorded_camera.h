// RecordedCamera (SOFA's Sofa.Component.Visual): a camera moved by the simulation's time along a
// scripted path, from `startTime` to `endTime` (a span of 0 counts as 200):
// - rotationMode: around `rotationAxis` through `rotationCenter`, starting at
//   `rotationStartPoint`, one turn over the span, looking at `rotationLookAt`;
// - translationMode: along `cameraPositions`, each segment in an equal share of the span (the
//   path repeats), looking at the segment's end;
// - navigationMode: along `cameraPositions` with `cameraOrientations` slerped.
// The camera is moved at each AnimateBeginEvent whose time reached the next step (SOFA's
// m_nextStep), and put back by a reset; the renderer reads the moved BaseCamera Data.
// `drawRotation` draws the rotation's circle and four lines to the point looked at,
// `drawTranslation` the segments between the cameraPositions (src/render). The viewer moves it
// under the mouse by its own law (zoomSpeed, panSpeed, pivot: viewer/camera_control.h).
#pragma once

#include <vector>

#include "visual/camera.h"

namespace sinew {

class RecordedCamera final : public BaseCamera {
 public:
  RecordedCamera() { listening.set(true); }

  Field<double> zoom_speed{this, "zoomSpeed", 250.0, "zoom speed of the mouse", "Camera"};
  Field<double> pan_speed{this, "panSpeed", 0.1, "pan speed of the mouse", "Camera"};
  Field<int> pivot{this, "pivot", 0, "rotation pivot of the mouse: 0 scene centre, 1 world centre", "Camera"};
  Field<double> start_time{this, "startTime", 0.0, "time the path starts", "Camera", "time"};
  Field<double> end_time{this, "endTime", 200.0, "time the path ends (or loops)", "Camera", "time"};
  Field<bool> rotation_mode{this, "rotationMode", false, "turn around rotationCenter", "Camera"};
  Field<bool> translation_mode{this, "translationMode", false, "follow cameraPositions", "Camera"};
  Field<bool> navigation_mode{this, "navigationMode", false, "follow cameraPositions and cameraOrientations",
                              "Camera"};
  Field<double> rotation_speed{this, "rotationSpeed", 0.1, "rotation speed (unused by SOFA's path)", "Camera"};
  Field<Vec3> rotation_center{this, "rotationCenter", Vec3(0, 10, 0), "centre of the rotation", "Camera", "length"};
  Field<Vec3> rotation_start_point{this, "rotationStartPoint", Vec3(0, 10, 50), "where the rotation starts",
                                   "Camera", "length"};
  Field<Vec3> rotation_look_at{this, "rotationLookAt", Vec3::Zero(), "point looked at during the rotation",
                               "Camera", "length"};
  Field<Vec3> rotation_axis{this, "rotationAxis", Vec3(0, 1, 0), "axis of the rotation", "Camera"};
  Field<Vec3> camera_up{this, "cameraUp", Vec3::Zero(), "up direction of the camera (0: chosen)", "Camera"};
  Field<bool> draw_rotation{this, "drawRotation", false, "draw the rotation's path", "Camera"};
  Field<bool> draw_translation{this, "drawTranslation", false, "draw the translation's path", "Camera"};
  Field<std::vector<Vec3>> camera_positions{this, "cameraPositions", {}, "the path's positions", "Camera",
                                            "length"};
  Field<std::vector<VecN<4>>> camera_orientations{this, "cameraOrientations", {},
                                                  "the path's orientations (quaternions x y z w)", "Camera"};

  void init() override;
  void reset() override;
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;

  // The rotation's path (100 points of the circle), drawn with drawRotation.
  std::vector<Vec3> rotation_path() const;

 private:
  void configure_rotation();
  void configure_translation();
  void configure_navigation();
  void move_rotation(double time);
  void move_translation(double time);
  void move_navigation(double time);
  void initialize_view_up();
  double span() const;
  double next_step_ = 0;
  bool first_rotation_ = true, first_translation_ = true, first_navigation_ = true;
};

}  // namespace sinew
