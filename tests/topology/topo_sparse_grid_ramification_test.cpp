// SparseGridRamificationTopology (spec/mechanics.md §5.5): cells split by the connectivity of
// the surface pieces they cover; connected surfaces give SparseGridTopology's cells.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "test_scene.h"
#include "topology/grid/sparse_grid_ramification_topology.h"
#include "test_paths.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

template <class T>
T& find(scene::LoadedScene& s, std::string_view name) {
  T* t = get<T>(*s.root, name);
  if (!t) throw std::runtime_error("component not found: " + std::string(name));
  return *t;
}

// Closed surface of the box [lo, hi] (12 outward triangles), appended to position/triangles.
void add_box(std::string& position, std::string& triangles, int& count, Vec3 lo, Vec3 hi) {
  for (int k = 0; k < 8; ++k) {
    const Vec3 p((k == 1 || k == 2 || k == 5 || k == 6) ? hi[0] : lo[0],
                 (k == 2 || k == 3 || k == 6 || k == 7) ? hi[1] : lo[1], k >= 4 ? hi[2] : lo[2]);
    position += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "  ";
  }
  static constexpr int kTris[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                       {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  for (const auto& t : kTris)
    for (int v : t) triangles += std::to_string(count + v) + " ";
  count += 8;
}

// A scene with one grid component `type` over the given boxes.
std::string grid_scene(const std::string& type, const std::string& attributes,
                       const std::vector<std::pair<Vec3, Vec3>>& boxes) {
  std::string position, triangles;
  int count = 0;
  for (const auto& [lo, hi] : boxes) add_box(position, triangles, count, lo, hi);
  return "<Node><" + type + " name=\"g\" " + attributes + " position=\"" + position + "\" triangles=\"" + triangles +
         "\"/></Node>";
}

std::set<unsigned> corners_of(const Hexa& h) { return {h.begin(), h.end()}; }

bool has_error(scene::LoadedScene& s, std::string_view needle) {
  return test::any_contains(test::messages(s.root->diagnostics(), Severity::error), needle);
}

}  // namespace

TEST(TopoSparseGridRamification, TwoPiecesInOneCoarseCellGetTwoHexahedra) {
  // Two unit boxes far apart along x inside one coarse cell; the finest level (4 cells per axis)
  // puts them in cells 0 and 3, with empty cells between: two connexions, two hexahedra.
  const std::vector<std::pair<Vec3, Vec3>> boxes{{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(5, 0, 0), Vec3(6, 1, 1)}};
  const std::string attrs = R"(n="2 2 2" nbVirtualFinerLevels="2" finestConnectivity="0")";
  auto plain = load(grid_scene("SparseGridTopology", attrs, boxes));
  auto& sg = find<SparseGridTopology>(plain, "g");
  ASSERT_EQ(sg.hexahedra().size(), 1u);
  EXPECT_EQ(sg.nb_points(), 8u);

  auto s = load(grid_scene("SparseGridRamificationTopology", attrs, boxes));
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  const auto& h = g.hexahedra();
  ASSERT_EQ(h.size(), 2u);
  ASSERT_EQ(g.nb_points(), 16u);
  EXPECT_EQ(h[0], (Hexa{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(h[1], (Hexa{8, 9, 10, 11, 12, 13, 14, 15}));
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(g.point(h[0][k]), g.point(h[1][k])) << k;  // same cell, same corners
    EXPECT_EQ(g.point(h[0][k]), sg.point(sg.hexahedra()[0][k])) << k;
  }
  EXPECT_EQ(g.cell_type(0), SparseGridTopology::CellType::boundary);
  EXPECT_EQ(g.cell_type(1), SparseGridTopology::CellType::boundary);
  // Look-ups go through the finest level: each box maps to its own hexahedron.
  double fx = -1, fy = -1, fz = -1;
  EXPECT_EQ(g.find_cube(Vec3(0.5, 0.5, 0.5), fx, fy, fz), 0u);
  EXPECT_NEAR(fx, (0.5 + 0.06) / 6.12, 1e-12);
  EXPECT_EQ(g.find_cube(Vec3(5.5, 0.5, 0.5), fx, fy, fz), 1u);
  EXPECT_EQ(g.find_cube(Vec3(3, 0.5, 0.5), fx, fy, fz), ~0u);  // between the boxes: outside
  EXPECT_EQ(g.find_nearest_cube(Vec3(5.9, 0.5, 0.5), fx, fy, fz), 1u);
}

TEST(TopoSparseGridRamification, FinestConnectivityUnlinksCellsNoEdgeCrosses) {
  // Two boxes in the two cells of a 3×2×2 grid: no surface edge crosses the common face at
  // x = 2.5, so with finestConnectivity the cells keep their own points (16 instead of 12).
  const std::vector<std::pair<Vec3, Vec3>> boxes{{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(4, 0, 0), Vec3(5, 1, 1)}};
  auto plain = load(grid_scene("SparseGridTopology", R"(n="3 2 2")", boxes));
  EXPECT_EQ(find<SparseGridTopology>(plain, "g").nb_points(), 12u);

  auto s = load(grid_scene("SparseGridRamificationTopology", R"(n="3 2 2" finestConnectivity="1")", boxes));
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  ASSERT_EQ(g.hexahedra().size(), 2u);
  EXPECT_EQ(g.nb_points(), 16u);
  std::set<unsigned> shared;
  for (unsigned p : corners_of(g.hexahedra()[0]))
    if (corners_of(g.hexahedra()[1]).count(p)) shared.insert(p);
  EXPECT_TRUE(shared.empty());

  // A box spanning both cells: its edges cross the common face, the cells stay glued.
  auto one = load(grid_scene("SparseGridRamificationTopology", R"(n="3 2 2" finestConnectivity="1")",
                             {{Vec3(0, 0, 0), Vec3(5, 1, 1)}}));
  auto& g1 = find<SparseGridRamificationTopology>(one, "g");
  ASSERT_EQ(g1.hexahedra().size(), 2u);
  EXPECT_EQ(g1.nb_points(), 12u);

  // Without finestConnectivity nor virtual levels, it is SparseGridTopology exactly.
  auto off = load(grid_scene("SparseGridRamificationTopology", R"(n="3 2 2" finestConnectivity="0")", boxes));
  auto& g0 = find<SparseGridRamificationTopology>(off, "g");
  auto& sg = find<SparseGridTopology>(plain, "g");
  EXPECT_EQ(g0.hexahedra(), sg.hexahedra());
  EXPECT_EQ(g0.position.get(), sg.position.get());
}

TEST(TopoSparseGridRamification, ConnectedSurfaceGivesTheSparseGrid) {
  // One closed box, one virtual finer level: each coarse cell holds one connected piece, so the
  // cells, their types and corner positions are SparseGridTopology's (points numbered differently).
  const std::vector<std::pair<Vec3, Vec3>> boxes{{Vec3(-1, -1, -1), Vec3(1, 1, 1)}};
  const std::string attrs = R"(n="3 3 3" nbVirtualFinerLevels="1" finestConnectivity="0")";
  auto plain = load(grid_scene("SparseGridTopology", attrs, boxes));
  auto s = load(grid_scene("SparseGridRamificationTopology", attrs, boxes));
  auto& sg = find<SparseGridTopology>(plain, "g");
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  ASSERT_EQ(g.hexahedra().size(), sg.hexahedra().size());
  ASSERT_EQ(g.hexahedra().size(), 8u);
  EXPECT_EQ(g.nb_points(), sg.nb_points());
  EXPECT_EQ(g.nb_points(), 27u);
  for (std::size_t e = 0; e < g.hexahedra().size(); ++e) {
    EXPECT_EQ(g.cell_type(e), sg.cell_type(e)) << e;
    EXPECT_FLOAT_EQ(g.stiffness_coef(e), sg.stiffness_coef(e)) << e;
    for (int k = 0; k < 8; ++k)
      EXPECT_EQ(g.point(g.hexahedra()[e][k]), sg.point(sg.hexahedra()[e][k])) << e << " " << k;
  }
  double fx, fy, fz, gx, gy, gz;
  EXPECT_EQ(g.find_cube(Vec3(0.3, -0.2, 0.7), fx, fy, fz), sg.find_cube(Vec3(0.3, -0.2, 0.7), gx, gy, gz));
  EXPECT_NEAR(fx, gx, 1e-12);
  EXPECT_NEAR(fz, gz, 1e-12);
}

TEST(TopoSparseGridRamification, SofaSceneGridsOfTheCShape) {
  // mesh/c.obj as in SOFA's SparseGridRamificationTopology.scn: the two arms of the C share
  // coarse cells. SOFA's reference states have 32 and 54 points.
  const std::filesystem::path mesh = std::filesystem::path(SINEW_DATA_DIR) / "share" / "mesh" / "c.obj";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "no " << mesh;
  auto s = load(
      "<Node><SparseGridRamificationTopology name=\"a\" n=\"5 2 2\" nbVirtualFinerLevels=\"3\" "
      "finestConnectivity=\"0\" fileTopology=\"" +
      mesh.string() +
      "\"/>"
      "<SparseGridRamificationTopology name=\"b\" n=\"5 3 3\" nbVirtualFinerLevels=\"0\" "
      "finestConnectivity=\"1\" fileTopology=\"" +
      mesh.string() + "\"/></Node>");
  auto& a = find<SparseGridRamificationTopology>(s, "a");
  EXPECT_EQ(a.nb_points(), 32u);
  ASSERT_EQ(a.hexahedra().size(), 7u);  // 4 cells along x; the 3 crossed by both arms are split
  EXPECT_EQ(a.hexahedra()[1], (Hexa{1, 8, 9, 2, 5, 10, 11, 6}));
  EXPECT_EQ(a.hexahedra()[2], (Hexa{1, 12, 13, 2, 5, 14, 15, 6}));
  EXPECT_NEAR(a.point(0)[0], -15.7071, 1e-4);
  auto& b = find<SparseGridRamificationTopology>(s, "b");
  EXPECT_EQ(b.nb_points(), 54u);
  EXPECT_EQ(b.hexahedra().size(), 16u);
  // Coefficients averaged over the children; a split hexahedron keeps only its last child, as in
  // SOFA (with these values HexahedronFEMForceFieldAndMass reproduces SOFA's trajectories).
  EXPECT_FLOAT_EQ(a.stiffness_coef(0), 47.0f / 128.0f);
  for (std::size_t e = 1; e < a.hexahedra().size(); ++e) {
    EXPECT_EQ(a.cell_type(e), SparseGridTopology::CellType::boundary) << e;
    EXPECT_FLOAT_EQ(a.stiffness_coef(e), 1.0f / 32.0f) << e;
    EXPECT_FLOAT_EQ(a.mass_coef(e), 1.0f / 32.0f) << e;
  }
}

TEST(TopoSparseGridRamification, SofaSceneGridOfTheOLetterFromVerticesOnly) {
  // Demos/SofaScene.scn builds its grid from the loader's vertices only (no facets); SOFA's
  // reference state has 32 points.
  const std::filesystem::path mesh = std::filesystem::path(SINEW_DATA_DIR) / "share" / "mesh" / "SofaScene" / "O.obj";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "no " << mesh;
  auto s = load("<Node><MeshOBJLoader name=\"l\" filename=\"" + mesh.string() +
                "\"/>"
                "<SparseGridRamificationTopology name=\"g\" n=\"4 2 4\" position=\"@l.position\" "
                "nbVirtualFinerLevels=\"2\" finestConnectivity=\"0\"/></Node>");
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  EXPECT_EQ(g.nb_points(), 32u);
  EXPECT_EQ(g.hexahedra().size(), 8u);  // the ring of a 3×1×3 grid: nothing to split
}

TEST(TopoSparseGridRamification, GridFromALoaderThroughSrcEqualsTheGridFromTheFile) {
  // Geomagic-DeformableSphere.scn gives its grid the loader's mesh with src="@loader": the
  // loader's (empty) hexahedra list is linked too, and must not replace the cells built from
  // the surface (it did: "no volume").
  const std::filesystem::path mesh = std::filesystem::path(SINEW_DATA_DIR) / "share" / "mesh" / "sphere_05.obj";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "no " << mesh;
  for (const char* type : {"SparseGridTopology", "SparseGridRamificationTopology"}) {
    const std::string attrs = R"( n="6 6 6" nbVirtualFinerLevels="3" finestConnectivity="0")";
    auto via_src = load(std::string("<Node><MeshOBJLoader name=\"l\" filename=\"") + mesh.string() +
                        "\"/><" + type + " name=\"g\" src=\"@l\"" + attrs + "/></Node>");
    auto via_file = load(std::string("<Node><") + type + " name=\"g\" fileTopology=\"" + mesh.string() + "\"" +
                         attrs + "/></Node>");
    auto& a = find<SparseGridTopology>(via_src, "g");
    auto& b = find<SparseGridTopology>(via_file, "g");
    EXPECT_EQ(a.state(), ComponentState::valid) << type;
    ASSERT_FALSE(a.hexahedra().empty()) << type;
    EXPECT_EQ(a.hexahedra(), b.hexahedra()) << type;
    ASSERT_EQ(a.nb_points(), b.nb_points()) << type;
    for (std::size_t i = 0; i < a.nb_points(); ++i) EXPECT_EQ(a.point(i), b.point(i)) << type << " " << i;
  }
}

TEST(TopoSparseGridRamification, MissingMeshFileIsAnError) {
  auto s =
      test::build(R"(<Node><SparseGridRamificationTopology name="g" fileTopology="/nonexistent/none.obj"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(has_error(s, "none.obj"));
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  EXPECT_EQ(g.state(), ComponentState::invalid);
  EXPECT_TRUE(g.hexahedra().empty());
}

TEST(TopoSparseGridRamification, EmptyMeshIsAnError) {
  sinew::test::TempDir dir;
  const std::string file = dir.write("empty.obj", "# nothing here\n");
  auto s = test::build("<Node><SparseGridRamificationTopology name=\"g\" fileTopology=\"" + file + "\"/></Node>");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(has_error(s, "empty.obj"));
  auto& g = find<SparseGridRamificationTopology>(s, "g");
  EXPECT_EQ(g.state(), ComponentState::invalid);

  // No file and no vertices: a warning, and no grid.
  auto none = test::build(R"(<Node><SparseGridRamificationTopology name="g" nbVirtualFinerLevels="2"/></Node>)");
  ASSERT_TRUE(none.root);
  init_root(*none.root);
  EXPECT_EQ(find<SparseGridRamificationTopology>(none, "g").state(), ComponentState::invalid);
}
