// Point additions (SOFA's addPoints with ancestors), the Triangle2Edge mapping
// following triangle removals and additions, the processor's PointInTriangle
// lines and its useDataInputs option, and springs following point removal
// (spec/interaction.md §7.2–7.4). Values hand-worked on small meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "forcefield/spring/spring_force_field.h"
#include "mass/diagonal_mass.h"
#include "mass/uniform_mass.h"
#include "core/node.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/edge_set_topology_container.h"
#include "topology/dynamic/element_removal.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "topology/mapping/triangle2_edge_topological_mapping.h"
#include "topology/utility/topological_change_processor.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

struct Recorder final : TopologyHandler {
  std::vector<TopologyChange> seen;
  void apply(const MeshTopologyBase&, const TopologyChange& c) override { seen.push_back(c); }
};

// AddingPointInTriangleProcess's mesh: points 0..4, triangles (0,1,4) (1,2,4) (0,4,3).
const char* kFan = R"(<Node>
  <TriangleSetTopologyContainer name="topo" position="0 0 20  10 0 20  20 0 20  0 10 20  10 10 20"
                                triangles="0 1 4  1 2 4  0 4 3"/>
  <TriangleSetTopologyModifier name="mod"/>
  <MechanicalObject name="dofs" position="@topo.position" velocity="1 0 0  0 2 0  0 0 4  8 0 0  0 16 0"/>
  <DiagonalMass name="mass" massDensity="1"/>
</Node>)";

std::set<std::pair<unsigned, unsigned>> as_set(const std::vector<Edge>& edges) {
  std::set<std::pair<unsigned, unsigned>> s;
  for (const Edge& e : edges) s.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
  return s;
}

// The edges of `tris` used by exactly one of them.
std::set<std::pair<unsigned, unsigned>> boundary(const std::vector<Triangle>& tris) {
  std::map<std::pair<unsigned, unsigned>, int> count;
  for (const Triangle& t : tris)
    for (int j = 0; j < 3; ++j) {
      const unsigned a = t[j], b = t[(j + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<std::pair<unsigned, unsigned>> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert(e);
  return out;
}

}  // namespace

// addPoints(2) with ancestors: new DoFs = Σ coef·ancestor in every allocated vector, exact with
// dyadic coefficients. Point 5 in triangle (0,1,4) with (0.25, 0.5, 0.25):
//   x = 0.25·(0,0,20) + 0.5·(10,0,20) + 0.25·(10,10,20) = (7.5, 2.5, 20);
//   v = 0.25·(1,0,0) + 0.5·(0,2,0) + 0.25·(0,16,0) = (0.25, 5, 0).
// Point 6 with no coefficients: SOFA's default 1/k (in float: 0.5f exactly for k = 2) of (2, 3):
//   x = (10, 5, 20), v = (4, 0, 2).
TEST(TopologyPointAddition, StatesGrowWithInterpolatedDofsAndTheEventCarriesAncestors) {
  auto s = load(kFan);
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TriangleSetTopologyModifier>(*s.root, "mod");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  auto& mass = *get<DiagonalMass>(*s.root, "mass");
  const double total_before = mass.total_mass.value();
  Recorder rec;
  rec.attach(&topo);
  ASSERT_TRUE(mod.add_points(2, {{0, 1, 4}, {2, 3}}, {{0.25, 0.5, 0.25}, {}}));
  EXPECT_EQ(topo.nb_points(), 7u);
  ASSERT_EQ(mo.size(), 7u);
  const auto& x = mo.read(kPosition);
  const auto& v = mo.read(kVelocity);
  const auto& x0 = mo.read(kRestPosition);
  EXPECT_EQ(std::vector<double>(x.begin() + 15, x.end()), (std::vector<double>{7.5, 2.5, 20, 10, 5, 20}));
  EXPECT_EQ(std::vector<double>(x0.begin() + 15, x0.end()), (std::vector<double>{7.5, 2.5, 20, 10, 5, 20}));
  EXPECT_EQ(std::vector<double>(v.begin() + 15, v.end()), (std::vector<double>{0.25, 5, 0, 4, 0, 2}));
  ASSERT_EQ(rec.seen.size(), 2u);
  EXPECT_EQ(rec.seen[0].type, TopologyChangeType::points_added);
  EXPECT_EQ(rec.seen[0].indices, (std::vector<unsigned>{5, 6}));
  EXPECT_EQ(rec.seen[0].ancestors, (std::vector<std::vector<unsigned>>{{0, 1, 4}, {2, 3}}));
  EXPECT_EQ(rec.seen[1].type, TopologyChangeType::ending);
  // DiagonalMass: new points have no mass until elements use them.
  ASSERT_EQ(mass.vertex_mass.value().size(), 7u);
  EXPECT_EQ(mass.vertex_mass.value()[5], 0.0);
  // A triangle on the new points brings its mass (area 25 at z = 20 → 25/3 per vertex).
  // Triangle (5, 1, 6): (7.5,2.5) (10,0) (10,5): area = |(2.5,-2.5)×(2.5,2.5)|/2 = 6.25.
  mod.add_triangles({{5, 1, 6}});
  EXPECT_DOUBLE_EQ(mass.vertex_mass.value()[5], 6.25 / 3.0);
  EXPECT_DOUBLE_EQ(mass.total_mass.value(), total_before + 6.25);
  // Out-of-range ancestors are refused, nothing added.
  EXPECT_FALSE(mod.add_points(1, {{0, 99}}, {}));
  EXPECT_EQ(topo.nb_points(), 7u);
  EXPECT_EQ(mo.size(), 7u);
}

// ADD= PointsInTriangle through the processor, as in AddingPointInTriangleProcess.txt: triangle 1
// = (1,2,4) with (0.5, 0.25) → coefficients (0.5, 0.25, 0.25):
//   x = 0.5·(10,0,20) + 0.25·(20,0,20) + 0.25·(10,10,20) = (12.5, 2.5, 20).
TEST(TopologicalChangeProcessor, AddsPointsInTriangles) {
  sinew::test::TempDir dir;
  const std::string file = dir.write("p.txt", "T= 0.1\n  ADD= PointsInTriangle 1\n1 0.5 0.25\nT= 0.2\n"
                                              "  ADD= PointInTriangle 1\n7 0.5 0.25\n");
  auto s = load(std::string(R"(<Node>
    <TriangleSetTopologyContainer name="topo" position="0 0 20  10 0 20  20 0 20  0 10 20  10 10 20"
                                  triangles="0 1 4  1 2 4  0 4 3"/>
    <TriangleSetTopologyModifier name="mod"/>
    <MechanicalObject name="dofs" position="@topo.position"/>
    <UniformMass name="mass" totalMass="1"/>
    <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
  </Node>)");
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  auto& mass = *get<UniformMass>(*s.root, "mass");
  auto& proc = *get<TopologicalChangeProcessor>(*s.root, "proc");
  proc.process(0.1);
  ASSERT_EQ(topo.nb_points(), 6u);
  ASSERT_EQ(mo.size(), 6u);
  const auto& x = mo.read(kPosition);
  EXPECT_EQ(std::vector<double>(x.begin() + 15, x.end()), (std::vector<double>{12.5, 2.5, 20}));
  // UniformMass (preserveTotalMass false): the vertex mass stays 1/5, the total follows.
  EXPECT_DOUBLE_EQ(mass.mass(), 0.2);
  EXPECT_DOUBLE_EQ(mass.total_mass.value(), 6 * 0.2);
  // Triangle 7 does not exist: refused naming the line, nothing added.
  proc.process(0.2);
  EXPECT_EQ(topo.nb_points(), 6u);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error),
                                        "p.txt:6: triangle 7 is out of range (3 triangles)"));
}

// A 3×3 grid of points (2×2 squares, 8 triangles); the mapped edges are the 8 boundary edges.
const char* kGrid = R"(<Node>
  <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0  0 2 0  1 2 0  2 2 0"
      triangles="0 1 4  0 4 3  1 2 5  1 5 4  3 4 7  3 7 6  4 5 8  4 8 7"/>
  <TriangleSetTopologyModifier name="mod"/>
  <Node name="edges">
    <EdgeSetTopologyContainer name="out"/>
    <EdgeSetTopologyModifier name="emod"/>
    <Triangle2EdgeTopologicalMapping name="map" input="@../topo" output="@out"/>
  </Node>
</Node>)";

void expect_mapping_consistent(const TriangleSetTopologyContainer& topo, const EdgeSetTopologyContainer& out,
                               const Triangle2EdgeTopologicalMapping& map, const std::string& when) {
  EXPECT_EQ(as_set(out.edges()), boundary(topo.triangles())) << when;
  ASSERT_EQ(map.loc2glob().size(), out.edges().size()) << when;
  for (std::size_t i = 0; i < out.edges().size(); ++i) {
    const Edge& o = out.edges()[i];
    const Edge& g = topo.edges()[map.loc2glob()[i]];
    EXPECT_EQ(as_set({o}), as_set({g})) << when << ": output edge " << i;
    EXPECT_EQ(map.glob2loc(map.loc2glob()[i]), i) << when;
  }
  EXPECT_EQ(out.nb_points(), topo.nb_points()) << when;
}

TEST(Triangle2EdgeMapping, OutputIsTheBoundaryOfTheRemainingTrianglesThroughRemovalsAndAdditions) {
  auto s = load(kGrid);
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TriangleSetTopologyModifier>(*s.root, "mod");
  Node& edges = *s.root->find_child_named("edges");
  auto& out = *get<EdgeSetTopologyContainer>(edges, "out");
  auto& map = *get<Triangle2EdgeTopologicalMapping>(edges, "map");
  ASSERT_EQ(out.edges().size(), 8u);
  expect_mapping_consistent(topo, out, map, "init");
  // The centre triangles one by one, then a corner square: inner edges become boundary, lone
  // edges and points go.
  const std::vector<std::vector<unsigned>> removals = {{3}, {0, 6}, {2}, {0}};
  for (std::size_t k = 0; k < removals.size(); ++k) {
    mod.remove_triangles(removals[k], true, true);
    expect_mapping_consistent(topo, out, map, "removal " + std::to_string(k));
    EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "") << k;
  }
  // Left: (4,1,2) (0,4,3) (3,4,2) on 5 points; boundary (1,4) (1,2) (0,4) (0,3) (2,3).
  ASSERT_EQ(topo.triangles(), (std::vector<Triangle>{{4, 1, 2}, {0, 4, 3}, {3, 4, 2}}));
  // Triangle (1,0,4) added: (0,1) joins; (0,4) and (1,4) are covered and leave the output.
  // Point 4 is then on no output edge: SOFA's removeEdges (removeIsolatedPoints by default)
  // removes it from the output, which keeps 4 points (4 was the last: no renumbering).
  mod.add_triangles({{1, 0, 4}});
  EXPECT_EQ(as_set(out.edges()), boundary(topo.triangles()));
  EXPECT_EQ(as_set(out.edges()), (std::set<std::pair<unsigned, unsigned>>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
  EXPECT_EQ(out.nb_points(), 4u);
  // loc2glob is not checked here: SOFA swap-pops it in decreasing input-edge order while the
  // output removes the same edges in decreasing local order, so two covered edges can leave
  // their survivors swapped in the map (reproduced as is).
  EXPECT_EQ(map.loc2glob().size(), 4u);
}

// useDataInputs (RemovingPointSprings): at the first time past timeToRemove the points go
// (removeItems), the springs using them go and the springs on the renumbered points follow;
// with interval 0 the next time is 2^32 − 1.
TEST(TopologicalChangeProcessor, UseDataInputsRemovesPointsAndSpringsFollow) {
  auto s = load(R"(<Node>
    <Node name="fixed"><MechanicalObject name="dof" position="0 2 0  1 2 0  2 2 0  3 2 0"/></Node>
    <Node name="mass">
      <PointSetTopologyContainer name="container" position="2 1 0  0 1 0  1 1 0  3 1 0"/>
      <PointSetTopologyModifier name="modifier"/>
      <MechanicalObject name="dof"/>
      <UniformMass name="m" vertexMass="10"/>
      <TopologicalChangeProcessor name="proc" useDataInputs="true" pointsToRemove="0 1" timeToRemove="1.2"/>
    </Node>
    <SpringForceField name="springs" object1="@fixed/dof" object2="@mass/dof"
        spring="2 0 100 0 1  1 2 100 0 1  3 3 100 0 1  0 1 100 0 1  1 0 100 0 1  0 2 100 0 1"/>
  </Node>)");
  Node& mass_node = *s.root->find_child_named("mass");
  auto& proc = *get<TopologicalChangeProcessor>(mass_node, "proc");
  auto& mo = *get<MechanicalObject>(mass_node, "dof");
  auto& ff = *get<SpringForceField>(*s.root, "springs");
  auto& m = *get<UniformMass>(mass_node, "m");
  proc.process_data_inputs(1.2);  // not yet: time must pass timeToRemove
  EXPECT_EQ(ff.spring_list().size(), 6u);
  proc.process_data_inputs(1.3);
  // Points removed in decreasing order: 1 (point 3 moves into slot 1), then 0 (point 2, the last
  // of three, moves into slot 0). Springs (m1, m2) on object2's side: removing 1 drops (0,1) and
  // renumbers (3,3) → (3,1); removing 0 drops (2,0) and (1,0), renumbers (1,2) → (1,0) and
  // (0,2) → (0,0). Left, in order: (1,0) (3,1) (0,0).
  ASSERT_EQ(ff.spring_list().size(), 3u);
  const std::vector<std::pair<unsigned, unsigned>> want = {{1, 0}, {3, 1}, {0, 0}};
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(ff.spring_list()[i].m1, want[i].first) << i;
    EXPECT_EQ(ff.spring_list()[i].m2, want[i].second) << i;
  }
  const auto& x = mo.read(kPosition);
  EXPECT_EQ(x, (std::vector<double>{1, 1, 0, 3, 1, 0}));
  EXPECT_DOUBLE_EQ(m.total_mass.value(), 20.0);
  EXPECT_EQ(proc.time_to_remove.value(), 4294967295.0);
}

// INCISE= blocks: malformed ones are refused at init naming the line; well-formed ones (both
// forms) cut when due. The unit square's two triangles (0 1 2) (1 3 2), cut from (0.2, 0.2) to
// (0.8, 0.6): triangle, diagonal (1, 2), triangle. Without saved indices SOFA snaps the ends with
// epsilonSnapBorder 0.25: (0.2, 0.2) has coefficient 0.2 on vertex 1, so it moves onto the
// opposite border edge x = 0, and (0.8, 0.6) (0.2 on vertex 2) onto x = 1: the cut crosses the
// square (3 edge points, 6 triangles, 12 edges) and, both ends on the border, every path point is
// duplicated: 10 points, 14 edges, two pieces. With saved indices and epsilonSnapBorder 0 the ends
// stay inside: 3 new points, 8 triangles, 14 edges, then only the diagonal's point duplicated: 8
// points, 16 edges. A point outside the mesh or both ends in one triangle: a warning naming the
// line, nothing cut.
TEST(TopologicalChangeProcessor, InciseBlocksAreCheckedAndApplied) {
  sinew::test::TempDir dir;
  const char* scene = R"(<Node>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
      <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  1 1 0" triangles="0 1 2  1 3 2"/>
      <TriangleSetTopologyModifier name="mod"/>
      <TopologicalChangeProcessor name="proc" filename="FILE"/>
    </Node>)";
  auto with = [&](const std::string& file, const std::string& attributes = "") {
    std::string xml = scene;
    xml.replace(xml.find("FILE\""), 5, file + "\" " + attributes);
    return xml;
  };
  {
    const std::string file = dir.write("bad.txt", "T= 0.1\n\tINCISE= 2\n0.2 0.2 0 0.8\n");
    auto s = sinew::test::build(with(file));
    init_root(*s.root);
    EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error),
                                          "bad.txt:2: INCISE= 2: line 3 needs 6 (coordinates) or 8 (triangle and "
                                          "coordinates) numbers, has 4"));
  }
  struct Case {
    const char* line;
    const char* attributes;
    std::size_t triangles, points, edges;
  };
  for (const Case& c : {Case{"0.2 0.2 0 0.8 0.6 0", "", 6, 10, 14}, Case{"0 0.2 0.2 0 1 0.8 0.6 0", "", 6, 10, 14},
                        Case{"0.2 0.2 0 0.8 0.6 0", "saveIndicesAtInit=\"true\" epsilonSnapBorder=\"0\"", 8, 8, 16}}) {
    const std::string file = dir.write("ok.txt", std::string("T= 0.1\n\tINCISE= 2\n") + c.line + "\n");
    auto s = load(with(file, c.attributes));
    auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
    animate(*s.root, 0.1);  // T= 0.1 is due at the second step (time 0.1, matched exactly)
    animate(*s.root, 0.1);
    EXPECT_TRUE(sinew::test::messages(s.root->diagnostics(), Severity::error).empty()) << c.line;
    EXPECT_EQ(topo.triangles().size(), c.triangles) << c.line;
    EXPECT_EQ(topo.nb_points(), c.points) << c.line;
    EXPECT_EQ(topo.edges().size(), c.edges) << c.line;
    EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->size(), c.points) << c.line;
  }
  for (const char* line : {"0.2 0.2 0 3 3 0", "0.1 0.1 0 0.2 0.3 0"}) {
    const std::string file = dir.write("out.txt", std::string("T= 0.1\n\tINCISE= 2\n") + line + "\n");
    auto s = load(with(file));
    get<TopologicalChangeProcessor>(*s.root, "proc")->process(0.1);
    const auto warnings = sinew::test::messages(s.root->diagnostics(), Severity::warning);
    EXPECT_TRUE(sinew::test::any_contains(warnings, "out.txt:2: invalid incision path from point 0 to point 1"))
        << line;
    auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
    EXPECT_EQ(topo.triangles().size(), 2u);
    EXPECT_EQ(topo.nb_points(), 4u);
  }
}
