// BarycentricMapping under topological changes. SOFA (BarycentricMapping::handleTopologyChange →
// TopologyBarycentricMapper::processTopologicalChanges, not virtual) clears the map and runs the
// mapper's init again, from the current positions, whenever a propagation reaches the mapping;
// Sinew does it once the change is over, from the positions of the last propagation. So a point
// whose element survives keeps its position, its table equals that of a mapping built afresh on
// the remaining mesh, and no entry names an element or a vertex that is gone.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "badinput_helpers.h"
#include "mapping/linear/barycentric_mapping.h"
#include "mapping/linear/barycentric_mapping_rigid.h"
#include "runner/session.h"
#include "state/mechanical_object.h"
#include "test_paths.h"
#include "test_scene.h"
#include "topology/dynamic/hexahedron_set_topology_modifier.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/point_set_topology_modifier.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

// Two unit cubes side by side along x: points (i, j, k), i = 0..2, j, k = 0..1, index i + 3(j + 2k).
std::string grid_points() {
  std::ostringstream s;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) s << i << ' ' << j << ' ' << k << "  ";
  return s.str();
}
unsigned gp(int i, int j, int k) { return static_cast<unsigned>(i + 3 * (j + 2 * k)); }

// Each cube cut into the 6 tetrahedra of its main diagonal (tetrahedra 0–5: cube 0, 6–11: cube 1).
std::vector<Tetra> kuhn_tetrahedra() {
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<Tetra> t;
  for (int c = 0; c < 2; ++c)
    for (const auto& p : perms) {
      int x[3] = {c, 0, 0};
      Tetra e{};
      e[0] = gp(x[0], x[1], x[2]);
      for (int s = 0; s < 3; ++s) {
        ++x[p[s]];
        e[s + 1] = gp(x[0], x[1], x[2]);
      }
      t.push_back(e);
    }
  return t;
}

template <class List>
std::string flat(const List& list) {
  std::ostringstream s;
  for (const auto& e : list)
    for (unsigned v : e) s << v << ' ';
  return s.str();
}
std::string flat_doubles(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(17);
  for (double d : v) s << d << ' ';
  return s.str();
}

// Output points: 0–3 in cube 0, 4–6 in cube 1, 7 beyond cube 1 (extrapolated).
const char* kOutput = "0.2 0.3 0.4  0.7 0.6 0.2  0.5 0.5 0.5  0.9 0.1 0.8  1.3 0.4 0.6  1.8 0.7 0.3  1.5 0.5 0.9  2.3 0.5 0.5";

// `element_list` is the container's attribute (tetrahedra="..." / hexahedra="..."); the output
// node has its own point topology (and modifier) so that output points can be removed.
std::string embedded_scene(const std::string& container, const std::string& element_list, const std::string& in_pos,
                           const std::string& out_pos, const std::string& modifier) {
  return R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="in" position=")" + in_pos + R"("/>
    <)" + container + R"( name="topo" )" + element_list + R"(/>
    <)" + modifier + R"( name="mod"/>
    <Node name="out">
      <MechanicalObject name="pts" position=")" + out_pos + R"("/>
      <PointSetTopologyContainer name="otopo" position=")" + out_pos + R"("/>
      <PointSetTopologyModifier name="omod"/>
      <BarycentricMapping name="map" input="@../in" output="@pts"/>
    </Node>
  </Node>)";
}

struct Embedded {
  scene::LoadedScene s;
  MechanicalState* in = nullptr;
  MechanicalState* out = nullptr;
  BarycentricMapping* map = nullptr;
  MeshTopologyBase* topo = nullptr;
};

Embedded load_embedded(const std::string& xml) {
  Embedded e{test::load(xml)};
  Node& out = *e.s.root->find_child_named("out");
  e.in = test::get<MechanicalState>(*e.s.root, "in");
  e.out = test::get<MechanicalState>(out, "pts");
  e.map = test::get<BarycentricMapping>(out, "map");
  e.topo = test::get<MeshTopologyBase>(*e.s.root, "topo");
  return e;
}

Embedded tetra_scene() {
  return load_embedded(embedded_scene("TetrahedronSetTopologyContainer",
                                      "tetrahedra=\"" + flat(kuhn_tetrahedra()) + "\"", grid_points(), kOutput,
                                      "TetrahedronSetTopologyModifier"));
}

std::vector<double> positions(MechanicalState& s) { return s.read(kPosition); }

// Every entry names an existing element of `count` and existing input vertices.
void expect_in_range(const BaryTable& t, std::size_t count, std::size_t n_in, const std::string& where) {
  for (std::size_t i = 0; i < t.points(); ++i) {
    EXPECT_LT(t.element(i), count) << where << ": point " << i;
    for (std::uint32_t k = t.begin(i); k < t.end(i); ++k) EXPECT_LT(t.vertex(k), n_in) << where << ": point " << i;
  }
}

// The same table, bit for bit.
void expect_same_table(const BaryTable& a, const BaryTable& b) {
  ASSERT_EQ(a.points(), b.points());
  for (std::size_t i = 0; i < a.points(); ++i) {
    EXPECT_EQ(a.element(i), b.element(i)) << "point " << i;
    ASSERT_EQ(a.end(i) - a.begin(i), b.end(i) - b.begin(i)) << "point " << i;
    for (std::uint32_t k = 0; k < a.end(i) - a.begin(i); ++k) {
      EXPECT_EQ(a.vertex(a.begin(i) + k), b.vertex(b.begin(i) + k)) << "point " << i;
      EXPECT_EQ(a.weight(a.begin(i) + k), b.weight(b.begin(i) + k)) << "point " << i;
    }
  }
}

// The table of `e` equals that of a mapping built afresh on e's input (current positions and
// `elements`, a <kind>SetTopologyContainer attribute) for the output points `out`.
void expect_as_fresh(Embedded& e, const std::string& kind, const std::string& elements,
                     const std::vector<double>& out) {
  Embedded fresh = load_embedded(embedded_scene(kind + "SetTopologyContainer", elements,
                                                flat_doubles(positions(*e.in)), flat_doubles(out),
                                                kind + "SetTopologyModifier"));
  ASSERT_EQ(fresh.map->state(), ComponentState::valid);
  expect_same_table(e.map->table(), fresh.map->table());
}

TEST(BarycentricMappingTopology, RemovedTetrahedraRelocateTheirPointsAsAFreshMapping) {
  Embedded e = tetra_scene();
  ASSERT_EQ(e.map->state(), ComponentState::valid);
  ASSERT_EQ(e.map->mapper_name(), "TetrahedronSet");
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LT(e.map->table().element(i), 6u) << i;
  for (std::size_t i = 4; i < 8; ++i) EXPECT_GE(e.map->table().element(i), 6u) << i;

  // Cube 1 goes: its far face's points (i = 2) become isolated and are removed as well.
  auto& mod = *test::get<TetrahedronSetTopologyModifier>(*e.s.root, "mod");
  mod.remove_tetrahedra({6, 7, 8, 9, 10, 11});
  ASSERT_EQ(e.topo->tetrahedra().size(), 6u);
  ASSERT_EQ(e.in->size(), 8u);
  e.map->apply(kPosition);
  const BaryTable& t = e.map->table();
  ASSERT_EQ(t.points(), 8u);
  expect_in_range(t, 6, 8, "after removal");
  const std::vector<double> after = positions(*e.out);
  // Points of cube 0 keep their positions (relocated in the same tetrahedron).
  for (std::size_t c = 0; c < 12; ++c) EXPECT_NEAR(after[c], before[c], 1e-15) << c;
  // Points of cube 1 moved onto the nearest surviving tetrahedron, extrapolated: their positions
  // are those of the relocation, i.e. unchanged as well (the input has not moved).
  for (std::size_t c = 12; c < 24; ++c) EXPECT_NEAR(after[c], before[c], 1e-14) << c;
  for (double v : after) EXPECT_TRUE(std::isfinite(v));

  // A mapping built on the remaining mesh with the same points gives the same table.
  expect_as_fresh(e, "Tetrahedron", "tetrahedra=\"" + flat(e.topo->tetrahedra()) + "\"", before);
}

// A tetrahedron whose vertices all stay (its boundary faces go, no point does): SOFA's last
// propagation still lists it (stale index); Sinew relocates among the survivors, and taking it
// back relocates its points into it again.
TEST(BarycentricMappingTopology, RemovingThenAddingATetrahedronKeepsThePositions) {
  Embedded e = tetra_scene();
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  const unsigned gone = e.map->table().element(0);  // a tetrahedron of cube 0: no vertex is isolated
  ASSERT_LT(gone, 6u);
  const Tetra removed = e.topo->tetrahedra()[gone];
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < 8; ++i)
    if (e.map->table().element(i) == gone) inside.push_back(i);

  auto& mod = *test::get<TetrahedronSetTopologyModifier>(*e.s.root, "mod");
  mod.remove_tetrahedra({gone});
  ASSERT_EQ(e.topo->tetrahedra().size(), 11u);
  ASSERT_EQ(e.in->size(), 12u);
  e.map->apply(kPosition);
  expect_in_range(e.map->table(), 11, 12, "after removal");
  for (std::size_t c = 0; c < 24; ++c) EXPECT_NEAR(positions(*e.out)[c], before[c], 1e-14) << c;

  mod.add_tetrahedra({removed});
  ASSERT_EQ(e.topo->tetrahedra().size(), 12u);
  e.map->apply(kPosition);
  const BaryTable& t = e.map->table();
  expect_in_range(t, 12, 12, "after addition");
  for (std::size_t i : inside) EXPECT_EQ(t.element(i), 11u) << "point " << i << " is back in the added tetrahedron";
  for (std::size_t c = 0; c < 24; ++c) EXPECT_NEAR(positions(*e.out)[c], before[c], 1e-14) << c;
}

// Output points removed through the output's own modifier: the states move their last point into
// each slot, and so does the map (entry of the last point into the slot).
TEST(BarycentricMappingTopology, RemovedOutputPointsFollowSwapWithLast) {
  Embedded e = tetra_scene();
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  std::vector<unsigned> elem(8);
  std::vector<std::vector<double>> w(8);
  {
    const BaryTable& t = e.map->table();
    for (std::size_t i = 0; i < 8; ++i) {
      elem[i] = t.element(i);
      for (std::uint32_t k = t.begin(i); k < t.end(i); ++k) w[i].push_back(t.weight(k));
    }
  }
  Node& out = *e.s.root->find_child_named("out");
  auto& omod = *test::get<PointSetTopologyModifier>(out, "omod");
  omod.remove_points({1, 3}, true);  // 3 ← 7, then 1 ← 6
  ASSERT_EQ(e.out->size(), 6u);
  e.map->apply(kPosition);
  const BaryTable& t = e.map->table();
  ASSERT_EQ(t.points(), 6u);
  expect_in_range(t, 12, 12, "after output removal");
  const std::size_t from[6] = {0, 6, 2, 7, 4, 5};
  const std::vector<double> after = positions(*e.out);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(t.element(i), elem[from[i]]) << "entry " << i;
    ASSERT_EQ(t.end(i) - t.begin(i), w[from[i]].size());
    for (std::uint32_t k = 0; k < t.end(i) - t.begin(i); ++k)
      EXPECT_NEAR(t.weight(t.begin(i) + k), w[from[i]][k], 1e-14) << "entry " << i;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[i * 3 + c], before[from[i] * 3 + c], 1e-15) << "entry " << i;
  }
}

// SOFA's hexahedron mapper relocates as the others (its own handler, which would re-map the points
// of removed hexahedra from their rest positions, is never called).
TEST(BarycentricMappingTopology, RemovedHexahedronRelocatesAsAFreshMapping) {
  const std::string hexas = "hexahedra=\"0 1 4 3 6 7 10 9  1 2 5 4 7 8 11 10\"";
  Embedded e = load_embedded(
      embedded_scene("HexahedronSetTopologyContainer", hexas, grid_points(), kOutput, "HexahedronSetTopologyModifier"));
  ASSERT_EQ(e.map->mapper_name(), "HexahedronSet");
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  EXPECT_EQ(e.map->table().element(0), 0u);
  EXPECT_EQ(e.map->table().element(4), 1u);

  auto& mod = *test::get<HexahedronSetTopologyModifier>(*e.s.root, "mod");
  mod.remove_hexahedra({0});  // hexahedron 1 takes slot 0; points x = 0 are removed (8 left)
  ASSERT_EQ(e.topo->hexahedra().size(), 1u);
  ASSERT_EQ(e.in->size(), 8u);
  e.map->apply(kPosition);
  const BaryTable& t = e.map->table();
  expect_in_range(t, 1, 8, "after removal");
  const std::vector<double> after = positions(*e.out);
  for (std::size_t c = 0; c < 24; ++c) EXPECT_NEAR(after[c], before[c], 1e-14) << c;

  expect_as_fresh(e, "Hexahedron", "hexahedra=\"" + flat(e.topo->hexahedra()) + "\"", before);
}

// Nothing left to map onto: SOFA's init would store an invalid element; Sinew keeps the output
// points where they are (velocities zero), with one warning.
TEST(BarycentricMappingTopology, NoElementLeftKeepsThePointsWithOneWarning) {
  Embedded e = tetra_scene();
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  auto& mod = *test::get<TetrahedronSetTopologyModifier>(*e.s.root, "mod");
  mod.remove_tetrahedra({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  ASSERT_EQ(e.topo->tetrahedra().size(), 0u);
  ASSERT_EQ(e.in->size(), 0u);
  e.map->apply(kPosition);
  e.map->apply_j(kVelocity, kVelocity);
  e.map->apply(kPosition);
  EXPECT_EQ(positions(*e.out), before);
  for (double v : e.out->read(kVelocity)) EXPECT_EQ(v, 0.0);
  const auto warnings = test::messages(e.s.root->diagnostics(), Severity::warning);
  int n = 0;
  for (const auto& m : warnings) n += m.find("keep their positions") != std::string::npos;
  EXPECT_EQ(n, 1);
}

// The lists changed under a modifier whose visit does not reach the mapping (another branch):
// SOFA would keep element indices that may be gone; Sinew notices the version, warns and relocates.
TEST(BarycentricMappingTopology, ChangeOutsideTheModifiersSubtreeIsNoticedByVersion) {
  Embedded e = load_embedded(R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="in" position=")" + grid_points() + R"("/>
    <TetrahedronSetTopologyContainer name="topo" tetrahedra=")" + flat(kuhn_tetrahedra()) + R"("/>
    <Node name="cutter"><TetrahedronSetTopologyModifier name="mod"/></Node>
    <Node name="out">
      <MechanicalObject name="pts" position=")" + std::string(kOutput) + R"("/>
      <BarycentricMapping name="map" input="@../in" output="@pts"/>
    </Node>
  </Node>)");
  e.map->apply(kPosition);
  const std::vector<double> before = positions(*e.out);
  auto& mod = *test::get<TetrahedronSetTopologyModifier>(*e.s.root->find_child_named("cutter"), "mod");
  mod.remove_tetrahedra({2, 11});  // no point becomes isolated (nothing to renumber)
  ASSERT_EQ(e.topo->tetrahedra().size(), 10u);
  e.map->apply(kPosition);
  expect_in_range(e.map->table(), 10, 12, "after removal");
  for (std::size_t c = 0; c < 24; ++c) EXPECT_NEAR(positions(*e.out)[c], before[c], 1e-14) << c;
  EXPECT_TRUE(test::any_contains(test::messages(e.s.root->diagnostics(), Severity::warning),
                                 "changed without a propagation reaching this mapping"));
}

// Vec3d → Rigid3d (same SOFA handler, the rigid mapper's init again): frames of removed
// tetrahedra are re-embedded among the survivors with their centre and axes; nothing moves; once
// no tetrahedron is left the frames stay (one warning).
TEST(BarycentricMappingTopology, RigidFramesAreReembeddedAmongTheRemainingTetrahedra) {
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="in" position=")" + grid_points() + R"("/>
    <TetrahedronSetTopologyContainer name="topo" tetrahedra=")" + flat(kuhn_tetrahedra()) + R"("/>
    <TetrahedronSetTopologyModifier name="mod"/>
    <Node name="out">
      <MechanicalObject name="frames" template="Rigid3d" position="0.3 0.4 0.5 0 0 0 1
          1.5 0.5 0.5 0 0 0.7071067811865476 0.7071067811865476  1.7 0.2 0.6 0.5 0.5 0.5 0.5"/>
      <BarycentricMapping name="map" input="@../in" output="@frames"/>
    </Node>
  </Node>)");
  Node& out = *s.root->find_child_named("out");
  auto* map = test::get<BarycentricMappingRigid>(out, "map");
  auto* frames = test::get<MechanicalState>(out, "frames");
  auto* topo = test::get<MeshTopologyBase>(*s.root, "topo");
  ASSERT_TRUE(map && frames && topo);
  ASSERT_EQ(map->state(), ComponentState::valid);
  map->apply(kPosition);
  const std::vector<double> before = positions(*frames);
  EXPECT_GE(map->embeddings()[1].tetra, 6u);

  auto& mod = *test::get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  mod.remove_tetrahedra({6, 7, 8, 9, 10, 11});
  map->apply(kPosition);
  ASSERT_EQ(map->embeddings().size(), 3u);
  for (const auto& e : map->embeddings()) EXPECT_LT(e.tetra, 6u);
  const std::vector<double> after = positions(*frames);
  ASSERT_EQ(after.size(), 21u);
  for (std::size_t c = 0; c < 21; ++c) EXPECT_NEAR(after[c], before[c], 1e-12) << c;

  mod.remove_tetrahedra({0, 1, 2, 3, 4, 5});
  map->apply(kPosition);
  map->apply_j(kVelocity, kVelocity);
  EXPECT_EQ(positions(*frames), after);
  for (double v : frames->read(kVelocity)) EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "frames keep their positions"));
}

// SOFA's RemovingTetraProcess.scn (TopologicalChangeProcessor removing the cube's 44
// tetrahedra, with their isolated points, 10 at t = 0.1, 0.2, 0.3, 0.4 and the last 4 at 0.5)
// with a lattice of points and a visual model mapped barycentrically: it runs without error,
// while tetrahedra remain every map entry names a live tetrahedron and live vertices, once none
// is left the points stay where they were; positions stay finite.
TEST(BarycentricMappingTopology, RemovingTetraProcessWithEmbeddedPointsAndVisual) {
  const fs::path data = SINEW_DATA_DIR;
  const fs::path changes = data / "examples/Component/Topology/Container/Dynamic/RemovingTetraProcess.txt";
  if (!fs::exists(changes)) GTEST_SKIP() << "SOFA data not found at " << data;
  std::ostringstream lattice;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) lattice << -3 + 1.5 * i << ' ' << -3 + 1.5 * j << ' ' << -3 + 1.5 * k << "  ";
  test::TempDir dir;
  const std::string scene = dir.write("scene.scn", R"(<Node name="root" dt="0.01" gravity="0 -9 0">
    <DefaultAnimationLoop/>
    <Node name="TT">
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
      <CGLinearSolver iterations="25" tolerance="1e-5" threshold="1e-5"/>
      <MeshGmshLoader name="loader" filename="mesh/cube_low_res.msh"/>
      <MechanicalObject src="@loader" name="Volume"/>
      <TetrahedronSetTopologyContainer name="Tetra_topo" src="@loader"/>
      <TetrahedronSetTopologyModifier name="Modifier"/>
      <TetrahedronSetGeometryAlgorithms template="Vec3"/>
      <DiagonalMass massDensity="1.0"/>
      <FixedProjectiveConstraint indices="7 8 14 15"/>
      <TetrahedralCorotationalFEMForceField youngModulus="360" poissonRatio="0.3" method="large"/>
      <Node name="Embedded">
        <MechanicalObject name="pts" position=")" + lattice.str() + R"("/>
        <UniformMass totalMass="0.1"/>
        <BarycentricMapping name="map"/>
      </Node>
      <Node name="Visu">
        <MeshOBJLoader name="obj" filename="mesh/cube.obj" scale="3"/>
        <OglModel name="Visual" src="@obj"/>
        <BarycentricMapping name="vmap" input="@../Volume" output="@Visual"/>
      </Node>
      <TopologicalChangeProcessor listening="1" filename=")" + changes.string() + R"("/>
    </Node>
  </Node>)");
  runner::SessionOptions opts;
  opts.data_paths = {(data / "share").string(), (data / "examples").string()};
  runner::Session session(scene, opts);
  ASSERT_TRUE(session.ok());
  Node& tt = *session.root().find_child_named("TT");
  auto* topo = tt.find_local<PointSetTopologyContainer>();
  auto* volume = test::get<MechanicalState>(tt, "Volume");
  auto* map = test::get<BarycentricMapping>(*tt.find_child_named("Embedded"), "map");
  auto* vmap = test::get<BarycentricMapping>(*tt.find_child_named("Visu"), "vmap");
  ASSERT_TRUE(topo && volume && map && vmap);
  ASSERT_EQ(topo->tetrahedra().size(), 44u);
  auto* pts = test::get<MechanicalState>(*tt.find_child_named("Embedded"), "pts");
  std::vector<double> last;
  std::vector<std::size_t> counts;
  for (int step = 0; step < 300; ++step) {
    ASSERT_TRUE(session.step()) << "step " << step;
    const std::string where = "step " + std::to_string(step);
    const std::size_t n = topo->tetrahedra().size();
    if (counts.empty() || counts.back() != n) counts.push_back(n);
    if (n > 0) {
      expect_in_range(map->table(), n, volume->size(), where);
      expect_in_range(vmap->table(), n, volume->size(), where);
      last = pts->read(kPosition);
    } else {
      for (std::size_t i = 0; i < map->table().points(); ++i)
        ASSERT_EQ(map->table().end(i), map->table().begin(i)) << where;
      ASSERT_EQ(pts->read(kPosition), last) << where << ": the points stay where the last tetrahedra left them";
    }
    if (testing::Test::HasFailure()) break;
  }
  EXPECT_EQ(counts, (std::vector<std::size_t>{44, 34, 24, 14, 4, 0}));
  EXPECT_EQ(map->table().points(), 125u);
  EXPECT_TRUE(test::all_finite(session.root()));
  const auto errors = test::messages(session.diagnostics(), Severity::error);
  EXPECT_TRUE(errors.empty()) << errors.front();
  const auto warnings = test::messages(session.diagnostics(), Severity::warning);
  EXPECT_FALSE(test::any_contains(warnings, "without a propagation")) << "every change reached the mappings";
  int frozen = 0;
  for (const auto& m : warnings) frozen += m.find("keep their positions") != std::string::npos;
  EXPECT_EQ(frozen, 2) << "one warning per mapping";
}

}  // namespace
}  // namespace sinew
