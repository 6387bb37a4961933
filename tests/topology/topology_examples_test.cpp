// Every SOFA example scene that uses TopologicalChangeProcessor runs to the end of its change
// file (its last `T=` block plus ten steps; 100 steps at least) as `sinew run` does: no error,
// finite states. One CTest case per scene; skipped without SOFA's data. The list must equal
// the scenes of examples/ that use the component (checked below), so a new one is not missed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "badinput_helpers.h"
#include "runner/session.h"
#include "test_scene.h"
#include "topology/dynamic/element_removal.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "test_paths.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

const fs::path kData = SINEW_DATA_DIR;

// Scene and steps: ceil(last T / dt) + 10, at least 100.
const std::vector<std::pair<std::string, int>> kScenes = {
    {"Benchmark/TopologicalChanges/AffineMovementConstraint__RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/FixedConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/FixedPlaneConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/LinearMovementConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/ProjectDirectionConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/ProjectToLineConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/ProjectToPlaneConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/ProjectToPointConstraint_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/TriangularBendingSprings_RemovingMeshTest.scn", 110},
    {"Benchmark/TopologicalChanges/TriangularFEMForceField_RemovingMeshTest.scn", 110},
    {"Component/Topology/Container/Dynamic/AddingHexa2QuadProcess.scn", 290},
    {"Component/Topology/Container/Dynamic/AddingPointInTriangleProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/AddingQuad2TriangleProcess.scn", 370},
    {"Component/Topology/Container/Dynamic/AddingTetra2TriangleProcess.scn", 130},
    {"Component/Topology/Container/Dynamic/AddingTetraProcess.scn", 130},
    {"Component/Topology/Container/Dynamic/AddingTriangle2EdgeProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/AddingTrianglesProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/HexahedronForceFieldTopologyChangeHandling.scn", 100},
    {"Component/Topology/Container/Dynamic/IncisionTrianglesProcess.scn", 460},
    {"Component/Topology/Container/Dynamic/QuadForceFieldTopologyChangeHandling.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingBilateralInteractionConstraint.scn", 160},
    {"Component/Topology/Container/Dynamic/RemovingHexa2QuadProcess.scn", 105},
    {"Component/Topology/Container/Dynamic/RemovingPointSprings.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingQuad2TriangleProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTetra2TriangleProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTetra2TriangleProcess_performanceTest.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTetra2Triangle_options1.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTetra2Triangle_options2.scn", 260},
    {"Component/Topology/Container/Dynamic/RemovingTetraProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTetraProcess_withCollisionModel.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTriangle2EdgeProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/RemovingTrianglesProcess.scn", 100},
    {"Component/Topology/Container/Dynamic/TetrahedronForceFieldTopologyChangeHandling.scn", 100},
    {"Component/Topology/Container/Dynamic/TriangularForceFieldTopologyChangeHandling.scn", 100},
    {"Component/Topology/Utility/TopologicalChangeProcessor_useDataInputs_option.scn", 100},
};

class TopologicalChangeExamples : public ::testing::TestWithParam<std::pair<std::string, int>> {};

TEST_P(TopologicalChangeExamples, RunToTheEndOfTheirChanges) {
  const auto& [rel, steps] = GetParam();
  if (!fs::exists(kData / "examples" / rel)) GTEST_SKIP() << "SOFA data not found at " << kData;
  runner::SessionOptions opts;
  opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
  runner::Session session((kData / "examples" / rel).string(), opts);
  ASSERT_TRUE(session.ok()) << "does not load";
  std::vector<PointSetTopologyContainer*> containers;
  session.root().collect_down(containers);
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(session.step()) << "step " << i;
    // Every dynamic container stays consistent: shells agree with the lists, no index dangles.
    for (PointSetTopologyContainer* c : containers)
      ASSERT_EQ(topo::check_dynamic_mesh(c->begin_edit()), "") << c->describe() << " after step " << i;
  }
  EXPECT_TRUE(test::all_finite(session.root()));
  const auto errors = test::messages(session.diagnostics(), Severity::error);
  EXPECT_TRUE(errors.empty()) << errors.front();
}

INSTANTIATE_TEST_SUITE_P(Sofa, TopologicalChangeExamples, ::testing::ValuesIn(kScenes), [](const auto& info) {
  std::string n = fs::path(info.param.first).stem().string();
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

// TopologyBoundingTrasher.scn: the square falls (gravity −1) out of its box; once its triangles'
// barycentres cross y = −10 (≈ 4.5 s) they are removed, all of them by step 800.
TEST(TopologicalChangeExamples, TopologyBoundingTrasherEmptiesTheFallenSquare) {
  const std::string rel = "Component/Topology/Utility/TopologyBoundingTrasher.scn";
  if (!fs::exists(kData / "examples" / rel)) GTEST_SKIP() << "SOFA data not found at " << kData;
  runner::SessionOptions opts;
  opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
  runner::Session session((kData / "examples" / rel).string(), opts);
  ASSERT_TRUE(session.ok());
  auto* c = session.root().find_child_named("SquareGravity")->find_local<PointSetTopologyContainer>();
  ASSERT_EQ(c->triangles().size(), 1450u);
  std::size_t at_400 = 0;
  for (int i = 0; i < 800; ++i) {
    ASSERT_TRUE(session.step()) << "step " << i;
    ASSERT_EQ(topo::check_dynamic_mesh(c->begin_edit()), "") << "after step " << i;
    if (i == 399) at_400 = c->triangles().size();
  }
  EXPECT_EQ(at_400, 1450u);  // still inside at t = 4 s
  EXPECT_EQ(c->triangles().size(), 0u);
  EXPECT_EQ(c->nb_points(), 0u);
  EXPECT_TRUE(test::messages(session.diagnostics(), Severity::error).empty());
}

// The list above is every example scene that uses the component.
TEST(TopologicalChangeExamples, ListIsEveryExampleUsingTheProcessor) {
  if (!fs::exists(kData / "examples")) GTEST_SKIP() << "SOFA data not found at " << kData;
  std::set<std::string> found, listed;
  for (const auto& e : fs::recursive_directory_iterator(kData / "examples")) {
    if (e.path().extension() != ".scn") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().find("<TopologicalChangeProcessor") != std::string::npos)
      found.insert(fs::relative(e.path(), kData / "examples").generic_string());
  }
  for (const auto& [rel, steps] : kScenes) listed.insert(rel);
  EXPECT_EQ(found, listed);
}

}  // namespace
}  // namespace sinew
