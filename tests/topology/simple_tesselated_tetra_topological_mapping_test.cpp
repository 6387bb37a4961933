// SimpleTesselatedTetraTopologicalMapping and SimpleTesselatedTetraMechanicalMapping: one
// tetrahedron refined into eight (points and tetrahedra checked by hand), the mapped DoFs, and
// SOFA's two propagation directions (input removals update the maps only; an input tetrahedron
// whose eight children were removed from the output is removed from the input).
#include "topology/mapping/simple_tesselated_tetra_topological_mapping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "mapping/linear/simple_tesselated_tetra_mechanical_mapping.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

using namespace sinew;

namespace {

// `tets` over points 0 (origin), 1 (x), 2 (y), 3 (z), 4 (1 1 1).
std::string refined_scene(const std::string& tets, bool mechanical = true) {
  return R"(<Node name="root" gravity="0 0 0">
    <TetrahedronSetTopologyContainer name="in" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1" tetrahedra=")" +
         tets + R"("/>
    <TetrahedronSetTopologyModifier name="inmod"/>
    <MechanicalObject name="dofs"/>
    <Node name="fine">
      <TetrahedronSetTopologyContainer name="out"/>
      <TetrahedronSetTopologyModifier name="outmod"/>
      <SimpleTesselatedTetraTopologicalMapping name="map" input="@../in" output="@out"/>)" +
         (mechanical ? R"(<MechanicalObject name="fdofs"/><SimpleTesselatedTetraMechanicalMapping name="mmap"/>)" : "") +
         R"(
    </Node>
  </Node>)";
}

Node& fine(const scene::LoadedScene& s) { return *s.root->find_child_named("fine"); }

double volume(const std::vector<Vec3>& p, const Tetra& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]]) / 6;
}

}  // namespace

TEST(SimpleTesselatedTetraTopologicalMapping, OneTetrahedronBecomesEightWithTheEdgeMidpoints) {
  auto s = test::load(refined_scene("0 1 2 3"));
  auto& map = *test::get<SimpleTesselatedTetraTopologicalMapping>(fine(s), "map");
  ASSERT_EQ(map.state(), ComponentState::valid);
  auto& in = *test::get<TetrahedronSetTopologyContainer>(*s.root, "in");
  auto& out = *test::get<TetrahedronSetTopologyContainer>(fine(s), "out");
  const auto& edges = in.edges();
  ASSERT_EQ(edges.size(), 6u);
  // The five input points (point 4 belongs to no tetrahedron: it is copied all the same).
  ASSERT_EQ(out.nb_points(), 11u);
  const std::vector<Vec3>& p = out.position.get();
  ASSERT_EQ(p.size(), 11u);
  EXPECT_EQ(p[4], Vec3(1, 1, 1));
  for (unsigned e = 0; e < 6; ++e) {  // point 5 + e is the midpoint of input edge e
    const Vec3 mid = (in.point(edges[e][0]) + in.point(edges[e][1])) / 2;
    EXPECT_EQ(p[5 + e], mid) << "edge " << e;
  }
  EXPECT_EQ(map.point_mapped_from_point.get(), (std::vector<unsigned>{0, 1, 2, 3, 4}));
  EXPECT_EQ(map.point_mapped_from_edge.get(), (std::vector<unsigned>{5, 6, 7, 8, 9, 10}));
  // pointSource: p+1 for the input points, −(e+1) for the edges, in SOFA's unsigned vector.
  EXPECT_EQ(map.point_source.get()[0], 1u);
  EXPECT_EQ(map.point_source.get()[4], 5u);
  EXPECT_EQ(map.point_source.get()[5], 4294967295u);
  EXPECT_EQ(map.source_of_point(10), -6);

  // SOFA's eight children, m_k the midpoint of local edge k of the tetrahedron.
  const auto& loc = in.edges_in_tetrahedron()[0];
  unsigned m[6];
  for (int k = 0; k < 6; ++k) m[k] = 5 + loc[k];
  const std::vector<Tetra> want = {{0, m[0], m[1], m[2]},    {1, m[0], m[4], m[3]},    {2, m[1], m[3], m[5]},
                                   {3, m[2], m[5], m[4]},    {m[1], m[0], m[3], m[5]}, {m[1], m[0], m[5], m[2]},
                                   {m[4], m[0], m[5], m[3]}, {m[4], m[0], m[2], m[5]}};
  EXPECT_EQ(out.tetrahedra(), want);
  // Each child holds an eighth of the volume (1/6).
  for (const Tetra& t : out.tetrahedra()) EXPECT_NEAR(std::abs(volume(p, t)), 1.0 / 48, 1e-15);
  EXPECT_EQ(map.tetra_source.get(), std::vector<unsigned>(8, 0u));
  EXPECT_EQ(map.tetrahedra_mapped_from_tetra.get()[0], (std::array<unsigned, 8>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(SimpleTesselatedTetraMechanicalMapping, PointsAndMidpointsAndTheirTranspose) {
  auto s = test::load(refined_scene("0 1 2 3"));
  auto& mm = *test::get<SimpleTesselatedTetraMechanicalMapping>(fine(s), "mmap");
  ASSERT_EQ(mm.state(), ComponentState::valid);
  auto& in = *test::get<TetrahedronSetTopologyContainer>(*s.root, "in");
  MechanicalState& dofs = *s.root->mechanical_state;
  MechanicalState& fdofs = *fine(s).mechanical_state;
  ASSERT_EQ(fdofs.size(), 11u);
  std::vector<double>& x = dofs.write(kPosition);
  x[3 * 3 + 2] = 3.0;  // point 3 moves to (0, 0, 3)
  x[1 * 3 + 1] = 2.0;  // point 1 to (1, 2, 0)
  mm.apply(kPosition);
  const std::vector<double>& y = fdofs.read(kPosition);
  EXPECT_DOUBLE_EQ(y[3 * 3 + 2], 3.0);
  const auto& edges = in.edges();
  for (unsigned e = 0; e < 6; ++e)
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(y[3 * (5 + e) + c], (x[3 * edges[e][0] + c] + x[3 * edges[e][1] + c]) * 0.5);

  // Jᵀ: a unit force on the midpoint of edge e gives half of it to each end.
  const unsigned e = 2;
  std::vector<double>& f_out = fdofs.write(kForce);
  std::fill(f_out.begin(), f_out.end(), 0.0);
  f_out[3 * (5 + e) + 0] = 1.0;
  f_out[3 * 0 + 1] = 2.0;  // and a force on output point 0 (input point 0)
  std::vector<double>& f_in = dofs.write(kForce);
  std::fill(f_in.begin(), f_in.end(), 0.0);
  mm.apply_jt(kForce, kForce);
  const std::vector<double>& g = dofs.read(kForce);
  EXPECT_DOUBLE_EQ(g[3 * edges[e][0]], 0.5);
  EXPECT_DOUBLE_EQ(g[3 * edges[e][1]], 0.5);
  EXPECT_DOUBLE_EQ(g[1], 2.0);
}

TEST(SimpleTesselatedTetraTopologicalMapping, InputRemovalUpdatesTheMapsOnly) {
  auto s = test::load(refined_scene("0 1 2 3  1 2 3 4", false));
  auto& map = *test::get<SimpleTesselatedTetraTopologicalMapping>(fine(s), "map");
  auto& inmod = *test::get<TetrahedronSetTopologyModifier>(*s.root, "inmod");
  auto& out = *test::get<TetrahedronSetTopologyContainer>(fine(s), "out");
  ASSERT_EQ(map.state(), ComponentState::valid);
  ASSERT_EQ(out.tetrahedra().size(), 16u);
  inmod.remove_tetrahedra({0});
  // SOFA: the output keeps its 16 tetrahedra; tetrahedron 1 became 0 and owns children 8..15,
  // the removed one's children have no source any more.
  EXPECT_EQ(out.tetrahedra().size(), 16u);
  ASSERT_EQ(map.tetrahedra_mapped_from_tetra.get().size(), 1u);
  EXPECT_EQ(map.tetrahedra_mapped_from_tetra.get()[0], (std::array<unsigned, 8>{8, 9, 10, 11, 12, 13, 14, 15}));
  for (unsigned t = 0; t < 8; ++t) EXPECT_EQ(map.tetra_source.get()[t], SimpleTesselatedTetraTopologicalMapping::kNone);
  for (unsigned t = 8; t < 16; ++t) EXPECT_EQ(map.tetra_source.get()[t], 0u);
  // Point 0 (isolated) left the input: point 4 took its slot; its output point (4) follows.
  auto& in = *test::get<TetrahedronSetTopologyContainer>(*s.root, "in");
  ASSERT_EQ(in.nb_points(), 4u);
  ASSERT_EQ(map.point_mapped_from_point.get().size(), 4u);
  EXPECT_EQ(map.point_mapped_from_point.get()[0], 4u);
  EXPECT_EQ(map.point_source.get()[4], 1u);
  EXPECT_EQ(map.point_source.get()[0], 0u);  // output point 0 has no source any more
  EXPECT_EQ(map.point_mapped_from_edge.get().size(), in.edges().size());
}

TEST(SimpleTesselatedTetraTopologicalMapping, InputTetrahedronStaysWhileOneChildIsLeft) {
  auto s = test::load(refined_scene("0 1 2 3  1 2 3 4"));
  auto& map = *test::get<SimpleTesselatedTetraTopologicalMapping>(fine(s), "map");
  auto& outmod = *test::get<TetrahedronSetTopologyModifier>(fine(s), "outmod");
  auto& in = *test::get<TetrahedronSetTopologyContainer>(*s.root, "in");
  outmod.remove_tetrahedra({0, 1, 2, 3, 4, 5, 6});
  EXPECT_EQ(in.tetrahedra().size(), 2u);
  int children_left = 0;
  for (unsigned c : map.tetrahedra_mapped_from_tetra.get()[0]) children_left += c != SimpleTesselatedTetraTopologicalMapping::kNone;
  EXPECT_EQ(children_left, 1);
}

TEST(SimpleTesselatedTetraTopologicalMapping, InputTetrahedronGoesWhenItsEightChildrenAreRemoved) {
  auto s = test::load(refined_scene("0 1 2 3  1 2 3 4"));
  auto& map = *test::get<SimpleTesselatedTetraTopologicalMapping>(fine(s), "map");
  auto& outmod = *test::get<TetrahedronSetTopologyModifier>(fine(s), "outmod");
  auto& in = *test::get<TetrahedronSetTopologyContainer>(*s.root, "in");
  auto& out = *test::get<TetrahedronSetTopologyContainer>(fine(s), "out");
  outmod.remove_tetrahedra({0, 1, 2, 3, 4, 5, 6, 7});
  // The output's removal reached the input at its ending event: tetrahedron 0 and its isolated
  // point 0 are gone (point 4 took slot 0).
  ASSERT_EQ(in.tetrahedra().size(), 1u);
  EXPECT_EQ(in.tetrahedra()[0], (Tetra{1, 2, 3, 0}));
  ASSERT_EQ(out.tetrahedra().size(), 8u);
  EXPECT_EQ(out.nb_points(), 10u);  // 14 − input point 0 − the midpoints of its three edges
  // SOFA's swaps: output tetrahedron k is the old 8 + k, all children of the remaining input one.
  ASSERT_EQ(map.tetrahedra_mapped_from_tetra.get().size(), 1u);
  EXPECT_EQ(map.tetrahedra_mapped_from_tetra.get()[0], (std::array<unsigned, 8>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(map.tetra_source.get(), std::vector<unsigned>(8, 0u));
  // The point maps still pair each input point and edge with the right output DoF.
  const std::vector<double>& x = s.root->mechanical_state->read(kPosition);
  const std::vector<double>& y = fine(s).mechanical_state->read(kPosition);
  ASSERT_EQ(x.size(), 12u);
  ASSERT_EQ(y.size(), 30u);
  const auto& from_point = map.point_mapped_from_point.get();
  ASSERT_EQ(from_point.size(), 4u);
  for (unsigned p = 0; p < 4; ++p)
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(y[3 * from_point[p] + c], x[3 * p + c]) << "point " << p;
  const auto& from_edge = map.point_mapped_from_edge.get();
  ASSERT_EQ(from_edge.size(), in.edges().size());
  for (unsigned e = 0; e < from_edge.size(); ++e) {
    ASSERT_NE(from_edge[e], SimpleTesselatedTetraTopologicalMapping::kNone) << "edge " << e;
    const Edge& ed = in.edges()[e];
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(y[3 * from_edge[e] + c], (x[3 * ed[0] + c] + x[3 * ed[1] + c]) / 2) << "edge " << e;
  }
}
