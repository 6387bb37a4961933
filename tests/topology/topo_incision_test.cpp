// Triangle incision (SOFA's SplitAlongPath + InciseAlongEdgeList, TopologicalChangeProcessor's
// INCISE=): a 4×4 grid of unit squares, each split along its diagonal (i,j)-(i+1,j+1), cut along
// y = 1.45 from x = 0.7 to x = 3.6. Hand count: the segment starts in the lower triangle of
// square (0,1), crosses the vertical edge x=1, then in each of squares 1..3 the diagonal and (for
// 1 and 2) the next vertical edge: 6 edges. Path = triangle, 6 edges, triangle → 8 new points;
// triangles: 4 (start) + 5×3 (edge to edge) + 4 (end) new, 7 removed: 32 + 23 − 7 = 48; edges by
// Euler (disk): 33 + 48 − 1 = 80. The incision duplicates the 6 inner path points (both ends are
// inside the mesh and stay shared): 39 points, 48 triangles, 80 + 7 = 87 edges (annulus: V − E + F = 0).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "mass/diagonal_mass.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/algorithm/triangle_incision.h"
#include "topology/dynamic/element_removal.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "topology/utility/topological_change_processor.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

std::string grid_scene(const std::string& extra = "") {
  std::ostringstream pos, tri;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) pos << i << " " << j << " 0  ";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int p00 = j * 5 + i, p10 = p00 + 1, p01 = p00 + 5, p11 = p00 + 6;
      tri << p00 << " " << p10 << " " << p11 << "  " << p00 << " " << p11 << " " << p01 << "  ";
    }
  return "<Node dt=\"0.01\" gravity=\"0 0 0\">\n"
         "  <MechanicalObject name=\"dofs\" position=\"" + pos.str() + "\"/>\n"
         "  <TriangleSetTopologyContainer name=\"topo\" position=\"" + pos.str() + "\" triangles=\"" + tri.str() + "\"/>\n"
         "  <TriangleSetTopologyModifier name=\"mod\"/>\n"
         "  <TriangleSetGeometryAlgorithms name=\"geo\"/>\n"
         "  <DiagonalMass name=\"mass\" massDensity=\"1.5\"/>\n" + extra + "</Node>";
}

// Every property the cut must leave, given the expected counts.
void expect_cut(Node& root, std::size_t points, std::size_t triangles, std::size_t edges, std::size_t twins) {
  auto& topo = *get<TriangleSetTopologyContainer>(root, "topo");
  auto& mo = *get<MechanicalObject>(root, "dofs");
  auto& mass = *get<DiagonalMass>(root, "mass");
  EXPECT_EQ(topo.nb_points(), points);
  EXPECT_EQ(topo.triangles().size(), triangles);
  EXPECT_EQ(topo.edges().size(), edges);
  ASSERT_EQ(mo.size(), points);
  ASSERT_EQ(mass.masses().size(), points);
  const auto& x = mo.read(kPosition);
  // Duplicated points: same position, different indices.
  std::map<std::array<double, 3>, int> seen;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < points; ++i) pairs += seen[{x[3 * i], x[3 * i + 1], x[3 * i + 2]}]++;
  EXPECT_EQ(pairs, twins);
  // Every triangle keeps the orientation of the grid (+z normal) and a positive area; total area 16.
  double area = 0;
  for (const Triangle& t : topo.triangles()) {
    const double ux = x[3 * t[1]] - x[3 * t[0]], uy = x[3 * t[1] + 1] - x[3 * t[0] + 1];
    const double vx = x[3 * t[2]] - x[3 * t[0]], vy = x[3 * t[2] + 1] - x[3 * t[0] + 1];
    const double z = ux * vy - uy * vx;
    EXPECT_GT(z, 1e-9);
    area += z / 2;
  }
  EXPECT_NEAR(area, 16.0, 1e-12);
  // The mass stays density × area, one entry per point.
  double total = 0;
  for (double m : mass.masses()) total += m;
  EXPECT_NEAR(total, 1.5 * 16.0, 1e-12);
  // No edge has more than two triangles; border edges: 16 outside + the two lips of the cut.
  std::size_t border = 0;
  for (std::size_t e = 0; e < topo.edges().size(); ++e) {
    ASSERT_LE(topo.triangles_around_edge()[e].size(), 2u);
    border += topo.triangles_around_edge()[e].size() == 1;
  }
  EXPECT_EQ(border, 16 + 2 * twins + 2);
}

incision::Mesh mesh_of(Node& root) {
  incision::Mesh m;
  m.topology = get<TriangleSetTopologyContainer>(root, "topo");
  m.state = get<MechanicalObject>(root, "dofs");
  m.modifier = get<TriangleSetTopologyModifier>(root, "mod");
  return m;
}

}  // namespace

TEST(TopologyIncision, PathCrossesSixEdges) {
  auto s = load(grid_scene());
  incision::Mesh m = mesh_of(*s.root);
  const Vec3 a(0.7, 1.45, 0), b(3.6, 1.45, 0);
  unsigned ta = incision::find_element_index(m, a, incision::kInvalid);
  unsigned tb = incision::find_element_index(m, b, incision::kInvalid);
  EXPECT_EQ(ta, 8u);   // square (0,1), lower triangle
  EXPECT_EQ(tb, 14u);  // square (3,1), lower triangle
  incision::Path path;
  std::string why;
  ASSERT_TRUE(incision::intersected_objects_list(m, incision::kInvalid, a, b, ta, tb, path, &why)) << why;
  ASSERT_EQ(path.kinds.size(), 8u);
  EXPECT_EQ(path.kinds.front(), incision::Elem::triangle);
  EXPECT_EQ(path.kinds.back(), incision::Elem::triangle);
  for (std::size_t i = 1; i + 1 < path.kinds.size(); ++i) EXPECT_EQ(path.kinds[i], incision::Elem::edge);
  EXPECT_NEAR(path.barycoefs[0].sum(), 1.0, 1e-15);
}

TEST(TopologyIncision, SplitThenInciseOpensTheSurface) {
  auto s = load(grid_scene());
  incision::Mesh m = mesh_of(*s.root);
  const Vec3 a(0.7, 1.45, 0), b(3.6, 1.45, 0);
  unsigned ta = incision::find_element_index(m, a, incision::kInvalid);
  unsigned tb = incision::find_element_index(m, b, incision::kInvalid);
  incision::Path path;
  std::string why;
  ASSERT_TRUE(incision::intersected_objects_list(m, incision::kInvalid, a, b, ta, tb, path, &why)) << why;
  std::vector<unsigned> new_edges;
  Vec3 a2 = a, b2 = b;
  ASSERT_EQ(incision::split_along_path(m, incision::kInvalid, a2, incision::kInvalid, b2, path, new_edges, 0.0, 0.0, &why), 8) << why;
  EXPECT_EQ(new_edges.size(), 7u);
  // After the split: nothing duplicated yet, the path is made of edges.
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  EXPECT_EQ(topo.nb_points(), 33u);
  EXPECT_EQ(topo.triangles().size(), 48u);
  EXPECT_EQ(topo.edges().size(), 80u);
  std::vector<unsigned> new_points, end_points;
  bool border = false;
  ASSERT_TRUE(incision::incise_along_edge_list(m, new_edges, new_points, end_points, border, &why)) << why;
  EXPECT_FALSE(border);
  EXPECT_EQ(new_points, (std::vector<unsigned>{33, 34, 35, 36, 37, 38}));
  EXPECT_EQ(end_points.size(), 2u);
  expect_cut(*s.root, 39, 48, 87, 6);
  // Each copy and its original share no edge.
  for (unsigned p : new_points) {
    const auto& x = get<MechanicalObject>(*s.root, "dofs")->read(kPosition);
    for (unsigned q = 0; q < 33; ++q)
      if (x[3 * q] == x[3 * p] && x[3 * q + 1] == x[3 * p + 1]) {
        EXPECT_EQ(topo.edge_index(p, q), incision::kInvalid) << p << " " << q;
      }
  }
}

// The processor: both INCISE= forms (coordinates only, triangle + coordinates), a two-segment
// polyline (the second segment starts at the first's end point), with and without saved indices.
TEST(TopologyIncision, ProcessorIncisesAlongAPolyline) {
  const auto dir = std::filesystem::temp_directory_path();
  for (int form = 0; form < 3; ++form) {
    const auto file = dir / ("sinew_incise_" + std::to_string(form) + ".txt");
    {
      std::ofstream f(file);
      f << "T= 0.02\n\tINCISE= " << (form == 1 ? 2 : 3) << "\n";
      if (form == 1) f << "8 0.7 1.45 0 14 3.6 1.45 0\n";  // one segment, triangles given
      else f << "0.7 1.45 0 2.5 1.45 0 3.6 1.45 0\n";
    }
    const std::string save = form == 2 ? "true" : "false";
    auto s = load(grid_scene("  <TopologicalChangeProcessor name=\"tcp\" filename=\"" + file.string() +
                             "\" saveIndicesAtInit=\"" + save + "\" epsilonSnapPath=\"0\" epsilonSnapBorder=\"0\"/>\n"));
    for (int k = 0; k < 4; ++k) animate(*s.root);
    // One segment: as above. Two segments: 0.7→2.5 (triangle, 4 edges, triangle: 31 points, 44
    // triangles, its 4 inner points duplicated: 35), then 2.5→3.6 from the first cut's end point
    // P (point, 2 edges, triangle: +3 points, +6 triangles); P is now the tip of the slit (fewer
    // triangles than edges around it), so it is duplicated too, with the 2 edge points: 41 points,
    // 50 triangles, 7 pairs, 91 edges — the same slit as one straight cut, split differently.
    if (form == 1) expect_cut(*s.root, 39, 48, 87, 6);
    else expect_cut(*s.root, 41, 50, 91, 7);
    std::filesystem::remove(file);
  }
}

// SnapAlongPath: along y = 1.05 from (0.5, 1.05) to (1.6, 1.05) the path crosses the edge
// (6, 11) and the diagonal (6, 12) both 0.05 from vertex 6 = (1, 1) (< epsilonSnapPath 0.1): the
// two crossings become vertex 6, which then moves to their mean (1.025, 1.05) between the path's
// new points 25 (0.5, 1.05) and 26 (1.6, 1.05). Path triangle 8, point 6, triangle 10: 2 new points,
// 3 + 3 triangles for the 2 split ones (36), 62 edges; the incision duplicates 6 (point 27):
// 28 points, 64 edges, mass and area unchanged (the move stays in the plane).
TEST(TopologyIncision, PathSnapsOntoACloseVertexWhichMoves) {
  auto s = load(grid_scene());
  incision::Mesh m = mesh_of(*s.root);
  Vec3 a(0.5, 1.05, 0), b(1.6, 1.05, 0);
  unsigned ta = incision::find_element_index(m, a, incision::kInvalid);
  unsigned tb = incision::find_element_index(m, b, incision::kInvalid);
  ASSERT_EQ(ta, 8u);
  ASSERT_EQ(tb, 10u);
  incision::Path path;
  std::string why;
  ASSERT_TRUE(incision::intersected_objects_list(m, incision::kInvalid, a, b, ta, tb, path, &why)) << why;
  ASSERT_EQ(path.kinds.size(), 4u);
  std::vector<unsigned> new_edges;
  ASSERT_EQ(incision::split_along_path(m, incision::kInvalid, a, incision::kInvalid, b, path, new_edges, 0.1, 0.0,
                                       &why), 2) << why;
  ASSERT_EQ(path.kinds.size(), 3u);
  EXPECT_EQ(path.kinds[1], incision::Elem::point);
  EXPECT_EQ(path.indices[1], 6u);
  EXPECT_EQ(new_edges.size(), 2u);
  const auto& x = get<MechanicalObject>(*s.root, "dofs")->read(kPosition);
  EXPECT_NEAR(x[3 * 6], 1.025, 1e-15);
  EXPECT_NEAR(x[3 * 6 + 1], 1.05, 1e-15);
  EXPECT_EQ(x[3 * 6 + 2], 0.0);
  std::vector<unsigned> new_points, end_points;
  bool border = false;
  ASSERT_TRUE(incision::incise_along_edge_list(m, new_edges, new_points, end_points, border, &why)) << why;
  EXPECT_EQ(new_points, (std::vector<unsigned>{27}));
  expect_cut(*s.root, 28, 36, 64, 1);
}

// Soak: 300 random segments cut one after the other across the grid (ends anywhere, the same or
// other triangles, crossing earlier cuts, on vertices now and then), with the border snapping.
// Refused paths leave the mesh as it was; after every cut the arrays and shells agree, no edge has
// more than two triangles, the state and the mass have one entry per point. Without the snapping
// along the path every triangle keeps its orientation and the area is kept; with it (second run)
// a snapped vertex moves to SOFA's distance-weighted point between its path neighbours, which
// may fold a small neighbour triangle (as in SOFA), so only consistency is checked then.
TEST(TopologyIncision, SoakRandomCutsKeepTheMeshConsistent) {
  for (const double eps_path : {0.0, 0.1}) {
    auto s = load(grid_scene());
    incision::Mesh m = mesh_of(*s.root);
    auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
    auto& mo = *get<MechanicalObject>(*s.root, "dofs");
    auto& mass = *get<DiagonalMass>(*s.root, "mass");
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.05, 3.95);
    int cut = 0, refused = 0;
    for (int k = 0; k < 300; ++k) {
      Vec3 a(u(rng), u(rng), 0), b(u(rng), u(rng), 0);
      if (k % 7 == 0) b = Vec3(std::round(b[0]), std::round(b[1]), 0);  // on a vertex now and then
      unsigned ta = incision::find_element_index(m, a, incision::kInvalid);
      unsigned tb = incision::find_element_index(m, b, incision::kInvalid);
      incision::Path path;
      std::string why;
      if (ta == incision::kInvalid || tb == incision::kInvalid ||
          !incision::intersected_objects_list(m, incision::kInvalid, a, b, ta, tb, path, &why)) {
        ++refused;
        continue;
      }
      std::vector<unsigned> new_edges, new_points, end_points;
      bool border = false;
      if (incision::split_along_path(m, incision::kInvalid, a, incision::kInvalid, b, path, new_edges, eps_path,
                                     0.25, &why) >= 0 &&
          incision::incise_along_edge_list(m, new_edges, new_points, end_points, border, &why))
        ++cut;
      else
        ++refused;
      ASSERT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "") << "cut " << k;
      ASSERT_EQ(mo.size(), topo.nb_points()) << "cut " << k;
      ASSERT_EQ(mass.masses().size(), topo.nb_points()) << "cut " << k;
      for (const auto& around : topo.triangles_around_edge()) ASSERT_LE(around.size(), 2u) << "cut " << k;
      if (eps_path != 0.0) continue;
      const auto& x = mo.read(kRestPosition);
      double area = 0;
      for (const Triangle& t : topo.triangles()) {
        const double z = (x[3 * t[1]] - x[3 * t[0]]) * (x[3 * t[2] + 1] - x[3 * t[0] + 1]) -
                         (x[3 * t[1] + 1] - x[3 * t[0] + 1]) * (x[3 * t[2]] - x[3 * t[0]]);
        ASSERT_GT(z, 0.0) << "cut " << k;
        area += z / 2;
      }
      ASSERT_NEAR(area, 16.0, 1e-9) << "cut " << k;
      double total = 0;
      for (double w : mass.masses()) total += w;
      ASSERT_NEAR(total, 1.5 * 16.0, 1e-9) << "cut " << k;
    }
    EXPECT_GT(cut, 20);
    std::printf("epsilonSnapPath %g: %d cuts made, %d refused; %zu points, %zu triangles\n", eps_path, cut, refused,
                topo.nb_points(), topo.triangles().size());
  }
}
