// Element removal in the dynamic containers (spec/interaction.md §7.2): exact
// arrays after SOFA's swap-with-last cascades, events in SOFA's order, states
// and masses following, and a soak test removing a whole simulated body.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/simulation.h"
#include "forcefield/fem/tetrahedral_corotational_fem_force_field.h"
#include "mass/diagonal_mass.h"
#include "mass/mesh_geometry.h"
#include "projective/fixed_projective_constraint.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "topology/mapping/tetra2_triangle_topological_mapping.h"
#include "topology/utility/topological_change_processor.h"
#include "visual/ogl_model.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

// Records every event a container propagates, in order.
struct Recorder final : TopologyHandler {
  std::vector<TopologyChange> seen;
  void apply(const MeshTopologyBase&, const TopologyChange& c) override { seen.push_back(c); }
};

// Three tetrahedra in a row sharing faces: (0,1,2,3), (1,2,3,4), (2,3,4,5); point k at (k, k², k³)
// so that each point is recognisable in the state.
const char* kThreeTetras = R"(<Node>
  <MechanicalObject name="dofs" position="0 0 0  1 1 1  2 4 8  3 9 27  4 16 64  5 25 125"/>
  <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3  1 2 3 4  2 3 4 5"/>
  <TetrahedronSetTopologyModifier name="mod"/>
</Node>)";

template <class T>
std::vector<T> list(std::initializer_list<T> v) { return v; }

}  // namespace

// Containers' creation orders (hand-derived):
//  edges by tetra then local edge (01,02,03,12,13,23), first occurrence, (min,max):
//   T0: e0(0,1) e1(0,2) e2(0,3) e3(1,2) e4(1,3) e5(2,3); T1: e6(1,4) e7(2,4) e8(3,4);
//   T2: e9(2,5) e10(3,5) e11(4,5)
//  faces (123),(032),(130),(021) rotated smallest-first, skipping an existing reverse:
//   T0: t0(1,2,3) t1(0,3,2) t2(0,1,3) t3(0,2,1); T1: t4(2,3,4) t5(1,4,3) t6(1,2,4) [(1,3,2) skipped];
//   T2: t7(3,4,5) t8(2,5,4) t9(2,3,5) [(2,4,3) skipped]
// removeTetrahedra({0}):
//  1. TETRAHEDRAREMOVED {0}; T0 leaves the shells: point 0, edges e0 e1 e2 and faces t1 t2 t3
//     become isolated; T2 (last) moves into slot 0 → tetrahedra (2,3,4,5), (1,2,3,4).
//  2. TRIANGLESREMOVED {3,2,1} and EDGESREMOVED {2,1,0}, one propagation; swap-with-last:
//     t3←t9 (2,3,5), t2←t8 (2,5,4), t1←t7 (3,4,5); e2←e11 (4,5), e1←e10 (3,5), e0←e9 (2,5).
//  3. POINTSREMOVED {0}: the last point 5 takes index 0 in every element (order kept) and in
//     the state: (2,3,4,0); (3,4,0) (2,0,4) (2,3,0); edges (2,0) (3,0) (4,0).
TEST(TopologyRemoval, RemoveFirstOfThreeTetrahedraGivesSofaArrays) {
  auto s = load(kThreeTetras);
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  ASSERT_EQ(topo.edges().size(), 12u);
  ASSERT_EQ(topo.triangles().size(), 10u);
  Recorder rec;
  rec.attach(&topo);

  mod.remove_tetrahedra({0});

  EXPECT_EQ(topo.tetrahedra(), list<Tetra>({{2, 3, 4, 0}, {1, 2, 3, 4}}));
  EXPECT_EQ(topo.triangles(),
            list<Triangle>({{1, 2, 3}, {3, 4, 0}, {2, 0, 4}, {2, 3, 0}, {2, 3, 4}, {1, 4, 3}, {1, 2, 4}}));
  EXPECT_EQ(topo.edges(),
            list<Edge>({{2, 0}, {3, 0}, {4, 0}, {1, 2}, {1, 3}, {2, 3}, {1, 4}, {2, 4}, {3, 4}}));
  EXPECT_EQ(topo.nb_points(), 5u);

  using T = TopologyChangeType;
  const std::vector<std::pair<T, std::vector<unsigned>>> want = {
      {T::tetrahedra_removed, {0}}, {T::ending, {}},         {T::triangles_removed, {3, 2, 1}},
      {T::edges_removed, {2, 1, 0}}, {T::ending, {}},        {T::points_removed, {0}},
      {T::ending, {}}};
  ASSERT_EQ(rec.seen.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(rec.seen[i].type, want[i].first) << i;
    EXPECT_EQ(rec.seen[i].indices, want[i].second) << i;
  }
  // The state lost point 0; point 5 (5, 25, 125) took its slot.
  ASSERT_EQ(mo.size(), 5u);
  const auto& x = mo.read(kPosition);
  EXPECT_EQ(std::vector<double>(x.begin(), x.begin() + 3), (std::vector<double>{5, 25, 125}));
  EXPECT_EQ(std::vector<double>(x.begin() + 3, x.begin() + 6), (std::vector<double>{1, 1, 1}));
  EXPECT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "");
  // Neighbourhood queries answer from the live arrays: vertex 0 (ex-5) is in tetrahedron 0 only.
  EXPECT_EQ(topo.tetrahedra_around_vertex()[0], (std::vector<unsigned>{0}));
  EXPECT_EQ(topo.edge_index(0, 4), 2u);
  EXPECT_EQ(topo.triangle_index(0, 2, 3), 3u);
}

// Removing the remaining tetrahedra one by one empties every list (cascades down to the points).
TEST(TopologyRemoval, CascadeEmptiesTheMesh) {
  auto s = load(kThreeTetras);
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  mod.remove_tetrahedra({1, 1, 7});  // duplicate and out-of-range ids: warned, removed once / skipped
  EXPECT_EQ(topo.tetrahedra().size(), 2u);
  // Tetra 1 = (1,2,3,4) shares all its points with the others: only faces t5 (1,4,3), t6 (1,2,4)
  // and edge e6 (1,4) are left without a tetrahedron.
  EXPECT_EQ(topo.nb_points(), 6u);
  EXPECT_EQ(topo.triangles().size(), 8u);
  EXPECT_EQ(topo.edges().size(), 11u);
  mod.remove_tetrahedra({0, 1});
  EXPECT_TRUE(topo.tetrahedra().empty());
  EXPECT_TRUE(topo.triangles().empty());
  EXPECT_TRUE(topo.edges().empty());
  EXPECT_EQ(topo.nb_points(), 0u);
  EXPECT_EQ(mo.size(), 0u);
}

// Triangle removal cascades to edges then points (removeItems = removeTriangles(ids, true, true)).
// Two triangles (0,1,2), (1,3,2): edges by triangle then (t[j+1], t[j+2]) as found:
// e0(1,2) e1(2,0) e2(0,1) e3(3,2) e4(2,1)→ same as e0, skipped; e5... → (1,3): e4.
// remove {0}: edges e1 (2,0) and e2 (0,1) isolated → EDGESREMOVED {2,1}: e2←e4 (1,3), e1←e3 (3,2);
// point 0 isolated → POINTSREMOVED {0}: point 3 → 0.
TEST(TopologyRemoval, TriangleRemovalCascadesEdgesThenPoints) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
    <TriangleSetTopologyContainer name="topo" triangles="0 1 2  1 3 2"/>
    <TriangleSetTopologyModifier name="mod"/>
  </Node>)");
  auto& topo = *get<TriangleSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TriangleSetTopologyModifier>(*s.root, "mod");
  ASSERT_EQ(topo.edges(), list<Edge>({{1, 2}, {2, 0}, {0, 1}, {3, 2}, {1, 3}}));
  std::string why;
  ASSERT_TRUE(mod.remove_items({0}, &why));
  EXPECT_EQ(topo.triangles(), list<Triangle>({{1, 0, 2}}));
  EXPECT_EQ(topo.edges(), list<Edge>({{1, 2}, {0, 2}, {1, 0}}));
  EXPECT_EQ(topo.nb_points(), 3u);
  EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->size(), 3u);
}

// DiagonalMass follows: after removals the vertex masses sum to ρ·(remaining volume) and each
// vertex holds ρ/4 of the volume of its remaining tetrahedra.
TEST(TopologyRemoval, DiagonalMassKeepsDensityTimesRemainingVolume) {
  auto s = load(R"(<Node gravity="0 -10 0">
    <RegularGridTopology name="grid" n="4 3 3" min="0 0 0" max="3 2 2"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="topo"/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topo"/>
    <DiagonalMass name="mass" massDensity="2"/>
  </Node>)");
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  auto& mass = *get<DiagonalMass>(*s.root, "mass");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  ASSERT_EQ(topo.tetrahedra().size(), 72u);
  mod.remove_tetrahedra({0, 5, 71, 30});
  mod.remove_tetrahedra({0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  ASSERT_EQ(topo.tetrahedra().size(), 58u);
  const auto& X = mo.read(kRestPosition);
  std::vector<double> want(mo.size(), 0.0);
  double volume = 0;
  for (const Tetra& t : topo.tetrahedra()) {
    const double v = meshgeo::tetra_volume(X, t[0], t[1], t[2], t[3]);
    volume += v;
    for (unsigned i : t) want[i] += 2.0 * v / 4.0;
  }
  ASSERT_EQ(mass.masses().size(), mo.size());
  double sum = 0;
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(mass.masses()[i], want[i], 1e-12) << i;
    sum += mass.masses()[i];
  }
  EXPECT_NEAR(sum, 2.0 * volume, 1e-12);
  EXPECT_NEAR(mass.total_mass.value(), 2.0 * volume, 1e-12);
}

// Soak: a simulated body of 10,296 tetrahedra loses one random tetrahedron at a time until it is
// empty, a step running every 16 removals; after every removal no index dangles, the shells
// agree with the lists, the state and the mass have one entry per point whose masses are
// ρ/4 of the remaining volume around it, and the state stays finite.
TEST(TopologyRemoval, SoakRemovesASimulatedBodyUntilEmpty) {
  auto s = load(R"(<Node gravity="0 -9.81 0" dt="0.01">
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>
    <RegularGridTopology name="grid" n="14 13 12" min="0 0 0" max="13 12 11"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="topo"/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topo"/>
    <DiagonalMass name="mass" massDensity="1"/>
    <FixedProjectiveConstraint name="fix" indices="0 1 2 3 4 5 6 7 8"/>
    <TetrahedralCorotationalFEMForceField youngModulus="500" poissonRatio="0.3" method="large"/>
  </Node>)");
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  auto& mass = *get<DiagonalMass>(*s.root, "mass");
  auto& mo = *get<MechanicalObject>(*s.root, "dofs");
  ASSERT_EQ(topo.tetrahedra().size(), 10296u);
  std::mt19937 rng(7);
  std::size_t step = 0;
  while (!topo.tetrahedra().empty()) {
    const auto n = static_cast<unsigned>(topo.tetrahedra().size());
    mod.remove_tetrahedra({std::uniform_int_distribution<unsigned>(0, n - 1)(rng)});
    ASSERT_EQ(topo.tetrahedra().size(), n - 1u);
    ASSERT_EQ(topo::check_dynamic_mesh(topo.begin_edit()), "") << "after removal " << step;
    ASSERT_EQ(mo.size(), topo.nb_points());
    ASSERT_EQ(mass.masses().size(), topo.nb_points());
    for (unsigned i : get<FixedProjectiveConstraint>(*s.root, "fix")->indices.value()) ASSERT_LT(i, mo.size());
    if (step % 16 == 0) {
      animate(*s.root);
      for (double v : mo.read(kPosition)) ASSERT_TRUE(std::isfinite(v)) << "step " << step;
    }
    if (step % 1000 == 0) {  // the mass is the one of the remaining elements
      const auto& X = mo.read(kRestPosition);
      std::vector<double> want(mo.size(), 0.0);
      for (const Tetra& t : topo.tetrahedra()) {
        const double v = meshgeo::tetra_volume(X, t[0], t[1], t[2], t[3]);
        for (unsigned i : t) want[i] += v / 4.0;
      }
      for (std::size_t i = 0; i < want.size(); ++i) ASSERT_NEAR(mass.masses()[i], want[i], 1e-9) << i;
    }
    ++step;
  }
  EXPECT_EQ(mo.size(), 0u);
  EXPECT_TRUE(topo.edges().empty());
  EXPECT_TRUE(topo.triangles().empty());
}

// TopologicalChangeProcessor: REMOVE= blocks at their time (only the last due block of a step),
// from a gzip file as well; ADD= lines are refused at init naming file:line.
TEST(TopologicalChangeProcessor, AppliesDueRemoveBlocksAndRefusesQuadAdd) {
  sinew::test::TempDir dir;
  const std::string plain = dir.write("c.txt", "T= 0.1\n  REMOVE= 1\n0\nT= 0.2\n  REMOVE= 1\n0\nT= 0.3\n  REMOVE= 1\n0\n");
  for (bool gz : {false, true}) {
    std::string file = plain;
    if (gz) {
      ASSERT_EQ(std::system(("gzip -kf " + plain).c_str()), 0);
      file = plain + ".gz";
    }
    auto s = load(std::string(R"(<Node>
      <MechanicalObject name="dofs" position="0 0 0  1 1 1  2 4 8  3 9 27  4 16 64  5 25 125"/>
      <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3  1 2 3 4  2 3 4 5"/>
      <TetrahedronSetTopologyModifier name="mod"/>
      <TopologicalChangeProcessor name="proc" filename=")") + file + R"("/>
    </Node>)");
    auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
    auto& proc = *get<TopologicalChangeProcessor>(*s.root, "proc");
    proc.process(0.05);
    EXPECT_EQ(topo.tetrahedra().size(), 3u);
    proc.process(0.1);  // the T= 0.1 block
    EXPECT_EQ(topo.tetrahedra(), list<Tetra>({{2, 3, 4, 0}, {1, 2, 3, 4}}));
    proc.process(0.35);  // blocks 0.2 and 0.3 are due: only the last one runs
    EXPECT_EQ(topo.tetrahedra().size(), 1u);
  }
  Diagnostics d;
  const std::string add = dir.write("a.txt", "T= 0.1\nADD= Quads 1\n0 1 2 5\n");
  auto s = sinew::test::build(std::string(R"(<Node>
      <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3"/>
      <TetrahedronSetTopologyModifier name="mod"/>
      <TopologicalChangeProcessor name="proc" filename=")") + add + R"("/>
    </Node>)");
  init_root(*s.root);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error),
                                        "a.txt:2: ADD= Quads needs a QuadSetTopologyModifier in the topology's "
                                        "node or its ancestors"));
}

// Tetra2TriangleTopologicalMapping following removeTetrahedra({0}) on the three tetrahedra
// (spec/interaction.md §7.3; input faces t0..t9 as above). Boundary at init: t1 t2 t3 t5 t6 t7
// t8 t9 → locals 0..7. Hand-worked:
//  TETRAHEDRAREMOVED {0}: t0 is shared with T1 = (1,2,3,4), where it is face 3 ((0,2,1) →
//   (1,3,2)); local 8 = (1,3,2), loc2glob[8] = 0.
//  TRIANGLESREMOVED {3,2,1} → locals {2,1,0}; the maps mirror both swap-pops:
//   loc2glob = [2,3,0,5,6,1]; the output removes its triangles 2,1,0 by swap-with-last:
//   (2,5,4) (2,3,5) (1,3,2) (1,4,3) (1,2,4) (3,4,5), and its edges (0,1) (0,2) (0,3).
//  POINTSREMOVED {0}: point 5 becomes 0 in the output too.
TEST(TopologyRemoval, Tetra2TriangleMappingFollowsTetrahedronRemoval) {
  auto s = load(R"(<Node>
  <MechanicalObject name="dofs" position="0 0 0  1 1 1  2 4 8  3 9 27  4 16 64  5 25 125"/>
  <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3  1 2 3 4  2 3 4 5"/>
  <TetrahedronSetTopologyModifier name="mod"/>
  <Node name="skin">
    <TriangleSetTopologyContainer name="tris"/>
    <TriangleSetTopologyModifier name="tmod"/>
    <Tetra2TriangleTopologicalMapping name="map" input="@../topo" output="@tris"/>
  </Node>
</Node>)");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  ASSERT_EQ(s.root->children().size(), 1u);
  Node& skin = *s.root->children()[0];
  ASSERT_NE(get<TriangleSetTopologyContainer>(skin, "tris"), nullptr);
  auto& tris = *get<TriangleSetTopologyContainer>(skin, "tris");
  auto& map = *get<Tetra2TriangleTopologicalMapping>(skin, "map");
  ASSERT_EQ(tris.triangles(), list<Triangle>({{0, 3, 2}, {0, 1, 3}, {0, 2, 1}, {1, 4, 3}, {1, 2, 4}, {3, 4, 5},
                                              {2, 5, 4}, {2, 3, 5}}));
  ASSERT_EQ(map.loc2glob(), list<unsigned>({1, 2, 3, 5, 6, 7, 8, 9}));

  mod.remove_tetrahedra({0});

  EXPECT_EQ(tris.triangles(),
            list<Triangle>({{2, 0, 4}, {2, 3, 0}, {1, 3, 2}, {1, 4, 3}, {1, 2, 4}, {3, 4, 0}}));
  EXPECT_EQ(map.loc2glob(), list<unsigned>({2, 3, 0, 5, 6, 1}));
  for (unsigned loc = 0; loc < map.loc2glob().size(); ++loc) EXPECT_EQ(map.glob2loc(map.loc2glob()[loc]), loc);
  EXPECT_EQ(tris.nb_points(), 5u);
  EXPECT_EQ(tris.edges().size(), 9u);  // 12 edges of the 8 faces, (0,1) (0,2) (0,3) gone
  for (const Edge& e : tris.edges()) EXPECT_TRUE(e[0] != 5 && e[1] != 5);
  EXPECT_EQ(topo::check_dynamic_mesh(tris.begin_edit()), "");

  // Removing the middle tetrahedron uncovers faces on both sides; the output keeps one face per
  // input boundary face.
  mod.remove_tetrahedra({1});
  auto& in = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  EXPECT_EQ(tris.triangles().size(), in.triangles().size());
  for (unsigned loc = 0; loc < map.loc2glob().size(); ++loc) {
    Triangle a = tris.triangles()[loc], b = in.triangles()[map.loc2glob()[loc]];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << "local " << loc;
  }
}

// TetrahedralCorotationalFEMForceField follows removals element by element (swap-with-last of
// its element data, points renamed): the motion is bit for bit the one of a force field rebuilt
// from the remaining elements.
TEST(TopologyRemoval, CorotationalFemFollowsRemovalsAsARebuildWould) {
  const char* xml = R"(<Node gravity="0 -9.81 0" dt="0.01">
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
    <RegularGridTopology name="grid" n="6 5 4" min="0 0 0" max="5 4 3"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="topo"/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topo"/>
    <DiagonalMass massDensity="1"/>
    <FixedProjectiveConstraint indices="0 1 2 3 4 5"/>
    <TetrahedralCorotationalFEMForceField name="fem" youngModulus="500" poissonRatio="0.3" method="large"/>
  </Node>)";
  auto a = load(xml);
  auto b = load(xml);
  auto& fem_a = *get<TetrahedralCorotationalFEMForceField>(*a.root, "fem");
  auto& fem_b = *get<TetrahedralCorotationalFEMForceField>(*b.root, "fem");
  std::mt19937 rng(3);
  for (int round = 0; round < 12; ++round) {
    animate(*a.root);
    animate(*b.root);
    const auto n = static_cast<unsigned>(get<TetrahedronSetTopologyContainer>(*a.root, "topo")->tetrahedra().size());
    std::vector<unsigned> ids;
    for (int k = 0; k < 7; ++k) ids.push_back(std::uniform_int_distribution<unsigned>(0, n - 1)(rng));
    get<TetrahedronSetTopologyModifier>(*a.root, "mod")->remove_tetrahedra(ids);
    get<TetrahedronSetTopologyModifier>(*b.root, "mod")->remove_tetrahedra(ids);
    fem_b.reinit();  // b: rebuilt from the remaining elements
    ASSERT_EQ(fem_a.kernel().tetra, fem_b.kernel().tetra) << "round " << round;
    ASSERT_EQ(fem_a.kernel().X0, fem_b.kernel().X0) << "round " << round;
  }
  animate(*a.root);
  animate(*b.root);
  EXPECT_EQ(get<MechanicalObject>(*a.root, "dofs")->read(kPosition),
            get<MechanicalObject>(*b.root, "dofs")->read(kPosition));
  EXPECT_DOUBLE_EQ(fem_a.kernel().rest_volume, fem_b.kernel().rest_volume);
}

// OglModel with handleDynamicTopology (default) takes its topology's triangles again after a
// step in which they changed (SOFA's updateVisual on a new revision); its positions follow
// through its mapping.
TEST(TopologyRemoval, OglModelFollowsItsSurface) {
  auto s = load(R"(<Node gravity="0 0 0" dt="0.01">
    <RegularGridTopology name="grid" n="4 3 3" min="0 0 0" max="3 2 2"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="topo"/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topo"/>
    <Node name="surface">
      <TriangleSetTopologyContainer name="skin"/>
      <TriangleSetTopologyModifier/>
      <Tetra2TriangleTopologicalMapping input="@../topo" output="@skin"/>
      <Node name="visu">
        <OglModel name="visual"/>
        <IdentityMapping input="@../../dofs" output="@visual"/>
      </Node>
    </Node>
  </Node>)");
  Node& surface = *s.root->find_child_named("surface");
  auto& skin = *get<TriangleSetTopologyContainer>(surface, "skin");
  auto& visual = *get<OglModel>(*surface.find_child_named("visu"), "visual");
  EXPECT_EQ(visual.triangles.value(), skin.triangles());
  get<TetrahedronSetTopologyModifier>(*s.root, "mod")->remove_tetrahedra({0, 1, 2, 3, 4, 5, 40});
  animate(*s.root);
  EXPECT_EQ(visual.triangles.value(), skin.triangles());
  EXPECT_EQ(visual.visual_size(), get<MechanicalObject>(*s.root, "dofs")->size());
  for (const Triangle& t : visual.triangles.value())
    for (unsigned v : t) EXPECT_LT(v, visual.visual_size());
}

// TopologyBoundingTrasher: after each step, the elements of the highest kind whose barycentre
// is outside the box go (with the points left unused); the rest stay.
TEST(TopologyBoundingTrasher, RemovesTheElementsWhoseBarycentreLeftTheBox) {
  auto s = load(R"(<Node gravity="0 0 0" dt="0.01">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  5 0 0  6 0 0  5 1 0  0 0 1"/>
    <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 6  3 4 5 6"/>
    <TetrahedronSetTopologyModifier/>
    <TopologyBoundingTrasher name="trasher" box="-1 -1 -1 2.5 2 2" position="@dofs.position"/>
  </Node>)");
  auto& topo = *get<TetrahedronSetTopologyContainer>(*s.root, "topo");
  ASSERT_EQ(topo.tetrahedra().size(), 2u);
  animate(*s.root);
  // Barycentres (0.25, 0.25, 0.25) inside, (4, 0.25, 0.25) outside: the second goes with its
  // three own points; the last point (6) takes a freed slot.
  ASSERT_EQ(topo.tetrahedra().size(), 1u);
  EXPECT_EQ(topo.nb_points(), 4u);
  EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->size(), 4u);
  for (unsigned v : topo.tetrahedra()[0]) EXPECT_LT(v, 4u);
  // A box with the wrong number of values is refused.
  auto bad = test::build(R"(<Node><MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
    <TriangleSetTopologyContainer triangles="0 1 2"/><TriangleSetTopologyModifier/>
    <TopologyBoundingTrasher name="t" box="0 0 0 1"/></Node>)");
  init_root(*bad.root);
  EXPECT_TRUE(test::any_contains(test::messages(bad.root->diagnostics(), Severity::error), "box needs 6 values"));
}
