// The viewer's camera under the mouse, rays through pixels, .view files, input scripts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <Eigen/Geometry>

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

TEST(CameraControl, TrackballTurnsAroundThePivotAndKeepsTheFrameRigid) {
  CameraControl c;
  c.reset(front_view(10), Vec3::Zero());
  for (int i = 0; i < 50; ++i) c.rotate(400, 300, 420, 290, 800, 600);
  const auto& f = c.frame();
  EXPECT_NEAR((f.position - c.pivot()).norm(), 10.0, 1e-9);
  EXPECT_NEAR((f.rotation.transpose() * f.rotation - Mat3::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.rotation.determinant(), 1.0, 1e-12);
  // Still looking at the pivot: the camera's −z points from the eye to the pivot.
  EXPECT_NEAR((-f.rotation.col(2) - (c.pivot() - f.position).normalized()).norm(), 0.0, 1e-9);
  // A drag to the right turns the scene to the right: the camera moved to the left (−x).
  EXPECT_LT(f.position[0], -1.0);
}

TEST(CameraControl, HorizontalDragAtTheCentreTurnsAboutTheVerticalAxis) {
  CameraControl c;
  c.reset(front_view(10), Vec3::Zero());
  c.rotate(400, 300, 500, 300, 800, 600);
  EXPECT_NEAR(c.frame().position[1], 0.0, 1e-12);  // no vertical motion
  EXPECT_NEAR(c.frame().rotation.col(1).dot(Vec3(0, 1, 0)), 1.0, 1e-12);
}

TEST(CameraControl, PanKeepsThePointUnderTheCursorAtThePivotDepth) {
  CameraControl c;
  c.reset(front_view(10), Vec3::Zero());
  const render::View before = view_of_frame(c.frame(), 800, 600);
  double x0, y0;
  ASSERT_TRUE(project(before, Vec3::Zero(), 800, 600, x0, y0));
  c.pan(40, -25, 800, 600);
  const render::View after = view_of_frame(c.frame(), 800, 600);
  double x1, y1;
  ASSERT_TRUE(project(after, Vec3::Zero(), 800, 600, x1, y1));
  // The view matrices are single precision, as OpenGL takes them.
  EXPECT_NEAR(x1 - x0, 40, 1e-4);
  EXPECT_NEAR(y1 - y0, -25, 1e-4);
}

TEST(CameraControl, ZoomMovesTowardsThePointLookedAt) {
  CameraControl c;
  c.reset(front_view(10), Vec3::Zero());
  c.zoom(1);
  EXPECT_NEAR(c.frame().position[2], 9.0, 1e-12);
  c.zoom(-2);
  EXPECT_NEAR(c.frame().position[2], 9.0 / 0.81, 1e-12);
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
