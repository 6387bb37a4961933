// TubularMapping: rings of points around Rigid3d frames, on hand-derived values
// (positions, velocities, forces, peaks); the conformance battery checks J
// against finite differences and Jᵀ against J, constraint_rows_test the rows.
#include "mapping/linear/tubular_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_scene.h"
#include "topology/mapping/edge2_quad_topological_mapping.h"

namespace sinew {
namespace {

// Frame 0 at the origin, frame 1 at (1, 0, 0) turned 90° about x (R·y = z, R·z = −y).
constexpr const char* kFrames =
    "template='Rigid3d' position='0 0 0 0 0 0 1  1 0 0 0.7071067811865476 0 0 0.7071067811865476'";

scene::LoadedScene tube(const std::string& map_attrs, const std::string& frames = kFrames) {
  return test::load("<Node name='root' gravity='0 0 0'><MechanicalObject name='in' " + frames +
                    "/><Node name='child'><MechanicalObject name='out'/><TubularMapping name='map' " + map_attrs +
                    "/></Node></Node>");
}

struct Parts {
  MechanicalState *in, *out;
  TubularMapping* map;
};
Parts parts(const scene::LoadedScene& s) {
  Node& child = *s.root->find_child_named("child");
  return {test::get<MechanicalState>(*s.root, "in"), test::get<MechanicalState>(child, "out"),
          test::get<TubularMapping>(child, "map")};
}

void expect_vec(const std::vector<double>& x, std::size_t i, double a, double b, double c, const char* what) {
  EXPECT_NEAR(x[i * 3 + 0], a, 1e-15) << what << " " << i;
  EXPECT_NEAR(x[i * 3 + 1], b, 1e-15) << what << " " << i;
  EXPECT_NEAR(x[i * 3 + 2], c, 1e-15) << what << " " << i;
}

TEST(TubularMapping, RingsAroundEachFrame) {
  auto s = tube("nbPointsOnEachCircle='4' radius='0.5'");
  auto [in, out, map] = parts(s);
  ASSERT_TRUE(map && map->state() == ComponentState::valid);
  ASSERT_EQ(out->size(), 8u);
  const std::vector<double>& x = out->read(kPosition);
  // c + 0.5·(R·y cos θj + R·z sin θj), θj = jπ/2.
  expect_vec(x, 0, 0, 0.5, 0, "x");
  expect_vec(x, 1, 0, 0, 0.5, "x");
  expect_vec(x, 2, 0, -0.5, 0, "x");
  expect_vec(x, 4, 1, 0, 0.5, "x");
  expect_vec(x, 5, 1, -0.5, 0, "x");
  expect_vec(x, 7, 1, 0.5, 0, "x");
  // Moving a frame moves its ring: frame 0 shifted by (0, 0, 2).
  in->write(kPosition)[2] = 2;
  map->apply(kPosition);
  expect_vec(out->read(kPosition), 1, 0, 0, 2.5, "moved");
}

TEST(TubularMapping, VelocitiesAndForcesOfTheRings) {
  auto s = tube("nbPointsOnEachCircle='4' radius='0.5'");
  auto [in, out, map] = parts(s);
  // Frame 0: v = (1, 0, 0), ω = (0, 0, 2); frame 1: v = 0, ω = (3, 0, 0).
  in->write(kVelocity) = {1, 0, 0, 0, 0, 2, 0, 0, 0, 3, 0, 0};
  map->apply_j(kVelocity, kVelocity);
  const std::vector<double>& v = out->read(kVelocity);
  expect_vec(v, 0, 0, 0, 0, "v");   // r = (0, 0.5, 0): (1,0,0) + (0,0,2) × r = (1,0,0) + (−1,0,0)
  expect_vec(v, 1, 1, 0, 0, "v");   // r = (0, 0, 0.5) ∥ ω
  expect_vec(v, 4, 0, -1.5, 0, "v");  // r = (0, 0, 0.5): (3,0,0) × r = (0, −1.5, 0)
  // A force on one point of each ring goes to that ring's frame only.
  out->write(kForce) = std::vector<double>(24, 0.0);
  std::vector<double>& f = out->write(kForce);
  f[0 * 3 + 2] = 1;  // (0, 0, 1) at r = (0, 0.5, 0): τ = r × f = (0.5, 0, 0)
  f[4 * 3 + 0] = 1;  // (1, 0, 0) at r = (0, 0, 0.5): τ = (0, 0.5, 0)
  in->write(kForce) = std::vector<double>(12, 0.0);
  map->apply_jt(kForce, kForce);
  const std::vector<double>& F = in->read(kForce);
  const std::vector<double> want = {0, 0, 1, 0.5, 0, 0, 1, 0, 0, 0, 0.5, 0};
  for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(F[k], want[k], 1e-15) << k;
}

TEST(TubularMapping, PeakNarrowsTheFirstOrLastRings) {
  const std::string three = "template='Rigid3d' position='0 0 0 0 0 0 1  1 0 0 0 0 0 1  2 0 0 0 0 0 1'";
  auto ring_radius = [](const MechanicalState& out, std::size_t frame) {
    const std::vector<double>& x = out.read(kPosition);
    return x[frame * 4 * 3 + 1];  // y of point j = 0: the radius
  };
  auto first = tube("nbPointsOnEachCircle='4' radius='1' peak='2'", three);
  const MechanicalState& a = *parts(first).out;
  EXPECT_NEAR(ring_radius(a, 0), 0.0, 1e-15);  // 0/2
  EXPECT_NEAR(ring_radius(a, 1), 0.5, 1e-15);  // 1/2
  EXPECT_NEAR(ring_radius(a, 2), 1.0, 1e-15);
  auto last = tube("nbPointsOnEachCircle='4' radius='1' peak='-2'", three);
  const MechanicalState& b = *parts(last).out;
  EXPECT_NEAR(ring_radius(b, 0), 1.0, 1e-15);
  EXPECT_NEAR(ring_radius(b, 1), 0.5, 1e-15);
  EXPECT_NEAR(ring_radius(b, 2), 0.0, 1e-15);
}

TEST(TubularMapping, SamePointsAsEdge2QuadTopologicalMapping) {
  // The topological mapping places the rings at init, the mapping moves them: same numbers, bit for bit.
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
    <EdgeSetTopologyContainer name="edges" position="0 0 0  0.5 0.1 0  1 0.3 0.2" edges="0 1  1 2"/>
    <MechanicalObject name="frames" template="Rigid3d"
        position="0 0 0 0 0 0 1  0.5 0.1 0 0.1 0.2 0.3 0.927362  1 0.3 0.2 0 0.6 0 0.8"/>
    <Node name="tube">
      <MechanicalObject name="ring"/>
      <QuadSetTopologyContainer name="quads"/>
      <QuadSetTopologyModifier/>
      <Edge2QuadTopologicalMapping name="topo" nbPointsOnEachCircle="7" radius="0.05" input="@../edges" output="@quads"/>
    </Node>
    <Node name="skin">
      <MechanicalObject name="ring"/>
      <TubularMapping nbPointsOnEachCircle="7" radius="0.05" input="@../frames" output="@ring"/>
    </Node>
  </Node>)");
  const auto& a = test::get<MechanicalState>(*s.root->find_child_named("tube"), "ring")->read(kPosition);
  const auto& b = test::get<MechanicalState>(*s.root->find_child_named("skin"), "ring")->read(kPosition);
  ASSERT_EQ(a.size(), 21u * 3);
  EXPECT_EQ(a, b);
}

TEST(TubularMapping, BadInputIsAnErrorNotACrash) {
  auto s = tube("nbPointsOnEachCircle='4'");
  EXPECT_EQ(parts(s).map->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "No radius"));
  // Vec3d input: no template fits.
  Diagnostics d;
  auto v = test::build(
      "<Node><MechanicalObject name='in'/><Node name='c'><MechanicalObject/>"
      "<TubularMapping nbPointsOnEachCircle='4' radius='1'/></Node></Node>");
  ASSERT_TRUE(v.root);
  EXPECT_TRUE(test::any_contains(test::messages(v.root->diagnostics(), Severity::error), "TubularMapping"));
}

}  // namespace
}  // namespace sinew
