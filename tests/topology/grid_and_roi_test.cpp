// RegularGridTopology (spec/mechanics.md §5.2, §0.3) and BoxROI (§7.7).
#include "engine/box_roi.h"
#include "topology/grid/regular_grid_topology.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "state/mechanical_object.h"
#include "badinput_helpers.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

double f32(double x) { return static_cast<double>(static_cast<float>(x)); }

RegularGridTopology& grid_of(scene::LoadedScene& s, std::string_view name = "grid") {
  auto* g = get<RegularGridTopology>(*s.root, name);
  if (!g) throw std::runtime_error("no grid");
  return *g;
}

BoxROI& roi_of(scene::LoadedScene& s, std::string_view name = "roi") {
  auto* r = get<BoxROI>(*s.root, name);
  if (!r) throw std::runtime_error("no BoxROI");
  return *r;
}

using Idx = std::vector<unsigned>;

// 3×3×3 grid with points on integer coordinates 0..2; point (i,j,k) has index i + 3j + 9k.
std::string grid333(const std::string& roi_attrs, const std::string& mo_attrs = "") {
  return R"(<Node>
    <RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>
    <MechanicalObject name="dofs" )" +
         mo_attrs + R"(/>
    <BoxROI name="roi" )" +
         roi_attrs + R"(/>
  </Node>)";
}

}  // namespace

// ---------------------------------------------------------------- RegularGridTopology

// §5.2: point (i,j,k) = min + i·dx + j·dy + k·dz, index i + nx·(j + ny·k).
TEST(RegularGridTopology, PointCoordinatesAndIndexOrder) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="4 1 3"/></Node>)");
  auto& g = grid_of(s);
  ASSERT_EQ(g.nb_points(), 12u);
  EXPECT_EQ(g.point(0), Vec3(0, 0, 0));
  EXPECT_EQ(g.point(1), Vec3(2, 0, 0));
  EXPECT_EQ(g.point(2), Vec3(4, 0, 0));
  EXPECT_EQ(g.point(3), Vec3(0, 1, 0));
  EXPECT_EQ(g.point(5), Vec3(4, 1, 0));
  EXPECT_EQ(g.point(7), Vec3(2, 0, 3));
  EXPECT_EQ(g.point(11), Vec3(4, 1, 3));
  EXPECT_EQ(g.point_index(1, 0, 1), 7u);
}

// §5.2: hexa count (nx−1)(ny−1)(nz−1), z outer / y / x inner, corner order of the first cell.
TEST(RegularGridTopology, HexahedraCountAndNodeOrder) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="4 1 3"/></Node>)");
  auto& g = grid_of(s);
  ASSERT_EQ(g.hexahedra().size(), 2u);
  EXPECT_EQ(g.hexahedra()[0], (Hexa{0, 1, 4, 3, 6, 7, 10, 9}));
  EXPECT_EQ(g.hexahedra()[1], (Hexa{1, 2, 5, 4, 7, 8, 11, 10}));
}

// §5.2: all grid faces: xy nz(ny−1)(nx−1) + xz (nz−1)ny(nx−1) + yz (nz−1)(ny−1)nx.
TEST(RegularGridTopology, QuadAndTriangleCounts) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="4 1 3"/></Node>)");
  auto& g = grid_of(s);
  ASSERT_EQ(g.quads().size(), 4u + 4u + 3u);
  EXPECT_EQ(g.quads()[0], (Quad{0, 1, 4, 3}));           // first xy face
  EXPECT_EQ(g.quads()[4], (Quad{0, 1, 7, 6}));           // first xz face
  EXPECT_EQ(g.quads()[8], (Quad{0, 3, 9, 6}));           // first yz face
  ASSERT_EQ(g.triangles().size(), 22u);                  // two per quad
  EXPECT_EQ(g.triangles()[0], (Triangle{0, 1, 4}));
  EXPECT_EQ(g.triangles()[1], (Triangle{0, 4, 3}));
}

// §5.2: edges derived from triangles: axis edges + one diagonal per quad, oriented as first seen.
TEST(RegularGridTopology, EdgesComeFromTheTriangles) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="4 1 3"/></Node>)");
  auto& g = grid_of(s);
  // Axis edges: x 2·2·2 = 8, y 2·1·3 = 6, z 1·2·3 = 6 → 20, plus 11 diagonals.
  ASSERT_EQ(g.edges().size(), 31u);
  EXPECT_EQ(g.edges()[0], (Edge{1, 4}));
  EXPECT_EQ(g.edges()[1], (Edge{4, 0}));
  EXPECT_EQ(g.edges()[2], (Edge{0, 1}));
}

TEST(RegularGridTopology, AxisEdgesWithoutTriangles) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="3 2 1" computeTriangleList="0"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_TRUE(g.triangles().empty());
  // x edges 1·2·2 = 4, y edges 1·1·3 = 3.
  ASSERT_EQ(g.edges().size(), 7u);
  EXPECT_EQ(g.edges()[0], (Edge{0, 1}));
  EXPECT_EQ(g.edges()[4], (Edge{0, 3}));
}

// §5.2: an axis with n == 1 is centred for x and y, but sits at min for z.
TEST(RegularGridTopology, SinglePointAxisRule) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="2 1 1" min="0 2 4" max="1 6 10"/></Node>)");
  auto& g = grid_of(s);
  ASSERT_EQ(g.nb_points(), 2u);
  EXPECT_EQ(g.point(0), Vec3(0, 4, 4));
  EXPECT_EQ(g.point(1), Vec3(1, 4, 4));
  EXPECT_TRUE(g.hexahedra().empty());
  EXPECT_TRUE(g.quads().empty());
  ASSERT_EQ(g.edges().size(), 1u);
}

TEST(RegularGridTopology, SinglePointAlongXIsCentred) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="1 2 1" min="2 0 5" max="4 1 9"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_EQ(g.point(0), Vec3(3, 0, 5));
  EXPECT_EQ(g.point(1), Vec3(3, 1, 5));
}

// mechanics §0.3: xmin..zmax are parsed as float.
TEST(RegularGridTopology, BoundsAttributesAreParsedAsFloat) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="2 2 2"
      xmin="0.1" ymin="0" zmin="-0.7" xmax="1.3" ymax="1" zmax="1"/></Node>)");
  auto& g = grid_of(s);
  ASSERT_NE(f32(0.1), 0.1);
  EXPECT_EQ(g.min.value(), Vec3(f32(0.1), 0.0, f32(-0.7)));
  EXPECT_EQ(g.max.value().x(), f32(1.3));
  EXPECT_EQ(g.point(0).x(), f32(0.1));
  EXPECT_EQ(g.point(1).x(), f32(1.3));
}

// §5.2: the bounds are multiplied by `scale` (float).
TEST(RegularGridTopology, BoundsAttributesAreScaled) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="2 2 2"
      xmin="0" ymin="0" zmin="0" xmax="1" ymax="2" zmax="3" scale="2"/></Node>)");
  EXPECT_EQ(grid_of(s).max.value(), Vec3(2, 4, 6));
}

// §5.2: the six bounds are used only when all six are given.
TEST(RegularGridTopology, IncompleteBoundsAttributesAreIgnored) {
  Diagnostics tree;
  auto s = sinew::test::build(R"(<Node><RegularGridTopology name="grid" xmin="5" xmax="6"/></Node>)", &tree);
  init_root(*s.root);
  EXPECT_EQ(grid_of(s).min.value(), Vec3(0, 0, 0));
  EXPECT_EQ(grid_of(s).max.value(), Vec3(1, 1, 1));
}

// §5.2: nx ny nz (all three) set n.
TEST(RegularGridTopology, NxNyNzSetTheSize) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" nx="4" ny="3" nz="2"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_EQ(g.n.value(), VecNi<3>(4, 3, 2));
  EXPECT_EQ(g.nb_points(), 24u);
}

// §5.2: values < 1 → reset to 2 2 2 with a warning.
TEST(RegularGridTopology, SizeBelowOneIsResetWithAWarning) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="0 3 3"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_EQ(g.n.value(), VecNi<3>(2, 2, 2));
  EXPECT_EQ(g.nb_points(), 8u);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::warning),
                                        "RegularGridTopology"));
}

// §5.2: cellWidth > 0 → n_i = ceil((max_i − min_i)/w) + 1.
TEST(RegularGridTopology, CellWidthComputesTheSize) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" min="0 0 0" max="1 2 2.5" cellWidth="1"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_EQ(g.n.value(), VecNi<3>(2, 3, 4));
}

// §5.2: p0 given → point 0 is p0.
TEST(RegularGridTopology, P0MovesTheOrigin) {
  auto s = load(R"(<Node><RegularGridTopology name="grid" n="2 2 2" p0="10 20 30"/></Node>)");
  auto& g = grid_of(s);
  EXPECT_EQ(g.point(0), Vec3(10, 20, 30));
  EXPECT_EQ(g.point(7), Vec3(11, 21, 31));
}

// ---------------------------------------------------------------- BoxROI

// §7.7: min ≤ p ≤ max on every axis, inclusive at both ends.
TEST(BoxROI, BoundsAreInclusive) {
  auto s = load(grid333(R"(box="0 0 0 1 1 1")"));
  auto& roi = roi_of(s);
  EXPECT_EQ(roi.indices.get(), (Idx{0, 1, 3, 4, 9, 10, 12, 13}));
  EXPECT_EQ(roi.nb_indices.get(), 8u);
  EXPECT_EQ(roi.indices_out.get().size(), 19u);
  EXPECT_EQ(roi.points_in_roi.get().data.size(), 24u);
  EXPECT_EQ(roi.points_in_roi.get().data[3], 1.0);  // point 1 = (1,0,0)
}

// §7.7: components are swapped per axis when min > max.
TEST(BoxROI, SwappedMinAndMaxAreNormalised) {
  auto s = load(grid333(R"(box="1 1 1 0 0 0")"));
  EXPECT_EQ(roi_of(s).indices.get(), (Idx{0, 1, 3, 4, 9, 10, 12, 13}));
}

TEST(BoxROI, SwappedOnOneAxisOnly) {
  auto s = load(grid333(R"(box="0 2 0 0 1 0")"));
  EXPECT_EQ(roi_of(s).indices.get(), (Idx{3, 6}));
}

// §7.7: a point is in the ROI if it is in any box; indices in increasing order.
TEST(BoxROI, SeveralBoxesUnionInScanOrder) {
  auto s = load(grid333(R"(box="2 2 2 2 2 2  0 0 0 0 0 0  1.5 -1 -1 2.5 0.5 0.5")"));
  EXPECT_EQ(roi_of(s).indices.get(), (Idx{0, 2, 26}));
}

// §7.7: default box (0,0,0,1,1,1).
TEST(BoxROI, DefaultBoxIsTheUnitCube) {
  auto s = load(grid333(""));
  EXPECT_EQ(roi_of(s).indices.get().size(), 8u);
}

// §7.7: position defaults to the local MechanicalObject's rest_position.
TEST(BoxROI, PositionDefaultsToTheLocalRestPosition) {
  auto s = load(grid333(R"(box="0 0 0 0 0 0")", R"(translation2="100 0 0")"));
  auto& roi = roi_of(s);
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  ASSERT_NE(mo, nullptr);
  EXPECT_EQ(roi.position.parent(), &mo->rest_position);
  // translation2 moves `position` but not `rest_position`: point 0 is still selected.
  EXPECT_EQ(mo->position.get().data[0], 100.0);
  EXPECT_EQ(roi.indices.get(), (Idx{0}));
}

TEST(BoxROI, PositionFollowsTheInitialTransformOfTheState) {
  auto s = load(grid333(R"(box="9.5 -0.5 -0.5 10.5 0.5 0.5")", R"(translation="10 0 0")"));
  EXPECT_EQ(roi_of(s).indices.get(), (Idx{0}));
}

TEST(BoxROI, ExplicitPositionIsUsed) {
  auto s = load(R"(<Node>
    <BoxROI name="roi" box="0 0 0 1 1 1" position="0.5 0.5 0.5  2 2 2  1 1 1"/>
  </Node>)");
  EXPECT_EQ(roi_of(s).indices.get(), (Idx{0, 2}));
  EXPECT_EQ(roi_of(s).indices_out.get(), (Idx{1}));
}

// §7.7: elements: strict → all vertices inside (default).
TEST(BoxROI, StrictElementSelectionNeedsAllVerticesInside) {
  auto s = load(grid333(R"(box="0 0 0 1 1 1")"));
  auto& roi = roi_of(s);
  EXPECT_EQ(roi.hexahedron_indices.get(), (Idx{0}));
  ASSERT_EQ(roi.hexahedra_in_roi.get().size(), 1u);
  EXPECT_EQ(roi.hexahedra_in_roi.get()[0], (Hexa{0, 1, 4, 3, 9, 10, 13, 12}));
  // Quads with all four corners in [0,1]^3: xy faces at z=0 and z=1, one xz at y=0 and y=1, one yz at x=0 and x=1.
  EXPECT_EQ(roi.quad_indices.get().size(), 6u);
}

// §7.7: non-strict → the centroid inside.
TEST(BoxROI, NonStrictElementSelectionUsesTheCentroid) {
  auto strict = load(grid333(R"(box="0 0 0 1.5 1.5 0.6")"));
  EXPECT_TRUE(roi_of(strict).hexahedron_indices.get().empty());
  auto loose = load(grid333(R"(box="0 0 0 1.5 1.5 0.6" strict="0")"));
  // Bottom-layer hexas have centroids (0.5|1.5, 0.5|1.5, 0.5): all four inside (inclusive).
  EXPECT_EQ(roi_of(loose).hexahedron_indices.get(), (Idx{0, 1, 2, 3}));
}

// §7.7 / framework §2.5: outputs are recomputed lazily when an input changed, and only then.
TEST(BoxROI, RecomputesLazilyWhenTheBoxChanges) {
  auto s = load(grid333(R"(box="0 0 0 0 0 0")"));
  auto& roi = roi_of(s);
  EXPECT_EQ(roi.indices.get(), (Idx{0}));
  const auto v = roi.indices.version();
  roi.indices.get();
  EXPECT_EQ(roi.indices.version(), v);  // no input changed: nothing recomputed
  roi.box.set({(VecN<6>() << 2, 2, 2, 2, 2, 2).finished()});
  EXPECT_EQ(roi.indices.version(), v);  // still lazy
  EXPECT_EQ(roi.indices.get(), (Idx{26}));
  EXPECT_GT(roi.indices.version(), v);
}

TEST(BoxROI, RecomputesWhenTheRestPositionChanges) {
  auto s = load(grid333(R"(box="0 0 0 0 0 0")"));
  auto& roi = roi_of(s);
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  EXPECT_EQ(roi.indices.get(), (Idx{0}));
  mo->rest_position.edit().data[0] = 5;  // move point 0 out of the box
  EXPECT_TRUE(roi.indices.get().empty());
}

// A FixedProjectiveConstraint fed by a BoxROI (BoxConstraint pattern) gets the selected indices.
TEST(BoxROI, IndicesFeedALinkedField) {
  auto s = load(grid333(R"(box="0 0 0 2 2 0")") /* z = 0 layer */);
  auto& roi = roi_of(s);
  Field<std::vector<unsigned>> consumer{nullptr, "indices", {}, ""};
  consumer.set_parent(&roi.indices);
  EXPECT_EQ(consumer.get(), (Idx{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

namespace sinew {
namespace {

// CylinderGridTopology: a 3×3 square layer mapped onto a disc of radius 2
// (corners (±2, ±2) become (±√2, ±√2), edge midpoints stay at distance 2),
// two layers 4 apart along the axis; the grid's connectivity.
TEST(CylinderGridTopology, PlacesTheGridInACylinder) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <CylinderGridTopology name="cyl" n="3 3 2" radius="2" length="4" axis="0 0 1" center="1 0 0"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* t = test::get<MeshTopologyBase>(*s.root, "cyl");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->nb_points(), 18u);
  const double r2 = std::sqrt(2.0);
  EXPECT_TRUE((t->point(0) - Vec3(1 - r2, -r2, 0)).norm() < 1e-12);  // corner (−2, −2)
  EXPECT_TRUE((t->point(1) - Vec3(1, -2, 0)).norm() < 1e-12);        // edge midpoint (0, −2)
  EXPECT_TRUE((t->point(4) - Vec3(1, 0, 0)).norm() < 1e-12);         // centre
  EXPECT_TRUE((t->point(17) - Vec3(1 + r2, r2, 4)).norm() < 1e-12);  // last corner, second layer
  EXPECT_EQ(t->hexahedra().size(), 4u);
}

// SphereGridTopology: a 3×3×3 cube [−2, 2]³ mapped onto the ball of radius 2 (corners at
// distance 2 along the diagonals, face centres stay, the middle point at the centre), the
// grid's z along the axis (0, 1, 0): grid (x, y, z) → world (x, z, −y).
TEST(SphereGridTopology, PlacesTheGridInABall) {
  scene::LoadedScene s = test::load(R"(<Node name="root">
    <SphereGridTopology name="ball" n="3 3 3" radius="2" axis="0 1 0" center="0 5 0"/></Node>)");
  ASSERT_TRUE(s.root);
  auto* t = test::get<MeshTopologyBase>(*s.root, "ball");
  ASSERT_NE(t, nullptr);
  ASSERT_EQ(t->nb_points(), 27u);
  const double c = 2 / std::sqrt(3.0);
  EXPECT_TRUE((t->point(0) - Vec3(-c, 5 - c, c)).norm() < 1e-12);  // grid corner (−2, −2, −2)
  EXPECT_TRUE((t->point(13) - Vec3(0, 5, 0)).norm() < 1e-12);      // the middle point
  EXPECT_TRUE((t->point(4) - Vec3(0, 3, 0)).norm() < 1e-12);       // face centre (0, 0, −2)
  EXPECT_TRUE((t->point(26) - Vec3(c, 5 + c, -c)).norm() < 1e-12);  // corner (2, 2, 2)
  for (std::size_t i = 0; i < 27; ++i) EXPECT_LE((t->point(i) - Vec3(0, 5, 0)).norm(), 2 + 1e-12) << i;
  EXPECT_EQ(t->hexahedra().size(), 8u);
}

TEST(SphereGridTopology, OnePointAlongADirectionIsAnError) {
  scene::LoadedScene s = test::build(R"(<Node name="root"><SphereGridTopology n="3 3 1"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_FALSE(test::messages(s.root->diagnostics(), Severity::error).empty());
}

TEST(SphereGridTopology, SofaExampleRuns100Steps) {
  const test::Outcome o = test::run_sofa_example("Component/Topology/Container/Grid/SphereGridTopology.scn", 100);
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  EXPECT_EQ(o.steps, 100) << o.all();
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
}

TEST(CylinderGridTopology, OnePointAcrossIsAnError) {
  scene::LoadedScene s = test::build(R"(<Node name="root"><CylinderGridTopology n="1 3 2"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_FALSE(test::messages(s.root->diagnostics(), Severity::error).empty());
}

}  // namespace
}  // namespace sinew
