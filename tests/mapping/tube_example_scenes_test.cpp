// SOFA's three example scenes with a tubular skin (Edge2QuadTopologicalMapping +
// TubularMapping), run for 100 steps as `sinew run` does: they load without a
// message about these components, stay finite, keep their fixed points fixed,
// and move as the physics says.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "badinput_helpers.h"
#include "runner/session.h"
#include "test_scene.h"
#include "topology/dynamic/quad_set_topology_container.h"
#include "test_paths.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

const fs::path kData = SINEW_DATA_DIR;

// The scene loaded and run for `steps` steps; skipped when SOFA's data is absent.
struct SceneRun {
  std::unique_ptr<runner::Session> session;
  explicit SceneRun(const std::string& rel, long steps = 100) {
    const fs::path scene = kData / "examples" / rel;
    if (!fs::exists(scene)) return;
    runner::SessionOptions opts;
    opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
    session = std::make_unique<runner::Session>(scene.string(), opts);
    if (!session->ok()) return;
    for (long i = 0; i < steps; ++i)
      if (!session->step()) break;
  }
  Node& node(std::initializer_list<const char*> path) {
    Node* n = &session->root();
    for (const char* name : path) n = n ? n->find_child_named(name) : nullptr;
    if (!n) throw std::runtime_error("node not found");
    return *n;
  }
  // Errors, and warnings about the components of this change.
  std::vector<std::string> problems() const {
    std::vector<std::string> out = test::messages(session->diagnostics(), Severity::error);
    for (const std::string& w : test::messages(session->diagnostics(), Severity::warning)) {
      const std::string text = w.substr(w.find("warning:"));  // not the file name, which may hold a class name
      for (const char* c : {"Edge2Quad", "Tubular", "Barycentric", "UniformMass", "vertexMass"})
        if (text.find(c) != std::string::npos) out.push_back(w);
    }
    return out;
  }
};

#define SKIP_OR_CHECK_RUN(run)                                                   \
  if (!(run).session) GTEST_SKIP() << "SOFA data not found at " << kData;       \
  ASSERT_TRUE((run).session->ok()) << (run).problems().front();                 \
  ASSERT_EQ((run).session->steps_done(), 100)

// Distances of every ring point to its frame's centre: min and max.
std::pair<double, double> ring_radii(const MechanicalState& frames, const std::vector<double>& rings, unsigned n) {
  const std::vector<double>& c = frames.read(kPosition);
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < frames.size(); ++i)
    for (unsigned j = 0; j < n; ++j) {
      const double* p = &rings[(i * n + j) * 3];
      const double d = std::hypot(p[0] - c[i * 7], p[1] - c[i * 7 + 1], p[2] - c[i * 7 + 2]);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  return {lo, hi};
}

TEST(TubeExampleScenes, FixedLagrangianConstraintRigid3HoldsACantilever) {
  SceneRun run("Component/Constraint/Lagrangian/FixedLagrangianConstaint_Rigid3.scn");
  SKIP_OR_CHECK_RUN(run);
  EXPECT_TRUE(run.problems().empty()) << run.problems().front();
  EXPECT_TRUE(test::all_finite(run.session->root()));
  const MechanicalState& beam = *test::get<MechanicalState>(run.node({"Needle"}), "mstate");
  const std::vector<double>& x = beam.read(kPosition);
  // Node 0 is held by the Lagrangian constraint.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(x[k], 0.0, 1e-9) << k;
  // The tip (0.13 m, r = 0.723 mm, E = 2e11, 1 g) sags under gravity (−z) about as a cantilever
  // under its weight, w·L⁴/(8·E·I) = 6.3e-5 m (lumped masses put a little more load near the tip).
  const double tip_z = x[13 * 7 + 2];
  EXPECT_LT(tip_z, -5.5e-5);
  EXPECT_GT(tip_z, -8e-5);
  // The skin: 10 points around each of the 14 frames, at the radius of the beam.
  const auto& skin = *test::get<MechanicalState>(run.node({"Needle", "VM"}), "VisualDOFs");
  ASSERT_EQ(skin.size(), 140u);
  const auto [lo, hi] = ring_radii(beam, skin.read(kPosition), 10);
  EXPECT_NEAR(lo, 0.000723, 1e-9);
  EXPECT_NEAR(hi, 0.000723, 1e-9);
  EXPECT_EQ(test::get<QuadSetTopologyContainer>(run.node({"Needle", "VM"}), "ContainerCath")->quads().size(), 130u);
}

TEST(TubeExampleScenes, Edge2QuadTopologicalMappingSkinsAFallingBeam) {
  SceneRun run("Component/Topology/Mapping/Edge2QuadTopologicalMapping.scn");
  SKIP_OR_CHECK_RUN(run);
  EXPECT_TRUE(run.problems().empty()) << run.problems().front();
  EXPECT_TRUE(test::all_finite(run.session->root()));
  const MechanicalState& beam = *test::get<MechanicalState>(run.node({"Beam"}), "BeamDof");
  const std::vector<double>& x = beam.read(kPosition);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(x[k], 0.0) << k;  // FixedProjectiveConstraint on node 0
  // The soft 100-unit beam bends down under gravity (−y), slower than free fall (½·9·0.99² = 4.4).
  const double tip_y = x[99 * 7 + 1];
  EXPECT_LT(tip_y, -2.0);
  EXPECT_GT(tip_y, -4.4);
  Node& visu = run.node({"Beam", "VisuBeam"});
  EXPECT_EQ(test::get<QuadSetTopologyContainer>(visu, "Container")->quads().size(), 990u);
  auto* skin = test::get<VisualState>(visu, "SurfDof");
  ASSERT_EQ(skin->visual_size(), 1000u);
  const auto [lo, hi] = ring_radii(beam, *skin->visual_vec(kPosition), 10);
  EXPECT_NEAR(lo, 2.0, 1e-6);
  EXPECT_NEAR(hi, 2.0, 1e-6);
}

TEST(TubeExampleScenes, BarycentricMappingTrussBeamCarriesTheBeamWithTheTruss) {
  SceneRun run("Component/Mapping/Linear/BarycentricMappingTrussBeam.scn");
  SKIP_OR_CHECK_RUN(run);
  EXPECT_TRUE(run.problems().empty()) << run.problems().front();
  EXPECT_TRUE(test::all_finite(run.session->root()));
  Node& beam_node = run.node({"Truss", "Beam"});
  const MechanicalState& beam = *test::get<MechanicalState>(beam_node, "BeamMO");
  const std::vector<double>& b = beam.read(kPosition);
  ASSERT_EQ(beam.size(), 6u);
  // Frame 0 sits on the truss corner held by the BoxConstraint.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b[k], 0.0, 1e-12) << k;
  // The truss, pushed along −y, carries the beam's tip down by a few millimetres in 1 s,
  // twisting it about x (the −10 torque on the tip only slows that twist).
  EXPECT_LT(b[5 * 7 + 1], -0.002);
  EXPECT_GT(b[5 * 7 + 1], -0.02);
  EXPECT_GT(b[5 * 7 + 3], 0.0);
  const auto& skin = *test::get<MechanicalState>(run.node({"Truss", "Beam", "VisuThread"}), "Quads");
  ASSERT_EQ(skin.size(), 60u);
  const auto [lo, hi] = ring_radii(beam, skin.read(kPosition), 10);
  EXPECT_NEAR(lo, 0.005, 1e-8);
  EXPECT_NEAR(hi, 0.005, 1e-8);
}

}  // namespace
}  // namespace sinew
