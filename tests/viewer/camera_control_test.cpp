// The viewer's camera under the mouse, rays through pixels, .view files, input scripts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <Eigen/Geometry>

#include "test_scene.h"
#include "viewer/camera_control.h"
#include "viewer/input_script.h"
#include "viewer/view_file.h"

namespace sinew::viewer {
namespace {

render::CameraFrame front_view(double distance) {
  render::CameraFrame f;
  f.position = Vec3(0, 0, distance);
  f.look_at = Vec3::Zero();
  return f;
}

// Perspective view of `f` for a w × h window (as view_of builds it, without a scene).
render::View view_of_frame(const render::CameraFrame& f, int w, int h) {
  render::View v;
  const Mat3 rt = f.rotation.transpose();
  v.view.setIdentity();
  v.view.topLeftCorner<3, 3>() = rt.cast<float>();
  v.view.topRightCorner<3, 1>() = (-(rt * f.position)).cast<float>();
  const double n = 0.1, far = 100, s = 1.0 / std::tan(f.fov_deg * M_PI / 360.0), aspect = double(w) / h;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = s / aspect, p(1, 1) = s, p(2, 2) = -(far + n) / (far - n), p(2, 3) = -2 * far * n / (far - n);
  p(3, 2) = -1;
  v.projection = p.cast<float>();
  return v;
}

// A camera 10 in front of a scene box [−1, 1]³ (radius √3), InteractiveCamera's law unless said.
CameraControl front_control(const Navigation& nav = {}) {
  CameraControl c;
  c.reset(front_view(10), nav);
  c.set_scene_box(Vec3::Constant(-1), Vec3::Constant(1));
  return c;
}

// SOFA's trackball (InteractiveCamera, from the frame of the press): a 100-pixel drag to the
// right in an 800-pixel-wide window is (0.25, 0) in viewport units; on the sphere of radius 0.8
// the two points are θ = acos(0.8 · √(0.64 − 0.0625) / 0.64) = 0.31782 rad apart, the angle the
// camera turns about the vertical through the scene's centre. The frame stays rigid, still
// looking at its point 10 ahead, and the drag is measured from the press, not summed.
TEST(CameraControl, TrackballIsSofasFromThePress) {
  CameraControl c = front_control();
  c.press(CameraControl::Mode::trackball, 400, 300);
  c.move(600, 300, 800, 600);
  c.move(500, 300, 800, 600);
  const double theta = std::acos(0.8 * std::sqrt(0.64 - 0.0625) / 0.64);
  EXPECT_NEAR(theta, 0.31782, 1e-5);
  const auto& f = c.frame();
  EXPECT_NEAR(f.position[0], -10 * std::sin(theta), 1e-9);  // a drag to the right: the camera goes left
  EXPECT_NEAR(f.position[1], 0.0, 1e-12);
  EXPECT_NEAR(f.position[2], 10 * std::cos(theta), 1e-9);
  EXPECT_NEAR((f.rotation.transpose() * f.rotation - Mat3::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.rotation.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((f.look_at - Vec3::Zero()).norm(), 0.0, 1e-9);  // still the centre, 10 ahead
  // Outside the sphere's inner part the point is on the hyperbolic sheet: a 300-pixel drag
  // (u = 0.75 > 0.8/√2) turns by 2·asin(|p1 − p2| / 1.6) with z = 0.32 / 0.75.
  c.move(700, 300, 800, 600);
  const double z = 0.32 / 0.75, turn = 2 * std::asin(std::sqrt(0.75 * 0.75 + (0.8 - z) * (0.8 - z)) / 1.6);
  EXPECT_NEAR(std::atan2(-c.frame().position[0], c.frame().position[2]), turn, 1e-9);
  c.release();
  c.move(100, 100, 800, 600);  // no button: nothing moves
  EXPECT_NEAR(std::atan2(-c.frame().position[0], c.frame().position[2]), turn, 1e-9);
}

// The pivots: 0 the point looked at, 1 the camera itself, 3 the world's origin.
TEST(CameraControl, TrackballPivots) {
  Navigation on_camera;
  on_camera.pivot = 1;
  CameraControl c = front_control(on_camera);
  c.press(CameraControl::Mode::trackball, 400, 300);
  c.move(500, 300, 800, 600);
  EXPECT_NEAR((c.frame().position - Vec3(0, 0, 10)).norm(), 0.0, 1e-12);  // turned on the spot
  // The view turned right, as the scene turns left around the eye.
  EXPECT_NEAR(c.frame().look_at[0], 10 * std::sin(std::acos(0.8 * std::sqrt(0.64 - 0.0625) / 0.64)), 1e-9);
  Navigation world;
  world.pivot = 3;
  CameraControl w = front_control(world);
  w.set_scene_box(Vec3(4, -1, -1), Vec3(6, 1, 1));  // centre (5, 0, 0): not the pivot
  w.press(CameraControl::Mode::trackball, 400, 300);
  w.move(500, 300, 800, 600);
  EXPECT_NEAR(w.frame().position.norm(), 10.0, 1e-9);
}

// InteractiveCamera's pan: (x0 − x, y − y0) pixels along the camera's axes times panSpeed times
// 1 % of the scene radius; the point looked at follows.
TEST(CameraControl, PanIsScaledByTheSceneRadius) {
  CameraControl c = front_control();
  c.press(CameraControl::Mode::pan, 400, 300);
  c.move(440, 275, 800, 600);
  const double k = 0.1 * 0.01 * std::sqrt(3.0);
  EXPECT_NEAR((c.frame().position - Vec3(-40 * k, -25 * k, 10)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.frame().look_at - Vec3(-40 * k, -25 * k, 0)).norm(), 0.0, 1e-12);
}

// InteractiveCamera's zooms: zoomSpeed · 1 % of the scene radius / window height per pixel of a
// middle drag (down: forwards), and per half tenth of a wheel notch; the point looked at is
// pushed ahead of a camera that passed it.
TEST(CameraControl, ZoomIsScaledByTheSceneRadius) {
  CameraControl c = front_control();
  const double step = 250 * 0.01 * std::sqrt(3.0) / 600;
  c.press(CameraControl::Mode::zoom, 400, 300);
  c.move(400, 360, 800, 600);
  EXPECT_NEAR(c.frame().position[2], 10 - 60 * step, 1e-12);
  c.release();
  c.wheel(1, 600);  // SofaGLFW: a notch is a wheel delta of 10, half of it in steps
  EXPECT_NEAR(c.frame().position[2], 10 - 65 * step, 1e-12);
  c.wheel(-2, 600);
  EXPECT_NEAR(c.frame().position[2], 10 - 55 * step, 1e-12);
  EXPECT_NEAR(c.frame().look_at.norm(), 0.0, 1e-12);

  CameraControl near;
  near.reset(front_view(0.1));
  near.set_scene_box(Vec3::Constant(-1), Vec3::Constant(1));
  near.wheel(5, 600);  // 25 steps = 0.18 forwards: past the point looked at
  EXPECT_NEAR(near.frame().position[2], 0.1 - 25 * step, 1e-12);
  EXPECT_NEAR(near.frame().look_at[2], near.frame().position[2] - step, 1e-12);
}

// RecordedCamera's own law: the trackball from the last motion, pans by panSpeed and zooms by
// zoomSpeed / height per pixel, whatever the scene's size; a plain Camera does not move.
TEST(CameraControl, RecordedCameraAndPlainCameraLaws) {
  Navigation recorded;
  recorded.law = Navigation::Law::recorded;
  CameraControl r = front_control(recorded);
  r.press(CameraControl::Mode::trackball, 400, 300);
  r.move(450, 300, 800, 600);
  r.move(500, 300, 800, 600);  // two 50-pixel turns
  const double half = std::acos(0.8 * std::sqrt(0.64 - 0.125 * 0.125) / 0.64);
  EXPECT_NEAR(std::atan2(-r.frame().position[0], r.frame().position[2]), 2 * half, 1e-9);
  CameraControl p = front_control(recorded);
  p.press(CameraControl::Mode::pan, 400, 300);
  p.move(410, 300, 800, 600);
  EXPECT_NEAR((p.frame().position - Vec3(-1, 0, 10)).norm(), 0.0, 1e-12);  // 10 px · 0.1
  CameraControl z = front_control(recorded);
  z.wheel(1, 500);
  EXPECT_NEAR(z.frame().position[2], 10 - 250 * 5.0 / 500, 1e-12);
  EXPECT_NEAR(z.frame().look_at[2], -250 * 5.0 / 500, 1e-12);

  Navigation none;
  none.law = Navigation::Law::none;
  CameraControl n = front_control(none);
  n.press(CameraControl::Mode::trackball, 400, 300);
  n.move(500, 300, 800, 600);
  n.wheel(3, 600);
  EXPECT_EQ(n.frame().position, Vec3(0, 0, 10));
}

// The scene camera's Data reach the mouse: InteractiveCamera's speeds and pivot, RecordedCamera's
// own law, a plain Camera's none, the defaults without a camera.
TEST(Navigation, FromTheScenesCamera) {
  auto with = [](const std::string& camera) {
    return test::load("<Node name=\"root\">" + camera + "<MechanicalObject position=\"0 0 0\"/></Node>");
  };
  auto interactive = with(R"(<InteractiveCamera position="0 0 5" lookAt="0 0 0" zoomSpeed="100" panSpeed="0.5"
      pivot="0" fixedLookAt="1"/>)");
  Navigation n = navigation_of(*interactive.root);
  EXPECT_EQ(n.law, Navigation::Law::interactive);
  EXPECT_EQ(n.zoom_speed, 100);
  EXPECT_EQ(n.pan_speed, 0.5);
  EXPECT_EQ(n.pivot, 0);
  EXPECT_TRUE(n.fixed_look_at);
  auto recorded = with(R"(<RecordedCamera position="0 0 5" lookAt="0 0 0" pivot="1"/>)");
  n = navigation_of(*recorded.root);
  EXPECT_EQ(n.law, Navigation::Law::recorded);
  EXPECT_EQ(n.pivot, 1);
  auto plain = with(R"(<Camera position="0 0 5" lookAt="0 0 0"/>)");
  EXPECT_EQ(navigation_of(*plain.root).law, Navigation::Law::none);
  auto none = with("");
  n = navigation_of(*none.root);
  EXPECT_EQ(n.law, Navigation::Law::interactive);
  EXPECT_EQ(n.zoom_speed, 250);
  EXPECT_EQ(n.pivot, 2);
}

TEST(Ray, ThroughAPixelAndProjectedBack) {
  const render::View v = view_of_frame(front_view(10), 800, 600);
  const Ray centre = ray_through(v, 399.5, 299.5, 800, 600);
  EXPECT_NEAR((centre.dir - Vec3(0, 0, -1)).norm(), 0.0, 1e-6);
  const Ray r = ray_through(v, 123, 456, 800, 600);
  EXPECT_NEAR(r.dir.norm(), 1.0, 1e-12);
  const Vec3 p = r.origin + 7.0 * r.dir;
  double x, y;
  ASSERT_TRUE(project(v, p, 800, 600, x, y));
  EXPECT_NEAR(x, 123, 1e-3);
  EXPECT_NEAR(y, 456, 1e-3);
  EXPECT_FALSE(project(v, Vec3(0, 0, 20), 800, 600, x, y));  // behind the camera
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("sinew_viewer_test_" + name);
  std::ofstream(path) << text;
  return path.string();
}

TEST(ViewFile, ReadsSofaXmlCameraFiles) {
  const std::string path = write_temp("a.view", R"(<?xml version="1.0" ?>
<Camera version="1.0">
    <position value="0 0 31.7381" />
    <orientation value="-0 -0 -0 1" />
    <lookAt value="5 5 5" />
    <fieldOfView value="30" />
    <distance value="31.7381" />
    <zNear value="0.395403" />
    <zFar value="44.0358" />
    <projectionType value="Perspective" />
</Camera>)");
  std::string err;
  const auto f = read_view_file(path, &err);
  ASSERT_TRUE(f) << err;
  EXPECT_NEAR((f->position - Vec3(0, 0, 31.7381)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f->rotation - Mat3::Identity()).norm(), 0.0, 1e-12);
  EXPECT_EQ(f->fov_deg, 30.0);
  EXPECT_FALSE(f->ortho);
  // lookAt is not read back, as in SOFA: position − distance·z.
  EXPECT_NEAR(f->look_at.norm(), 0.0, 1e-12);
}

TEST(ViewFile, ReadsTheOldTwoLineFormatAndRoundTrips) {
  const double h = std::sqrt(0.5);
  const std::string path = write_temp("b.view", "1 2 3\n0 " + std::to_string(h) + " 0 " + std::to_string(h) + "\n");
  std::string err;
  const auto f = read_view_file(path, &err);
  ASSERT_TRUE(f) << err;
  EXPECT_NEAR((f->position - Vec3(1, 2, 3)).norm(), 0.0, 1e-12);
  // 90° about y: the camera's z is the world's x.
  EXPECT_NEAR((f->rotation.col(2) - Vec3(1, 0, 0)).norm(), 0.0, 1e-6);

  const std::string out = write_temp("c.view", "");
  ASSERT_TRUE(write_view_file(out, *f, &err)) << err;
  const auto back = read_view_file(out, &err);
  ASSERT_TRUE(back) << err;
  EXPECT_NEAR((back->position - f->position).norm(), 0.0, 1e-8);
  EXPECT_NEAR((back->rotation - f->rotation).norm(), 0.0, 1e-8);
  EXPECT_NEAR((back->look_at - f->look_at).norm(), 0.0, 1e-7);
}

TEST(ViewFile, BadFilesAreReportedNotApplied) {
  std::string err;
  EXPECT_FALSE(read_view_file("/nonexistent/x.view", &err));
  EXPECT_NE(err.find("cannot open"), std::string::npos);
  EXPECT_FALSE(read_view_file(write_temp("d.view", "<Camera><position value=\"1 2\"/></Camera>"), &err));
  EXPECT_NE(err.find("position"), std::string::npos);
  EXPECT_FALSE(read_view_file(write_temp("e.view", "1 2 3\nnan 0 0 1\n"), &err));
  EXPECT_FALSE(read_view_file(write_temp("f.view", "<Camera"), &err));
}

TEST(InputScript, ParsesAndSortsByFrame) {
  const std::string path = write_temp("s.txt", "# a drag\n5 move 10 20\n0 play\n5 press left\n7 screenshot out.png\n");
  std::vector<ScriptEvent> ev;
  std::string err;
  ASSERT_TRUE(read_input_script(path, ev, &err)) << err;
  ASSERT_EQ(ev.size(), 4u);
  EXPECT_EQ(ev[0].command, "play");
  EXPECT_EQ(ev[1].command, "move");
  EXPECT_EQ(ev[1].args, (std::vector<std::string>{"10", "20"}));
  EXPECT_EQ(ev[2].command, "press");  // same frame: file order kept
  EXPECT_EQ(ev[3].line, 5);
}

TEST(InputScript, ErrorsNameTheLine) {
  std::vector<ScriptEvent> ev;
  std::string err;
  EXPECT_FALSE(read_input_script(write_temp("t1.txt", "0 play\n3 jump\n"), ev, &err));
  EXPECT_NE(err.find(":2: unknown command 'jump'"), std::string::npos) << err;
  EXPECT_FALSE(read_input_script(write_temp("t2.txt", "x play\n"), ev, &err));
  EXPECT_NE(err.find(":1:"), std::string::npos);
  EXPECT_FALSE(read_input_script(write_temp("t3.txt", "1 move 3\n"), ev, &err));
  EXPECT_FALSE(read_input_script(write_temp("t4.txt", "1 press top\n"), ev, &err));
  EXPECT_FALSE(read_input_script(write_temp("t5.txt", "1 key ab\n"), ev, &err));
  EXPECT_FALSE(read_input_script("/nonexistent/script", ev, &err));
}

}  // namespace
}  // namespace sinew::viewer
