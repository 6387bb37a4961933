// Topological mappings (spec/mechanics.md §5.7): output lists in SOFA's order,
// checked against hand-derived indices on small grids and meshes.
#include "topology/mapping/hexa2_tetra_topological_mapping.h"
#include "topology/mesh_topology.h"
#include "topology/dynamic/quad_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/edge_set_topology_container.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

template <class T>
T& find(Node& n, std::string_view name) {
  T* t = get<T>(n, name);
  if (!t) throw std::runtime_error("component not found: " + std::string(name));
  return *t;
}

double signed_volume(const MeshTopologyBase& grid, const Tetra& t) {
  const Vec3 a = grid.point(t[0]), b = grid.point(t[1]), c = grid.point(t[2]), d = grid.point(t[3]);
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

}  // namespace

// 2×2×2 cells (3×3×3 points on integer coordinates): point (i,j,k) = i + 3j + 9k.
TEST(TopoHexa2Tetra, SwappedSplitOfA2x2x2Grid) {
  auto s = load(R"(<Node>
      <RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>
      <TetrahedronSetTopologyContainer name="tets"/>
      <TetrahedronSetTopologyModifier/>
      <Hexa2TetraTopologicalMapping name="map" input="@grid" output="@tets" swapping="true"/>
    </Node>)");
  auto& grid = find<MeshContainer>(*s.root, "grid");
  auto& tets = find<TetrahedronSetTopologyContainer>(*s.root, "tets");
  const auto& t = tets.tetrahedra();
  ASSERT_EQ(t.size(), 48u);
  // Cell 0 = (0,1,4,3,9,10,13,12): x cell index 0 is even → x-mirrored (1,0,3,4,10,9,12,13),
  // one swap → odd pattern (0,5,6,1),(0,1,6,3),(1,3,2,6),(6,3,7,0),(6,7,5,0),(7,5,0,4).
  const std::vector<Tetra> cell0{{1, 9, 12, 0}, {1, 0, 12, 4}, {0, 4, 3, 12},
                                 {12, 4, 13, 1}, {12, 13, 9, 1}, {13, 9, 1, 10}};
  // Cell 1 = (1,2,5,4,10,11,14,13): x index 1 odd, y and z even → no swap, even pattern
  // (0,5,1,6),(0,1,3,6),(1,3,6,2),(6,3,0,7),(6,7,0,5),(7,5,4,0).
  const std::vector<Tetra> cell1{{1, 11, 2, 14}, {1, 2, 4, 14}, {2, 4, 14, 5},
                                 {14, 4, 1, 13}, {14, 13, 1, 11}, {13, 11, 10, 1}};
  // Cell 2 = (3,4,7,6,12,13,16,15): x even and y odd → two swaps → even pattern on
  // (7,6,3,4,16,15,12,13).
  const std::vector<Tetra> cell2{{7, 15, 6, 12}, {7, 6, 4, 12}, {6, 4, 12, 3},
                                 {12, 4, 7, 13}, {12, 13, 7, 15}, {13, 15, 16, 7}};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(t[k], cell0[k]) << "cell 0 tet " << k;
    EXPECT_EQ(t[6 + k], cell1[k]) << "cell 1 tet " << k;
    EXPECT_EQ(t[12 + k], cell2[k]) << "cell 2 tet " << k;
  }
  // Every tetrahedron keeps the same orientation and they tile the 2×2×2 box.
  double total = 0;
  const double s0 = signed_volume(grid, t[0]);
  for (const Tetra& tet : t) {
    const double v = signed_volume(grid, tet);
    EXPECT_GT(v * s0, 0) << "inverted tetrahedron";
    total += std::abs(v);
  }
  EXPECT_NEAR(total, 8.0, 1e-12);
  EXPECT_EQ(tets.nb_points(), 27u);
  EXPECT_FALSE(tets.has_positions());
  EXPECT_FALSE(tets.edges().empty());       // created by the container's init
  EXPECT_FALSE(tets.triangles().empty());
}

TEST(TopoHexa2Tetra, WithoutSwappingEveryCellUsesTheEvenPattern) {
  std::vector<Tetra> out;
  Hexa2TetraTopologicalMapping::split({0, 1, 2, 3, 4, 5, 6, 7}, 0, 2, 1, false, out);
  EXPECT_EQ(out, (std::vector<Tetra>{{0, 5, 1, 6}, {0, 1, 3, 6}, {1, 3, 6, 2}, {6, 3, 0, 7}, {6, 7, 0, 5},
                                     {7, 5, 4, 0}}));
  out.clear();
  // Outside a grid: nx = 2, ny = 1; hexa 1 has an odd x index → not mirrored even with swapping.
  Hexa2TetraTopologicalMapping::split({0, 1, 2, 3, 4, 5, 6, 7}, 1, 2, 1, true, out);
  EXPECT_EQ(out[0], (Tetra{0, 5, 1, 6}));
}

TEST(TopoTetra2Triangle, BoundaryTrianglesInInputOrder) {
  auto s = load(R"(<Node>
      <TetrahedronSetTopologyContainer name="tets" tetrahedra="0 1 2 3  1 2 3 4"/>
      <Node name="surf">
        <TriangleSetTopologyContainer name="tri"/>
        <TriangleSetTopologyModifier/>
        <Tetra2TriangleTopologicalMapping input="@../tets" output="@tri"/>
      </Node>
      <Node name="flipped">
        <TriangleSetTopologyContainer name="tri"/>
        <TriangleSetTopologyModifier/>
        <Tetra2TriangleTopologicalMapping input="@../tets" output="@tri" flipNormals="true"/>
      </Node>
    </Node>)");
  auto& tri = find<TriangleSetTopologyContainer>(*s.root->find_child_named("surf"), "tri");
  EXPECT_EQ(tri.triangles(), (std::vector<Triangle>{{0, 3, 2}, {0, 1, 3}, {0, 2, 1}, {2, 3, 4}, {1, 4, 3}, {1, 2, 4}}));
  EXPECT_EQ(tri.nb_points(), 5u);
  EXPECT_EQ(tri.edges().size(), 9u);  // edges of the triangles, created at the container's init
  EXPECT_EQ(tri.edges()[0], (Edge{3, 2}));
  auto& flipped = find<TriangleSetTopologyContainer>(*s.root->find_child_named("flipped"), "tri");
  EXPECT_EQ(flipped.triangles()[0], (Triangle{0, 2, 3}));
}

TEST(TopoHexa2Quad, BoundaryQuadsOfAGrid) {
  // 2×1×1 cells: 11 grid faces; the shared yz face (index 9: x = 1) is interior.
  auto s = load(R"(<Node>
      <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
      <Node name="q">
        <QuadSetTopologyContainer name="quads"/>
        <QuadSetTopologyModifier/>
        <Hexa2QuadTopologicalMapping input="@../grid" output="@quads"/>
      </Node>
    </Node>)");
  auto& grid = find<MeshContainer>(*s.root, "grid");
  auto& quads = find<QuadSetTopologyContainer>(*s.root->find_child_named("q"), "quads");
  ASSERT_EQ(grid.quads().size(), 11u);
  std::vector<Quad> expected = grid.quads();
  expected.erase(expected.begin() + 9);
  EXPECT_EQ(quads.quads(), expected);
}

TEST(TopoHexa2Quad, MissingModifierIsAnError) {
  auto s = test::build(R"(<Node>
      <RegularGridTopology name="grid" n="2 2 2"/>
      <QuadSetTopologyContainer name="quads"/>
      <Hexa2QuadTopologicalMapping name="map" input="@grid" output="@quads"/>
    </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "QuadSetTopologyModifier"));
  EXPECT_TRUE(find<QuadSetTopologyContainer>(*s.root, "quads").quads().empty());
}

TEST(TopoQuad2Triangle, CheckerboardDiagonals) {
  auto s = load(R"(<Node>
      <RegularGridTopology name="grid" n="3 3 1" min="0 0 0" max="2 2 0"/>
      <TriangleSetTopologyContainer name="tri"/>
      <TriangleSetTopologyModifier/>
      <Quad2TriangleTopologicalMapping input="@grid" output="@tri"/>
    </Node>)");
  auto& tri = find<TriangleSetTopologyContainer>(*s.root, "tri");
  // Quads (0,1,4,3),(1,2,5,4),(3,4,7,6),(4,5,8,7); nx = 2: quads 1 and 2 are swapped.
  EXPECT_EQ(tri.triangles(), (std::vector<Triangle>{{1, 4, 0}, {3, 0, 4}, {1, 2, 4}, {5, 4, 2},
                                                    {3, 4, 6}, {7, 6, 4}, {5, 8, 4}, {7, 4, 8}}));
}

TEST(TopoTriangle2Edge, BoundaryEdges) {
  auto s = load(R"(<Node>
      <TriangleSetTopologyContainer name="tri" triangles="0 1 2  0 2 3"/>
      <Node name="e">
        <EdgeSetTopologyContainer name="edges"/>
        <EdgeSetTopologyModifier/>
        <Triangle2EdgeTopologicalMapping input="@../tri" output="@edges"/>
      </Node>
    </Node>)");
  auto& e = find<EdgeSetTopologyContainer>(*s.root->find_child_named("e"), "edges");
  EXPECT_EQ(e.edges(), (std::vector<Edge>{{1, 2}, {0, 1}, {2, 3}, {3, 0}}));
}

TEST(TopoHexa2Tetra, IntoAMeshTopologyDerivesItsEdgesLazily) {
  auto s = load(R"(<Node>
      <RegularGridTopology name="grid" n="2 2 2"/>
      <Node name="t">
        <MeshTopology name="Container"/>
        <Hexa2TetraTopologicalMapping input="@../grid" output="@Container"/>
      </Node>
    </Node>)");
  auto& m = find<MeshTopology>(*s.root->find_child_named("t"), "Container");
  EXPECT_EQ(m.tetrahedra().size(), 6u);
  EXPECT_EQ(m.nb_points(), 8u);
  // 12 cube edges + 6 face diagonals + 1 inner diagonal.
  EXPECT_EQ(m.edges().size(), 19u);
  EXPECT_EQ(m.edges()[0], (Edge{0, 5}));
}

TEST(TopoMesh2Point, PointsFromVerticesThenEdges) {
  auto s = load(R"(<Node>
      <EdgeSetTopologyContainer name="in" position="0 0 0  2 0 0  2 4 0" edges="0 1  1 2"/>
      <Node name="p">
        <PointSetTopologyContainer name="out"/>
        <Mesh2PointTopologicalMapping input="@../in" output="@out" pointBaryCoords="0 0 1"
                                      edgeBaryCoords="0.5 0 0  0.25 0 0" copyEdges="true"/>
      </Node>
    </Node>)");
  auto& out = find<MeshContainer>(*s.root->find_child_named("p"), "out");
  ASSERT_EQ(out.nb_points(), 7u);
  // One point per vertex (offset by pointBaryCoords), then per edge one point per edgeBaryCoords entry.
  EXPECT_EQ(out.point(0), Vec3(0, 0, 1));
  EXPECT_EQ(out.point(2), Vec3(2, 4, 1));
  EXPECT_EQ(out.point(3), Vec3(1, 0, 0));
  EXPECT_EQ(out.point(4), Vec3(0.5, 0, 0));
  EXPECT_EQ(out.point(5), Vec3(2, 2, 0));
  EXPECT_EQ(out.point(6), Vec3(2, 1, 0));
  EXPECT_EQ(out.edges(), (std::vector<Edge>{{0, 1}, {1, 2}}));
}
