// DistanceToPlaneMapping, AreaMapping, VolumeMapping and CenterOfMassMapping on
// hand-computed values (SOFA's Sofa.Component.Mapping.Linear and .NonLinear);
// the conformance battery checks J and the geometric stiffness against finite
// differences.
#include <gtest/gtest.h>

#include <vector>

#include "mapping/linear/center_of_mass_mapping.h"
#include "mapping/linear/distance_to_plane_mapping.h"
#include "mapping/nonlinear/area_mapping.h"
#include "mapping/nonlinear/volume_mapping.h"
#include "test_scene.h"

namespace sinew {
namespace {

struct Setup {
  scene::LoadedScene s;
  MechanicalState* in = nullptr;
  MechanicalState* out = nullptr;
  Mapping* map = nullptr;
};

// `extra` after the input state in the root; the output (with `out_attrs`) and the mapping in a child.
Setup make(const std::string& in_attrs, const std::string& cls, const std::string& map_attrs,
           const std::string& extra = "", const std::string& out_attrs = "template='Vec1d'") {
  Setup r;
  r.s = test::load("<Node name='root' gravity='0 0 0'><MechanicalObject name='in' " + in_attrs + "/>" + extra +
                   "<Node name='child'><MechanicalObject name='out' " + out_attrs + "/><" + cls + " name='map' " +
                   map_attrs + "/></Node></Node>");
  if (!r.s.root) return r;
  Node& child = *r.s.root->find_child_named("child");
  r.in = test::get<MechanicalState>(*r.s.root, "in");
  r.out = test::get<MechanicalState>(child, "out");
  r.map = test::get<Mapping>(child, "map");
  return r;
}

std::vector<std::string> init_errors(const std::string& xml) {
  auto s = test::build(xml);
  if (!s.root) return {"not built"};
  init_root(*s.root);
  return test::messages(s.root->diagnostics(), Severity::error);
}

void expect_near(const std::vector<double>& got, const std::vector<double>& want, double tol, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << what << " [" << i << "]";
}

TEST(DistanceToPlaneMapping, SignedDistancesToTheNormalisedPlane) {
  // planeNormal (0 0 2) is normalised; the plane z = 2 (the example scene's).
  auto e = make("position='4 2 5  1 5 -8'", "DistanceToPlaneMapping", "planeNormal='0 0 2' planePoint='0 0 2'");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  // Nothing is applied during the mapping's init (SOFA's); the propagation after the scene's init does it.
  EXPECT_EQ(e.out->read(kPosition), (std::vector<double>{3, -10}));
  EXPECT_EQ(dynamic_cast<DistanceToPlaneMapping*>(e.map)->plane_normal.get(), (std::vector<double>{0, 0, 1}));
  e.in->write(kDx) = {1, 2, 3, -1, -1, 0.5};
  e.map->apply_j(kDx, kDx);
  EXPECT_EQ(e.out->read(kDx), (std::vector<double>{3, 0.5}));
  e.in->write(kForce) = {1, 1, 1, 0, 0, 0};
  e.out->write(kForce) = {2, -4};
  e.map->apply_jt(kForce, kForce);
  EXPECT_EQ(e.in->read(kForce), (std::vector<double>{1, 1, 3, 0, 0, -4}));
}

TEST(DistanceToPlaneMapping, Rigid3dFramesUseTheirCentres) {
  auto e = make("template='Rigid3d' position='1 2 3 0 0 0.6 0.8'", "DistanceToPlaneMapping",
                "template='Rigid3d' planeNormal='0 3 4'");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  e.map->apply(kPosition);
  EXPECT_NEAR(e.out->read(kPosition)[0], (2 * 3 + 3 * 4) / 5.0, 1e-15);  // the plane through the origin
  e.in->write(kForce) = std::vector<double>(6, 0.0);
  e.out->write(kForce) = {5};
  e.map->apply_jt(kForce, kForce);
  expect_near(e.in->read(kForce), {0, 3, 4, 0, 0, 0}, 1e-15, "Jᵀ·5");
}

TEST(DistanceToPlaneMapping, NullOrMissizedNormalIsRefused) {
  const std::string head =
      "<Node name='root'><MechanicalObject position='0 0 0'/><Node name='c'><MechanicalObject template='Vec1d'/>";
  auto errors = init_errors(head + "<DistanceToPlaneMapping planeNormal='0 0 0'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "planeNormal has a null norm"));
  errors = init_errors(head + "<DistanceToPlaneMapping planeNormal='0 1'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "planeNormal has 2 values; a Vec3d input needs 3"));
}

TEST(AreaMapping, AreaGradientAndCurvatureOfARightTriangle) {
  // Legs 2 (along x) and 3 (along y): area 3.
  auto e = make("position='0 0 0  2 0 0  0 3 0'", "AreaMapping", "topology='@../topo'",
                "<MeshTopology name='topo' triangles='0 1 2'/>");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  EXPECT_DOUBLE_EQ(e.out->read(kPosition)[0], 3.0);
  // ∂A/∂x0 = (−1.5, −1, 0), ∂A/∂x1 = (1.5, 0, 0) (half the height), ∂A/∂x2 = (0, 1, 0) (half the base).
  std::vector<JacobianEntry> j;
  ASSERT_TRUE(e.map->jacobian(j));
  std::vector<double> row(9, 0.0);
  for (const auto& en : j) row[en.col] += en.value;
  expect_near(row, {-1.5, -1, 0, 1.5, 0, 0, 0, 1, 0}, 1e-15, "J");
  // Lifting x2 along z: A = ½·2·√(9 + z²), ∂²A/∂z² = 1/3 at z = 0; by translation invariance
  // x0 gets −1/3 and x1 nothing. λ = −1 (stretched: kept by Stabilized).
  e.out->write(kForce) = {-1};
  e.in->write(kDx) = {0, 0, 0, 0, 0, 0, 0, 0, 1};
  e.in->write(kDforce) = std::vector<double>(9, 0.0);
  e.map->apply_djt(kDforce, kDx, 1.0);
  expect_near(e.in->read(kDforce), {0, 0, 1.0 / 3, 0, 0, 0, 0, 0, -1.0 / 3}, 1e-15, "geometric stiffness");
  // Compressed (λ > 0): nothing with Stabilized.
  e.out->write(kForce) = {1};
  e.in->write(kDforce) = std::vector<double>(9, 0.0);
  e.map->apply_djt(kDforce, kDx, 1.0);
  expect_near(e.in->read(kDforce), std::vector<double>(9, 0.0), 0.0, "stabilized, λ > 0");
}

TEST(AreaMapping, QuadsOrNoTrianglesAreRefused) {
  const std::string head = "<Node name='root'><MechanicalObject position='0 0 0  1 0 0  1 1 0  0 1 0'/>";
  auto errors = init_errors(head + "<MeshTopology name='t' triangles='0 1 2' quads='0 1 2 3'/><Node name='c'>"
                                   "<MechanicalObject template='Vec1d'/><AreaMapping topology='@../t'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "has quads"));
  errors = init_errors(head + "<MeshTopology name='t' edges='0 1'/><Node name='c'>"
                              "<MechanicalObject template='Vec1d'/><AreaMapping topology='@../t'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "has no triangles"));
}

TEST(VolumeMapping, SignedVolumeGradientAndCurvature) {
  auto e = make("position='0 0 0  1 0 0  0 1 0  0 0 1'", "VolumeMapping", "topology='@../topo'",
                "<MeshTopology name='topo' tetrahedra='0 1 2 3  0 1 3 2'/>");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  // The second tetrahedron is the first inverted.
  expect_near(e.out->read(kPosition), {1.0 / 6, -1.0 / 6}, 1e-16, "volumes");
  std::vector<JacobianEntry> j;
  ASSERT_TRUE(e.map->jacobian(j));
  std::vector<double> row(12, 0.0);
  for (const auto& en : j)
    if (en.row == 0) row[en.col] += en.value;
  const double s = 1.0 / 6;
  expect_near(row, {-s, -s, -s, s, 0, 0, 0, s, 0, 0, 0, s}, 1e-16, "J row 0");
  // ∂(∂V/∂x0)/∂x1 along y = (1/6, 0, 0) (block [x2 − x3]×/6); only tetrahedron 0 stressed,
  // in extension (λ < 0: kept by the default Stabilized).
  e.out->write(kForce) = {-1, 0};
  e.in->write(kDx) = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  e.in->write(kDforce) = std::vector<double>(12, 0.0);
  e.map->apply_djt(kDforce, kDx, 1.0);
  const std::vector<double> df = e.in->read(kDforce);
  EXPECT_NEAR(df[0], -s, 1e-16);
  EXPECT_NEAR(df[1], 0.0, 1e-16);
  EXPECT_NEAR(df[2], 0.0, 1e-16);
}

TEST(VolumeMapping, NeedsTetrahedra) {
  const auto errors =
      init_errors("<Node name='root'><MechanicalObject position='0 0 0  1 0 0  0 1 0'/>"
                  "<MeshTopology name='t' triangles='0 1 2'/><Node name='c'><MechanicalObject template='Vec1d'/>"
                  "<VolumeMapping topology='@../t'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "has no tetrahedra"));
}

TEST(CenterOfMassMapping, MassWeightedCentreOfTheFrames) {
  // Two frames of mass 2 (UniformMass): the centre is their mean.
  auto e = make("template='Rigid3d' position='1 0 0 0 0 0 1  3 4 -2 0 0 0.6 0.8'", "CenterOfMassMapping", "",
                "<UniformMass template='Rigid3d' vertexMass='2'/>", "position='9 9 9'");
  ASSERT_TRUE(e.map && e.map->state() == ComponentState::valid);
  auto* m = dynamic_cast<CenterOfMassMapping*>(e.map);
  EXPECT_DOUBLE_EQ(m->total_mass(), 4.0);
  EXPECT_EQ(e.out->read(kPosition), (std::vector<double>{2, 2, -1}));
  e.in->write(kVelocity) = {1, 0, 0, 5, 5, 5, 0, 2, 0, 7, 7, 7};
  e.map->apply_j(kVelocity, kVelocity);
  EXPECT_EQ(e.out->read(kVelocity), (std::vector<double>{0.5, 1, 0}));
  // Jᵀ: each frame's translation gets m_i/M of the force, its torque nothing.
  e.in->write(kForce) = std::vector<double>(12, 0.0);
  e.out->write(kForce) = {4, 0, -2};
  e.map->apply_jt(kForce, kForce);
  EXPECT_EQ(e.in->read(kForce), (std::vector<double>{2, 0, -1, 0, 0, 0, 2, 0, -1, 0, 0, 0}));
}

TEST(CenterOfMassMapping, NeedsAMassBesideItsInput) {
  const auto errors = init_errors(
      "<Node name='root'><MechanicalObject template='Rigid3d' position='0 0 0 0 0 0 1'/><Node name='c'>"
      "<MechanicalObject position='0 0 0'/><CenterOfMassMapping template='Rigid3d,Vec3d'/></Node></Node>");
  EXPECT_TRUE(test::any_contains(errors, "no mass in the input's node"));
}

}  // namespace
}  // namespace sinew
