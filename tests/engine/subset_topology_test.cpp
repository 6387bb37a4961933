// SubsetTopology on a small mesh: two unit squares side by side in z = 0
// (points 0..5), two apexes above them at z = 1 (6 over point 0, 7 over
// point 2), four triangles, two quads, three tetrahedra. Lists hand-derived.
#include <gtest/gtest.h>

#include "engine/subset_topology.h"
#include "test_scene.h"

namespace sinew {
namespace {

//   3 (0,1) --- 4 (1,1) --- 5 (2,1)
//   0 (0,0) --- 1 (1,0) --- 2 (2,0)        6 = (0,0,1), 7 = (2,0,1)
const char* kMesh = R"(
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0  0 0 1  2 0 1"/>
    <MeshTopology name="topo" edges="0 1  1 5  4 5" triangles="0 1 4  0 4 3  1 2 5  1 5 4"
                  quads="0 1 4 3  1 2 5 4" tetrahedra="0 1 3 6  1 2 5 7  1 4 5 6"/>)";

std::string scene(const std::string& subset) {
  return std::string("<Node name=\"root\">") + kMesh + subset + "</Node>";
}

std::vector<double> coords(std::initializer_list<unsigned> ids) {
  const double p[8][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 0, 1}, {2, 0, 1}};
  std::vector<double> out;
  for (unsigned i : ids) out.insert(out.end(), p[i], p[i] + 3);
  return out;
}

using U = std::vector<unsigned>;

TEST(SubsetTopology, BoxSplitsPointsAndElementsInGlobalIndices) {
  // Box x ≤ 1.2: points 0 1 3 4 6 in, 2 5 7 out.
  scene::LoadedScene s = test::load(scene(R"(<SubsetTopology name="s" box="1.2 1.5 1 -0.5 -0.5 -1" quads="@topo.quads"/>)"));
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  EXPECT_EQ(st->indices.get(), (U{0, 1, 3, 4, 6}));
  EXPECT_EQ(st->points_in_roi.get().data, coords({0, 1, 3, 4, 6}));
  EXPECT_EQ(st->points_out_roi.get().data, coords({2, 5, 7}));
  // The box's corners were swapped into min/max order (written back).
  EXPECT_EQ(st->box.get()[0], (VecN<6>() << -0.5, -0.5, -1, 1.2, 1.5, 1).finished());
  EXPECT_EQ(st->edge_indices.get(), (U{0}));
  EXPECT_EQ(st->edges_in_roi.get(), (std::vector<Edge>{{0, 1}}));
  EXPECT_EQ(st->edges_out_roi.get(), (std::vector<Edge>{{1, 5}, {4, 5}}));
  EXPECT_EQ(st->triangle_indices.get(), (U{0, 1}));
  EXPECT_EQ(st->triangles_in_roi.get(), (std::vector<Triangle>{{0, 1, 4}, {0, 4, 3}}));
  EXPECT_EQ(st->triangles_out_roi.get(), (std::vector<Triangle>{{1, 2, 5}, {1, 5, 4}}));
  EXPECT_EQ(st->quad_indices.get(), (U{0}));
  EXPECT_EQ(st->quads_in_roi.get(), (std::vector<Quad>{{0, 1, 4, 3}}));
  EXPECT_EQ(st->quads_out_roi.get(), (std::vector<Quad>{{1, 2, 5, 4}}));
  EXPECT_EQ(st->tetrahedron_indices.get(), (U{0}));
  EXPECT_EQ(st->tetrahedra_in_roi.get(), (std::vector<Tetra>{{0, 1, 3, 6}}));
  EXPECT_EQ(st->tetrahedra_out_roi.get(), (std::vector<Tetra>{{1, 2, 5, 7}, {1, 4, 5, 6}}));
  EXPECT_EQ(st->nbrborder.get(), 0u);
}

TEST(SubsetTopology, LocalIndicesPutTheBorderFirstAndRenumberEachElement) {
  scene::LoadedScene s =
      test::load(scene(R"(<SubsetTopology name="s" box="-0.5 -0.5 -1  1.2 1.5 1" localIndices="1"
                                             quads="@topo.quads"/>)"));
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  // Border (from the tetrahedra): tetra 1 has 1 inside, tetra 2 has 1 4 6 inside, both have points outside.
  EXPECT_EQ(st->nbrborder.get(), 3u);
  EXPECT_EQ(st->indices.get(), (U{1, 4, 6, 0, 3}));
  EXPECT_EQ(st->points_in_roi.get().data, coords({1, 4, 6, 0, 3}));
  EXPECT_EQ(st->points_out_roi.get().data, coords({1, 4, 6, 2, 5, 7}));
  // Local numbers: in list 1→0 4→1 6→2 0→3 3→4; out list 1→0 4→1 6→2 2→3 5→4 7→5.
  EXPECT_EQ(st->edges_in_roi.get(), (std::vector<Edge>{{3, 0}}));
  EXPECT_EQ(st->edges_out_roi.get(), (std::vector<Edge>{{0, 4}, {1, 4}}));
  EXPECT_EQ(st->triangles_in_roi.get(), (std::vector<Triangle>{{3, 0, 1}, {3, 1, 4}}));
  EXPECT_EQ(st->triangles_out_roi.get(), (std::vector<Triangle>{{0, 3, 4}, {0, 4, 1}}));
  EXPECT_EQ(st->quads_in_roi.get(), (std::vector<Quad>{{3, 0, 1, 4}}));
  EXPECT_EQ(st->quads_out_roi.get(), (std::vector<Quad>{{0, 3, 4, 1}}));
  EXPECT_EQ(st->tetrahedra_in_roi.get(), (std::vector<Tetra>{{3, 0, 4, 2}}));
  EXPECT_EQ(st->tetrahedra_out_roi.get(), (std::vector<Tetra>{{0, 3, 4, 5}, {0, 1, 4, 2}}));
  EXPECT_EQ(st->triangle_indices.get(), (U{0, 1}));
  EXPECT_EQ(st->tetrahedron_indices.get(), (U{0}));

  // Element by element: each local vertex of an output element has the coordinates of its global vertex.
  const std::vector<Tetra> global_in{{0, 1, 3, 6}}, global_out{{1, 2, 5, 7}, {1, 4, 5, 6}};
  const FlatVec &pin = st->points_in_roi.get(), &pout = st->points_out_roi.get();
  auto check = [](const std::vector<Tetra>& local, const std::vector<Tetra>& global, const FlatVec& pts) {
    ASSERT_EQ(local.size(), global.size());
    for (std::size_t e = 0; e < local.size(); ++e)
      for (int k = 0; k < 4; ++k) {
        const std::vector<double> want = coords({global[e][k]});
        for (int c = 0; c < 3; ++c) EXPECT_EQ(pts.data[local[e][k] * 3 + c], want[c]) << "element " << e;
      }
  };
  check(st->tetrahedra_in_roi.get(), global_in, pin);
  check(st->tetrahedra_out_roi.get(), global_out, pout);
}

TEST(SubsetTopology, LocalIndicesTakeTheBorderFromTrianglesWithoutTetrahedra) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <MechanicalObject position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0"/>
    <MeshTopology triangles="0 1 4  0 4 3  1 2 5  1 5 4"/>
    <SubsetTopology name="s" box="-0.5 -0.5 -1  1.2 1.5 1" localIndices="1"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  // Triangles 2 and 3 straddle the box: border 1 4.
  EXPECT_EQ(st->nbrborder.get(), 2u);
  EXPECT_EQ(st->indices.get(), (U{1, 4, 0, 3}));
  EXPECT_EQ(st->points_out_roi.get().data, coords({1, 4, 2, 5}));
  EXPECT_EQ(st->triangles_in_roi.get(), (std::vector<Triangle>{{2, 0, 1}, {2, 1, 3}}));
  EXPECT_EQ(st->triangles_out_roi.get(), (std::vector<Triangle>{{0, 2, 3}, {0, 3, 1}}));
}

TEST(SubsetTopology, SpheresNeedAllVerticesInOneSameSphere) {
  // Sphere 1 around point 0, radius 1 (boundary points 1 3 6 included); sphere 2 around point 5.
  scene::LoadedScene s =
      test::load(scene(R"(<SubsetTopology name="s" centers="0 0 0  2 1 0" radii="1 0.5"/>)"));
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  EXPECT_EQ(st->indices.get(), (U{0, 1, 3, 5, 6}));
  EXPECT_EQ(st->points_out_roi.get().data, coords({2, 4, 7}));
  // Edge 1-5 has both ends in spheres, but not in the same one.
  EXPECT_EQ(st->edge_indices.get(), (U{0}));
  EXPECT_EQ(st->edges_out_roi.get(), (std::vector<Edge>{{1, 5}, {4, 5}}));
  EXPECT_TRUE(st->triangle_indices.get().empty());
  EXPECT_EQ(st->triangles_out_roi.get().size(), 4u);
  EXPECT_EQ(st->tetrahedron_indices.get(), (U{0}));
  EXPECT_EQ(st->tetrahedra_in_roi.get(), (std::vector<Tetra>{{0, 1, 3, 6}}));
  // Only edges, triangles and tetrahedra are taken from the topology (as SOFA does), not quads.
  EXPECT_TRUE(st->quads_in_roi.get().empty());
  EXPECT_TRUE(st->quads_out_roi.get().empty());
}

TEST(SubsetTopology, TetrahedraInputChoosesTheTetrahedraByIndex) {
  scene::LoadedScene s = test::load(scene(R"(<SubsetTopology name="s" box="-0.5 -0.5 -1  1.2 1.5 1" tetrahedraInput="2"/>)"));
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  EXPECT_EQ(st->tetrahedron_indices.get(), (U{2}));
  EXPECT_EQ(st->tetrahedra_in_roi.get(), (std::vector<Tetra>{{1, 4, 5, 6}}));
  EXPECT_EQ(st->tetrahedra_out_roi.get(), (std::vector<Tetra>{{0, 1, 3, 6}, {1, 2, 5, 7}}));
  // Point lists rebuilt from the tetrahedra; `indices` keeps the box's points, then the chosen tetrahedron's.
  EXPECT_EQ(st->points_in_roi.get().data, coords({1, 4, 5, 6}));
  EXPECT_EQ(st->points_out_roi.get().data, coords({0, 1, 3, 6, 2, 5, 7}));
  EXPECT_EQ(st->indices.get(), (U{0, 1, 3, 4, 6, 1, 4, 5, 6}));

  scene::LoadedScene l = test::load(
      scene(R"(<SubsetTopology name="s" box="-0.5 -0.5 -1  1.2 1.5 1" tetrahedraInput="2" localIndices="1"/>)"));
  ASSERT_TRUE(l.root);
  st = test::get<SubsetTopology>(*l.root, "s");
  EXPECT_EQ(st->tetrahedra_in_roi.get(), (std::vector<Tetra>{{0, 1, 2, 3}}));
  EXPECT_EQ(st->tetrahedra_out_roi.get(), (std::vector<Tetra>{{0, 1, 2, 3}, {1, 4, 5, 6}}));
}

TEST(SubsetTopology, ExplicitInputsAndLazyUpdate) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <SubsetTopology name="s" rest_position="0 0 0  3 0 0  0.5 0.5 0.5" triangles="0 2 1  0 2 2"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  // Default box: the unit cube.
  EXPECT_EQ(st->indices.get(), (U{0, 2}));
  EXPECT_EQ(st->triangle_indices.get(), (U{1}));
  st->rest_position.set(FlatVec{3, {0, 0, 0, 0.9, 0, 0, 0.5, 0.5, 0.5}});
  EXPECT_EQ(st->indices.get(), (U{0, 1, 2}));
  EXPECT_EQ(st->triangle_indices.get(), (U{0, 1}));
}

TEST(SubsetTopology, BadInputWarnsWithoutCrashing) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <SubsetTopology name="s" rest_position="0 0 0  0.5 0 0" triangles="0 1 7" localIndices="1"/>
    <SubsetTopology name="sp" rest_position="0 0 0" centers="0 0 0  1 1 1" radii="1"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* st = test::get<SubsetTopology>(*s.root, "s");
  ASSERT_NE(st, nullptr);
  EXPECT_TRUE(st->triangle_indices.get().empty());
  EXPECT_EQ(st->triangles_out_roi.get(), (std::vector<Triangle>{{0, 1, 7}}));
  auto* sp = test::get<SubsetTopology>(*s.root, "sp");
  ASSERT_NE(sp, nullptr);
  EXPECT_EQ(sp->indices.get(), (U{0}));  // left at its default
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "beyond the 2 rest positions")) << ::testing::PrintToString(warnings);
  EXPECT_TRUE(test::any_contains(warnings, "radii (1) do not match")) << ::testing::PrintToString(warnings);
}

}  // namespace
}  // namespace sinew
