// Assembled linear systems and direct solvers (spec/solvers.md §2–§3):
// every matrix solver against a dense reference solve on random SPD systems,
// block storage against dense products, ordering effects on fill-in, and
// error reporting on singular systems.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/node.h"
#include "core/registry.h"
#include "math/block_csr.h"
#include "solver/linear/amd_ordering_method.h"
#include "solver/linear/assembled_cg_linear_solver.h"
#include "solver/linear/btd_linear_solver.h"
#include "solver/linear/colamd_ordering_method.h"
#include "solver/linear/eigen_simplicial_ldlt.h"
#include "solver/linear/eigen_simplicial_llt.h"
#include "solver/linear/eigen_sparse_lu.h"
#include "solver/linear/eigen_sparse_qr.h"
#include "solver/system/matrix_linear_system.h"
#include "solver/linear/metis_ordering_method.h"
#include "solver/linear/natural_ordering_method.h"
#include "solver/linear/sparse_ldl_solver.h"
#include "linsys_helpers.h"
#include "test_scene.h"

using namespace sinew;

namespace {

using test::fill;
using test::random_spd;

// A solver driven without a scene: its own system, filled by hand.
struct Standalone {
  std::unique_ptr<MatrixLinearSystem> system = std::make_unique<MatrixLinearSystem>();
  std::unique_ptr<OrderingMethod> ordering;
  std::unique_ptr<MatrixLinearSolver> solver;

  Standalone(std::unique_ptr<MatrixLinearSolver> s, std::unique_ptr<OrderingMethod> o) : ordering(std::move(o)),
                                                                                        solver(std::move(s)) {
    solver->linear_system.set(system.get());
    if (auto* ldl = dynamic_cast<SparseLDLSolver*>(solver.get())) ldl->ordering_method.set(ordering.get());
    if (auto* e = dynamic_cast<EigenDirectSolver*>(solver.get())) e->ordering_method.set(ordering.get());
    solver->init();
  }
  Eigen::VectorXd solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, int bs) {
    fill(system->matrix(), A, bs);
    system->factorization_invalidation.set(true);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    solver->solve_global(x, b);
    return x;
  }
};

std::unique_ptr<OrderingMethod> make_ordering(const std::string& name) {
  if (name == "Natural") return std::make_unique<NaturalOrderingMethod>();
  if (name == "AMD") return std::make_unique<AMDOrderingMethod>();
  if (name == "COLAMD") return std::make_unique<COLAMDOrderingMethod>();
  return std::make_unique<MetisOrderingMethod>();
}

std::unique_ptr<MatrixLinearSolver> make_solver(const std::string& name) {
  if (name == "SparseLDLSolver") return std::make_unique<SparseLDLSolver>();
  if (name == "EigenSimplicialLDLT") return std::make_unique<EigenSimplicialLDLT>();
  if (name == "EigenSimplicialLLT") return std::make_unique<EigenSimplicialLLT>();
  if (name == "EigenSparseLU") return std::make_unique<EigenSparseLU>();
  if (name == "EigenSparseQR") return std::make_unique<EigenSparseQR>();
  if (name == "BTDLinearSolver") return std::make_unique<BTDLinearSolver>();
  auto cg = std::make_unique<AssembledCGLinearSolver>();
  cg->iterations.set(1000);
  cg->tolerance.set(1e-14);
  cg->threshold.set(1e-300);
  return cg;
}

}  // namespace

// ---------------------------------------------------------------- BlockCsrMatrix

TEST(LinsysBlockCsr, ProductMatchesDenseForScalarAndBlockStorage) {
  for (int bs : {1, 3}) {
    const Eigen::MatrixXd A = random_spd(24, 7u + bs);
    BlockCsrMatrix M;
    fill(M, A, bs);
    EXPECT_EQ(M.block_size(), bs);
    EXPECT_TRUE(M.to_dense().isApprox(A, 0.0));
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(24, -1.0, 2.0), y(24);
    M.mult(x.data(), y.data());
    EXPECT_LT((y - A * x).norm(), 1e-12 * (A * x).norm());
  }
}

TEST(LinsysBlockCsr, DirichletClearsRowAndColumnAndSetsDiagonal) {
  for (int bs : {1, 3}) {
    Eigen::MatrixXd A = random_spd(12, 3u);
    BlockCsrMatrix M;
    fill(M, A, bs);
    M.clear_row_col_set_diag(4, 1.0);
    A.row(4).setZero();
    A.col(4).setZero();
    A(4, 4) = 1.0;
    EXPECT_TRUE(M.to_dense().isApprox(A, 0.0)) << "bs=" << bs;
    // Zeros created by the clearing are not in the filtered copy.
    std::vector<int> rb, ci;
    std::vector<double> v;
    M.to_filtered_csr(rb, ci, v);
    EXPECT_EQ(rb[5] - rb[4], 1);
    for (double x : v) EXPECT_NE(x, 0.0);
  }
}

TEST(LinsysBlockCsr, StructureFiltersDropOffDiagonalEntries) {
  const Eigen::MatrixXd A = random_spd(9, 11u, 0.9);
  BlockCsrMatrix D;
  D.reset(9, 1, BlockCsrMatrix::Structure::diagonal);
  std::vector<std::uint64_t> keys;
  for (std::uint64_t i = 0; i < 9; ++i)
    for (std::uint64_t j = 0; j < 9; ++j) keys.push_back((i << 32) | j);
  D.build_pattern(keys);
  EXPECT_EQ(D.nnz_blocks(), 9u);
  EXPECT_EQ(D.slot(0, 1), -1);
  BlockCsrMatrix B;
  B.reset(9, 3, BlockCsrMatrix::Structure::block_diagonal);
  B.build_pattern(keys);
  EXPECT_EQ(B.nnz_blocks(), 3u);
  EXPECT_GE(B.slot(1, 2), 0);
  EXPECT_EQ(B.slot(2, 3), -1);
}

// ---------------------------------------------------------------- solvers vs dense reference

class LinsysSolverAccuracy : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(LinsysSolverAccuracy, MatchesDenseSolveOnRandomSpdSystems) {
  const auto& [solver_name, ordering_name] = GetParam();
  for (int bs : {1, 3})
    for (int n : {3, 12, 48, 150}) {
      const Eigen::MatrixXd A = random_spd(n, static_cast<unsigned>(n * 31 + bs));
      Eigen::VectorXd b(n);
      std::mt19937 rng(static_cast<unsigned>(n));
      std::normal_distribution<double> g;
      for (int i = 0; i < n; ++i) b[i] = g(rng);
      const Eigen::VectorXd ref = A.ldlt().solve(b);
      Standalone s(make_solver(solver_name), make_ordering(ordering_name));
      const Eigen::VectorXd x = s.solve(A, b, bs);
      ASSERT_EQ(x.size(), n);
      EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm()) << solver_name << "/" << ordering_name << " n=" << n
                                                       << " bs=" << bs;
      // A second factorization with different values and the same pattern (symbolic part reused).
      const Eigen::MatrixXd A2 = A * 2.0;
      const Eigen::VectorXd x2 = s.solve(A2, b, bs);
      EXPECT_LT((x2 - ref * 0.5).norm(), 1e-10 * ref.norm());
    }
}

INSTANTIATE_TEST_SUITE_P(
    All, LinsysSolverAccuracy,
    ::testing::Values(std::make_tuple("SparseLDLSolver", "Natural"), std::make_tuple("SparseLDLSolver", "AMD"),
                      std::make_tuple("SparseLDLSolver", "COLAMD"), std::make_tuple("SparseLDLSolver", "Metis"),
                      std::make_tuple("EigenSimplicialLDLT", "Natural"), std::make_tuple("EigenSimplicialLDLT", "AMD"),
                      std::make_tuple("EigenSimplicialLLT", "Natural"), std::make_tuple("EigenSimplicialLLT", "Metis"),
                      std::make_tuple("EigenSparseLU", "Natural"), std::make_tuple("EigenSparseLU", "COLAMD"),
                      std::make_tuple("EigenSparseQR", "Natural"), std::make_tuple("EigenSparseQR", "AMD"),
                      std::make_tuple("CGLinearSolver", "Natural")),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

TEST(LinsysSparseLDL, SymbolicFactorizationRecomputedOnlyWhenPatternChanges) {
  Standalone s(make_solver("SparseLDLSolver"), make_ordering("AMD"));
  auto* ldl = static_cast<SparseLDLSolver*>(s.solver.get());
  Eigen::MatrixXd A = random_spd(30, 5u);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(30);
  s.solve(A, b, 1);
  s.solve(A * 3.0, b, 1);
  EXPECT_EQ(ldl->symbolic_count(), 1);
  A(0, 29) = A(29, 0) = 0.25;  // new entries: new pattern
  A(0, 0) += 1.0;
  const Eigen::VectorXd x = s.solve(A, b, 1);
  EXPECT_EQ(ldl->symbolic_count(), 2);
  EXPECT_LT((x - A.ldlt().solve(b)).norm(), 1e-10 * x.norm());
}

// ---------------------------------------------------------------- ordering and fill-in

TEST(LinsysOrdering, FillReducingOrderingsBeatNaturalOnAShuffledGrid) {
  // 2D 5-point Laplacian on a 20×20 grid, unknowns randomly renumbered.
  const int g = 20, n = g * g;
  std::vector<int> relabel(n);
  for (int i = 0; i < n; ++i) relabel[i] = i;
  std::shuffle(relabel.begin(), relabel.end(), std::mt19937(42));
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < g; ++i)
    for (int j = 0; j < g; ++j) {
      const int p = relabel[i * g + j];
      A(p, p) = 4.5;
      if (i + 1 < g) A(p, relabel[(i + 1) * g + j]) = A(relabel[(i + 1) * g + j], p) = -1;
      if (j + 1 < g) A(p, relabel[i * g + j + 1]) = A(relabel[i * g + j + 1], p) = -1;
    }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Eigen::VectorXd ref = A.ldlt().solve(b);
  std::map<std::string, int> fill_in;
  for (const char* o : {"Natural", "AMD", "COLAMD", "Metis"}) {
    Standalone s(make_solver("SparseLDLSolver"), make_ordering(o));
    const Eigen::VectorXd x = s.solve(A, b, 1);
    EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm()) << o;
    fill_in[o] = static_cast<SparseLDLSolver*>(s.solver.get())->l_nnz.value();
  }
  EXPECT_LT(fill_in["AMD"] * 3, fill_in["Natural"]);
  EXPECT_LT(fill_in["Metis"] * 3, fill_in["Natural"]);
  // COLAMD orders the columns of AᵀA: not fill-reducing for LDLᵀ, only checked for correctness above.
}

TEST(LinsysOrdering, NaturalIsIdentityAndOthersArePermutations) {
  const Eigen::MatrixXd A = random_spd(40, 9u);
  BlockCsrMatrix M;
  fill(M, A, 1);
  std::vector<int> rb, ci;
  std::vector<double> v;
  M.to_filtered_csr(rb, ci, v);
  for (const char* o : {"Natural", "AMD", "COLAMD", "Metis"}) {
    std::vector<int> perm;
    make_ordering(o)->compute_permutation(40, rb.data(), ci.data(), perm);
    ASSERT_EQ(perm.size(), 40u);
    std::vector<int> sorted = perm;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < 40; ++i) EXPECT_EQ(sorted[i], i) << o;
    if (std::string(o) == "Natural") {
      for (int i = 0; i < 40; ++i) EXPECT_EQ(perm[i], i);
    }
  }
}

// ---------------------------------------------------------------- failures are reported

TEST(LinsysSingular, ZeroPivotIsAnErrorAndTheSolutionStaysFinite) {
  Eigen::MatrixXd A = random_spd(6, 1u);
  A.row(2).setZero();
  A.col(2).setZero();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(6);
  for (const char* name : {"SparseLDLSolver", "EigenSimplicialLLT", "EigenSimplicialLDLT"}) {
    Node root("root");
    Standalone s(make_solver(name), make_ordering("Natural"));
    s.solver->set_node(&root);
    s.solver->set_type(name, "CompressedRowSparseMatrixd");
    const int before = root.diagnostics().error_count();
    const Eigen::VectorXd x = s.solve(A, b, 1);
    EXPECT_GT(root.diagnostics().error_count(), before) << name;
    EXPECT_TRUE(x.allFinite()) << name;
  }
}

TEST(LinsysSingular, IndefiniteMatrixIsRejectedByCholesky) {
  Eigen::MatrixXd A = random_spd(8, 2u);
  A(3, 3) = -A(3, 3);
  Node root("root");
  Standalone s(make_solver("EigenSimplicialLLT"), make_ordering("AMD"));
  s.solver->set_node(&root);
  const Eigen::VectorXd x = s.solve(A, Eigen::VectorXd::Ones(8), 1);
  EXPECT_GT(root.diagnostics().error_count(), 0);
  EXPECT_TRUE(x.allFinite());
  EXPECT_EQ(x.norm(), 0.0);
}

// ---------------------------------------------------------------- BTDLinearSolver (§3.8)

TEST(LinsysBTD, BlockThomasMatchesDenseSolveOnBlockTridiagonalSystems) {
  for (int nb : {1, 2, 8}) {
    const int n = 6 * nb;
    Eigen::MatrixXd A = random_spd(n, static_cast<unsigned>(nb), 0.9);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (std::abs(i / 6 - j / 6) > 1) A(i, j) = 0.0;
    for (int i = 0; i < n; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 1.0;  // keep it SPD
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0);
    Standalone s(make_solver("BTDLinearSolver"), make_ordering("Natural"));
    const Eigen::VectorXd x = s.solve(A, b, 6);
    const Eigen::VectorXd ref = A.ldlt().solve(b);
    EXPECT_LT((x - ref).norm(), 1e-10 * ref.norm()) << "blocks=" << nb;
  }
}

TEST(LinsysBTD, DiagonalBlocksAreInvertedEntryWise) {
  BTDLinearSolver::Block d = BTDLinearSolver::Block::Zero();
  for (int i = 0; i < 6; ++i) d(i, i) = 1.0 + i;
  const BTDLinearSolver::Block inv = BTDLinearSolver::invert_block(d);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(inv(i, i), 1.0 / (1.0 + i));
  d(0, 5) = 0.5;  // not diagonal any more: full inverse
  EXPECT_LT((BTDLinearSolver::invert_block(d) * d - BTDLinearSolver::Block::Identity()).norm(), 1e-14);
}

TEST(LinsysBlockCsr, BlockTridiagonalStructureKeepsThreeBlockDiagonals) {
  BlockCsrMatrix M;
  M.reset(24, 6, BlockCsrMatrix::Structure::block_tridiagonal);
  std::vector<std::uint64_t> keys;
  for (std::uint64_t i = 0; i < 24; ++i)
    for (std::uint64_t j = 0; j < 24; ++j) keys.push_back((i << 32) | j);
  M.build_pattern(keys);
  EXPECT_EQ(M.nnz_blocks(), 4u + 3u + 3u);
  EXPECT_GE(M.slot(6, 12), 0);
  EXPECT_EQ(M.slot(0, 12), -1);
}

// SOFA's BTDMatrix stores block (bi, bj) at 3·bi + (bj − bi + 1) and refuses
// only bj > bi + 1: an entry left of the band is written into another block of
// its array (BeamFEMForceField.scn's floor contacts depend on it).
TEST(LinsysBlockCsr, BlockTridiagonalEntriesLeftOfTheBandLandWhereSofasBtdMatrixPutsThem) {
  BlockCsrMatrix M;
  M.reset(24, 6, BlockCsrMatrix::Structure::block_tridiagonal);  // 4 block rows
  std::vector<std::uint64_t> keys;
  for (std::uint64_t i = 0; i < 24; ++i)
    for (std::uint64_t j = 0; j < 24; ++j) keys.push_back((i << 32) | j);
  M.build_pattern(keys);
  EXPECT_EQ(M.nnz_blocks(), 10u);  // nothing but the band is stored
  // (2, 0): index 3·2 − 1 = 5, block (1, 2); inner (1, 4) stays.
  EXPECT_EQ(M.slot(13, 4), M.slot(7, 16));
  // (3, 0): index 7, block (2, 2).
  EXPECT_EQ(M.slot(18, 0), M.slot(12, 12));
  // (3, 1): index 8, block (2, 3).
  EXPECT_EQ(M.slot(20, 9), M.slot(14, 21));
  // Rows below the matrix still land inside the array: (4, 1) is index 10, block (3, 3).
  EXPECT_EQ(M.slot(24, 6), M.slot(18, 18));
  // Index 11 is the unused slot (3, 4); 12 and beyond are past SOFA's array.
  EXPECT_EQ(M.slot(24, 12), -1);
  EXPECT_EQ(M.slot(30, 6), -1);
  // Right of the band: refused, as SOFA's add().
  EXPECT_EQ(M.slot(0, 12), -1);
  // Values added through the slots sum in the target block.
  M.set_zero();
  M.values()[M.slot(18, 0)] += 2.0;
  M.values()[M.slot(12, 12)] += 0.5;
  EXPECT_EQ(M.coeff(12, 12), 2.5);
  EXPECT_EQ(M.coeff(18, 0), 2.5);  // read through the same storage
}

// ---------------------------------------------------------------- constraint-correction product (§3.0)

TEST(LinsysCompliance, JMinvJtMatchesDenseProduct) {
  const Eigen::MatrixXd A = random_spd(18, 77u);
  Eigen::MatrixXd Jd = Eigen::MatrixXd::Zero(4, 18);
  Jd(0, 1) = 1.0;
  Jd(0, 7) = -0.5;
  Jd(2, 3) = 2.0;  // row 1 and 3 empty
  Jd(2, 17) = 0.25;
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> J = Jd.sparseView();
  for (const char* name : {"SparseLDLSolver", "EigenSparseLU"}) {
    Standalone s(make_solver(name), make_ordering("AMD"));
    fill(s.system->matrix(), A, 3);
    s.system->factorization_invalidation.set(true);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(4, 4);
    s.solver->add_jminvjt(W, J, 0.5);
    const Eigen::MatrixXd ref = 0.5 * Jd * A.inverse() * Jd.transpose();
    EXPECT_LT((W - ref).norm(), 1e-12 * ref.norm()) << name;
  }
}

// Each Eigen solver runs its own factorization. The four solver files once
// named their Eigen type alias `Impl` alike, and GCC's weak symbols for
// make_eigen_factorization<Impl> made the linker keep one factorization for
// several solvers (EigenSparseQR ran SparseLU in Release builds; at -O1
// EigenSimplicialLLT ran LDLᵀ). A singular, consistent system tells them apart:
// LU stops on the zero pivot, QR (rank-revealing) solves it.
TEST(LinsysEigen, EachSolverRunsItsOwnFactorization) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 1, 0,  //
      1, 1, 0,   //
      0, 0, 1;   // rows 1 and 2 equal: rank 2, an exact zero pivot for LU
  const Eigen::VectorXd b = A * Eigen::Vector3d(1, -1, 2);  // consistent
  {
    Node root("root");
    Standalone s(make_solver("EigenSparseQR"), make_ordering("COLAMD"));
    s.solver->set_node(&root);
    const Eigen::VectorXd x = s.solve(A, b, 1);
    EXPECT_EQ(root.diagnostics().error_count(), 0) << "SparseQR solves a consistent rank-deficient system";
    EXPECT_LT((A * x - b).norm(), 1e-10);
  }
  {
    Node root("root");
    Standalone s(make_solver("EigenSparseLU"), make_ordering("COLAMD"));
    s.solver->set_node(&root);
    s.solve(A, b, 1);
    EXPECT_GT(root.diagnostics().error_count(), 0) << "SparseLU stops on the zero pivot";
  }
  {
    Eigen::MatrixXd M = random_spd(8, 2u);
    M(3, 3) = -M(3, 3);  // indefinite: LLᵀ refuses it, LDLᵀ factorizes it
    Node r1("root"), r2("root");
    Standalone llt(make_solver("EigenSimplicialLLT"), make_ordering("AMD"));
    Standalone ldlt(make_solver("EigenSimplicialLDLT"), make_ordering("AMD"));
    llt.solver->set_node(&r1);
    ldlt.solver->set_node(&r2);
    llt.solve(M, Eigen::VectorXd::Ones(8), 1);
    const Eigen::VectorXd x = ldlt.solve(M, Eigen::VectorXd::Ones(8), 1);
    EXPECT_GT(r1.diagnostics().error_count(), 0);
    EXPECT_EQ(r2.diagnostics().error_count(), 0);
    EXPECT_LT((M * x - Eigen::VectorXd::Ones(8)).norm(), 1e-10);
  }
}
