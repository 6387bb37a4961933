// Edge2QuadTopologicalMapping: the quads of a tube around a line of frames and
// the ring positions it writes into the output state, checked against values
// derived by hand on a three-frame beam (rings of 4 points, radius 0.5).
#include "topology/mapping/edge2_quad_topological_mapping.h"

#include <gtest/gtest.h>

#include <cmath>

#include "topology/dynamic/edge_set_topology_modifier.h"
#include "topology/dynamic/quad_set_topology_container.h"
#include "test_scene.h"

using namespace sinew;

namespace {

// Frames at x = 0, 1, 2; frame 1 turned 90° about x (its y axis is the world z, its z axis −y).
std::string beam(const std::string& mapping_attrs, const std::string& out_state = "<MechanicalObject name='ring'/>") {
  return R"(<Node name="root" gravity="0 0 0">
    <EdgeSetTopologyContainer name="edges" position="0 0 0  1 0 0  2 0 0" edges="0 1  1 2"/>
    <MechanicalObject name="frames" template="Rigid3d"
        position="0 0 0 0 0 0 1  1 0 0 0.7071067811865476 0 0 0.7071067811865476  2 0 0 0 0 0 1"/>
    <Node name="tube">)" +
         out_state + R"(
      <QuadSetTopologyContainer name="quads"/>
      <QuadSetTopologyModifier/>
      <Edge2QuadTopologicalMapping name="map" input="@../edges" output="@quads" )" +
         mapping_attrs + R"(/>
    </Node>
  </Node>)";
}

Node& tube(const scene::LoadedScene& s) { return *s.root->find_child_named("tube"); }

std::vector<std::string> errors(const scene::LoadedScene& s) {
  return test::messages(s.root->diagnostics(), Severity::error);
}

}  // namespace

TEST(Edge2QuadTopologicalMapping, QuadsJoinTheRingsOfEachEdge) {
  auto s = test::load(beam("nbPointsOnEachCircle='4' radius='0.5'"));
  auto& map = *test::get<Edge2QuadTopologicalMapping>(tube(s), "map");
  ASSERT_EQ(map.state(), ComponentState::valid);
  auto& quads = *test::get<QuadSetTopologyContainer>(tube(s), "quads");
  // Edge (p0, p1), ring point j: (p0·4+j, p1·4+j, p1·4+j+1, p0·4+j+1), wrapping at j = 3.
  const std::vector<Quad> want = {{0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0},
                                  {4, 8, 9, 5}, {5, 9, 10, 6}, {6, 10, 11, 7}, {7, 11, 8, 4}};
  EXPECT_EQ(quads.quads(), want);
  EXPECT_EQ(quads.nb_points(), 12u);
  EXPECT_EQ(map.quad_to_edge(), (std::vector<unsigned>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(quads.edges().size(), 20u);  // 4 per ring (3 rings) + 4 along each of the 2 edges
}

TEST(Edge2QuadTopologicalMapping, RingsAroundEachFrameInItsYZPlane) {
  auto s = test::load(beam("nbPointsOnEachCircle='4' radius='0.5'"));
  auto* ring = test::get<MechanicalState>(tube(s), "ring");
  ASSERT_NE(ring, nullptr);
  ASSERT_EQ(ring->size(), 12u);
  const std::vector<double>& x = ring->read(kPosition);
  auto expect_point = [&](std::size_t i, double px, double py, double pz) {
    EXPECT_NEAR(x[i * 3 + 0], px, 1e-15) << "point " << i;
    EXPECT_NEAR(x[i * 3 + 1], py, 1e-15) << "point " << i;
    EXPECT_NEAR(x[i * 3 + 2], pz, 1e-15) << "point " << i;
  };
  // Frame 0 (identity): c + 0.5·(y cos θ + z sin θ), θ = 0, π/2, π, 3π/2.
  expect_point(0, 0, 0.5, 0);
  expect_point(1, 0, 0, 0.5);
  expect_point(2, 0, -0.5, 0);
  expect_point(3, 0, 0, -0.5);
  // Frame 1, turned 90° about x: R·y = z, R·z = −y.
  expect_point(4, 1, 0, 0.5);
  expect_point(5, 1, -0.5, 0);
  expect_point(6, 1, 0, -0.5);
  // Frame 2 (identity) at x = 2.
  expect_point(9, 2, 0, 0.5);
}

TEST(Edge2QuadTopologicalMapping, FlipNormalsReversesTheQuadsAsSofaDoes) {
  // Every edge mapped: (q3, q2, q1, q0).
  auto s = test::load(beam("nbPointsOnEachCircle='4' radius='0.5' flipNormals='true'"));
  const auto& q = test::get<QuadSetTopologyContainer>(tube(s), "quads")->quads();
  ASSERT_EQ(q.size(), 8u);
  EXPECT_EQ(q[0], (Quad{1, 5, 4, 0}));
  EXPECT_EQ(q[3], (Quad{0, 4, 7, 3}));
  // With an edgeList, SOFA writes (q0, q3, q2, q1) instead, and only the listed edges.
  auto e = test::load(beam("nbPointsOnEachCircle='4' radius='0.5' flipNormals='true' edgeList='1'"));
  auto& map = *test::get<Edge2QuadTopologicalMapping>(tube(e), "map");
  const auto& qe = test::get<QuadSetTopologyContainer>(tube(e), "quads")->quads();
  ASSERT_EQ(qe.size(), 4u);
  EXPECT_EQ(qe[0], (Quad{4, 5, 9, 8}));
  EXPECT_EQ(qe[3], (Quad{7, 4, 8, 11}));
  EXPECT_EQ(map.quad_to_edge(), (std::vector<unsigned>{1, 1, 1, 1}));
}

TEST(Edge2QuadTopologicalMapping, EllipsesAlongTheFocalAxis) {
  // focalAxis = y: Z0 = y, Y0 = y × x = −z; point j = c + Y·cos θ·radius + Z·sin θ·radiusFocal.
  auto s = test::load(beam("nbPointsOnEachCircle='4' radius='0.5' radiusFocal='0.2' focalAxis='0 3 0'"));
  const std::vector<double>& x = test::get<MechanicalState>(tube(s), "ring")->read(kPosition);
  EXPECT_NEAR(x[0 * 3 + 2], -0.5, 1e-15);  // j = 0 on frame 0: (0, 0, −0.5)
  EXPECT_NEAR(x[0 * 3 + 1], 0.0, 1e-15);
  EXPECT_NEAR(x[1 * 3 + 1], 0.2, 1e-15);  // j = 1: (0, 0.2, 0)
  EXPECT_NEAR(x[1 * 3 + 2], 0.0, 1e-15);
  // Frame 1 (R·y = z, R·z = −y): j = 1 → (1, 0, 0.2).
  EXPECT_NEAR(x[5 * 3 + 0], 1.0, 1e-15);
  EXPECT_NEAR(x[5 * 3 + 2], 0.2, 1e-15);
}

TEST(Edge2QuadTopologicalMapping, WritesTheRingsIntoAVisualModel) {
  auto s = test::load(beam("nbPointsOnEachCircle='3' radius='2'", "<OglModel name='skin'/>"));
  auto* skin = test::get<VisualState>(tube(s), "skin");
  ASSERT_NE(skin, nullptr);
  ASSERT_EQ(skin->visual_size(), 9u);
  const std::vector<double>& x = *skin->visual_vec(kPosition);
  EXPECT_NEAR(x[1], 2.0, 1e-15);                                  // frame 0, j = 0: (0, 2, 0)
  EXPECT_NEAR(x[1 * 3 + 1], 2.0 * std::cos(2 * M_PI / 3), 1e-15);  // j = 1
  EXPECT_NEAR(x[1 * 3 + 2], 2.0 * std::sin(2 * M_PI / 3), 1e-15);
}

TEST(Edge2QuadTopologicalMapping, BadInputIsAnErrorNotACrash) {
  struct Case {
    std::string attrs, needle;
  };
  const std::vector<Case> cases = {
      {"nbPointsOnEachCircle='4'", "No radius"},
      {"nbPointsOnEachCircle='4' radius='-1'", "radius is zero or negative"},
      {"nbPointsOnEachCircle='4' radius='1' edgeList='0 7'", "edgeList names edge 7"},
  };
  for (const Case& c : cases) {
    auto s = test::load(beam(c.attrs));
    EXPECT_EQ(test::get<Component>(tube(s), "map")->state(), ComponentState::invalid) << c.attrs;
    EXPECT_TRUE(test::any_contains(errors(s), c.needle)) << c.attrs;
  }
  // The input's frames must be Rigid3d when there is an output state to place the rings in.
  auto v = test::load(R"(<Node name="root">
    <EdgeSetTopologyContainer name="edges" position="0 0 0  1 0 0" edges="0 1"/>
    <MechanicalObject name="points"/>
    <Node name="tube"><MechanicalObject/><QuadSetTopologyContainer name="quads"/><QuadSetTopologyModifier/>
      <Edge2QuadTopologicalMapping name="map" nbPointsOnEachCircle="4" radius="1" input="@../edges" output="@quads"/>
    </Node></Node>)");
  EXPECT_TRUE(test::any_contains(errors(v), "must be Rigid3d"));
  // A quad input is not an edge topology; a missing modifier is reported.
  auto q = test::load(R"(<Node name="root">
    <QuadSetTopologyContainer name="in" quads="0 1 2 3"/>
    <Node name="tube"><QuadSetTopologyContainer name="quads"/><QuadSetTopologyModifier/>
      <Edge2QuadTopologicalMapping name="map" nbPointsOnEachCircle="4" radius="1" input="@../in" output="@quads"/>
    </Node></Node>)");
  EXPECT_TRUE(test::any_contains(errors(q), "valid 'Edge' topology"));
  auto m = test::load(R"(<Node name="root">
    <EdgeSetTopologyContainer name="edges" position="0 0 0  1 0 0" edges="0 1"/>
    <Node name="tube"><QuadSetTopologyContainer name="quads"/>
      <Edge2QuadTopologicalMapping name="map" nbPointsOnEachCircle="4" radius="1" input="@../edges" output="@quads"/>
    </Node></Node>)");
  EXPECT_TRUE(test::any_contains(errors(m), "quad modifier"));
}

// ---------------------------------------------------------------- topological changes
namespace {

// The beam with a modifier on its edges, so that they can change while the tube follows.
std::string dynamic_beam(const std::string& mapping_attrs) {
  std::string xml = beam(mapping_attrs);
  const std::string after = R"(edges="0 1  1 2"/>)";
  xml.insert(xml.find(after) + after.size(), R"(<EdgeSetTopologyModifier name="emod"/>)");
  return xml;
}

}  // namespace

TEST(Edge2QuadTopologicalMapping, RemovedEdgeTakesItsQuadsAndIsolatedRingAway) {
  auto s = test::load(dynamic_beam("nbPointsOnEachCircle='4' radius='0.5'"));
  auto& map = *test::get<Edge2QuadTopologicalMapping>(tube(s), "map");
  auto& quads = *test::get<QuadSetTopologyContainer>(tube(s), "quads");
  auto* emod = test::get<EdgeSetTopologyModifier>(*s.root, "emod");
  auto* ring = test::get<MechanicalState>(tube(s), "ring");
  ASSERT_NE(emod, nullptr);
  ASSERT_EQ(map.state(), ComponentState::valid);
  const std::vector<double> x_before = ring->read(kPosition);
  emod->remove_edges({0}, false);
  // Edge 0's quads 0..3 go (quads 7, 6, 5, 4 move into their slots, in that order of removal),
  // then ring 0 (points 0..3), isolated, goes with its DoFs: points 11, 10, 9, 8 fill the slots.
  const std::vector<Quad> want = {{4, 0, 1, 5}, {5, 1, 2, 6}, {6, 2, 3, 7}, {7, 3, 0, 4}};
  EXPECT_EQ(quads.quads(), want);
  EXPECT_EQ(quads.nb_points(), 8u);
  ASSERT_EQ(ring->size(), 8u);
  EXPECT_DOUBLE_EQ(ring->read(kPosition)[0], x_before[8 * 3]);  // the old ring of frame 2 (x = 2)
  EXPECT_DOUBLE_EQ(ring->read(kPosition)[4 * 3], x_before[4 * 3]);
  // SOFA's bookkeeping: the input's last edge (1) took slot 0 and owns the four quads left.
  EXPECT_EQ(map.quad_to_edge(), (std::vector<unsigned>{0, 0, 0, 0}));
  EXPECT_EQ(map.edge_to_quads(0), (std::vector<unsigned>{0, 1, 2, 3}));
  EXPECT_TRUE(map.edge_to_quads(1).empty());
  EXPECT_EQ(quads.edges().size(), 12u);  // two rings of 4 and 4 along the edge

  // Removing the remaining edge empties the tube.
  emod->remove_edges({0}, false);
  EXPECT_TRUE(quads.quads().empty());
  EXPECT_EQ(quads.nb_points(), 0u);
  EXPECT_TRUE(map.quad_to_edge().empty());
}

TEST(Edge2QuadTopologicalMapping, AddedEdgeGetsItsRingOfQuads) {
  auto s = test::load(dynamic_beam("nbPointsOnEachCircle='4' radius='0.5' flipNormals='1'"));
  auto& map = *test::get<Edge2QuadTopologicalMapping>(tube(s), "map");
  auto& quads = *test::get<QuadSetTopologyContainer>(tube(s), "quads");
  auto* emod = test::get<EdgeSetTopologyModifier>(*s.root, "emod");
  ASSERT_NE(emod, nullptr);
  emod->add_edges({Edge{0, 2}});
  // Quads of the new edge 2 = (0, 2) are appended unflipped (SOFA ignores flipNormals here).
  ASSERT_EQ(quads.quads().size(), 12u);
  EXPECT_EQ(quads.quads()[8], (Quad{0, 8, 9, 1}));
  EXPECT_EQ(quads.quads()[11], (Quad{3, 11, 8, 0}));
  EXPECT_EQ(quads.quads()[0], (Quad{1, 5, 4, 0}));  // the init ones stay flipped
  EXPECT_EQ(map.edge_to_quads(2), (std::vector<unsigned>{8, 9, 10, 11}));
  std::vector<unsigned> in;
  ASSERT_TRUE(map.input_elements(9, in));
  EXPECT_EQ(in, std::vector<unsigned>{2});
}

TEST(Edge2QuadTopologicalMapping, AddedPointsGetARingWithSofasAncestorRows) {
  auto s = test::load(dynamic_beam("nbPointsOnEachCircle='4' radius='0.5'"));
  auto& quads = *test::get<QuadSetTopologyContainer>(tube(s), "quads");
  auto* emod = test::get<EdgeSetTopologyModifier>(*s.root, "emod");
  auto* ring = test::get<MechanicalState>(tube(s), "ring");
  ASSERT_NE(emod, nullptr);
  ASSERT_TRUE(emod->add_points(1, {{0, 2}}, {{0.5, 0.5}}));
  EXPECT_EQ(quads.nb_points(), 16u);
  ASSERT_EQ(ring->size(), 16u);
  // Ring 0 of the new point: ancestors {0·4, 2·4} with coefficients {0.5·4, 0.5·4} (SOFA maps the
  // coefficients as indices): 2·(0, 0.5, 0) + 2·(2, 0.5, 0) = (4, 2, 0).
  const std::vector<double>& x = ring->read(kPosition);
  EXPECT_NEAR(x[12 * 3 + 0], 4.0, 1e-12);
  EXPECT_NEAR(x[12 * 3 + 1], 2.0, 1e-12);
  EXPECT_NEAR(x[12 * 3 + 2], 0.0, 1e-12);
}
