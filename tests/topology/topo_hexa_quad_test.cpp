// Quads and hexahedra changing (spec/interaction.md §7.2–7.4): exact arrays and
// events after removing a hexahedron of two and after adding quads and a
// hexahedron to empty containers (hand-worked below, in SOFA's orders), the
// Hexa2Quad and Quad2Triangle mappings following, and the processor's ADD= lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "constraint/model/bilateral_lagrangian_constraint.h"
#include "core/simulation.h"
#include "mass/diagonal_mass.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/hexahedron_set_topology_container.h"
#include "topology/dynamic/hexahedron_set_topology_modifier.h"
#include "topology/dynamic/quad_set_topology_container.h"
#include "topology/dynamic/quad_set_topology_modifier.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/mapping/hexa2_quad_topological_mapping.h"
#include "topology/mapping/quad2_triangle_topological_mapping.h"
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

// Two unit cubes side by side along x: points k = (k%3, (k/3)%2, k/6), i.e. bottom layer 0..5,
// top layer 6..11. H0 = (0,1,4,3, 6,7,10,9), H1 = (1,2,5,4, 7,8,11,10); they share the face
// 1 4 10 7. The boundary quads follow the hexahedra (Hexa2QuadTopologicalMapping).
const char* kTwoHexahedra = R"(<Node>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0
                                          0 0 1  1 0 1  2 0 1  0 1 1  1 1 1  2 1 1"/>
  <HexahedronSetTopologyContainer name="topo" hexahedra="0 1 4 3 6 7 10 9  1 2 5 4 7 8 11 10"/>
  <HexahedronSetTopologyModifier name="mod"/>
  <DiagonalMass name="mass" massDensity="2"/>
  <Node name="skin">
    <QuadSetTopologyContainer name="quads"/>
    <QuadSetTopologyModifier name="qmod"/>
    <Hexa2QuadTopologicalMapping name="map" input="@../topo" output="@quads"/>
  </Node>
</Node>)";

std::array<unsigned, 4> sorted(Quad q) {
  std::sort(q.begin(), q.end());
  return q;
}

}  // namespace

// Containers' creation orders (hand-derived):
//  edges by hexahedron then local edge (01 03 04 12 15 23 26 37 45 47 56 67), first occurrence,
//  (min,max): H0: e0(0,1) e1(0,3) e2(0,6) e3(1,4) e4(1,7) e5(3,4) e6(4,10) e7(3,9) e8(6,7) e9(6,9)
//  e10(7,10) e11(9,10); H1: e12(1,2) e13(2,5) e14(2,8) e15(4,5) e16(5,11) e17(7,8) e18(8,11) e19(10,11).
//  faces (0321) (4567) (0154) (1265) (2376) (3047), rotated smallest-first, skipping a reverse:
//  H0: q0(0,3,4,1) q1(6,7,10,9) q2(0,1,7,6) q3(1,4,10,7) q4(3,9,10,4) q5(0,6,9,3);
//  H1: q6(1,4,5,2) q7(7,8,11,10) q8(1,2,8,7) q9(2,5,11,8) q10(4,10,11,5) [(1,7,10,4) = q3 reversed].
// removeHexahedra({0}):
//  1. HEXAHEDRAREMOVED {0}; H0 leaves the shells: points 0 3 6 9, edges e0 e1 e2 e5 e7 e8 e9 e11 and
//     faces q0 q1 q2 q4 q5 are left alone; H1 moves into slot 0.
//  2. QUADSREMOVED {5,4,2,1,0} and EDGESREMOVED {11,9,8,7,5,2,1,0}, one propagation; swap-with-last:
//     q5←q10, q4←q9, q2←q8, q1←q7, q0←q6; e11←e19, e9←e18, e8←e17, e7←e16, e5←e15, e2←e14,
//     e1←e13, e0←e12.
//  3. POINTSREMOVED {9,6,3,0}: 11→9→3, 10→6, 8→0 in every element and in the state.
TEST(TopologyHexaQuad, RemoveOneOfTwoHexahedraGivesSofaArrays) {
  auto s = load(kTwoHexahedra);
  auto& topo = *get<HexahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<HexahedronSetTopologyModifier>(*s.root, "mod");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  ASSERT_EQ(topo.edges().size(), 20u);
  ASSERT_EQ(topo.quads(), list<Quad>({{0, 3, 4, 1},
                                      {6, 7, 10, 9},
                                      {0, 1, 7, 6},
                                      {1, 4, 10, 7},
                                      {3, 9, 10, 4},
                                      {0, 6, 9, 3},
                                      {1, 4, 5, 2},
                                      {7, 8, 11, 10},
                                      {1, 2, 8, 7},
                                      {2, 5, 11, 8},
                                      {4, 10, 11, 5}}));
  Recorder rec;
  rec.attach(&topo);

  mod.remove_hexahedra({0});

  EXPECT_EQ(topo.hexahedra(), list<Hexa>({{1, 2, 5, 4, 7, 0, 3, 6}}));
  EXPECT_EQ(topo.quads(),
            list<Quad>({{1, 4, 5, 2}, {7, 0, 3, 6}, {1, 2, 0, 7}, {1, 4, 6, 7}, {2, 5, 3, 0}, {4, 6, 3, 5}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{1, 2}, {2, 5}, {2, 0}, {1, 4}, {1, 7}, {4, 5}, {4, 6}, {5, 3}, {7, 0},
                                      {0, 3}, {7, 6}, {6, 3}}));
  EXPECT_EQ(topo.nb_points(), 8u);
  expect_events(rec, {{T::hexahedra_removed, {0}},
                      {T::ending, {}},
                      {T::quads_removed, {5, 4, 2, 1, 0}},
                      {T::edges_removed, {11, 9, 8, 7, 5, 2, 1, 0}},
                      {T::ending, {}},
                      {T::points_removed, {9, 6, 3, 0}},
                      {T::ending, {}}});
  // The state follows: slot 0 holds old point 8 (2,0,1), slot 3 old 11 (2,1,1), slot 6 old 10 (1,1,1).
  ASSERT_EQ(mo.size(), 8u);
  const auto& x = mo.read(kPosition);
  EXPECT_EQ(std::vector<double>(x.begin(), x.begin() + 3), (std::vector<double>{2, 0, 1}));
  EXPECT_EQ(std::vector<double>(x.begin() + 9, x.begin() + 12), (std::vector<double>{2, 1, 1}));
  EXPECT_EQ(std::vector<double>(x.begin() + 18, x.begin() + 21), (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
  EXPECT_EQ(topo.hexahedra_around_quad()[3], list<unsigned>({0}));
  EXPECT_EQ(topo.quad_index(6, 3, 5, 4), 5u);
  // DiagonalMass took 2·1/8 from each vertex of H0: 8 points of mass 0.25 (H1 alone), total 2.
  auto& mass = *get<DiagonalMass>(*s.root, "mass");
  ASSERT_EQ(mass.vertex_mass.value().size(), 8u);
  for (double m : mass.vertex_mass.value()) EXPECT_NEAR(m, 0.25, 1e-14);
  EXPECT_NEAR(mass.total_mass.value(), 2.0, 1e-13);
}

// Hexa2QuadTopologicalMapping follows: the output is the boundary of the remaining hexahedron,
// each output quad naming (loc2glob) the input quad with the same vertices, points relayed.
TEST(TopologyHexaQuad, Hexa2QuadOutputIsTheBoundaryAfterRemoval) {
  auto s = load(kTwoHexahedra);
  auto& topo = *get<HexahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<HexahedronSetTopologyModifier>(*s.root, "mod");
  ASSERT_EQ(s.root->children().size(), 1u);
  Node& skin = *s.root->children()[0];
  auto& quads = *get<QuadSetTopologyContainer>(skin, "quads");
  auto& map = *get<Hexa2QuadTopologicalMapping>(skin, "map");
  ASSERT_EQ(quads.quads().size(), 10u);  // every face but the shared q3
  EXPECT_EQ(map.loc2glob(), list<unsigned>({0, 1, 2, 4, 5, 6, 7, 8, 9, 10}));

  mod.remove_hexahedra({0});

  // The shared face is added from H1's side (face 5: h3 h0 h4 h7 = 4 1 7 10), then the five faces
  // of H0 leave one at a time.
  ASSERT_EQ(quads.quads().size(), 6u);
  EXPECT_EQ(quads.nb_points(), 8u);
  std::set<std::array<unsigned, 4>> in, out;
  for (const Quad& q : topo.quads()) in.insert(sorted(q));
  for (const Quad& q : quads.quads()) out.insert(sorted(q));
  EXPECT_EQ(in, out);
  ASSERT_EQ(map.loc2glob().size(), 6u);
  for (unsigned loc = 0; loc < 6; ++loc) {
    const unsigned glob = map.loc2glob()[loc];
    ASSERT_LT(glob, topo.quads().size());
    EXPECT_EQ(sorted(quads.quads()[loc]), sorted(topo.quads()[glob])) << loc;
    EXPECT_EQ(map.glob2loc(glob), loc);
  }
  EXPECT_EQ(topo::check_dynamic_mesh(quads.begin_edit()), "");
  // Removing the last hexahedron empties both.
  mod.remove_hexahedra({0});
  EXPECT_TRUE(topo.quads().empty());
  EXPECT_TRUE(quads.quads().empty());
  EXPECT_EQ(quads.nb_points(), 0u);
}

// addQuads on an empty quad container: each quad's missing edges (q[j+1], q[j+2]) first, one
// EDGESADDED each: (0,1,4,3): e0(1,4) e1(4,3) e2(3,0) e3(0,1); (1,2,5,4): e4(2,5) e5(5,4),
// (4,1) = e0, e6(1,2). Quad2TriangleTopologicalMapping splits the new quads p0 p1 p2 / p0 p2 p3.
TEST(TopologyHexaQuad, AddQuadsCreatesEdgesInSofaOrderAndQuad2TriangleFollows) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0"/>
    <QuadSetTopologyContainer name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0"/>
    <QuadSetTopologyModifier name="mod"/>
    <Node name="T">
      <TriangleSetTopologyContainer name="tris"/>
      <TriangleSetTopologyModifier name="tmod"/>
      <Quad2TriangleTopologicalMapping name="map" input="@../topo" output="@tris"/>
    </Node>
  </Node>)");
  auto& topo = *get<QuadSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<QuadSetTopologyModifier>(*s.root, "mod");
  ASSERT_EQ(s.root->children().size(), 1u);
  Node& sub = *s.root->children()[0];
  auto& tris = *get<TriangleSetTopologyContainer>(sub, "tris");
  auto& map = *get<Quad2TriangleTopologicalMapping>(sub, "map");
  Recorder rec;
  rec.attach(&topo);
  mod.add_quads({{0, 1, 4, 3}, {1, 2, 5, 4}});
  EXPECT_EQ(topo.quads(), list<Quad>({{0, 1, 4, 3}, {1, 2, 5, 4}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{1, 4}, {4, 3}, {3, 0}, {0, 1}, {2, 5}, {5, 4}, {1, 2}}));
  expect_events(rec, {{T::edges_added, {0}},
                      {T::edges_added, {1}},
                      {T::edges_added, {2}},
                      {T::edges_added, {3}},
                      {T::edges_added, {4}},
                      {T::edges_added, {5}},
                      {T::edges_added, {6}},
                      {T::quads_added, {0, 1}},
                      {T::ending, {}}});
  EXPECT_EQ(topo.edges_in_quad()[1], (std::array<unsigned, 4>{4, 5, 0, 6}));
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
  EXPECT_EQ(tris.triangles(), list<Triangle>({{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}}));
  EXPECT_EQ(map.loc2glob(), list<unsigned>({0, 0, 1, 1}));

  // Removing quad 0 (removeItems: isolated edges and points go too) takes its two triangles.
  std::string why;
  ASSERT_TRUE(mod.remove_items({0}, &why)) << why;
  // Edges (4,3) (3,0) (0,1) isolated → EDGESREMOVED {3,2,1}; points 0 and 3 → POINTSREMOVED {3,0}.
  EXPECT_EQ(topo.nb_points(), 4u);
  // Points: 3 ← 5, then 0 ← 4: quad (1,2,5,4) → (1,2,3,0).
  EXPECT_EQ(topo.quads(), list<Quad>({{1, 2, 3, 0}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{1, 0}, {2, 3}, {3, 0}, {1, 2}}));
  EXPECT_EQ(tris.triangles(), list<Triangle>({{1, 2, 3}, {1, 3, 0}}));
  EXPECT_EQ(map.loc2glob(), list<unsigned>({0, 0}));
  EXPECT_EQ(map.in2out(0), (std::array<unsigned, 2>{0, 1}));
  EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->size(), 4u);
}

// addHexahedra on an empty container: faces in kQuadsInHexa order, each after its missing edges
// (q[j+1], q[j+2]): f0 (0,3,4,1): e0(3,4) e1(4,1) e2(1,0) e3(0,3), q0; f1 (6,7,10,9): e4(7,10)
// e5(10,9) e6(9,6) e7(6,7), q1; f2 (0,1,7,6): e8(1,7), (7,6)=e7, e9(6,0), q2; f3 (1,4,10,7):
// e10(4,10), q3; f4 (4,3,9,10): e11(3,9), q4; f5 (3,0,6,9): q5. Then HEXAHEDRAADDED.
TEST(TopologyHexaQuad, AddHexahedronCreatesFacesThenEdgesInSofaOrder) {
  auto s = load(R"(<Node>
    <HexahedronSetTopologyContainer name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0
                                                         0 0 1  1 0 1  2 0 1  0 1 1  1 1 1  2 1 1"/>
    <HexahedronSetTopologyModifier name="mod"/>
  </Node>)");
  auto& topo = *get<HexahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<HexahedronSetTopologyModifier>(*s.root, "mod");
  Recorder rec;
  rec.attach(&topo);
  mod.add_hexahedra({{0, 1, 4, 3, 6, 7, 10, 9}});
  EXPECT_EQ(topo.quads(), list<Quad>({{0, 3, 4, 1}, {6, 7, 10, 9}, {0, 1, 7, 6}, {1, 4, 10, 7}, {4, 3, 9, 10},
                                      {3, 0, 6, 9}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{3, 4}, {4, 1}, {1, 0}, {0, 3}, {7, 10}, {10, 9}, {9, 6}, {6, 7}, {1, 7},
                                      {6, 0}, {4, 10}, {3, 9}}));
  expect_events(rec, {{T::edges_added, {0}},  {T::edges_added, {1}},  {T::edges_added, {2}},
                      {T::edges_added, {3}},  {T::quads_added, {0}},  {T::edges_added, {4}},
                      {T::edges_added, {5}},  {T::edges_added, {6}},  {T::edges_added, {7}},
                      {T::quads_added, {1}},  {T::edges_added, {8}},  {T::edges_added, {9}},
                      {T::quads_added, {2}},  {T::edges_added, {10}}, {T::quads_added, {3}},
                      {T::edges_added, {11}}, {T::quads_added, {4}},  {T::quads_added, {5}},
                      {T::hexahedra_added, {0}}, {T::ending, {}}});
  // The second cube shares face 3 (1,4,10,7): found in any vertex order, not duplicated.
  mod.add_hexahedra({{1, 2, 5, 4, 7, 8, 11, 10}});
  EXPECT_EQ(topo.quads().size(), 11u);
  EXPECT_EQ(topo.edges().size(), 20u);
  EXPECT_EQ(topo.hexahedra_around_quad()[3], list<unsigned>({0, 1}));
  EXPECT_EQ(topo.quads_in_hexahedron()[1][5], 3u);
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
}

// ADD= Quads / Hexahedra lines (SOFA's keywords) go through the quad / hexahedron modifiers;
// REMOVE= through the hexahedron modifier's removeItems.
TEST(TopologyHexaQuad, ProcessorAddsAndRemovesHexahedra) {
  sinew::test::TempDir dir;
  const std::string file = dir.write(
      "hexa.txt", "T= 0.1\n  ADD= Hexahedra 2\n0 1 4 3 6 7 10 9 1 2 5 4 7 8 11 10\nT= 0.2\n  REMOVE= 1\n0\n");
  auto s = load(std::string(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0
                                            0 0 1  1 0 1  2 0 1  0 1 1  1 1 1  2 1 1"/>
    <HexahedronSetTopologyContainer name="topo" position="@dofs.position"/>
    <HexahedronSetTopologyModifier name="mod"/>
    <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
  </Node>)");
  auto& topo = *get<HexahedronSetTopologyContainer>(*s.root, "topo");
  auto& proc = *get<TopologicalChangeProcessor>(*s.root, "proc");
  EXPECT_EQ(proc.state(), ComponentState::valid);
  proc.process(0.1);
  EXPECT_EQ(topo.hexahedra(), list<Hexa>({{0, 1, 4, 3, 6, 7, 10, 9}, {1, 2, 5, 4, 7, 8, 11, 10}}));
  EXPECT_EQ(topo.quads().size(), 11u);
  proc.process(0.2);
  EXPECT_EQ(topo.hexahedra(), list<Hexa>({{1, 2, 5, 4, 7, 0, 3, 6}}));
  EXPECT_EQ(topo.nb_points(), 8u);
  EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->size(), 8u);
}

// A malformed ADD= Quads line is refused at init naming file:line; nothing is added.
TEST(TopologyHexaQuad, ProcessorRefusesMalformedQuadLine) {
  sinew::test::TempDir dir;
  const std::string file = dir.write("bad.txt", "T= 0.1\nADD= Quads 2\n0 1 4 3 1 2 5\n");
  auto s = sinew::test::build(std::string(R"(<Node>
    <QuadSetTopologyContainer name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0"/>
    <QuadSetTopologyModifier name="mod"/>
    <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
  </Node>)");
  init_root(*s.root);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error),
                                        "bad.txt:2: ADD= Quads 2: line 3 needs 8 non-negative vertex indices"));
  get<TopologicalChangeProcessor>(*s.root, "proc")->process(1.0);
  EXPECT_TRUE(get<QuadSetTopologyContainer>(*s.root, "topo")->quads().empty());
}

// BilateralLagrangianConstraint with topology1 (RemovingBilateralInteractionConstraint): the
// removal of points {9,6,3,0} (the cascade of removing H0 above) first drops the pairs naming a
// removed point (9 at pair 1, then 0 at pair 0, rest vectors with them), then first_point
// follows the renumbering (11 → 9 → 3); second_point is another topology's and is kept.
TEST(TopologyHexaQuad, BilateralConstraintDropsPairsOfRemovedPoints) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0
                                            0 0 1  1 0 1  2 0 1  0 1 1  1 1 1  2 1 1"/>
    <HexahedronSetTopologyContainer name="topo" hexahedra="0 1 4 3 6 7 10 9  1 2 5 4 7 8 11 10"/>
    <HexahedronSetTopologyModifier name="mod"/>
    <Node name="other">
      <MechanicalObject name="x" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
    </Node>
    <BilateralLagrangianConstraint name="c" object1="@dofs" object2="@other/x" topology1="@topo"
        first_point="0 9 5 11" second_point="0 1 2 3" rest_vector="0 0 0  1 1 1  2 2 2  3 3 3"/>
  </Node>)");
  auto& c = *get<BilateralLagrangianConstraint>(*s.root, "c");
  get<HexahedronSetTopologyModifier>(*s.root, "mod")->remove_hexahedra({0});
  EXPECT_EQ(c.first_point.value(), list<unsigned>({5, 3}));
  EXPECT_EQ(c.second_point.value(), list<unsigned>({2, 3}));
  EXPECT_EQ(c.rest_vector.value().data, (std::vector<double>{2, 2, 2, 3, 3, 3}));
}

// DiagonalMass on quads follows additions (SOFA's applyQuadCreation): density·area/4 on each
// vertex of the new quad, and to the total.
TEST(TopologyHexaQuad, DiagonalMassFollowsQuadAddition) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0"/>
    <QuadSetTopologyContainer name="topo" quads="0 1 4 3"/>
    <QuadSetTopologyModifier name="mod"/>
    <DiagonalMass name="mass" massDensity="2"/>
  </Node>)");
  auto& mass = *get<DiagonalMass>(*s.root, "mass");
  ASSERT_EQ(mass.vertex_mass.value().size(), 6u);
  get<QuadSetTopologyModifier>(*s.root, "mod")->add_quads({{1, 2, 5, 4}});
  const std::vector<double> want = {0.5, 1.0, 0.5, 0.5, 1.0, 0.5};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(mass.vertex_mass.value()[i], want[i], 1e-14) << i;
  EXPECT_NEAR(mass.total_mass.value(), 4.0, 1e-13);
}
