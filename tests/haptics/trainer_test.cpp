// The skin-suture trainer (scenes/trainer/skin_suture.scn, issue 16 done-when 2):
// the scripted needle goes into the skin, through it and out while the scalpel
// cuts a groove. The test plays the servo thread's part synchronously so that it
// is reproducible: after each simulation step (10 ms) it makes ten haptic
// updates (1 kHz of simulated time) at the device's scripted pose, as the
// device moves on while the next step computes; each update is the force
// LCPForceFeedback sends to the device. Checked:
// * continuity: no jump between consecutive haptic updates above kMaxJump, and
//   99.9% of them below kMaxJump999 (see below for why);
// * passivity: the work the device does on the hand over the 10 s,
//   Σ ½(F_k + F_{k−1})·(x_k − x_{k−1}), is not positive;
// * a suture thread is created;
// * the scalpel's pass removes tetrahedra, all of them along the tools' paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/roles.h"
#include "forcefield/spring/suture_spring_force_field.h"
#include "haptics/geomagic_driver.h"
#include "haptics/lcp_force_feedback.h"
#include "haptics/scripted_device.h"
#include "runner/session.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::haptics;
namespace fs = std::filesystem;

namespace {

const fs::path kTrainer = fs::path(SINEW_SOURCE_DIR) / "scenes" / "trainer";

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A tetrahedron as its sorted vertex set (indices are stable: the scene keeps isolated points).
std::set<std::array<unsigned, 4>> tetra_set(const MeshTopologyBase& t) {
  std::set<std::array<unsigned, 4>> out;
  for (const auto& e : t.tetrahedra()) {
    std::array<unsigned, 4> a{e[0], e[1], e[2], e[3]};
    std::sort(a.begin(), a.end());
    out.insert(a);
  }
  return out;
}

// Distance from p to the segment ab.
double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + u * ab - p).norm();
}

// Bounds on the change of the device force between consecutive haptic updates (the peak
// force is about 0.4). Within a snapshot the re-solve follows the device smoothly; the
// large changes come when a step's carving removes the tetrahedra the needle's tip was
// pushing on (the "pop" of piercing, felt at the next snapshot): a few updates, none
// above kMaxJump; 999 of 1000 updates change by less than kMaxJump999.
constexpr double kMaxJump = 0.35;
constexpr double kMaxJump999 = 0.05;

}  // namespace

TEST(Trainer, NeedleThroughTheSkinWithContinuousPassiveForceAThreadAndAScalpelGroove) {
  const fs::path scene = kTrainer / "skin_suture.scn";
  ASSERT_TRUE(fs::exists(scene)) << scene;
  runner::Session session(scene.string(), {});
  ASSERT_TRUE(session.ok()) << ::testing::PrintToString(test::messages(session.diagnostics(), Severity::error));
  Node& root = session.root();
  auto* needle_device = test::get<GeomagicDriver>(root, "needleDevice");
  auto* scalpel_device = test::get<GeomagicDriver>(root, "scalpelDevice");
  ASSERT_TRUE(needle_device && scalpel_device);
  // The test is the needle's servo: the threads stop (the simulation still samples the devices).
  needle_device->stop_device();
  scalpel_device->stop_device();
  Node& needle = *root.find_child_named("Needle");
  auto* ff = test::get<LCPForceFeedback>(needle, "haptics");
  ASSERT_TRUE(ff);
  EXPECT_EQ(needle_device->force_feedback.get(), ff) << "the needle's device finds the needle's force feedback by tag";
  // Reproducible: the haptic solves run to convergence (or solverMaxIt), not to a wall-clock
  // budget that a loaded machine may cut short (the budget is what --haptics-report measures).
  ff->solver_timeout.set(1.0);
  Node& skin = *root.find_child_named("Skin");
  auto* suture = test::get<SutureSpringForceField>(skin, "suture");
  ASSERT_TRUE(suture);
  MeshTopologyBase* volume = skin.get_mesh_topology_link();
  ASSERT_TRUE(volume);
  const auto tets0 = tetra_set(*volume);
  const std::vector<double> rest = skin.get_mechanical_state()->read(kRestPosition);
  ASSERT_EQ(tets0.size(), 1728u);

  std::vector<TrajectorySample> path;
  std::string err;
  ASSERT_TRUE(parse_trajectory(read_file(kTrainer / "needle.csv"), path, err)) << err;

  const double dt = root.dt.value();
  const int steps = static_cast<int>(std::lround(10.0 / dt));
  const int per_step = 10;  // haptic updates per step: 1 kHz
  Vec3 F_prev = Vec3::Zero(), x_prev = sample_trajectory(path, 0.0).position;
  double work = 0, max_jump = 0, max_force = 0, jump_at = 0;
  long nonzero = 0;
  std::vector<double> jumps;
  jumps.reserve(static_cast<std::size_t>(steps) * per_step);
  for (int k = 0; k < steps; ++k) {
    ASSERT_TRUE(session.step()) << "step " << k;
    const double t = root.time.value();
    for (int j = 1; j <= per_step; ++j) {
      const double tau = t + dt * j / per_step;
      const Vec3 x = sample_trajectory(path, tau).position;  // positionBase 0, scale 1, no base rotation
      const Vec3 F = ff->compute_force(x, Quat{});
      ASSERT_TRUE(std::isfinite(F.norm())) << tau;
      work += 0.5 * (F + F_prev).dot(x - x_prev);
      const double jump = (F - F_prev).norm();
      jumps.push_back(jump);
      if (jump > max_jump) max_jump = jump, jump_at = tau;
      max_force = std::max(max_force, F.norm());
      if (F.norm() > 0) ++nonzero;
      F_prev = F;
      x_prev = x;
    }
  }
  std::sort(jumps.begin(), jumps.end());
  const double p99_jump = jumps[jumps.size() * 99 / 100];
  std::printf("trainer: force jumps between haptic updates: p99 %.3g, p99.9 %.3g, max %.3g (%llu solves, %llu "
              "timed out)\n",
              p99_jump, jumps[jumps.size() * 999 / 1000], max_jump, static_cast<unsigned long long>(ff->solves()),
              static_cast<unsigned long long>(ff->timeouts()));
  RecordProperty("max_force", std::to_string(max_force));
  RecordProperty("max_jump", std::to_string(max_jump));
  RecordProperty("work", std::to_string(work));
  std::printf("trainer: %ld of %d haptic updates with contact force, max |F| %.4g, max jump %.4g at t = %.3f s, "
              "device work %.4g, %zu threads, %d vertices pierced\n",
              nonzero, steps * per_step, max_force, max_jump, jump_at, work, suture->spring_list().size(),
              suture->pierced_count.value());
  // Forces were sent while the needle was in the skin (and continuously).
  EXPECT_GT(nonzero, 3000);
  EXPECT_GT(max_force, 0.1);
  EXPECT_LE(max_jump, kMaxJump) << "at t = " << jump_at;
  EXPECT_LE(jumps[jumps.size() * 999 / 1000], kMaxJump999);
  EXPECT_LE(work, 0.0) << "the device injected energy";
  EXPECT_GE(suture->spring_list().size(), 1u);

  // Tetrahedra removed, each along a tool's path: the scalpel's groove (y = 4, x from 5 to 25,
  // at the top) or the needle's arc (plane y = 10, centre (15, 8.75), radius 6.25).
  const auto tets1 = tetra_set(*volume);
  std::size_t near_scalpel = 0, elsewhere = 0;
  for (const auto& t : tets0) {
    if (tets1.count(t)) continue;
    Vec3 c = Vec3::Zero();
    for (unsigned v : t) c += Vec3(rest[3 * v], rest[3 * v + 1], rest[3 * v + 2]) / 4;
    const double d_scalpel = segment_distance(c, Vec3(5, 4, 4.8), Vec3(25, 4, 4.8));
    const double d_arc = std::hypot(std::abs(std::hypot(c[0] - 15, c[2] - 8.75) - 6.25), c[1] - 10);
    if (d_scalpel < 3.0) ++near_scalpel;
    else if (d_arc > 3.0) ++elsewhere;
  }
  std::printf("trainer: %zu of %zu tetrahedra removed, %zu along the scalpel's path, %zu away from both paths\n",
              tets0.size() - tets1.size(), tets0.size(), near_scalpel, elsewhere);
  EXPECT_GE(near_scalpel, 8u) << "the scalpel's pass removes tetrahedra along its 20-long path";
  EXPECT_EQ(elsewhere, 0u);
}
