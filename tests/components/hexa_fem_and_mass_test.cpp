// HexahedronFEMForceFieldAndMass: SOFA's element mass (8/27·ρ·vol on every
// node pair) and gravity on the physical lumped masses (ρ·vol/8 per corner).
#include <gtest/gtest.h>

#include "core/mechanical_ops.h"
#include "forcefield/hexahedron_fem_force_field.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace {

const char* kCube =
    "<Node dt=\"0.01\" gravity=\"0 -10 0\"><DefaultAnimationLoop/>"
    "<EulerImplicitSolver/><CGLinearSolver iterations=\"50\" tolerance=\"1e-12\" threshold=\"1e-20\"/>"
    "<RegularGridTopology n=\"2 2 2\" min=\"0 0 0\" max=\"1 1 1\"/><MechanicalObject name=\"dofs\"/>"
    "<HexahedronFEMForceFieldAndMass name=\"fem\" youngModulus=\"1000\" poissonRatio=\"0.3\" density=\"2\"%s/></Node>";

std::string cube(const char* extra = "") {
  char buf[1024];
  std::snprintf(buf, sizeof buf, kCube, extra);
  return buf;
}

TEST(HexahedronFEMForceFieldAndMass, GravityUsesTheLumpedPhysicalMass) {
  auto s = test::load(cube());
  auto* fem = test::get<HexahedronFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_NE(fem, nullptr);
  EXPECT_DOUBLE_EQ(fem->total(), 2.0);  // ρ·V
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  MechParams p;
  auto& f = mo->vec(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  fem->add_force(p);  // at rest: no elastic force, gravity only
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(f[3 * i + 1], -10 * 0.25, 1e-12);
    EXPECT_NEAR(f[3 * i], 0.0, 1e-12);
  }
}

TEST(HexahedronFEMForceFieldAndMass, ElementMassCouplesEveryNodePair) {
  auto s = test::load(cube());
  auto* fem = test::get<HexahedronFEMForceFieldAndMass>(*s.root, "fem");
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  const int dx = MechanicalOps::alloc_vec(), res = MechanicalOps::alloc_vec();
  auto& d = mo->vec(dx);
  for (std::size_t i = 0; i < 8; ++i) d[3 * i] = 1.0;  // unit x translation
  MechParams p;
  fem->add_mdx(p, res, dx, 0.5);
  const auto& r = mo->vec(res);
  const double block = 2.0 * 8.0 / 27.0;  // ρ·vol·8/27
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_NEAR(r[3 * i], 0.5 * 8 * block, 1e-12);  // every pair (i, j) contributes
    EXPECT_EQ(r[3 * i + 1], 0.0);
  }
  MatrixSink M;
  ASSERT_TRUE(fem->build_mass(M));
  double sum = 0;
  for (const auto& e : M.entries()) sum += e.value;
  EXPECT_NEAR(sum, 3 * 64 * block, 1e-9);  // 64 node pairs, 3 diagonal entries each
  EXPECT_FALSE(fem->is_diagonal());
}

TEST(HexahedronFEMForceFieldAndMass, LumpedMassIsTheRowSum) {
  auto s = test::load(cube(" lumpedMass=\"1\""));
  auto* fem = test::get<HexahedronFEMForceFieldAndMass>(*s.root, "fem");
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  const int dx = MechanicalOps::alloc_vec(), res = MechanicalOps::alloc_vec();
  auto& d = mo->vec(dx);
  d[4] = 3.0;  // point 1, y
  MechParams p;
  fem->add_mdx(p, res, dx, 1.0);
  const auto& r = mo->vec(res);
  EXPECT_NEAR(r[4], 3.0 * 8 * (2.0 * 8.0 / 27.0), 1e-12);
  EXPECT_EQ(r[1], 0.0);  // lumped: no coupling to other points
}

TEST(HexahedronFEMForceFieldAndMass, FallsUnderGravityWithoutDeforming) {
  auto s = test::load(cube());
  for (int i = 0; i < 5; ++i) animate(*s.root);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  const auto x = as_vec3(mo->vec(kPosition));
  // A free body under uniform gravity translates: all points move alike.
  for (std::size_t i = 1; i < 8; ++i) EXPECT_NEAR(x[i].y() - x[0].y(), (i & 2) ? 1.0 : 0.0, 1e-9);
  EXPECT_LT(x[0].y(), 0.0);
}

}  // namespace
}  // namespace sinew
