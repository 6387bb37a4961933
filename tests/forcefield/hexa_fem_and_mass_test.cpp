// HexahedronFEMForceFieldAndMass: SOFA's element mass (8/27·ρ·vol on every
// node pair) and gravity on the physical lumped masses (ρ·vol/8 per corner).
#include <gtest/gtest.h>

#include <cmath>

#include "core/mechanical_ops.h"
#include "forcefield/fem/hexahedron_fem_force_field.h"
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
  auto& f = mo->write(kForce);
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
  auto& d = mo->write(dx);
  for (std::size_t i = 0; i < 8; ++i) d[3 * i] = 1.0;  // unit x translation
  MechParams p;
  fem->add_mdx(p, res, dx, 0.5);
  const auto& r = mo->read(res);
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
  auto& d = mo->write(dx);
  d[4] = 3.0;  // point 1, y
  MechParams p;
  fem->add_mdx(p, res, dx, 1.0);
  const auto& r = mo->read(res);
  EXPECT_NEAR(r[4], 3.0 * 8 * (2.0 * 8.0 / 27.0), 1e-12);
  EXPECT_EQ(r[1], 0.0);  // lumped: no coupling to other points
}

TEST(HexahedronFEMForceFieldAndMass, FallsUnderGravityWithoutDeforming) {
  auto s = test::load(cube());
  for (int i = 0; i < 5; ++i) animate(*s.root);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  const auto x = as_vec3(mo->read(kPosition));
  // A free body under uniform gravity translates: all points move alike.
  for (std::size_t i = 1; i < 8; ++i) EXPECT_NEAR(x[i].y() - x[0].y(), (i & 2) ? 1.0 : 0.0, 1e-9);
  EXPECT_LT(x[0].y(), 0.0);
}

}  // namespace
}  // namespace sinew

namespace sinew {

// On a SparseGridTopology the element masses (matrix and gravity) and the
// element stiffnesses are scaled by the grid's filling coefficients
// (spec/mechanics.md §2.3, §2.4): 26 boundary cells at 0.5, one inner cell at 1.
TEST(HexahedronFEMForceFieldAndMass, SparseGridCoefficientsScaleMassAndStiffness) {
  const char* grid = R"(<SparseGridTopology name="g" n="4 4 4"
      position="-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1"
      triangles="0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7"/>)";
  auto with = [&](const char* topo) {
    return test::load(std::string("<Node dt=\"0.01\" gravity=\"0 -10 0\"><DefaultAnimationLoop/>") + topo +
                      "<MechanicalObject name=\"dofs\"/><HexahedronFEMForceFieldAndMass name=\"fem\" "
                      "youngModulus=\"1000\" poissonRatio=\"0.3\" density=\"2\"/></Node>");
  };
  auto sparse = with(grid);
  // The same 27 cells as a regular grid (no coefficients).
  auto regular = with(R"(<RegularGridTopology n="4 4 4" min="-1.02 -1.02 -1.02" max="1.02 1.02 1.02"/>)");
  auto* fs = test::get<HexahedronFEMForceFieldAndMass>(*sparse.root, "fem");
  auto* fr = test::get<HexahedronFEMForceFieldAndMass>(*regular.root, "fem");
  ASSERT_NE(fs, nullptr);
  ASSERT_NE(fr, nullptr);
  auto* ms = test::get<MechanicalObject>(*sparse.root, "dofs");
  auto* mr = test::get<MechanicalObject>(*regular.root, "dofs");
  ASSERT_EQ(ms->size(), mr->size());

  // Gravity: ρ·V·g over coefficient-weighted cells, (26·0.5 + 1)/27 of the regular total.
  MechParams p;
  auto total_weight = [&](HexahedronFEMForceFieldAndMass& fem, MechanicalObject& mo) {
    auto& f = mo.write(kForce);
    std::fill(f.begin(), f.end(), 0.0);
    fem.add_force(p);
    double sum = 0;
    for (std::size_t i = 0; i < mo.size(); ++i) sum += f[3 * i + 1];
    return sum;
  };
  const double ws = total_weight(*fs, *ms), wr = total_weight(*fr, *mr);
  EXPECT_NEAR(wr, -10 * 2 * std::pow(2.04, 3), 1e-9);
  EXPECT_NEAR(ws / wr, (26 * 0.5 + 1) / 27, 1e-12);

  // Stiffness and element mass of a boundary cell: half the regular grid's.
  const int dx = MechanicalOps::alloc_vec(), df = MechanicalOps::alloc_vec();
  for (auto* mo : {ms, mr}) {
    auto& d = mo->write(dx);
    d.assign(3 * mo->size(), 0.0);
    d[0] = 1e-3;  // corner point 0: only in boundary cell 0
    mo->write(df).assign(3 * mo->size(), 0.0);
  }
  p.dx = dx;
  p.df = df;
  fs->add_dforce(p, 1.0);
  fr->add_dforce(p, 1.0);
  EXPECT_NEAR(ms->read(df)[0] / mr->read(df)[0], 0.5, 1e-12);
  auto& rs = ms->write(df);
  auto& rr = mr->write(df);
  std::fill(rs.begin(), rs.end(), 0.0);
  std::fill(rr.begin(), rr.end(), 0.0);
  fs->add_mdx(p, df, dx, 1.0);
  fr->add_mdx(p, df, dx, 1.0);
  EXPECT_NEAR(rs[0] / rr[0], 0.5, 1e-12);
}

}  // namespace sinew
