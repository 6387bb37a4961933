// SVDLinearSolver and CholeskySolver (dense direct solvers): solutions
// against Eigen's dense reference on random SPD systems, the pseudo-inverse
// on a rank-deficient system, the condition number, and the errors on
// matrices they cannot factorize. The FEMBAR and sandbox examples that use
// them run.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <filesystem>

#include "core/node.h"
#include "badinput_helpers.h"
#include "linsys_helpers.h"
#include "runner/session.h"
#include "solver/linear/cholesky_solver.h"
#include "solver/linear/svd_linear_solver.h"
#include "solver/system/matrix_linear_system.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;

namespace {

template <class Solver>
struct Rig {
  Node root{"root"};
  MatrixLinearSystem system;
  Solver solver;
  Rig() {
    solver.set_node(&root);
    solver.linear_system.set(&system);
    solver.init();
  }
  Eigen::VectorXd solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
    test::fill(system.matrix(), A, 1);
    system.factorization_invalidation.set(true);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    solver.solve_global(x, b);
    return x;
  }
  bool error_contains(const std::string& text) {
    for (const Message& m : root.diagnostics().messages())
      if (m.severity == Severity::error && m.text.find(text) != std::string::npos) return true;
    return false;
  }
};

}  // namespace

TEST(SVDLinearSolver, MatchesDenseSolveAndReportsTheConditionNumber) {
  Rig<SVDLinearSolver> rig;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::MatrixXd A = test::random_spd(30, seed, 0.3);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(30, -2.0, 1.0);
    const Eigen::VectorXd x = rig.solve(A, b);
    EXPECT_LT((x - A.ldlt().solve(b)).norm(), 1e-11 * x.norm());
    const Eigen::VectorXd s = A.jacobiSvd().singularValues();
    EXPECT_NEAR(rig.solver.condition_number.value(), s(0) / s(29), 1e-9 * s(0) / s(29));
  }
}

TEST(SVDLinearSolver, RankDeficientSystemGetsTheMinimumNormSolution) {
  // A = diag(4, 2, 0) in a rotated basis: the null direction is dropped.
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd A = Q * Eigen::Vector3d(4, 2, 0).asDiagonal() * Q.transpose();
  const Eigen::VectorXd b = Q * Eigen::Vector3d(8, -2, 5);  // its null-space part (5) is not reachable
  Rig<SVDLinearSolver> rig;
  const Eigen::VectorXd x = rig.solve(A, b);
  const Eigen::VectorXd expected = Q * Eigen::Vector3d(2, -1, 0);
  EXPECT_LT((x - expected).norm(), 1e-12);
  // Raising the threshold above 2 drops the second direction too.
  rig.solver.min_singular_value.set(3.0);
  EXPECT_LT((rig.solve(A, b) - Q * Eigen::Vector3d(2, 0, 0)).norm(), 1e-12);
}

TEST(CholeskySolver, MatchesDenseSolve) {
  Rig<CholeskySolver> rig;
  for (unsigned seed : {4u, 5u}) {
    const Eigen::MatrixXd A = test::random_spd(40, seed);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(40, 1.0, 3.0);
    const Eigen::VectorXd x = rig.solve(A, b);
    EXPECT_LT((x - A.llt().solve(b)).norm(), 1e-12 * x.norm());
  }
}

TEST(CholeskySolver, IndefiniteMatrixIsAnErrorAndTheSolutionStaysFinite) {
  Rig<CholeskySolver> rig;
  Eigen::MatrixXd A = test::random_spd(6, 9u);
  A(3, 3) = -1.0;
  const Eigen::VectorXd x = rig.solve(A, Eigen::VectorXd::Ones(6));
  EXPECT_TRUE(rig.error_contains("not positive definite (pivot 3)"));
  EXPECT_TRUE(x.allFinite());
  EXPECT_EQ(x.norm(), 0.0);
}

namespace {
namespace fs = std::filesystem;
const fs::path kData = SINEW_DATA_DIR;

// Runs an example scene; returns its error messages (nullopt-like: skipped when absent).
std::vector<std::string> run_example(const std::string& rel, long steps, long* done) {
  runner::SessionOptions opts;
  opts.data_paths = {(kData / "share").string(), (kData / "examples").string()};
  runner::Session session((kData / "examples" / rel).string(), opts);
  for (long i = 0; i < steps && session.ok(); ++i) session.step();
  *done = session.steps_done();
  auto errors = test::messages(session.diagnostics(), Severity::error);
  if (session.loaded() && !test::all_finite(session.root())) errors.push_back("non-finite state");
  return errors;
}
}  // namespace

TEST(DenseDirectSolvers, ExampleScenesRun) {
  // FEMBAR has 960 unknowns: a dense SVD per step takes a while, so a few steps.
  for (const auto& [rel, steps] : std::vector<std::pair<const char*, long>>{
           {"Component/LinearSolver/Direct/FEMBAR_SVDLinearSolver.scn", 3},
           {"Component/LinearSolver/Direct/Eigen3-SVD.scn", 100},
           {"Tutorials/sandbox/linearsolver_direct_or_iterative.scn", 100}}) {
    if (!fs::exists(kData / "examples" / rel)) GTEST_SKIP() << "SOFA data not found at " << kData;
    long done = 0;
    const auto errors = run_example(rel, steps, &done);
    EXPECT_TRUE(errors.empty()) << rel << ": " << ::testing::PrintToString(errors);
    EXPECT_EQ(done, steps) << rel;
  }
}
