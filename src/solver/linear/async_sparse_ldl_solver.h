// AsyncSparseLDLSolver: SparseLDLSolver whose factorization runs on another
// thread while the simulation goes on (spec/solvers.md §3.4). Solves use a
// factorization that is one step old: the first solve after init or reset
// waits for its own factorization; afterwards, when the system matrix
// changes, the factorization of the new matrix starts on a worker thread and
// the solves keep the previous one until the next step. The result is an
// approximation of the implicit step (an older tangent matrix), as in SOFA.
//
// SOFA swaps in a finished factorization whenever the worker happens to be
// done, so its motion depends on thread timing (its own header says so).
// Sinew swaps at fixed points, reproducing SOFA's course when the
// factorization takes less than a step, deterministically:
//   - at the first solve of a step (AnimateBeginEvent seen), the factorization
//     launched during an earlier step is waited for and used;
//   - a new matrix while a factorization is pending waits for it first (its
//     buffer is about to be reused), uses it, and launches the new one.
// The matrix is copied on the simulation thread before the launch, so the
// next assembly never races the worker (SOFA instead pauses assembly through
// `enableAssembly` until the factorization is done).
#pragma once

#include <future>

#include "solver/linear/sparse_ldl_solver.h"

namespace sinew {

class AsyncSparseLDLSolver final : public SparseLDLSolver {
 public:
  // SOFA's Data, parent of the linear system's `enableAssembly`.
  Field<bool> enable_assembly{this, "enableAssembly", true, "allow assembly of the linear system", "Solver"};

  ~AsyncSparseLDLSolver() override;
  void init() override;
  void reset() override;
  void cleanup() override;
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;

  void solve_global(Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                   double fact) override;

  // Tests: factorizations launched so far, and whether one is in flight.
  long launches() const { return launches_; }
  bool pending() const { return pending_.valid(); }

 protected:
  void invert(const BlockCsrMatrix& A) override;

 private:
  // Copies the new matrix into the worker's factorization and starts it.
  void launch(const BlockCsrMatrix& A);
  // Waits for the pending factorization and, when usable, makes it the one solves use.
  void finish_pending();
  // Swaps in a factorization launched in an earlier step; takes a new matrix.
  void prepare();

  LdlFactorization second_;
  LdlFactorization* worker_ = &second_;
  std::future<LdlOutcome> pending_;
  long step_ = 0, pending_step_ = 0, launches_ = 0;
  bool wait_for_first_ = true;
};

}  // namespace sinew
