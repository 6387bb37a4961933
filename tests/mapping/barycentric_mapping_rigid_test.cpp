// BarycentricMapping Vec3d → Rigid3d (SOFA's BarycentricMapperTetrahedronSetTopologyRigid):
// frames embedded in tetrahedra, on hand-derived values. J and Jᵀ are SOFA's
// (ω = Σ x_k × v_k over the tetrahedron's vertices, not the derivative of apply).
#include "mapping/linear/barycentric_mapping_rigid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_scene.h"

namespace sinew {
namespace {

// The unit tetrahedron (0..3) and a second one (1, 2, 3, 4) beyond its slanted face.
// Frame 0 sits inside tetrahedron 0, frame 1 (turned 90° about z) inside tetrahedron 1,
// frame 2 outside both (nearest centroid: tetrahedron 0).
scene::LoadedScene embedded(const std::string& topology = "TetrahedronSetTopologyContainer") {
  return test::load(R"(<Node name="root" gravity="0 0 0">
    <)" + topology + R"( name="tets" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1" tetrahedra="0 1 2 3  1 2 3 4"/>
    <MechanicalObject name="in" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1"/>
    <Node name="child">
      <MechanicalObject name="out" template="Rigid3d"
          position="0.25 0.25 0.25 0 0 0 1  0.6 0.6 0.6 0 0 0.7071067811865476 0.7071067811865476  -1 -1 -1 0 0 0 1"/>
      <BarycentricMapping name="map" input="@../in" output="@out"/>
    </Node>
  </Node>)");
}

struct Parts {
  MechanicalState *in, *out;
  BarycentricMappingRigid* map;
};
Parts parts(const scene::LoadedScene& s) {
  Node& child = *s.root->find_child_named("child");
  return {test::get<MechanicalState>(*s.root, "in"), test::get<MechanicalState>(child, "out"),
          test::get<BarycentricMappingRigid>(child, "map")};
}

TEST(BarycentricMappingRigid, ChosenForAVec3dToRigid3dPair) {
  auto s = embedded();
  auto [in, out, map] = parts(s);
  ASSERT_NE(map, nullptr) << "BarycentricMapping between Vec3d and Rigid3d states is not the rigid mapper";
  EXPECT_EQ(map->template_name(), "Vec3d,Rigid3d");
  EXPECT_EQ(map->class_name(), "BarycentricMapping");
  ASSERT_EQ(map->state(), ComponentState::valid);
}

TEST(BarycentricMappingRigid, EmbedsCentresAndAxesInTheNearestTetrahedron) {
  auto s = embedded();
  const auto& e = parts(s).map->embeddings();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].tetra, 0u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[0].bary[k], 0.25, 1e-15);
  // Edge basis of tetrahedron 0 = identity: the axes are the frame's own (identity).
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[0].axis[c][k], c == k ? 1.0 : 0.0, 1e-15);
  // Frame 1 lies in tetrahedron 1 (edges (−1,1,0), (−1,0,1), (0,1,1) from vertex 1).
  EXPECT_EQ(e[1].tetra, 1u);
  // (0.6,0.6,0.6) − (1,0,0) = −0.4·(−1,1,0)... solved by hand: coordinates (0.2, 0.2, 0.4).
  EXPECT_NEAR(e[1].bary[0], 0.2, 1e-15);
  EXPECT_NEAR(e[1].bary[1], 0.2, 1e-15);
  EXPECT_NEAR(e[1].bary[2], 0.4, 1e-15);
  EXPECT_EQ(e[2].tetra, 0u);  // outside both; centroid of 0 (0.25³) is nearer than that of 1 (0.5, 0.5, 0.5)
}

TEST(BarycentricMappingRigid, FramesFollowTheTetrahedron) {
  auto s = embedded();
  auto [in, out, map] = parts(s);
  // At rest the frames are reproduced.
  map->apply(kPosition);
  const std::vector<double> rest = {0.25, 0.25, 0.25, 0, 0, 0, 1};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(out->read(kPosition)[k], rest[k], 1e-15) << k;
  // Stretching tetrahedron 0 along x (vertex 1 to (2, 0, 0)): the centre moves, the rotation does not.
  in->write(kPosition)[3] = 2;
  map->apply(kPosition);
  const std::vector<double> stretched = {0.5, 0.25, 0.25, 0, 0, 0, 1};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(out->read(kPosition)[k], stretched[k], 1e-12) << k;
  // Turning the whole mesh 90° about z: (x, y, z) → (−y, x, z); frame 0 turns with it.
  std::vector<double>& x = in->write(kPosition);
  x = {0, 0, 0, 0, 1, 0, -1, 0, 0, 0, 0, 1, -1, 1, 1};
  map->apply(kPosition);
  const std::vector<double>& y = out->read(kPosition);
  const double h = std::sqrt(0.5);
  const std::vector<double> turned = {-0.25, 0.25, 0.25, 0, 0, h, h};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(y[k], turned[k], 1e-12) << k;
  // Frame 1 (turned 90° about z at rest) is now turned 180°: q = (0, 0, 1, 0) up to sign.
  EXPECT_NEAR(std::abs(y[7 + 5]), 1.0, 1e-12);
  EXPECT_NEAR(y[7 + 6], 0.0, 1e-12);
}

TEST(BarycentricMappingRigid, SofasJacobianAndItsTranspose) {
  auto s = embedded();
  auto [in, out, map] = parts(s);
  map->apply(kPosition);
  // Vertex 1 (at (1, 0, 0)) moving along y: v = 0.25·(0, 1, 0), ω = x_1 × v_1 = (0, 0, 1).
  in->write(kVelocity) = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  map->apply_j(kVelocity, kVelocity);
  const std::vector<double>& v = out->read(kVelocity);
  const std::vector<double> want = {0, 0.25, 0, 0, 0, 1};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(v[k], want[k], 1e-15) << k;
  // A torque τ = (0, 0, 1) on frame 0 pushes each vertex by τ × x_k; a force by the weights.
  out->write(kForce) = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  in->write(kForce) = std::vector<double>(15, 0.0);
  map->apply_jt(kForce, kForce);
  const std::vector<double>& f = in->read(kForce);
  const std::vector<double> fw = {0.5, 0, 0,  0.5, 1, 0,  -0.5, 0, 0,  0.5, 0, 0,  0, 0, 0};
  for (int k = 0; k < 15; ++k) EXPECT_NEAR(f[k], fw[k], 1e-15) << k;
  // Constraint rows carry only the translation part (SOFA's applyJT on constraint matrices).
  ConstraintMatrix& rows = out->constraint_jacobian();
  rows.clear(6);
  const double row[6] = {2, 0, 0, 0, 0, 1};
  rows.add(0, 0, row);
  in->constraint_jacobian().clear(3);
  ASSERT_TRUE(map->apply_jt_constraints());
  ConstraintMatrix& mapped = in->constraint_jacobian();
  mapped.compress();
  ASSERT_EQ(mapped.rows().size(), 1u);
  ASSERT_EQ(mapped.entries().size(), 4u);
  for (int e = 0; e < 4; ++e) {
    EXPECT_EQ(mapped.entries()[e].dof, e);
    EXPECT_NEAR(mapped.value(e)[0], 0.5, 1e-15);
    EXPECT_EQ(mapped.value(e)[1], 0.0);
  }
}

TEST(BarycentricMappingRigid, OtherInputTopologiesAreRefused) {
  auto s = embedded("MeshTopology");
  EXPECT_EQ(parts(s).map->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "must be a TetrahedronSetTopologyContainer"));
}

}  // namespace
}  // namespace sinew
