// SparseGridMultipleTopology (spec/mechanics.md §5.4): several surfaces voxelized on one grid,
// each cell with the stiffness and mass coefficients of the surfaces it is in.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <unistd.h>

#include "badinput_helpers.h"
#include "runner/session.h"
#include "test_paths.h"
#include "test_scene.h"
#include "topology/grid/sparse_grid_multiple_topology.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

namespace fs = std::filesystem;

// Writes the closed surface of the box [lo, hi] (12 outward triangles) as an OBJ file. The
// name carries the process id: ctest runs these tests in parallel processes, and two of them
// writing one file while the other reads it gave an empty mesh.
std::string box_obj(const std::string& name, Vec3 lo, Vec3 hi) {
  const fs::path path =
      fs::temp_directory_path() / ("sinew_sgm_" + std::to_string(::getpid()) + "_" + name + ".obj");
  std::ofstream out(path);
  out.precision(17);
  for (int k = 0; k < 8; ++k)
    out << "v " << ((k == 1 || k == 2 || k == 5 || k == 6) ? hi[0] : lo[0]) << ' '
        << ((k == 2 || k == 3 || k == 6 || k == 7) ? hi[1] : lo[1]) << ' ' << (k >= 4 ? hi[2] : lo[2]) << '\n';
  static constexpr int kTris[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                       {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  for (const auto& t : kTris) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return path.string();
}

// Coefficients of the grid's hexahedra, counted by value.
std::map<float, int> histogram(const SparseGridMultipleTopology& g, bool stiffness) {
  std::map<float, int> h;
  for (std::size_t i = 0; i < g.hexahedra().size(); ++i) ++h[stiffness ? g.stiffness_coef(i) : g.mass_coef(i)];
  return h;
}

}  // namespace

// No fileTopology: with ramifications at the finest level nothing would connect the cells.
TEST(SparseGridMultipleTopology, RamificationsWithoutTheirSurfaceAreAnError) {
  const std::string outer = box_obj("outer", Vec3(0.1, 0.1, 0.1), Vec3(3.9, 3.9, 3.9));
  auto s = test::build("<Node><SparseGridMultipleTopology name='g' n='7 7 7' fileTopologies='" + outer + "'/></Node>");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "fileTopology is needed"));
}

// A box [0.1, 3.9]³ holding a box [1.6, 2.4]³, on the grid of unit cells [-1, 5]³: the outer
// surface crosses the shell of 56 cells around the 8 cells [1, 3]³, which the inner surface
// crosses. So the outer box gives 56 boundary cells (k/2 with fillWeighted) and 8 inside cells
// (k); the inner one, whose cells are all boundary, blends its coefficient into those 8.
TEST(SparseGridMultipleTopology, NestedBoxesBlendTheirCoefficients) {
  const std::string outer = box_obj("outer", Vec3(0.1, 0.1, 0.1), Vec3(3.9, 3.9, 3.9));
  const std::string inner = box_obj("inner", Vec3(1.6, 1.6, 1.6), Vec3(2.4, 2.4, 2.4));
  auto scene = [&](const std::string& extra) {
    return "<Node><SparseGridMultipleTopology name='g' n='7 7 7' min='-1 -1 -1' max='5 5 5' "
           "computeRamifications='0' fileTopologies='" +
           outer + " " + inner + "' stiffnessCoefs='10 100' massCoefs='2 0.2' " + extra + "/></Node>";
  };
  {
    auto s = load(scene(""));
    auto* g = get<SparseGridMultipleTopology>(*s.root, "g");
    ASSERT_NE(g, nullptr);
    ASSERT_EQ(g->hexahedra().size(), 64u);
    EXPECT_EQ(g->nb_points(), 125u);
    EXPECT_EQ(histogram(*g, true), (std::map<float, int>{{5.0f, 56}, {55.0f, 8}}));
    EXPECT_EQ(histogram(*g, false), (std::map<float, int>{{1.0f, 56}, {(2.0f + 0.2f) * .5f, 8}}));
    // Boundary cells first: the shell, then the 8 inner cells (inside for the outer box).
    for (std::size_t h = 0; h < 64; ++h)
      EXPECT_EQ(g->cell_type(h), h < 56 ? SparseGridTopology::CellType::boundary
                                        : SparseGridTopology::CellType::inside);
  }
  {
    // Each surface cell takes the file's coefficient: the shell 10 (not 10/2), the core 100.
    auto s = load(scene("erasePreviousCoef='1'"));
    auto* g = get<SparseGridMultipleTopology>(*s.root, "g");
    EXPECT_EQ(histogram(*g, true), (std::map<float, int>{{10.0f, 56}, {100.0f, 8}}));
  }
  {
    auto s = load(scene("fillWeighted='0'"));
    auto* g = get<SparseGridMultipleTopology>(*s.root, "g");
    EXPECT_EQ(histogram(*g, true), (std::map<float, int>{{10.0f, 56}, {100.0f, 8}}));
    for (std::size_t h = 0; h < 64; ++h) EXPECT_EQ(g->cell_type(h), SparseGridTopology::CellType::inside);
  }
}

// With one file the grid is SparseGridRamificationTopology's over that file (cells, points,
// coefficients), with and without virtual finer levels.
TEST(SparseGridMultipleTopology, OneFileGivesTheRamificationGrid) {
  const fs::path mesh = fs::path(SINEW_DATA_DIR) / "share" / "mesh" / "frog_body.obj";
  if (!fs::exists(mesh)) GTEST_SKIP() << "no " << mesh;
  for (const char* levels : {"0", "1"}) {
    const std::string common = std::string("n='9 9 7' nbVirtualFinerLevels='") + levels + "' ";
    auto s = load("<Node><SparseGridMultipleTopology name='m' " + common + "fileTopology='" + mesh.string() +
                  "' fileTopologies='" + mesh.string() + "' stiffnessCoefs='1' massCoefs='1'/>"
                  "<SparseGridRamificationTopology name='r' " + common + "fileTopology='" + mesh.string() +
                  "'/></Node>");
    auto* m = get<SparseGridMultipleTopology>(*s.root, "m");
    auto* r = get<SparseGridRamificationTopology>(*s.root, "r");
    ASSERT_TRUE(m && r);
    ASSERT_GT(r->hexahedra().size(), 50u) << levels;
    EXPECT_EQ(m->hexahedra(), r->hexahedra()) << levels;
    EXPECT_EQ(m->position.value(), r->position.value()) << levels;
    for (std::size_t h = 0; h < r->hexahedra().size(); ++h) {
      ASSERT_EQ(m->stiffness_coef(h), r->stiffness_coef(h)) << levels << " hexahedron " << h;
      ASSERT_EQ(m->mass_coef(h), r->mass_coef(h)) << levels << " hexahedron " << h;
    }
  }
}

// SOFA's example: the frog's body (10), eyes and eyebrows (100) and lips (0.2) on one grid with a
// virtual finer level; 100 steps run with finite states.
TEST(SparseGridMultipleTopology, SofaExampleRuns) {
  const fs::path data = SINEW_DATA_DIR;
  const fs::path scene = data / "examples/Component/Topology/Container/Grid/SparseGridMultipleTopology.scn";
  if (!fs::exists(scene)) GTEST_SKIP() << "SOFA data not found at " << data;
  runner::SessionOptions opts;
  opts.data_paths = {(data / "share").string(), (data / "examples").string()};
  runner::Session session(scene.string(), opts);
  ASSERT_TRUE(session.ok());
  std::vector<SparseGridMultipleTopology*> grids;
  session.root().collect_down(grids);
  ASSERT_EQ(grids.size(), 1u);
  const SparseGridMultipleTopology& g = *grids[0];
  ASSERT_GT(g.hexahedra().size(), 100u);
  // Coarse coefficients average their 8 finer cells: the eyes' 100 raises some well above the
  // body's 10, the lips' 0.2 lowers others below it.
  float lo = 1e9f, hi = 0;
  for (std::size_t h = 0; h < g.hexahedra().size(); ++h) {
    lo = std::min(lo, g.stiffness_coef(h));
    hi = std::max(hi, g.stiffness_coef(h));
  }
  EXPECT_GT(hi, 10.0f);
  EXPECT_LT(lo, 5.0f);
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  EXPECT_TRUE(test::all_finite(session.root()));
  const auto errors = test::messages(session.diagnostics(), Severity::error);
  EXPECT_TRUE(errors.empty()) << errors.front();
}
