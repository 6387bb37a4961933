// RecordedCamera's scripted paths (visual/recorded_camera.h), as SOFA moves them at each
// AnimateBeginEvent: one turn of the rotation over [startTime, endTime], the translation's
// segments in equal shares of the span, the navigation's slerped orientations, and a reset.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scene.h"
#include "visual/recorded_camera.h"

namespace sinew {
namespace {

// Sends the AnimateBeginEvent of time t to the camera.
void begin_at(Node& root, RecordedCamera& c, double t) {
  root.time.set(t);
  Event e{Event::Kind::animate_begin};
  c.handle_event(e);
}

// Where the camera looks: its −z axis.
Vec3 looking(const RecordedCamera& c) { return quat_matrix(c.orientation.get()) * Vec3(0, 0, -1); }

TEST(RecordedCamera, RotationTurnsOnceOverItsSpanLookingAtItsPoint) {
  auto s = test::load("<Node name=\"root\" dt=\"0.5\"><RecordedCamera name=\"c\" position=\"0 10 0\" "
                      "rotationLookAt=\"0 30 0\" rotationStartPoint=\"0 100 100\" rotationCenter=\"0 100 0\" "
                      "startTime=\"0\" endTime=\"8\" rotationMode=\"1\"/></Node>");
  auto* c = test::get<RecordedCamera>(*s.root, "c");
  ASSERT_TRUE(c);
  begin_at(*s.root, *c, 0);  // first step: configured at the start point
  EXPECT_NEAR((c->position.get() - Vec3(0, 100, 100)).norm(), 0, 1e-12);
  EXPECT_NEAR((c->look_at.get() - Vec3(0, 30, 0)).norm(), 0, 1e-12);
  // Not yet due: a time before the next step (the previous one + dt, SOFA's m_nextStep).
  begin_at(*s.root, *c, 0.3);
  EXPECT_NEAR((c->position.get() - Vec3(0, 100, 100)).norm(), 0, 1e-12);
  begin_at(*s.root, *c, 2);  // a quarter turn about y: (0, 0, 100) → (100, 0, 0)
  EXPECT_NEAR((c->position.get() - Vec3(100, 100, 0)).norm(), 0, 1e-9);
  const Vec3 towards = (Vec3(0, 30, 0) - c->position.get()).normalized();
  EXPECT_NEAR(looking(*c).dot(towards), 1, 1e-12);
  EXPECT_GT((quat_matrix(c->orientation.get()) * Vec3(0, 1, 0)).y(), 0);  // upright
  begin_at(*s.root, *c, 4);  // half a turn
  EXPECT_NEAR((c->position.get() - Vec3(0, 100, -100)).norm(), 0, 1e-9);
  // The drawn path: 100 points of the circle.
  const auto path = c->rotation_path();
  ASSERT_EQ(path.size(), 100u);
  for (const Vec3& p : path) EXPECT_NEAR((p - Vec3(0, 100, 0)).norm(), 100, 1e-9);
  c->reset();
  EXPECT_NEAR((c->position.get() - Vec3(0, 100, 100)).norm(), 0, 1e-12);
}

// Translation: three points, two segments of 5 s each over [0, 10]; looking at the segment's
// end; the path repeats past the end.
TEST(RecordedCamera, TranslationFollowsItsSegments) {
  auto s = test::load("<Node name=\"root\" dt=\"1\"><RecordedCamera name=\"c\" position=\"0 0 10\" lookAt=\"0 0 0\" "
                      "cameraPositions=\"0 0 10  10 0 10  10 0 0\" endTime=\"10\" translationMode=\"1\"/></Node>");
  auto* c = test::get<RecordedCamera>(*s.root, "c");
  begin_at(*s.root, *c, 0);
  EXPECT_NEAR((c->position.get() - Vec3(0, 0, 10)).norm(), 0, 1e-12);
  for (double t = 1; t <= 3; ++t) begin_at(*s.root, *c, t);
  EXPECT_NEAR((c->position.get() - Vec3(6, 0, 10)).norm(), 0, 1e-12);
  EXPECT_NEAR(looking(*c).dot(Vec3(1, 0, 0)), 1, 1e-12);
  for (double t = 4; t <= 7; ++t) begin_at(*s.root, *c, t);
  EXPECT_NEAR((c->position.get() - Vec3(10, 0, 6)).norm(), 0, 1e-12);
  EXPECT_NEAR(looking(*c).dot(Vec3(0, 0, -1)), 1, 1e-12);
  for (double t = 8; t <= 12; ++t) begin_at(*s.root, *c, t);
  EXPECT_NEAR((c->position.get() - Vec3(4, 0, 10)).norm(), 0, 1e-12);  // 12 mod 10: back on the first segment
}

// Navigation: positions interpolated, orientations slerped (identity to a half turn about y).
TEST(RecordedCamera, NavigationSlerpsItsOrientations) {
  auto s = test::load("<Node name=\"root\" dt=\"1\"><RecordedCamera name=\"c\" position=\"0 0 10\" lookAt=\"0 0 0\" "
                      "cameraPositions=\"0 0 10  0 0 -10\" cameraOrientations=\"0 0 0 1  0 1 0 0\" endTime=\"4\" "
                      "navigationMode=\"1\"/></Node>");
  auto* c = test::get<RecordedCamera>(*s.root, "c");
  for (double t = 0; t <= 2; ++t) begin_at(*s.root, *c, t);
  EXPECT_NEAR((c->position.get() - Vec3(0, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(looking(*c).dot(Vec3(-1, 0, 0)), 1, 1e-9);  // a quarter turn about y
}

TEST(RecordedCamera, UnknownAttributeIsReported) {
  auto d = test::build("<Node name=\"root\"><RecordedCamera rotationModee=\"1\"/></Node>");
  bool reported = false;
  for (const auto& m : d.root->diagnostics().messages()) reported |= m.text.find("rotationModee") != std::string::npos;
  EXPECT_TRUE(reported);
}

}  // namespace
}  // namespace sinew
