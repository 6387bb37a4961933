// Haptics module: scripted device interpolation, the Geomagic driver's rest pose
// and published trajectory, the servo thread's rate and shutdown,
// MechanicalStateController's Vec1 rule, SOFA's haptic scenes loading and running.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <thread>

#include <unistd.h>

#include "haptics/force_feedback.h"
#include "haptics/geomagic_driver.h"
#include "haptics/mechanical_state_controller.h"
#include "haptics/scripted_device.h"
#include "runner/session.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;
using namespace sinew::haptics;
namespace fs = std::filesystem;

namespace {

const char* kCsv =
    "time, x, y, z, qx, qy, qz, qw, buttons\n"
    "0.0, 0, 0, 0, 0, 0, 0, 1, 0\n"
    "0.1, 1, 2, -1, 0, 0, 0.7071067811865476, 0.7071067811865476, 1\n"
    "0.3, 1, 0, 3, 0, 0, 0.7071067811865476, 0.7071067811865476, 3\n";

Quat q_of(const FlatVec& v) { return {v.data[3], v.data[4], v.data[5], v.data[6]}; }

}  // namespace

TEST(ScriptedDevice, InterpolatesPositionSlerpsOrientationHoldsButtons) {
  std::vector<TrajectorySample> s;
  std::string err;
  ASSERT_TRUE(parse_trajectory(kCsv, s, err)) << err;
  ASSERT_EQ(s.size(), 3u);
  DeviceState d = sample_trajectory(s, 0.025);  // a quarter of the first segment
  EXPECT_NEAR(d.position[0], 0.25, 1e-15);
  EXPECT_NEAR(d.position[1], 0.5, 1e-15);
  EXPECT_NEAR(d.position[2], -0.25, 1e-15);
  // A quarter of a 90° turn about z: 22.5°.
  EXPECT_NEAR(d.orientation.z, std::sin(std::numbers::pi / 16), 1e-12);
  EXPECT_NEAR(d.orientation.w, std::cos(std::numbers::pi / 16), 1e-12);
  EXPECT_EQ(d.buttons, 0u);
  EXPECT_NEAR(d.linear_velocity[1], 20.0, 1e-12);
  EXPECT_NEAR(d.angular_velocity[2], (std::numbers::pi / 2) / 0.1, 1e-9);
  d = sample_trajectory(s, 0.2);
  EXPECT_NEAR(d.position[1], 1.0, 1e-15);
  EXPECT_NEAR(d.position[2], 1.0, 1e-15);
  EXPECT_EQ(d.buttons, 1u);
  d = sample_trajectory(s, 5.0);  // after the end: holds the last sample
  EXPECT_EQ(d.position, Vec3(1, 0, 3));
  EXPECT_EQ(d.buttons, 3u);
  EXPECT_EQ(d.linear_velocity, Vec3::Zero());
}

TEST(ScriptedDevice, MalformedFilesAreRefusedWithTheLine) {
  std::vector<TrajectorySample> s;
  std::string err;
  EXPECT_FALSE(parse_trajectory("0 0 0 0 0 0 0 1 0\n0.1 1 2 3\n", s, err));
  EXPECT_NE(err.find("line 2"), std::string::npos) << err;
  EXPECT_FALSE(parse_trajectory("0.1 0 0 0 0 0 0 1 0\n0.1 0 0 0 0 0 0 1 0\n", s, err));
  EXPECT_NE(err.find("does not increase"), std::string::npos) << err;
  EXPECT_FALSE(parse_trajectory("0 0 0 0 0 0 0 0 0\n", s, err));
  EXPECT_NE(err.find("zero quaternion"), std::string::npos) << err;
}

TEST(GeomagicDriver, NoDeviceHoldsTheRestPose) {
  // positionBase, orientationBase (60° about (1,1,1)/√3), orientationTool (90° about x), scale 2.
  const double h = std::sqrt(0.5), s3 = std::sqrt(1.0 / 3.0);
  const Quat qb{0.5 * s3, 0.5 * s3, 0.5 * s3, std::cos(std::numbers::pi / 6)};
  const std::string xml = "<Node name='root' dt='0.01'><GeomagicDriver name='drv' positionBase='1 -2 3.5' "
                          "orientationBase='" + std::to_string(qb.x) + " " + std::to_string(qb.y) + " " +
                          std::to_string(qb.z) + " " + std::to_string(qb.w) + "' orientationTool='" +
                          std::to_string(h) + " 0 0 " + std::to_string(h) + "' scale='2'/></Node>";
  auto sc = test::load(xml);
  ASSERT_TRUE(sc.root);
  auto* drv = test::get<GeomagicDriver>(*sc.root, "drv");
  ASSERT_TRUE(drv);
  EXPECT_TRUE(test::any_contains(test::messages(sc.root->diagnostics(), Severity::info), "no haptic device"));
  for (int i = 0; i < 3; ++i) animate(*sc.root);
  const FlatVec& p = drv->position_device.value();
  EXPECT_EQ(p.data[0], 1.0);
  EXPECT_EQ(p.data[1], -2.0);
  EXPECT_EQ(p.data[2], 3.5);
  // orientationBase · identity · orientationTool, from the Data as parsed.
  const auto& b = drv->orientation_base.value();
  const auto& t = drv->orientation_tool.value();
  const Quat expect = quat_mul(quat_mul({b[0], b[1], b[2], b[3]}, Quat{}), {t[0], t[1], t[2], t[3]});
  const Quat got = q_of(p);
  EXPECT_NEAR(got.x, expect.x, 1e-15);
  EXPECT_NEAR(got.y, expect.y, 1e-15);
  EXPECT_NEAR(got.z, expect.z, 1e-15);
  EXPECT_NEAR(got.w, expect.w, 1e-15);
  // Numbers: (cos30°·h + ..): the product of 60° about the diagonal and 90° about x.
  EXPECT_NEAR(got.w, std::cos(std::numbers::pi / 6) * h - 0.5 * s3 * h, 1e-6);
  EXPECT_NEAR(got.x, std::cos(std::numbers::pi / 6) * h + 0.5 * s3 * h, 1e-6);
  // Zero joint angles: SOFA's angle formula.
  const Vec6 a = drv->angle.value();
  const double hp = std::numbers::pi / 2;
  EXPECT_EQ(a, (Vec6() << 0, 0, -hp, -hp, 0, -hp).finished());
  EXPECT_FALSE(drv->servo().running());  // nothing to serve without a device
}

TEST(GeomagicDriver, PublishesTheScriptedPoseAtAnimateBegin) {
  test::TempDir dir;
  const std::string csv = dir.write("traj.csv", kCsv);
  auto sc = test::load("<Node name='root' dt='0.01'><GeomagicDriver name='drv' trajectory='" + csv +
                       "' positionBase='0.5 0 0' scale='2'/>"
                       "<Node name='omni'><MechanicalObject name='dofs' template='Rigid3d' "
                       "position='@../drv.positionDevice'/></Node></Node>");
  ASSERT_TRUE(sc.root);
  auto* drv = test::get<GeomagicDriver>(*sc.root, "drv");
  ASSERT_TRUE(drv);
  EXPECT_TRUE(drv->servo().running());
  std::vector<TrajectorySample> samples;
  std::string err;
  ASSERT_TRUE(parse_trajectory(kCsv, samples, err));
  for (int n = 1; n <= 25; ++n) {
    animate(*sc.root);
    const DeviceState d = sample_trajectory(samples, n * 0.01);
    const FlatVec& p = drv->position_device.value();
    EXPECT_NEAR(p.data[0], 0.5 + 2 * d.position[0], 1e-12) << n;
    EXPECT_NEAR(p.data[1], 2 * d.position[1], 1e-12) << n;
    EXPECT_NEAR(p.data[2], 2 * d.position[2], 1e-12) << n;
    EXPECT_NEAR(p.data[5], d.orientation.z, 1e-12) << n;
    EXPECT_NEAR(p.data[6], d.orientation.w, 1e-12) << n;
    // Buttons jump at a sample: compared at the time the step reached (t accumulates dt,
    // so at step 10 it is 0.1 − 1.4e-17, before the sample at 0.1).
    const DeviceState at_t = sample_trajectory(samples, sc.root->time.value());
    EXPECT_EQ(drv->button1.value(), (at_t.buttons & 1u) != 0) << n;
    EXPECT_EQ(drv->button2.value(), (at_t.buttons & 2u) != 0) << n;
  }
  // After 25 steps of 0.01 the pose is the CSV's at t = 0.25 (second segment, u = 0.75).
  const FlatVec& p = drv->position_device.value();
  EXPECT_NEAR(p.data[0], 0.5 + 2 * 1.0, 1e-12);
  EXPECT_NEAR(p.data[1], 2 * 0.5, 1e-12);
  EXPECT_NEAR(p.data[2], 2 * 2.0, 1e-12);
  // The proxy state linked to positionDevice follows.
  auto* mo = sc.root->children()[0]->get_mechanical_state();
  EXPECT_NEAR(mo->read(kPosition)[2], 4.0, 1e-12);
}


namespace {
// Counts calls and answers a fixed force (thread-safe: atomics only).
class CountingFeedback final : public ForceFeedback {
 public:
  Vec3 compute_force(const Vec3& p, const Quat&) override {
    calls.fetch_add(1);
    last_x.store(p[0]);
    return Vec3(3, 0, 4);
  }
  std::atomic<int> calls{0};
  std::atomic<double> last_x{0};
};
}  // namespace

TEST(GeomagicDriver, ServoRunsAtOneKilohertzAndStopsOnDestruction) {
  CountingFeedback ff;  // outlives the driver: counts the servo's calls
  auto driver = std::make_unique<GeomagicDriver>();
  driver->force_feedback.set(&ff);
  driver->set_device(std::make_unique<ScriptedDevice>(std::vector<TrajectorySample>{{0, Vec3(1, 0, 0), {}, 0}}));
  driver->init();
  ASSERT_TRUE(driver->servo().running());
  // Ticks over 200 ms, measured on the same clock (the test's own sleep may overrun on a
  // loaded machine: the count is scaled to the 200 ms the window should have lasted).
  const auto c0 = std::chrono::steady_clock::now();
  const auto t0 = driver->servo().ticks();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto t1 = driver->servo().ticks();
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0).count();
  const double n = static_cast<double>(t1 - t0) * 200.0 / ms;
  EXPECT_GE(n, 150.0) << (t1 - t0) << " ticks in " << ms << " ms";
  EXPECT_LE(n, 250.0) << (t1 - t0) << " ticks in " << ms << " ms";
  driver->stop_device();
  EXPECT_FALSE(driver->servo().running());
  const auto after = driver->servo().ticks();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(driver->servo().ticks(), after);
  driver->start_device();
  EXPECT_TRUE(driver->servo().running());
  Event begin{Event::Kind::animate_begin, 0.01};
  driver->handle_event(begin);  // started: the servo calls the force feedback
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_GT(ff.calls.load(), 0);
  driver.reset();  // joins the thread
  const int calls = ff.calls.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(ff.calls.load(), calls);
}

TEST(GeomagicDriver, ServoSendsTheForceFeedbackOrTheClampedManualForce) {
  // orientationBase 90° about z, forceScale 0.5, a force feedback answering (3, 0, 4).
  const double h = std::sqrt(0.5);
  GeomagicDriver drv;
  CountingFeedback ff;
  drv.orientation_base.set(VecN<4>(0, 0, h, h));
  drv.force_scale.set(0.5);
  drv.scale.set(2);
  drv.position_base.set(Vec3(10, 0, 0));
  drv.force_feedback.set(&ff);
  drv.set_device(std::make_unique<ScriptedDevice>(std::vector<TrajectorySample>{{0, Vec3(1, 0, 0), {}, 0}}));
  drv.init();
  Event begin{Event::Kind::animate_begin, 0.01};
  drv.handle_event(begin);  // the simulation started: forces from now on
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_GT(ff.calls.load(), 5);
  // Tool at positionBase + R·(2·(1,0,0)) = (10, 2, 0).
  EXPECT_NEAR(ff.last_x.load(), 10.0, 1e-12);
  // Sent: R⁻¹·(3, 0, 4)·0.5 = (0, −1.5, 2).
  DeviceCommand c = drv.last_command();
  EXPECT_NEAR(c.force[0], 0.0, 1e-12);
  EXPECT_NEAR(c.force[1], -1.5, 1e-12);
  EXPECT_NEAR(c.force[2], 2.0, 1e-12);
  drv.stop_device();
  // No force feedback: inputForceFeedback (6, 8, 0) clamped to norm 2 → (1.2, 1.6, 0).
  drv.force_feedback.set(nullptr);
  GeomagicDriver manual;
  manual.input_force_feedback.set(Vec3(6, 8, 0));
  manual.max_input_force_feedback.set(2);
  manual.set_device(std::make_unique<ScriptedDevice>(std::vector<TrajectorySample>{{0, Vec3::Zero(), {}, 0}}));
  manual.init();
  manual.handle_event(begin);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  c = manual.last_command();
  EXPECT_NEAR(c.force[0], 1.2, 1e-12);
  EXPECT_NEAR(c.force[1], 1.6, 1e-12);
  EXPECT_NEAR(manual.input_force_feedback.value()[0], 1.2, 1e-12);  // SOFA rewrites the Data
}

TEST(GeomagicDriver, ForceFeedbackDestroyedFirstIsNeverCalledAgain) {
  GeomagicDriver drv;
  auto ff = std::make_unique<CountingFeedback>();
  drv.force_feedback.set(ff.get());
  drv.set_device(std::make_unique<ScriptedDevice>(std::vector<TrajectorySample>{{0, Vec3::Zero(), {}, 0}}));
  drv.init();
  Event begin{Event::Kind::animate_begin, 0.01};
  drv.handle_event(begin);
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ff.reset();  // while the servo runs
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_TRUE(drv.servo().running());
}

TEST(GeomagicEmulator, StartsAtSofasRecordedArmPose) {
  auto sc = test::load("<Node name='root' dt='0.01'><GeomagicEmulator name='emu' positionBase='0 0 0'/></Node>");
  ASSERT_TRUE(sc.root);
  auto* drv = test::get<GeomagicDriver>(*sc.root, "emu");
  ASSERT_TRUE(drv);
  animate(*sc.root);
  const FlatVec& p = drv->position_device.value();
  EXPECT_NEAR(p.data[0], 0.0, 1e-12);
  EXPECT_NEAR(p.data[1], -6.55107, 1e-12);
  EXPECT_NEAR(p.data[2], -8.81142, 1e-12);
  EXPECT_NEAR(drv->angle.value()[1], 0.26889, 1e-15);
  // Key '4' turns joint 2 by speedFactor (0.1): angle[1] follows at the next step.
  Event key{Event::Kind::key_pressed};
  key.key = '4';
  propagate_event(*sc.root, key);
  animate(*sc.root);
  EXPECT_NEAR(drv->angle.value()[1], 0.36889, 1e-12);
}

TEST(MechanicalStateController, Vec1RestPositionRuleOverSteps) {
  auto sc = test::load(
      "<Node name='root' dt='0.01' gravity='0 0 0'>"
      "<MechanicalObject name='dofs' template='Vec1d' position='-0.3 0.2 0.7'/>"
      "<MechanicalStateController name='c' template='Vec1d' listening='1' buttonDeviceState='1'/></Node>");
  ASSERT_TRUE(sc.root);
  auto* st = sc.root->get_mechanical_state();
  for (int i = 0; i < 4; ++i) {
    animate(*sc.root);
    // The gripper rule, then SOFA's second block: x0[0] = x0[1] = 0, x0[2] untouched.
    EXPECT_EQ(st->read(kRestPosition), (std::vector<double>{0, 0, 0.7})) << i;
  }
  // Fewer than two DoFs: a clear error, never an out-of-bounds write.
  auto bad = test::build(
      "<Node name='root'><MechanicalObject template='Vec1d' position='1'/>"
      "<MechanicalStateController name='c' template='Vec1d' listening='1'/></Node>");
  init_root(*bad.root);
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::error), "DoFs 0 and 1"));
  animate(*bad.root);
}

// ---------------------------------------------------------------- SOFA scenes
namespace {
const fs::path kData = SINEW_DATA_DIR;

struct Outcome {
  std::vector<std::string> errors;
  long steps = 0;
};

Outcome run_scene(const fs::path& path, long steps, const std::vector<std::string>& first_paths = {}) {
  runner::SessionOptions opts;
  opts.data_paths = first_paths;
  for (const char* sub : {"share", "examples"}) opts.data_paths.push_back((kData / sub).string());
  runner::Session session(path.string(), opts);
  Outcome r;
  if (session.ok())
    for (long i = 0; i < steps; ++i)
      if (!session.step()) break;
  r.steps = session.steps_done();
  r.errors = test::messages(session.diagnostics(), Severity::error);
  for (const auto& m : session.missing()) r.errors.push_back("missing component " + m.type);
  return r;
}
}  // namespace

class HapticScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(HapticScenes, LoadAndRun100Steps) {
  const fs::path p = kData / GetParam();
  if (!fs::exists(p)) GTEST_SKIP() << "SOFA data not found at " << p << " (set SINEW_DATA_DIR to the sofa-data folder)";
  const Outcome r = run_scene(p, 100);
  EXPECT_EQ(r.steps, 100);
  EXPECT_TRUE(r.errors.empty()) << ::testing::PrintToString(r.errors);
}

INSTANTIATE_TEST_SUITE_P(Scenes, HapticScenes,
                         ::testing::Values("plugins/Geomagic/scenes/Geomagic-Demo.scn",
                                           "plugins/Geomagic/scenes/Geomagic-DeformableCubes.scn",
                                           "plugins/Geomagic/scenes/Geomagic-DeformableSphere.scn",
                                           "plugins/Geomagic/scenes/Geomagic-FEMLiver.scn",
                                           "plugins/Geomagic/scenes/Geomagic-RigidCubes.scn",
                                           "plugins/Geomagic/scenes/Geomagic-RigidSphere.scn",
                                           "plugins/Geomagic/scenes/GeomagicEmulator-RigidCubes.scn",
                                           "examples/Component/Controller/MechanicalStateController.scn",
                                           "examples/Component/Controller/MechanicalStateControllerTranslation.scn"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = fs::path(info.param).stem().string();
                           std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                           return name;
                         });

TEST(MechanicalStateController, Rigid3ProjectsAndPropagatesBelowItsNode) {
  auto sc = test::load(
      "<Node name='root' dt='0.01' gravity='0 0 0'>"
      "<Node name='omni'><MechanicalObject name='dofs' template='Rigid3d' position='0 0 0 0 0 0 1'/>"
      "<MechanicalStateController name='c' template='Rigid3d' listening='1'/>"
      "<Node name='tip'><MechanicalObject name='tip' position='1 0 0'/><RigidMapping/></Node></Node></Node>");
  ASSERT_TRUE(sc.root);
  Node& omni = *sc.root->children()[0];
  auto* c = test::get<MechanicalStateController>(omni, "c");
  ASSERT_TRUE(c);
  // The proxy moved by something else (a device link): translated by (0, 2, 0), turned 90° about z.
  const double h = std::sqrt(0.5);
  omni.get_mechanical_state()->write(kPosition) = {0, 2, 0, 0, 0, h, h};
  c->apply();
  const auto& tip = omni.children()[0]->get_mechanical_state()->read(kPosition);
  EXPECT_NEAR(tip[0], 0.0, 1e-12);
  EXPECT_NEAR(tip[1], 3.0, 1e-12);
  EXPECT_NEAR(tip[2], 0.0, 1e-12);
}

namespace {
// Records the script events it receives.
class EventRecorder final : public Component {
 public:
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override {
    if (e.kind == Event::Kind::script) names.push_back(e.name);
  }
  std::vector<std::string> names;
};
}  // namespace

TEST(GeomagicDriver, EmitsButtonEventsFromTheRoot) {
  test::TempDir dir;
  // Button 1 pressed at t = 0.02, button 2 too at 0.04, both released at 0.06.
  const std::string csv = dir.write("buttons.csv",
                                    "0 0 0 0 0 0 0 1 0\n0.015 0 0 0 0 0 0 1 1\n0.035 0 0 0 0 0 0 1 3\n"
                                    "0.055 0 0 0 0 0 0 1 0\n");
  auto sc = test::load("<Node name='root' dt='0.01'><GeomagicDriver name='drv' emitButtonEvent='1' trajectory='" +
                       csv + "'/></Node>");
  ASSERT_TRUE(sc.root);
  auto rec = std::make_unique<EventRecorder>();
  EventRecorder* r = rec.get();
  sc.root->add_object(std::move(rec));
  for (int i = 0; i < 7; ++i) animate(*sc.root);
  EXPECT_EQ(r->names, (std::vector<std::string>{"button0pressed", "button1pressed", "button0released",
                                                "button1released"}));
}

TEST(GeomagicDriver, BadTrajectoryIsAnErrorNamingTheField) {
  test::TempDir dir;
  const std::string csv = dir.write("bad.csv", "0 0 0 0 0 0 0 1 0\n0.1 1 2\n");
  auto sc = test::build("<Node name='root' dt='0.01'><GeomagicDriver name='drv' trajectory='" + csv + "'/></Node>");
  ASSERT_TRUE(sc.root);
  init_root(*sc.root);
  const auto errors = test::messages(sc.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "trajectory")) << ::testing::PrintToString(errors);
  EXPECT_TRUE(test::any_contains(errors, "line 2")) << ::testing::PrintToString(errors);
  auto* drv = test::get<GeomagicDriver>(*sc.root, "drv");
  EXPECT_EQ(drv->state(), ComponentState::invalid);
  EXPECT_FALSE(drv->servo().running());
  for (int i = 0; i < 3; ++i) animate(*sc.root);  // holds the rest pose, no crash
  EXPECT_EQ(drv->position_device.value().data, (std::vector<double>{0, 0, 0, 0, 0, 0, 1}));
}

TEST(GeomagicDriver, FindsTheFirstForceFeedbackWithItsTagsFromTheRoot) {
  auto sc = test::load(
      "<Node name='root' dt='0.01'><GeomagicDriver name='drv' tags='tool'/>"
      "<Node name='a'><NullForceFeedback name='untagged'/></Node>"
      "<Node name='b'><NullForceFeedback name='mine' tags='tool other'/></Node></Node>");
  ASSERT_TRUE(sc.root);
  auto* drv = test::get<GeomagicDriver>(*sc.root, "drv");
  ASSERT_TRUE(drv && drv->force_feedback);
  EXPECT_EQ(drv->force_feedback->name.value(), "mine");
  auto none = test::load("<Node name='root' dt='0.01'><GeomagicDriver name='drv'/></Node>");
  EXPECT_TRUE(test::any_contains(test::messages(none.root->diagnostics(), Severity::warning),
                                 "no force feedback component found"));
}

// The two RigidSkull scenes need SOFA's Dentistry demo mesh, which the shared SOFA data
// lacks: the load stops with an error naming the file (nothing else is missing).
TEST(HapticScenes, RigidSkullScenesNameTheirMissingMesh) {
  for (const char* name : {"Geomagic-RigidSkull.scn", "Geomagic-RigidSkull-restShapeSpringForceField.scn"}) {
    const fs::path p = kData / "plugins/Geomagic/scenes" / name;
    if (!fs::exists(p)) GTEST_SKIP() << "SOFA data not found at " << p;
    if (fs::exists(kData / "share/Demos/Dentistry/data/mesh/skull_and_teeth.obj") ||
        fs::exists(kData / "examples/Demos/Dentistry/data/mesh/skull_and_teeth.obj"))
      GTEST_SKIP() << "the skull mesh is present: the scene is covered by LoadAndRun100Steps";
    const Outcome r = run_scene(p, 100);
    ASSERT_FALSE(r.errors.empty()) << name;
    bool names_the_mesh = false;
    for (const auto& e : r.errors) {
      names_the_mesh = names_the_mesh || e.find("skull_and_teeth.obj") != std::string::npos;
      EXPECT_EQ(e.find("missing component"), std::string::npos) << e;
    }
    EXPECT_TRUE(names_the_mesh) << ::testing::PrintToString(r.errors);
  }
}

// With the absent visual mesh stood in for by the coarse skull (present: the scenes' collision
// mesh), in a folder searched before the data, both RigidSkull scenes load and run 100 steps
// without an error: only the data file keeps them from LoadAndRun100Steps.
TEST(HapticScenes, RigidSkullScenesRunWithTheMeshStoodIn) {
  const fs::path coarse = kData / "examples/Demos/Dentistry/data/mesh/skull_and_teeth_coarse.obj";
  if (!fs::exists(coarse)) GTEST_SKIP() << "SOFA data not found at " << coarse;
  const fs::path dir = fs::temp_directory_path() / ("sinew_skull_" + std::to_string(::getpid()));
  fs::create_directories(dir / "Demos/Dentistry/data/mesh");
  fs::copy_file(coarse, dir / "Demos/Dentistry/data/mesh/skull_and_teeth.obj", fs::copy_options::overwrite_existing);
  for (const char* name : {"Geomagic-RigidSkull.scn", "Geomagic-RigidSkull-restShapeSpringForceField.scn"}) {
    const Outcome r = run_scene(kData / "plugins/Geomagic/scenes" / name, 100, {dir.string()});
    EXPECT_EQ(r.steps, 100) << name;
    EXPECT_TRUE(r.errors.empty()) << name << ": " << ::testing::PrintToString(r.errors);
  }
  fs::remove_all(dir);
}

// GeomagicEmulator-RigidCubes under a scripted input: the emulated arm replaced by a
// trajectory moving the device 3 units along its x over 0.5 s; the instrument (coupled
// by stiff springs to the proxy at positionDevice) follows the rotated displacement.
TEST(HapticScenes, EmulatorRigidCubesInstrumentFollowsAScriptedInput) {
  const fs::path p = kData / "plugins/Geomagic/scenes/GeomagicEmulator-RigidCubes.scn";
  if (!fs::exists(p)) GTEST_SKIP() << "SOFA data not found at " << p;
  runner::SessionOptions opts;
  opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
  runner::Session session(p.string(), opts);
  ASSERT_TRUE(session.ok()) << ::testing::PrintToString(test::messages(session.diagnostics(), Severity::error));
  auto* emu = test::get<GeomagicDriver>(session.root(), "GeomagicDevice");
  ASSERT_TRUE(emu);
  auto* instrument = session.root().find_child_named("Instrument")->get_mechanical_state();
  ASSERT_TRUE(instrument);
  // Settle at the emulator's home pose first.
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(session.step());
  const DeviceState home = emu->device()->read(0);
  const std::vector<double> x0 = instrument->read(kPosition);
  emu->stop_device();
  const double t0 = session.root().time.value();
  std::vector<TrajectorySample> samples{{0, home.position, home.orientation, 0},
                                        {t0, home.position, home.orientation, 0},
                                        {t0 + 0.5, home.position + Vec3(3, 0, 0), home.orientation, 1}};
  emu->set_device(std::make_unique<ScriptedDevice>(samples));
  emu->start_device();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(session.step());  // 1 s at dt 0.05
  const std::vector<double>& x1 = instrument->read(kPosition);
  // orientationBase (0 0.707 0 -0.707): the device's +x becomes the scene's +z (scale 1).
  const Quat qb = quat_normalized(Quat{0, 0.707, 0, -0.707});
  const Vec3 expected = quat_rotate(qb, Vec3(3, 0, 0));
  const Vec3 moved(x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]);
  EXPECT_NEAR((moved - expected).norm(), 0.0, 0.05) << moved.transpose() << " vs " << expected.transpose();
  EXPECT_TRUE(emu->button1.value());
  // The servo ran with the instrument's LCPForceFeedback (linked by forceFeedBack).
  EXPECT_NE(emu->force_feedback.get(), nullptr);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_GT(emu->servo().ticks(), 0u);
}
