// MeshMatrixMass (spec/mechanics.md §1.3).
#include "mass/mesh_matrix_mass.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numeric>
#include <stdexcept>

#include "core/mechanical_ops.h"
#include "forcefield/fem/tetra_fem.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

template <class T>
T& must(scene::LoadedScene& s, std::string_view name) {
  T* c = get<T>(*s.root, name);
  if (!c) throw std::runtime_error("missing component " + std::string(name));
  return *c;
}

std::string one_tet(const std::string& mass) {
  return R"(<Node gravity="0 0 -2">
    <TetrahedronSetTopologyContainer name="topo" position="0 0 0  2 0 0  0 3 0  0 0 1" tetrahedra="0 1 2 3"/>
    <MechanicalObject name="dofs"/>
    )" + mass + R"(
  </Node>)";
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

// Dense M (one spatial component) from build_mass.
Eigen::MatrixXd dense_mass(MeshMatrixMass& m, std::size_t n) {
  MatrixSink sink;
  EXPECT_TRUE(m.build_mass(sink));
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (const auto& e : sink.entries()) M(e.row, e.col) += e.value;
  return M;
}

}  // namespace

// Tetra: vertex ρV/10, edge ρV/20 (6 edges); total ρV.
TEST(MeshMatrixMass, TetraConsistentMassFromDensity) {
  auto s = load(one_tet(R"(<MeshMatrixMass name="mass" massDensity="3"/>)"));
  auto& m = must<MeshMatrixMass>(s, "mass");
  const double V = 1.0;  // 2·3·1/6
  ASSERT_EQ(m.vertex_mass.value().size(), 4u);
  for (double v : m.vertex_mass.value()) EXPECT_NEAR(v, 3 * V / 10, 1e-14);
  ASSERT_EQ(m.edge_mass.value().size(), 6u);
  for (double v : m.edge_mass.value()) EXPECT_NEAR(v, 3 * V / 20, 1e-14);
  EXPECT_NEAR(m.total(), 3 * V, 1e-12);
  EXPECT_FALSE(m.is_diagonal());
  // Consistent tetra mass: ρV/20·(1 + δij) per component.
  const Eigen::MatrixXd M = dense_mass(m, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(M(3 * i + 1, 3 * j + 1), 3 * V / 20 * (i == j ? 2 : 1), 1e-14);
}

// totalMass path: density inferred; gravity uses the lumped row sums c·vm = Σ_j M_ij.
TEST(MeshMatrixMass, TotalMassAndGravityRowSums) {
  auto s = load(one_tet(R"(<MeshMatrixMass name="mass" totalMass="5"/>)"));
  auto& m = must<MeshMatrixMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  EXPECT_DOUBLE_EQ(m.total(), 5.0);
  EXPECT_NEAR(sum(m.vertex_mass.value()) + 2 * sum(m.edge_mass.value()), 5.0, 1e-12);
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  const Eigen::MatrixXd M = dense_mass(m, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(mo.write(kForce)[3 * i + 2], -2 * M.row(3 * i + 2).sum(), 1e-12);
    EXPECT_NEAR(mo.write(kForce)[3 * i + 2], -2 * 2.5 * m.vertex_mass.value()[i], 1e-12);
  }
}

// add_mdx equals the assembled M times dx.
TEST(MeshMatrixMass, AddMdxMatchesAssembledMatrix) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <MeshMatrixMass name="mass" totalMass="7"/>
  </Node>)");
  auto& m = must<MeshMatrixMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  const std::size_t n = mo.size();
  ASSERT_EQ(n, 12u);
  EXPECT_NEAR(sum(m.vertex_mass.value()) + 2 * sum(m.edge_mass.value()), 7.0, 1e-12);
  // hexa: vertex ρV/20 per corner of each cell
  EXPECT_NEAR(m.vertex_mass.value()[0], 7.0 / 2 / 20 * 2.5 / 2.5, 1e-12);
  const Eigen::MatrixXd M = dense_mass(m, n);
  Eigen::VectorXd dx(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) dx[i] = std::sin(static_cast<double>(i));
  std::vector<double>& d = mo.write(kDx);
  for (std::size_t i = 0; i < 3 * n; ++i) d[i] = dx[i];
  std::vector<double>& r = mo.write(kDforce);
  std::fill(r.begin(), r.end(), 0.0);
  m.add_mdx(MechParams{}, kDforce, kDx, 0.3);
  const Eigen::VectorXd ref = 0.3 * M * dx;
  for (std::size_t i = 0; i < 3 * n; ++i) EXPECT_NEAR(r[i], ref[i], 1e-12);
  // M is symmetric and its total equals the mass.
  EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(M.sum() / 3, 7.0, 1e-12);
}

// Lumped: diagonal c·vm; accFromF inverts it.
TEST(MeshMatrixMass, LumpedMassIsDiagonal) {
  auto s = load(one_tet(R"(<MeshMatrixMass name="mass" totalMass="2" lumping="true"/>)"));
  auto& m = must<MeshMatrixMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  EXPECT_TRUE(m.is_diagonal());
  for (double v : m.vertex_mass.value()) EXPECT_NEAR(2.5 * v, 0.5, 1e-12);
  for (double v : m.edge_mass.value()) EXPECT_EQ(v, 0.0);
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  m.acc_from_f(MechParams{}, kDx, kForce);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(mo.write(kDx)[3 * i + 2], -2.0, 1e-12);
}

// Non-lumped accFromF is refused with an error (as SOFA).
TEST(MeshMatrixMass, AccFromFNeedsLumping) {
  auto s = load(one_tet(R"(<MeshMatrixMass name="mass" totalMass="2"/>)"));
  auto& m = must<MeshMatrixMass>(s, "mass");
  m.acc_from_f(MechParams{}, kDx, kForce);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "lumping"));
}

// Triangles: ρA/6 per vertex, ρA/12 per edge.
TEST(MeshMatrixMass, TriangleShares) {
  auto s = load(R"(<Node>
    <TriangleSetTopologyContainer name="topo" position="0 0 0  2 0 0  0 3 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <MeshMatrixMass name="mass" massDensity="2"/>
  </Node>)");
  auto& m = must<MeshMatrixMass>(s, "mass");
  for (double v : m.vertex_mass.value()) EXPECT_NEAR(v, 2 * 3.0 / 6, 1e-14);
  for (double v : m.edge_mass.value()) EXPECT_NEAR(v, 2 * 3.0 / 12, 1e-14);
  EXPECT_NEAR(m.total(), 6.0, 1e-12);
}
