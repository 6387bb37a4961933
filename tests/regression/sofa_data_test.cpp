// Checks against SOFA's stored lists and reference files (SINEW_DATA_DIR).
// Every test skips when the data folder is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "regression/gzip_text.h"
#include "regression/scene_list.h"
#include "regression/state_compare.h"
#include "regression/state_file.h"
#include "regression/topology_compare.h"
#include "regression/topology_file.h"
#include "test_paths.h"

namespace sinew::regression {
namespace {

namespace fs = std::filesystem;

const std::string kDataDir = SINEW_DATA_DIR;
const std::string kReferences = kDataDir + "/references/examples";

#define SKIP_WITHOUT_DATA()                                                       \
  do {                                                                            \
    if (!fs::is_directory(kReferences))                                           \
      GTEST_SKIP() << "SOFA data not found at " << kDataDir << " (SINEW_DATA_DIR)"; \
  } while (0)

ListEnvironment data_environment() {
  ListEnvironment env;
  env.regression_dir = kDataDir;  // the lists say $REGRESSION_DIR/references/examples
  return env;
}

// Number of lines of a list file that are neither skipped (empty, '#' first)
// nor the reference-folder line: what the parser must account for.
int scene_lines(const std::string& path) {
  const auto text = read_text_file(path);
  int count = -1;  // the first such line is the reference folder
  std::size_t start = 0;
  while (text && start < text->size()) {
    std::size_t end = text->find('\n', start);
    if (end == std::string::npos) end = text->size();
    if (end > start && (*text)[start] != '#') ++count;
    start = end + 1;
  }
  return count;
}

// Feeds every block of a state file back as the live state, at its own time.
double self_compare(const std::vector<StateBlock>& blocks, int* compared) {
  StateComparer cmp(blocks, 0.01);
  for (const StateBlock& block : blocks) {
    const StateLine* x = nullptr;
    const StateLine* v = nullptr;
    for (const StateLine& line : block.lines) (line.tag == 'X' ? x : v) = &line;
    const std::size_t points = x ? std::max<std::size_t>(1, x->values.size() / 3) : 1;
    cmp.on_step_begin(block.time, x ? x->values.data() : nullptr, x ? x->values.size() : 0,
                      v ? v->values.data() : nullptr, v ? v->values.size() : 0, points);
  }
  *compared = cmp.compared_blocks();
  return cmp.error();
}

TEST(SofaData, FembarStateFile) {
  SKIP_WITHOUT_DATA();
  const std::string path = kReferences +
      "/Component/LinearSolver/Iterative/FEMBAR_CGLinearSolver.scn.reference_0_DoFs_mstate.txt.gz";
  std::string error;
  const auto blocks = read_state_file(path, &error);
  ASSERT_TRUE(blocks.has_value()) << error;
  ASSERT_EQ(blocks->size(), 2u);
  EXPECT_EQ((*blocks)[0].time, 0.0);
  EXPECT_EQ((*blocks)[1].time, 1.98);
  for (const StateBlock& block : *blocks) {
    ASSERT_EQ(block.lines.size(), 2u);
    EXPECT_EQ(block.lines[0].tag, 'X');
    EXPECT_EQ(block.lines[0].values.size(), 960u);  // 320 Vec3 points
    EXPECT_EQ(block.lines[1].tag, 'V');
    EXPECT_EQ(block.lines[1].values.size(), 960u);
  }
  EXPECT_EQ((*blocks)[0].lines[0].values[0], -9.0);
  EXPECT_EQ((*blocks)[1].lines[0].values[48], -9.31076);

  // The reference against its own values, through the real schedule
  // (dt 0.02, 100 steps, accumulated clock): exactly 0, both blocks compared.
  StateComparer cmp(*blocks, 0.02);
  double t = 0.0;
  for (int k = 0; k < 100; ++k) {
    const StateBlock& live = (*blocks)[k == 99 ? 1 : 0];
    cmp.on_step_begin(t, live.lines[0].values.data(), 960, live.lines[1].values.data(), 960, 320);
    t += 0.02;
  }
  EXPECT_EQ(cmp.compared_blocks(), 2);
  EXPECT_EQ(cmp.error(), 0.0);

  // Perturb one scalar at the last step by 1e-5 (a last-digit difference):
  // the §6 noise-floor estimate 1e-5 / 960 / 320.
  StateComparer noisy(*blocks, 0.02);
  t = 0.0;
  for (int k = 0; k < 100; ++k) {
    std::vector<double> x = (*blocks)[k == 99 ? 1 : 0].lines[0].values;
    if (k == 99) x[48] += 1e-5;
    noisy.on_step_begin(t, x.data(), 960, nullptr, 0, 320);
    t += 0.02;
  }
  EXPECT_NEAR(noisy.error(), 1e-5 / 960 / 320, 1e-15);
}

TEST(SofaData, StateSceneList) {
  SKIP_WITHOUT_DATA();
  std::string error;
  const auto list =
      read_scene_list(kDataDir + "/RegressionStateScenes.regression-tests", data_environment(), &error);
  ASSERT_TRUE(list.has_value()) << error;
  EXPECT_TRUE(list->problems.empty()) << list->problems.front();
  EXPECT_EQ(list->reference_dir, kReferences);
  // SOFA's list has 87 state scenes (10 mapped); the data folder may hold a
  // subset (75 and 8 in the visible pack), so check consistency, not totals.
  EXPECT_EQ(static_cast<int>(list->scenes.size()),
            scene_lines(kDataDir + "/RegressionStateScenes.regression-tests"));
  EXPECT_GE(list->scenes.size(), 75u);
  EXPECT_LE(list->scenes.size(), 87u);
  const auto mapped = std::count_if(list->scenes.begin(), list->scenes.end(),
                                    [](const SceneEntry& e) { return e.mapped; });
  EXPECT_GE(mapped, 8);
  EXPECT_LE(mapped, 10);
  // Every listed scene has its compare-mode marker.
  for (const SceneEntry& e : list->scenes) {
    EXPECT_TRUE(fs::is_regular_file(reference_base(*list, e))) << e.scene;
  }
  EXPECT_TRUE(std::all_of(list->scenes.begin(), list->scenes.end(),
                          [](const SceneEntry& e) { return e.last_only && e.period == 0; }));
  const auto liver = std::find_if(list->scenes.begin(), list->scenes.end(),
                                  [](const SceneEntry& e) { return e.scene == "Demos/liver.scn"; });
  ASSERT_NE(liver, list->scenes.end());
  EXPECT_EQ(liver->steps, 100);
  EXPECT_DOUBLE_EQ(liver->epsilon, 1e-4);
  EXPECT_TRUE(liver->mapped);
  EXPECT_EQ(reference_base(*list, *liver), kReferences + "/Demos/liver.scn.reference");
  // The reference base is an (empty) marker file: compare mode.
  EXPECT_TRUE(fs::is_regular_file(reference_base(*list, *liver)));
  EXPECT_TRUE(fs::exists(reference_base(*list, *liver) + "_0_dofs_mstate.txt.gz"));
  const SceneEntry& first = list->scenes.front();
  EXPECT_EQ(first.scene, "Demos/TriangleSurfaceCutting.scn");
  EXPECT_EQ(first.line, 25);
}

TEST(SofaData, TopologySceneList) {
  SKIP_WITHOUT_DATA();
  const auto list = read_scene_list(kDataDir + "/RegressionTopologyScenes.regression-tests",
                                    data_environment(), nullptr);
  ASSERT_TRUE(list.has_value());
  // 15 scenes in SOFA's list (13 in the visible pack); all but one mapped.
  EXPECT_EQ(static_cast<int>(list->scenes.size()),
            scene_lines(kDataDir + "/RegressionTopologyScenes.regression-tests"));
  EXPECT_GE(list->scenes.size(), 13u);
  EXPECT_LE(list->scenes.size(), 15u);
  EXPECT_EQ(std::count_if(list->scenes.begin(), list->scenes.end(),
                          [](const SceneEntry& e) { return !e.mapped; }),
            1);
  EXPECT_TRUE(list->problems.empty());
  const auto removing = std::find_if(list->scenes.begin(), list->scenes.end(), [](const auto& e) {
    return e.scene == "Component/Topology/Container/Dynamic/RemovingTriangle2EdgeProcess.scn";
  });
  ASSERT_NE(removing, list->scenes.end());
  EXPECT_EQ(removing->steps, 30);
  EXPECT_FALSE(removing->mapped);  // only 3 tokens on that line
  EXPECT_FALSE(removing->last_only);
}

TEST(SofaData, TruncatedTopologyFile) {
  SKIP_WITHOUT_DATA();
  const std::string path = kReferences +
      "/Component/Topology/Container/Dynamic/"
      "RemovingTriangle2EdgeProcess.scn.reference_1_Edge_topo_topology.txt.gz";
  std::string error;
  const auto blocks = read_topology_file(path, &error);
  ASSERT_TRUE(blocks.has_value()) << error;
  ASSERT_EQ(blocks->size(), 21u);
  EXPECT_EQ(blocks->front().time, 0.0);
  EXPECT_EQ(blocks->back().time, 0.2);
  EXPECT_EQ(blocks->front().counts, (std::array<long long, 5>{96, 0, 0, 0, 0}));
  for (const TopologyBlock& block : *blocks) {
    EXPECT_EQ(block.indices[0].size(), static_cast<std::size_t>(2 * block.counts[0]));
  }
  // Replaying the file as the live topology (30 steps, dt 0.01): 16 blocks
  // compared (0.1 ... 0.14 skipped, end of file after 0.2), no error.
  TopologyComparer cmp(*blocks);
  double t = 0.0;
  std::size_t last_written = 0;
  std::vector<std::uint32_t> edges;
  for (int k = 0; k < 30; ++k) {
    last_written = std::min<std::size_t>(k, blocks->size() - 1);
    const auto& ref = (*blocks)[last_written].indices[0];
    edges.assign(ref.begin(), ref.end());
    TopologyView live;
    live.indices[0] = edges;
    cmp.on_step_begin(t, live);
    t += 0.01;
  }
  EXPECT_EQ(cmp.compared_blocks(), 16);
  EXPECT_EQ(cmp.total_error(), 0);
}

TEST(SofaData, EveryReferenceFileReads) {
  SKIP_WITHOUT_DATA();
  int state_files = 0, topology_files = 0, truncated = 0, with_v = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kReferences)) {
    const std::string path = entry.path().string();
    const bool state = path.ends_with("_mstate.txt.gz");
    if (!state && !path.ends_with("_topology.txt.gz")) continue;
    std::string error;
    if (state) {
      const auto blocks = read_state_file(path, &error);
      ASSERT_TRUE(blocks.has_value()) << error;
      ++state_files;
      EXPECT_TRUE(blocks->size() == 2 || blocks->size() == 100) << path;
      with_v += blocks->front().lines.size() == 2;
      int compared = 0;
      EXPECT_EQ(self_compare(*blocks, &compared), 0.0) << path;
      EXPECT_EQ(compared, static_cast<int>(blocks->size())) << path;
    } else {
      const auto blocks = read_topology_file(path, &error);
      ASSERT_TRUE(blocks.has_value()) << error;
      ++topology_files;
      EXPECT_TRUE(blocks->size() == 30 || blocks->size() == 21) << path;
      truncated += blocks->size() == 21;
    }
  }
  // SOFA's full set: 208 state files (147 with V) and 38 topology files; the
  // data folder may hold a subset. The 3 truncated files are all present.
  EXPECT_GE(state_files, 182);
  EXPECT_LE(state_files, 208);
  EXPECT_GE(with_v, 1);
  EXPECT_LT(with_v, state_files);  // both generations (X only, X and V) occur
  EXPECT_GE(topology_files, 32);
  EXPECT_LE(topology_files, 38);
  EXPECT_EQ(truncated, 3);
}

}  // namespace
}  // namespace sinew::regression
