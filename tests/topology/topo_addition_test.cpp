// Element addition in the dynamic containers (spec/interaction.md §7.2, §7.4):
// exact arrays and events after adding tetrahedra and triangles to small
// hand-worked meshes, Tetra2TriangleTopologicalMapping following, and the
// TopologicalChangeProcessor's ADD= lines (applied, or refused naming file:line).
#include <gtest/gtest.h>

#include "core/simulation.h"
#include "forcefield/fem/tetrahedral_corotational_fem_force_field.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "topology/mapping/tetra2_triangle_topological_mapping.h"
#include "topology/utility/topological_change_processor.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

struct Recorder final : TopologyHandler {
  std::vector<TopologyChange> seen;
  void apply(const MeshTopologyBase&, const TopologyChange& c) override { seen.push_back(c); }
};

template <class T>
std::vector<T> list(std::initializer_list<T> v) { return v; }

using T = TopologyChangeType;
void expect_events(const Recorder& rec, const std::vector<std::pair<T, std::vector<unsigned>>>& want) {
  ASSERT_EQ(rec.seen.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(rec.seen[i].type, want[i].first) << "event " << i;
    EXPECT_EQ(rec.seen[i].indices, want[i].second) << "event " << i;
  }
}

// Five points, no element yet (as a loader giving only nodes).
const char* kFivePoints = R"(<Node>
  <TetrahedronSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1"/>
  <TetrahedronSetTopologyModifier name="mod"/>
  <Node name="skin">
    <TriangleSetTopologyContainer name="tris"/>
    <TriangleSetTopologyModifier name="tmod"/>
    <Tetra2TriangleTopologicalMapping name="map" input="@../topo" output="@tris"/>
  </Node>
</Node>)";

}  // namespace

// addTetrahedra on an empty container, hand-worked. Tetra (0,1,2,3): faces (t1,t2,t3) (t0,t3,t2)
// (t1,t3,t0) (t0,t2,t1) = (1,2,3) (0,3,2) (1,3,0) (0,2,1), each created in turn with its missing
// edges (t[j+1], t[j+2]) first:
//   (1,2,3): e0 (2,3), e1 (3,1), e2 (1,2); (0,3,2): e3 (2,0), e4 (0,3); (1,3,0): e5 (0,1); (0,2,1): none.
// edgesInTetrahedron by local edges 01 02 03 12 13 23 = e5 e3 e4 e2 e1 e0.
// Tetra (1,2,3,4): faces (2,3,4) (1,4,3) (2,4,1) (1,3,2); the last is triangle 0 (any order).
//   (2,3,4): e6 (3,4), e7 (4,2); (1,4,3): e8 (1,4); (2,4,1): none.
// edgesInTetrahedron: (1,2) (1,3) (1,4) (2,3) (2,4) (3,4) = e2 e1 e8 e0 e7 e6.
TEST(TopologyAddition, AddTetrahedraCreatesFacesThenEdgesInSofaOrder) {
  auto s = load(kFivePoints);
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  ASSERT_TRUE(topo.tetrahedra().empty());
  ASSERT_EQ(topo.nb_points(), 5u);
  Recorder rec;
  rec.attach(&topo);

  mod.add_tetrahedra({{0, 1, 2, 3}});
  EXPECT_EQ(topo.tetrahedra(), list<Tetra>({{0, 1, 2, 3}}));
  EXPECT_EQ(topo.triangles(), list<Triangle>({{1, 2, 3}, {0, 3, 2}, {1, 3, 0}, {0, 2, 1}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{2, 3}, {3, 1}, {1, 2}, {2, 0}, {0, 3}, {0, 1}}));
  EXPECT_EQ(topo.edges_in_tetrahedron()[0], (std::array<unsigned, 6>{5, 3, 4, 2, 1, 0}));
  EXPECT_EQ(topo.triangles_in_tetrahedron()[0], (std::array<unsigned, 4>{0, 1, 2, 3}));
  expect_events(rec, {{T::edges_added, {0}},
                      {T::edges_added, {1}},
                      {T::edges_added, {2}},
                      {T::triangles_added, {0}},
                      {T::edges_added, {3}},
                      {T::edges_added, {4}},
                      {T::triangles_added, {1}},
                      {T::edges_added, {5}},
                      {T::triangles_added, {2}},
                      {T::triangles_added, {3}},
                      {T::tetrahedra_added, {0}},
                      {T::ending, {}}});

  rec.seen.clear();
  mod.add_tetrahedra({{1, 2, 3, 4}});
  EXPECT_EQ(topo.tetrahedra(), list<Tetra>({{0, 1, 2, 3}, {1, 2, 3, 4}}));
  EXPECT_EQ(topo.triangles(), list<Triangle>({{1, 2, 3}, {0, 3, 2}, {1, 3, 0}, {0, 2, 1}, {2, 3, 4}, {1, 4, 3},
                                              {2, 4, 1}}));
  EXPECT_EQ(topo.edges(),
            list<Edge>({{2, 3}, {3, 1}, {1, 2}, {2, 0}, {0, 3}, {0, 1}, {3, 4}, {4, 2}, {1, 4}}));
  EXPECT_EQ(topo.edges_in_tetrahedron()[1], (std::array<unsigned, 6>{2, 1, 8, 0, 7, 6}));
  EXPECT_EQ(topo.triangles_in_tetrahedron()[1], (std::array<unsigned, 4>{4, 5, 6, 0}));
  EXPECT_EQ(topo.tetrahedra_around_triangle()[0], list<unsigned>({0, 1}));
  expect_events(rec, {{T::edges_added, {6}},
                      {T::edges_added, {7}},
                      {T::triangles_added, {4}},
                      {T::edges_added, {8}},
                      {T::triangles_added, {5}},
                      {T::triangles_added, {6}},
                      {T::tetrahedra_added, {1}},
                      {T::ending, {}}});
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");

  // Removal after addition works on the same live arrays: removing tetra 0 leaves tetra 1 with
  // its 4 faces and 6 edges (point 0 goes: the last point, 4, takes its index).
  mod.remove_tetrahedra({0});
  EXPECT_EQ(topo.tetrahedra(), list<Tetra>({{1, 2, 3, 0}}));
  EXPECT_EQ(topo.triangles().size(), 4u);
  EXPECT_EQ(topo.edges().size(), 6u);
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
}

// The mapping copies the input's new edges (EDGESADDED → addEdges) and adds the faces the new
// tetrahedra leave on the boundary (input order). With the second tetrahedron, triangle 0
// (1,2,3) becomes inner: created locals 4..6 = (2,3,4) (1,4,3) (2,4,1), then local 0 is removed
// by swap-with-last: (2,4,1) takes its slot, loc2glob = [6,1,2,3,4,5]; no edge is isolated.
TEST(TopologyAddition, Tetra2TriangleMappingFollowsTetrahedronAddition) {
  auto s = load(kFivePoints);
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  ASSERT_EQ(s.root->children().size(), 1u);
  Node& skin = *s.root->children()[0];
  auto& tris = *get<TriangleSetTopologyContainer>(skin, "tris");
  auto& map = *get<Tetra2TriangleTopologicalMapping>(skin, "map");
  ASSERT_TRUE(tris.triangles().empty());

  mod.add_tetrahedra({{0, 1, 2, 3}});
  EXPECT_EQ(tris.triangles(), topo.triangles());
  EXPECT_EQ(tris.edges(), topo.edges());
  EXPECT_EQ(map.loc2glob(), list<unsigned>({0, 1, 2, 3}));

  mod.add_tetrahedra({{1, 2, 3, 4}});
  EXPECT_EQ(tris.triangles(), list<Triangle>({{2, 4, 1}, {0, 3, 2}, {1, 3, 0}, {0, 2, 1}, {2, 3, 4}, {1, 4, 3}}));
  EXPECT_EQ(map.loc2glob(), list<unsigned>({6, 1, 2, 3, 4, 5}));
  for (unsigned loc = 0; loc < map.loc2glob().size(); ++loc) EXPECT_EQ(map.glob2loc(map.loc2glob()[loc]), loc);
  EXPECT_EQ(tris.edges(), topo.edges());
  EXPECT_EQ(topo::check_dynamic_mesh(tris.begin_edit()), "");
}

// ADD= lines replayed: triangles with ancestors, then an edge. Triangles (0,1,2), (1,3,2):
// edges (1,2) (2,0) (0,1), then (3,2) and (1,3) ((2,1) exists); then the edge (0,3).
TEST(TopologicalChangeProcessor, AppliesAddBlocks) {
  sinew::test::TempDir dir;
  const std::string file =
      dir.write("add.txt", "T= 0.1\n  ADD= Triangles 2 Ancestors 7 8\n0 1 2 1 3 2\nT= 0.2\n  ADD= Edge 1\n0 3\n");
  auto s = load(std::string(R"(<Node>
    <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
    <TriangleSetTopologyModifier name="mod"/>
    <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
  </Node>)");
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  auto& proc = *get<TopologicalChangeProcessor>(*s.root, "proc");
  Recorder rec;
  rec.attach(&topo);
  proc.process(0.05);
  EXPECT_TRUE(topo.triangles().empty());
  proc.process(0.1);
  EXPECT_EQ(topo.triangles(), list<Triangle>({{0, 1, 2}, {1, 3, 2}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{1, 2}, {2, 0}, {0, 1}, {3, 2}, {1, 3}}));
  ASSERT_EQ(rec.seen.size(), 7u);  // 5 edges, the triangles, the ending event
  EXPECT_EQ(rec.seen[5].type, T::triangles_added);
  EXPECT_EQ(rec.seen[5].indices, list<unsigned>({0, 1}));
  EXPECT_EQ(rec.seen[5].ancestors, (std::vector<std::vector<unsigned>>{{7}, {8}}));
  proc.process(0.2);
  EXPECT_EQ(topo.edges().back(), (Edge{0, 3}));
  EXPECT_EQ(topo.edges().size(), 6u);
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
}

// Malformed or unsupported ADD= lines are refused at init, naming file:line; nothing is applied.
TEST(TopologicalChangeProcessor, RefusesMalformedAddLinesNamingTheLine) {
  sinew::test::TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"T= 0.1\nADD= Triangles 2\n0 1 2 1 3\n", "bad.txt:2: ADD= Triangles 2: line 3 needs 6 non-negative vertex indices"},
      {"T= 0.1\nADD= Triangles two\n0 1 2\n", "bad.txt:2: ADD= Triangles needs a count of elements"},
      {"T= 0.1\n\nADD= Prisms 1\n0 1 2\n", "bad.txt:3: ADD= of unknown kind 'Prisms'"},
      {"T= 0.1\nADD= Tetrahedra 1\n0 1 2 3\n",
       "bad.txt:2: ADD= Tetrahedra needs a TetrahedronSetTopologyModifier in the topology's node or its ancestors"},
      {"T= 0.1\nADD= PointInTriangle 1\n0 0.2\n",
       "bad.txt:2: ADD= PointInTriangle 1: line 3 needs 1 groups 'triangle b0 b1' (non-negative triangle index)"},
      {"T= 0.1\nADD= Triangles 1\n", "bad.txt:2: ADD= Triangles 1: line 3 needs 3 non-negative vertex indices"},
  };
  for (const auto& [text, error] : cases) {
    const std::string file = dir.write("bad.txt", text);
    auto s = sinew::test::build(std::string(R"(<Node>
      <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
      <TriangleSetTopologyModifier name="mod"/>
      <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
    </Node>)");
    init_root(*s.root);
    EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error), error))
        << error;
    auto& proc = *get<TopologicalChangeProcessor>(*s.root, "proc");
    proc.process(1.0);
    EXPECT_TRUE(get<TriangleSetTopologyContainer>(*s.root, "topo")->triangles().empty()) << error;
  }
}

// A tetrahedral FEM on a container that starts without tetrahedra (AddingTetraProcess): SOFA
// warns and adds no force; the tetrahedra added later are simulated.
TEST(TopologyAddition, TetrahedralCorotationalFEMStartsEmptyThenFollowsAdditions) {
  auto s = sinew::test::build(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
    <TetrahedronSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <TetrahedralCorotationalFEMForceField name="fem" youngModulus="100" poissonRatio="0.3"/>
  </Node>)");
  init_root(*s.root);
  EXPECT_TRUE(sinew::test::messages(s.root->diagnostics(), Severity::error).empty());
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::warning),
                                        "no tetrahedra found"));
  auto& fem = *get<TetrahedralCorotationalFEMForceField>(*s.root, "fem");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  EXPECT_EQ(fem.state(), ComponentState::valid);
  EXPECT_EQ(fem.kernel().size(), 0u);

  mo.write(kPosition)[9] = 0.5;  // point 3 pulled along x
  MechParams p;
  std::fill(mo.write(kForce).begin(), mo.write(kForce).end(), 0.0);
  fem.add_force(p);
  EXPECT_EQ(mo.read(kForce)[9], 0.0);  // no tetrahedron yet

  get<TetrahedronSetTopologyModifier>(*s.root, "mod")->add_tetrahedra({{0, 1, 2, 3}});
  fem.add_force(p);
  EXPECT_EQ(fem.kernel().size(), 1u);
  EXPECT_LT(mo.read(kForce)[9], 0.0);  // pulled back
}
