// Topology containers (spec/mechanics.md §5.1, §5.6): derived element lists
// and neighbourhood queries on small meshes, checked against hand-derived lists.
#include "topology/grid/cube_topology.h"
#include "topology/dynamic/edge_set_topology_container.h"
#include "topology/grid/sparse_grid_topology.h"
#include "topology/dynamic/hexahedron_set_topology_container.h"
#include "topology/mesh_topology.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/quad_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

#include <gtest/gtest.h>

#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

using IdxLists = std::vector<std::vector<unsigned>>;

template <class T>
T& find(scene::LoadedScene& s, std::string_view name) {
  T* t = get<T>(*s.root, name);
  if (!t) throw std::runtime_error("component not found: " + std::string(name));
  return *t;
}

// Two tetrahedra sharing the face {1,2,3}.
const char* kTwoTets = "0 1 2 3  1 2 3 4";

}  // namespace

TEST(TopoMeshTopology, EdgesAndTrianglesFromTetrahedra) {
  auto s = load(std::string(R"(<Node><MeshTopology name="t" tetrahedra=")") + kTwoTets + R"("/></Node>)");
  auto& t = find<MeshTopology>(s, "t");
  const std::vector<Edge> edges{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}, {1, 4}, {2, 4}, {3, 4}};
  EXPECT_EQ(t.edges(), edges);
  // Faces (1,2,3),(0,3,2),(1,3,0),(0,2,1) rotated smallest-first; the shared face (1,3,2) of the
  // second tetrahedron is the reverse of (1,2,3) and is not added again.
  const std::vector<Triangle> tris{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}, {2, 3, 4}, {1, 4, 3}, {1, 2, 4}};
  EXPECT_EQ(t.triangles(), tris);
  EXPECT_TRUE(t.quads().empty());
  EXPECT_EQ(t.nb_points(), 5u);

  const auto& tat = t.tetrahedra_around_triangle();
  ASSERT_EQ(tat.size(), 7u);
  EXPECT_EQ(tat[0], (std::vector<unsigned>{0, 1}));
  for (std::size_t i = 1; i < 7; ++i) EXPECT_EQ(tat[i].size(), 1u) << i;
  const auto& tit = t.triangles_in_tetrahedron();
  ASSERT_EQ(tit.size(), 2u);
  EXPECT_EQ(tit[0], (std::array<unsigned, 4>{0, 1, 2, 3}));
  // Second tet (1,2,3,4): faces opposite each vertex: (2,3,4),(3,4,1),(4,1,2),(1,2,3).
  EXPECT_EQ(tit[1], (std::array<unsigned, 4>{4, 5, 6, 0}));
  const auto& eit = t.edges_in_tetrahedron();
  EXPECT_EQ(eit[1], (std::array<unsigned, 6>{3, 4, 6, 5, 7, 8}));
  EXPECT_EQ(t.tetrahedra_around_edge()[5], (std::vector<unsigned>{0, 1}));  // edge (2,3)
  EXPECT_EQ(t.edges_around_vertex()[4], (std::vector<unsigned>{6, 7, 8}));
  EXPECT_EQ(t.edge_index(3, 2), 5u);
  EXPECT_EQ(t.edge_index(0, 4), MeshTopologyBase::kInvalidIndex);
}

TEST(TopoMeshTopology, EdgesFromSurfacesKeepTriangleOrientation) {
  auto s = load(R"(<Node><MeshTopology name="t" triangles="0 1 2  0 2 3"/>
                   <MeshTopology name="q" quads="0 1 2 3"/>
                   <MeshTopology name="given" triangles="0 1 2" edges="0 1"/></Node>)");
  auto& t = find<MeshTopology>(s, "t");
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{1, 2}, {2, 0}, {0, 1}, {2, 3}, {3, 0}}));
  EXPECT_EQ(t.edges_in_triangle()[1], (std::array<unsigned, 3>{3, 4, 1}));
  // Edge (2,0) runs along triangle 0 (…,2,0 …) so triangle 0 comes first; triangle 1 has (0,2).
  EXPECT_EQ(t.triangles_around_edge()[1], (std::vector<unsigned>{0, 1}));
  EXPECT_EQ(t.triangles_around_vertex()[0], (std::vector<unsigned>{0, 1}));
  EXPECT_EQ(t.triangle_index(2, 3, 0), 1u);
  // Quad edges are stored with the smaller index first.
  EXPECT_EQ(find<MeshTopology>(s, "q").edges(), (std::vector<Edge>{{1, 2}, {2, 3}, {0, 3}, {0, 1}}));
  // A list given in the scene is never regenerated.
  EXPECT_EQ(find<MeshTopology>(s, "given").edges(), (std::vector<Edge>{{0, 1}}));
}

TEST(TopoMeshTopology, QuadsFromHexahedron) {
  auto s = load(R"(<Node><MeshTopology name="t" hexas="0 1 2 3 4 5 6 7"/></Node>)");
  auto& t = find<MeshTopology>(s, "t");
  EXPECT_EQ(t.quads(), (std::vector<Quad>{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                          {0, 4, 7, 3}}));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5},
                                          {4, 7}, {5, 6}, {6, 7}}));
  EXPECT_EQ(t.quads_in_hexahedron()[0], (std::array<unsigned, 6>{0, 1, 2, 3, 4, 5}));
  for (const auto& around : t.hexahedra_around_quad()) EXPECT_EQ(around, (std::vector<unsigned>{0}));
  EXPECT_EQ(t.edges_in_quad()[5], (std::array<unsigned, 4>{9, 7, 1, 2}));  // quad (0,4,7,3)
}

TEST(TopoDynamicContainers, TetrahedronContainerCreatesEdgesThenTriangles) {
  auto s = load(std::string(R"(<Node><TetrahedronSetTopologyContainer name="t" tetrahedra=")") + kTwoTets +
                R"("/></Node>)");
  auto& t = find<TetrahedronSetTopologyContainer>(s, "t");
  EXPECT_EQ(t.edges().size(), 9u);
  EXPECT_EQ(t.edges()[6], (Edge{1, 4}));
  EXPECT_EQ(t.triangles(), (std::vector<Triangle>{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}, {2, 3, 4}, {1, 4, 3},
                                                  {1, 2, 4}}));
  EXPECT_EQ(t.nb_points(), 5u);
  EXPECT_EQ(t.nb_points_f.value(), 5u);
}

TEST(TopoDynamicContainers, TriangleAndQuadContainers) {
  auto s = load(R"(<Node>
      <TriangleSetTopologyContainer name="t" position="0 0 0  1 0 0  1 1 0  0 1 0  5 5 5" triangles="0 1 2  0 2 3"/>
      <QuadSetTopologyContainer name="q" quads="0 1 2 3"/>
      <HexahedronSetTopologyContainer name="h" hexahedra="0 1 2 3 4 5 6 7"/>
      <EdgeSetTopologyContainer name="e" edges="0 1  1 5"/>
      <PointSetTopologyContainer name="p" position="0 0 0  1 1 1"/>
    </Node>)");
  auto& t = find<TriangleSetTopologyContainer>(s, "t");
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{1, 2}, {2, 0}, {0, 1}, {2, 3}, {3, 0}}));
  EXPECT_EQ(t.nb_points(), 5u);  // position given: its size wins over the indices
  EXPECT_EQ(find<QuadSetTopologyContainer>(s, "q").edges(), (std::vector<Edge>{{1, 2}, {2, 3}, {0, 3}, {0, 1}}));
  auto& h = find<HexahedronSetTopologyContainer>(s, "h");
  EXPECT_EQ(h.quads().size(), 6u);
  EXPECT_EQ(h.quads()[5], (Quad{0, 4, 7, 3}));
  EXPECT_EQ(h.edges().size(), 12u);
  auto& e = find<EdgeSetTopologyContainer>(s, "e");
  EXPECT_EQ(e.nb_points(), 6u);
  EXPECT_TRUE(e.triangles().empty());
  EXPECT_EQ(e.edges_around_vertex()[1], (std::vector<unsigned>{0, 1}));
  EXPECT_EQ(find<PointSetTopologyContainer>(s, "p").nb_points(), 2u);
}

TEST(TopoDynamicContainers, ListsFromLoaderAreKept) {
  // Triangles given with the tetrahedra: only the edges are created (from the tetrahedra).
  auto s = load(R"(<Node><TetrahedronSetTopologyContainer name="t" tetrahedra="0 1 2 3" triangles="0 1 2"/></Node>)");
  auto& t = find<TetrahedronSetTopologyContainer>(s, "t");
  EXPECT_EQ(t.triangles(), (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(t.edges().size(), 6u);
}

TEST(TopoDynamicContainers, ModifierFindsItsContainer) {
  auto s = load(R"(<Node><TriangleSetTopologyContainer name="c" triangles="0 1 2"/>
                   <Node name="child"><TriangleSetTopologyModifier name="m"/></Node></Node>)");
  Node* child = s.root->find_child_named("child");
  ASSERT_NE(child, nullptr);
  auto* m = get<TriangleSetTopologyModifier>(*child, "m");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->container(), get<MeshContainer>(*s.root, "c"));
}

TEST(TopoCubeTopology, SurfaceLatticeWithoutInteriorPoints) {
  auto s = load(R"(<Node><CubeTopology name="c" nx="3" ny="3" nz="3" min="0 0 0" max="2 2 2"/></Node>)");
  auto& c = find<MeshTopology>(s, "c");
  // 2 full layers of 9 points, then the ring of the middle layer.
  ASSERT_EQ(c.nb_points(), 26u);
  EXPECT_EQ(c.point(18), Vec3(0, 0, 1));
  EXPECT_EQ(c.point(21), Vec3(0, 2, 1));
  EXPECT_EQ(c.point(24), Vec3(0, 1, 1));
  EXPECT_EQ(c.point(25), Vec3(2, 1, 1));
  EXPECT_EQ(c.point(13), Vec3(1, 1, 2));
  EXPECT_EQ(c.edges().size(), 48u);
  EXPECT_EQ(c.edges()[0], (Edge{0, 1}));
  ASSERT_EQ(c.quads().size(), 24u);
  EXPECT_EQ(c.quads()[0], (Quad{0, 3, 4, 1}));    // z = 0 face, (x,y) → (x,y+1) → (x+1,y+1) → (x+1,y)
  EXPECT_EQ(c.quads()[4], (Quad{9, 10, 13, 12}));  // z = nz-1 face, opposite winding
  EXPECT_TRUE(c.triangles().empty());
}

TEST(TopoSparseGrid, ClosedCubeSurfaceKeepsTheInnerCell) {
  // Surface of the cube [-1,1]³; 4³ grid points over its bounding box (+1 % margin each side).
  auto s = load(R"(<Node><SparseGridTopology name="g" n="4 4 4"
      position="-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1"
      triangles="0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7"/></Node>)");
  auto& g = find<SparseGridTopology>(s, "g");
  const auto& h = g.hexahedra();
  ASSERT_EQ(h.size(), 27u);
  ASSERT_EQ(g.nb_points(), 64u);
  for (std::size_t i = 0; i < 26; ++i) {
    EXPECT_EQ(g.cell_type(i), SparseGridTopology::CellType::boundary) << i;
    EXPECT_FLOAT_EQ(g.mass_coef(i), 0.5f);
  }
  EXPECT_EQ(g.cell_type(26), SparseGridTopology::CellType::inside);
  EXPECT_FLOAT_EQ(g.stiffness_coef(26), 1.0f);
  // Points are numbered in lexicographic (x, y, z) order: z varies fastest.
  EXPECT_NEAR(g.point(0)[0], -1.02, 1e-12);
  EXPECT_NEAR(g.point(1)[2], -1.02 + 2.04 / 3, 1e-12);
  EXPECT_EQ(h[26][0], 16u + 4u + 1u);  // inner cell starts at grid point (1,1,1)
  EXPECT_EQ(h[26][6], 32u + 8u + 2u);  // and ends at (2,2,2)
  double fx = -1, fy = -1, fz = -1;
  EXPECT_EQ(g.find_cube(Vec3(0, 0, 0), fx, fy, fz), 26u);
  EXPECT_NEAR(fx, 0.5, 1e-12);
  EXPECT_NEAR(fz, 0.5, 1e-12);
  EXPECT_TRUE(g.edges().empty());
  EXPECT_TRUE(g.quads().empty());
}

TEST(TopoMeshTopology, LoadsItsFilename) {
  sinew::test::TempDir dir;
  const std::string file = dir.write("m.obj",
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 2 0\n"
                                     "f 1 2 3\nf 1 2 3 4\nf 1 2 3 5 4\nf 2 1\n");
  auto s = load("<Node><MeshTopology name=\"t\" filename=\"" + file + "\"/></Node>");
  auto& t = find<MeshTopology>(s, "t");
  EXPECT_EQ(t.nb_points(), 5u);
  EXPECT_EQ(t.point(4), Vec3(0.5, 2, 0));
  // Triangles, the fan of the pentagon, the quad, and the 2-vertex face as a sorted edge.
  EXPECT_EQ(t.triangles(), (std::vector<Triangle>{{0, 1, 2}, {0, 1, 2}, {0, 2, 4}, {0, 4, 3}}));
  EXPECT_EQ(t.quads(), (std::vector<Quad>{{0, 1, 2, 3}}));
  EXPECT_EQ(t.edges(), (std::vector<Edge>{{0, 1}}));
}

TEST(TopoMeshTopology, MissingFileIsAnError) {
  auto s = test::build(R"(<Node><MeshTopology name="t" filename="/nonexistent/none.obj"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  bool reported = false;
  for (const Message& m : s.root->diagnostics().messages())
    reported = reported || (m.severity == Severity::error && Diagnostics::format(m).find("none.obj") != std::string::npos);
  EXPECT_TRUE(reported);
}

TEST(TopoDynamicContainers, IndexBeyondThePointsIsReported) {
  auto s = test::build(R"(<Node><TriangleSetTopologyContainer name="t" position="0 0 0  1 0 0  0 1 0"
                                 triangles="0 1 2  0 2 5"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning),
                                 "uses point 5 but the topology has 3 points"));
  // The neighbourhood buffers stay usable.
  auto& t = find<TriangleSetTopologyContainer>(s, "t");
  EXPECT_EQ(t.triangles_around_vertex().size(), 6u);
  EXPECT_EQ(t.triangles_around_vertex()[5], (std::vector<unsigned>{1}));
}

TEST(TopoSparseGrid, VirtualFinerLevelIsCoarsened) {
  // Finest level: 3³ points (2×2×2 boundary cells), coarsened once into one boundary cell
  // whose coefficients average its 8 children (0.5 each).
  auto s = load(R"(<Node><SparseGridTopology name="g" n="2 2 2" nbVirtualFinerLevels="1"
      position="-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1"
      triangles="0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7"/></Node>)");
  auto& g = find<SparseGridTopology>(s, "g");
  ASSERT_EQ(g.hexahedra().size(), 1u);
  EXPECT_EQ(g.nb_points(), 8u);
  EXPECT_EQ(g.cell_type(0), SparseGridTopology::CellType::boundary);
  EXPECT_FLOAT_EQ(g.mass_coef(0), 0.5f);
  EXPECT_EQ(g.hexahedra()[0], (Hexa{0, 4, 6, 2, 1, 5, 7, 3}));  // lexicographic numbering of the corners
  EXPECT_NEAR(g.point(7)[0], 1.02, 1e-12);
}
