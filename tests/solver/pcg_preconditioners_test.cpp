// Preconditioners against their mathematical definitions on small assembled
// matrices (spec/solvers.md §4.1–§4.3): Jacobi z = D⁻¹r, block-Jacobi
// z_b = A_bb⁻¹ r_b, SSOR z = (2−ω)·[(D/ω+U)(D/ω)⁻¹(D/ω+L)]⁻¹ r (scalar CRS;
// the 3×3 block variant has no (2−ω) factor).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/registry.h"
#include "math/block_csr.h"
#include "solver/preconditioner/block_jacobi_preconditioner.h"
#include "solver/preconditioner/jacobi_preconditioner.h"
#include "solver/system/matrix_linear_system.h"
#include "solver/preconditioner/ssor_preconditioner.h"
#include "test_scene.h"

using namespace sinew;

namespace {

Eigen::MatrixXd random_spd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pick(0.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (pick(rng) < 0.3) A(i, j) = A(j, i) = u(rng);
  for (int i = 0; i < n; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 0.5 + 3.0 * pick(rng);
  return A;
}

Eigen::VectorXd random_vec(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = g(rng);
  return v;
}

void fill(BlockCsrMatrix& M, const Eigen::MatrixXd& A, int bs) {
  const std::size_t n = static_cast<std::size_t>(A.rows());
  M.reset(n, bs);
  std::vector<std::uint64_t> keys;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (A(i, j) != 0.0) keys.push_back((static_cast<std::uint64_t>(i) << 32) | j);
  M.build_pattern(keys);
  for (std::uint64_t k : keys) M.values()[M.slot(k >> 32, k & 0xffffffffu)] += A(k >> 32, k & 0xffffffffu);
}

// z = P⁻¹ r through the solver's public interface (invert once, then solve).
Eigen::VectorXd apply(MatrixLinearSolver& s, MatrixLinearSystem& sys, const Eigen::MatrixXd& A, int bs,
                      const Eigen::VectorXd& r) {
  s.linear_system.set(&sys);
  fill(sys.matrix(), A, bs);
  sys.factorization_invalidation.set(true);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(r.size());
  s.solve_global(z, r);
  EXPECT_FALSE(sys.matrix_changed());
  return z;
}

Eigen::VectorXd ssor_reference(const Eigen::MatrixXd& A, double w, const Eigen::VectorXd& r, bool scale) {
  const Eigen::MatrixXd D = A.diagonal().asDiagonal();
  const Eigen::MatrixXd L = A.triangularView<Eigen::StrictlyLower>();
  const Eigen::MatrixXd U = A.triangularView<Eigen::StrictlyUpper>();
  const Eigen::MatrixXd M = (D / w + U) * (D / w).inverse() * (D / w + L);
  Eigen::VectorXd z = M.lu().solve(r);
  if (scale) z *= (2 - w);
  return z;
}

}  // namespace

TEST(PcgJacobi, IsTheInverseDiagonal) {
  const Eigen::MatrixXd A = random_spd(15, 1);
  const Eigen::VectorXd r = random_vec(15, 2);
  JacobiPreconditioner p;
  MatrixLinearSystem sys;
  const Eigen::VectorXd z = apply(p, sys, A, 1, r);
  const Eigen::VectorXd ref = r.cwiseQuotient(A.diagonal());
  EXPECT_LT((z - ref).norm(), 1e-15 * ref.norm());
  // Invert runs once per assembly: a second solve reuses it.
  Eigen::VectorXd z2 = Eigen::VectorXd::Zero(15);
  p.solve_global(z2, r);
  EXPECT_EQ((z2 - z).norm(), 0.0);
}

TEST(PcgBlockJacobi, IsTheInverseOfThe3x3DiagonalBlocks) {
  const Eigen::MatrixXd A = random_spd(18, 3);
  const Eigen::VectorXd r = random_vec(18, 4);
  BlockJacobiPreconditioner p;
  MatrixLinearSystem sys;
  const Eigen::VectorXd z = apply(p, sys, A, 3, r);
  Eigen::VectorXd ref(18);
  for (int b = 0; b < 6; ++b) ref.segment<3>(3 * b) = A.block<3, 3>(3 * b, 3 * b).inverse() * r.segment<3>(3 * b);
  EXPECT_LT((z - ref).norm(), 1e-13 * ref.norm());
}

TEST(PcgBlockJacobi, ClosedFormInverse) {
  Mat3 m;
  m << 4, 1, 0.5, 1, 3, -1, 0.5, -1, 5;
  Mat3 inv;
  ASSERT_TRUE(BlockJacobiPreconditioner::invert3(m, inv));
  EXPECT_LT((inv * m - Mat3::Identity()).norm(), 1e-14);
  EXPECT_FALSE(BlockJacobiPreconditioner::invert3(Mat3::Zero(), inv));
}

TEST(PcgSSOR, ScalarSweepsMatchTheDefinition) {
  for (double w : {1.0, 1.3, 0.7}) {
    const Eigen::MatrixXd A = random_spd(20, 5);
    const Eigen::VectorXd r = random_vec(20, 6);
    SSORPreconditioner p;
    p.omega.set(w);
    MatrixLinearSystem sys;
    const Eigen::VectorXd z = apply(p, sys, A, 1, r);
    const Eigen::VectorXd ref = ssor_reference(A, w, r, true);
    EXPECT_LT((z - ref).norm(), 1e-12 * ref.norm()) << "omega=" << w;
  }
}

TEST(PcgSSOR, BlockSweepsMatchTheDefinitionWithoutScaling) {
  for (double w : {1.0, 1.3}) {
    const Eigen::MatrixXd A = random_spd(21, 7);
    const Eigen::VectorXd r = random_vec(21, 8);
    SSORPreconditioner p;
    p.omega.set(w);
    MatrixLinearSystem sys;
    const Eigen::VectorXd z = apply(p, sys, A, 3, r);
    const Eigen::VectorXd ref = ssor_reference(A, w, r, false);  // SOFA's block variant omits (2 − ω)
    EXPECT_LT((z - ref).norm(), 1e-12 * ref.norm()) << "omega=" << w;
  }
}

TEST(PcgPreconditioners, ZeroDiagonalIsReported) {
  Eigen::MatrixXd A = random_spd(6, 9);
  A(2, 2) = 0.0;
  auto s = test::build("<Node name='root'><JacobiPreconditioner name='j'/></Node>");
  init_root(*s.root);
  auto* p = test::get<JacobiPreconditioner>(*s.root, "j");
  ASSERT_NE(p, nullptr);
  MatrixLinearSystem sys;
  apply(*p, sys, A, 1, random_vec(6, 1));
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "zero diagonal"));
}

TEST(PcgPreconditioners, RegisteredWithSofaNamesAndAliases) {
  register_all_components();
  for (const char* name : {"JacobiPreconditioner", "JacobiLinearSolver", "BlockJacobiPreconditioner",
                           "SSORPreconditioner", "SSORSolver", "WarpPreconditioner", "PrecomputedWarpPreconditioner",
                           "PCGLinearSolver", "MinResLinearSolver", "MINRESSolver", "PreconditionedMatrixFreeSystem",
                           "RotationMatrixSystem", "PrecomputedMatrixSystem", "CompositeLinearSystem"})
    EXPECT_NE(registry().find(name), nullptr) << name;
  EXPECT_EQ(renamed_component("ShewchukPCGLinearSolver"), "PCGLinearSolver");
}
