// BlockGaussSeidel, NNCG, UnbuiltGaussSeidel and ImprovedJacobi on
// hand-written problems: analytic solutions of 1- and 3-row unilateral
// problems and of one Coulomb contact, the same answer from every solver on a
// well-posed problem, and non-convergence reported with iterations and error.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "constraint/solver/block_gauss_seidel_constraint_solver.h"
#include "constraint/solver/improved_jacobi_constraint_solver.h"
#include "constraint/solver/nncg_constraint_solver.h"
#include "constraint/solver/unbuilt_gauss_seidel_constraint_solver.h"
#include "constraint_test_helpers.h"
#include "test_scene.h"

namespace sinew {
namespace {

using Kind = ConstraintBlock::Kind;
using test::block;
using test::Exposed;

struct Problem {
  int n;
  std::vector<double> W, dfree;
  std::vector<ConstraintBlock> blocks;
};

Problem one_row() { return {1, {2.0}, {-1.0}, {block(Kind::unilateral, 0, 1)}}; }

// Solution (1/2, 0, 1/2): see lcp_gauss_seidel_test.cpp.
Problem three_rows() {
  return {3,
          {2, 1, 0, 1, 2, 1, 0, 1, 2},
          {-1, 1, -1},
          {block(Kind::unilateral, 0, 1), block(Kind::unilateral, 1, 1), block(Kind::unilateral, 2, 1)}};
}

// One contact: fn = 1/2, (ft, fs) = (−0.06, −0.08) on the cone mu·fn = 0.1.
Problem friction_contact() {
  return {3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, 0.3, 0.4}, {block(Kind::unilateral_friction, 0, 3, 0.2)}};
}

// A well-posed mixed problem: a random SPD W (diagonally dominant) with two
// unilateral rows, one 3-row friction contact and one 3-row bilateral.
Problem mixed() {
  const int n = 8;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> A(n * n);
  for (double& a : A) a = u(rng);
  std::vector<double> W(n * n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) W[i * n + j] += 0.1 * A[i * n + k] * A[j * n + k];
      if (i == j) W[i * n + j] += 2.0;
    }
  return {n,
          W,
          {-0.5, 0.3, -1.0, 0.2, -0.1, 0.05, -0.02, 0.03},
          {block(Kind::unilateral, 0, 1), block(Kind::unilateral, 1, 1),
           block(Kind::unilateral_friction, 2, 3, 0.4), block(Kind::bilateral3, 5, 3)}};
}

// The solvers run inside a scene node (the unbuilt one needs its correction
// in the graph); the problem is written directly.
class SolverRun : public ::testing::Test {
 public:
  void SetUp() override {
    scene_ = test::load(R"(<Node name="root" dt="0.01"/>)");
    ASSERT_TRUE(scene_.root);
  }
  template <class S>
  Exposed<S>* add(const char* name) {
    auto s = std::make_unique<Exposed<S>>();
    s->name.set(name);
    return static_cast<Exposed<S>*>(scene_.root->add_object(std::move(s)));
  }
  // Runs solver `s` on `p` (built: W as given; unbuilt: through a correction holding W).
  template <class S>
  std::vector<double> run(Exposed<S>& s, const Problem& p) {
    test::set_problem(s.prob(), p.n, p.W, p.dfree, p.blocks);
    if constexpr (std::is_same_v<S, UnbuiltGaussSeidelConstraintSolver>) {
      if (!dense_) dense_ = static_cast<test::DenseCorrection*>(
                       scene_.root->add_object(std::make_unique<test::DenseCorrection>()));
      dense_->n = p.n;
      dense_->W = p.W;
      s.scope().corrections = {dense_};
      // Only the diagonal blocks of W reach the unbuilt solver.
      std::fill(s.prob().W.begin(), s.prob().W.end(), 0.0);
      ConstraintParams cp;
      cp.dt = 0.01;
      s.build(cp);
    }
    s.solve();
    return s.prob().f;
  }
  scene::LoadedScene scene_;
  test::DenseCorrection* dense_ = nullptr;
};

template <class S>
void expect_analytic(SolverRun& t, Exposed<S>& s) {
  s.tolerance.set(1e-12);
  std::vector<double> f = t.run(s, one_row());
  EXPECT_NEAR(f[0], 0.5, 1e-10);
  EXPECT_TRUE(s.converged());
  f = t.run(s, three_rows());
  EXPECT_NEAR(f[0], 0.5, 1e-10);
  EXPECT_NEAR(f[1], 0.0, 1e-10);
  EXPECT_NEAR(f[2], 0.5, 1e-10);
  EXPECT_TRUE(s.converged());
  f = t.run(s, friction_contact());
  EXPECT_NEAR(f[0], 0.5, 1e-10);
  EXPECT_NEAR(f[1], -0.06, 1e-10);
  EXPECT_NEAR(f[2], -0.08, 1e-10);
}

TEST_F(SolverRun, BlockGaussSeidelAnalytic) {
  expect_analytic(*this, *add<BlockGaussSeidelConstraintSolver>("bgs"));
}
TEST_F(SolverRun, NNCGAnalytic) { expect_analytic(*this, *add<NNCGConstraintSolver>("nncg")); }
TEST_F(SolverRun, UnbuiltGaussSeidelAnalytic) {
  expect_analytic(*this, *add<UnbuiltGaussSeidelConstraintSolver>("ugs"));
}
TEST_F(SolverRun, ImprovedJacobiAnalytic) {
  expect_analytic(*this, *add<ImprovedJacobiConstraintSolver>("jacobi"));
}

// Every solver finds BGS's answer on a well-posed problem (Jacobi needs its
// spectral correction to converge on a coupled W).
TEST_F(SolverRun, AllSolversAgreeWithBlockGaussSeidel) {
  const Problem p = mixed();
  auto* bgs = add<BlockGaussSeidelConstraintSolver>("bgs");
  bgs->tolerance.set(1e-14);
  bgs->max_iterations.set(10000);
  const std::vector<double> ref = run(*bgs, p);
  ASSERT_TRUE(bgs->converged());
  auto* nncg = add<NNCGConstraintSolver>("nncg");
  nncg->tolerance.set(1e-13);
  auto* ugs = add<UnbuiltGaussSeidelConstraintSolver>("ugs");
  ugs->tolerance.set(1e-13);
  auto* jacobi = add<ImprovedJacobiConstraintSolver>("jacobi");
  jacobi->tolerance.set(1e-13);
  jacobi->max_iterations.set(100000);
  jacobi->use_spectral_correction.set(true);
  for (auto [name, f] : {std::pair{"nncg", run(*nncg, p)}, std::pair{"ugs", run(*ugs, p)},
                         std::pair{"jacobi", run(*jacobi, p)}}) {
    ASSERT_EQ(f.size(), ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) EXPECT_NEAR(f[i], ref[i], 1e-9) << name << " row " << i;
  }
  EXPECT_TRUE(nncg->converged());
  EXPECT_TRUE(ugs->converged());
  EXPECT_TRUE(jacobi->converged());
  // The unbuilt solver went through the correction for the coupling.
  EXPECT_GT(dense_->displacement_calls, 0);
  EXPECT_GT(dense_->dforce_calls, 0);
}

// The unbuilt solver discards the blocks' warm starts (SOFA's memset after
// init); the built one starts from them.
TEST_F(SolverRun, UnbuiltGaussSeidelDiscardsWarmStart) {
  Problem p = {3, {2, 0, 0, 0, 2, 0, 0, 0, 2}, {-1, -1, -1}, {block(Kind::bilateral3, 0, 3)}};
  double warm[3] = {0.5, 0.5, 0.5};  // the exact solution
  p.blocks[0].warm = warm;
  auto* bgs = add<BlockGaussSeidelConstraintSolver>("bgs");
  run(*bgs, p);
  EXPECT_EQ(bgs->iterations(), 2);  // converged in its first sweep (SOFA reports count + 1)
  warm[0] = warm[1] = warm[2] = 0.5;
  auto* ugs = add<UnbuiltGaussSeidelConstraintSolver>("ugs");
  run(*ugs, p);
  EXPECT_EQ(ugs->iterations(), 2);  // first sweep moves from 0 to the solution, second one confirms
  EXPECT_NEAR(ugs->prob().f[0], 0.5, 1e-14);
}

// Two coupled bilateral rows, W = [[2,1],[1,2]], dfree = (−1, −1): Gauss-
// Seidel approaches f = (1/3, 1/3) by a factor 1/4 per sweep. One measured
// sweep is not enough: not converged, with the iteration count (SOFA's
// count + 1) and the error of the last sweep (2·1/8 + 2·1/16 for the second).
TEST_F(SolverRun, NonConvergenceIsReported) {
  const Problem p = {2, {2, 1, 1, 2}, {-1, -1}, {block(Kind::bilateral, 0, 1), block(Kind::bilateral, 1, 1)}};
  auto* bgs = add<BlockGaussSeidelConstraintSolver>("bgs");
  auto* nncg = add<NNCGConstraintSolver>("nncg");
  auto* ugs = add<UnbuiltGaussSeidelConstraintSolver>("ugs");
  bgs->max_iterations.set(1);
  nncg->max_iterations.set(2);  // the first sweep is extra in NNCG
  ugs->max_iterations.set(1);
  for (GenericConstraintSolver* s : {static_cast<GenericConstraintSolver*>(bgs), static_cast<GenericConstraintSolver*>(nncg),
                                     static_cast<GenericConstraintSolver*>(ugs)})
    s->tolerance.set(1e-12);
  run(*bgs, p);
  run(*nncg, p);
  run(*ugs, p);
  EXPECT_FALSE(bgs->converged());
  EXPECT_EQ(bgs->iterations(), 2);
  EXPECT_DOUBLE_EQ(bgs->error(), 2 * 0.5 + 2 * 0.25);  // first sweep from zero
  EXPECT_FALSE(nncg->converged());
  EXPECT_EQ(nncg->iterations(), 2);
  EXPECT_DOUBLE_EQ(nncg->error(), 2 * 0.125 + 2 * 0.0625);  // its second sweep
  EXPECT_FALSE(ugs->converged());
  EXPECT_EQ(ugs->iterations(), 2);
  EXPECT_DOUBLE_EQ(ugs->error(), 2 * 0.5 + 2 * 0.25);
  // With enough iterations they all reach (1/3, 1/3).
  for (GenericConstraintSolver* s : {static_cast<GenericConstraintSolver*>(bgs), static_cast<GenericConstraintSolver*>(nncg),
                                     static_cast<GenericConstraintSolver*>(ugs)})
    s->max_iterations.set(200);
  for (const std::vector<double>& f : {run(*bgs, p), run(*nncg, p), run(*ugs, p)}) {
    EXPECT_NEAR(f[0], 1.0 / 3, 1e-11);
    EXPECT_NEAR(f[1], 1.0 / 3, 1e-11);
  }
}

}  // namespace
}  // namespace sinew
