#include "solver/linear/async_sparse_ldl_solver.h"

#include <exception>
#include <string>
#include <utility>

#include "core/registry.h"
#include "solver/linear/ordering_method.h"

namespace sinew {

AsyncSparseLDLSolver::~AsyncSparseLDLSolver() {
  // The worker writes into second_/first_: never let it outlive them.
  if (pending_.valid()) pending_.wait();
}

void AsyncSparseLDLSolver::init() {
  SparseLDLSolver::init();
  if (MatrixLinearSystem* sys = system()) sys->enable_assembly.set_parent(&enable_assembly);
  wait_for_first_ = true;
}

void AsyncSparseLDLSolver::reset() {
  enable_assembly.set(true);
  wait_for_first_ = true;
}

void AsyncSparseLDLSolver::cleanup() {
  if (pending_.valid()) pending_.wait();
}

void AsyncSparseLDLSolver::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_begin) ++step_;
}

void AsyncSparseLDLSolver::launch(const BlockCsrMatrix& A) {
  ldl_load(*worker_, A);
  OrderingMethod* ordering = worker_->n > 0 ? find_or_create_ordering(*this, ordering_method) : nullptr;
  const bool reuse = precompute_symbolic_decomposition.value();
  LdlFactorization* f = worker_;
  pending_ = std::async(std::launch::async, [f, ordering, reuse] { return ldl_factorize(*f, ordering, reuse); });
  pending_step_ = step_;
  ++launches_;
}

void AsyncSparseLDLSolver::finish_pending() {
  if (!pending_.valid()) return;
  LdlOutcome outcome;
  try {
    outcome = pending_.get();
  } catch (const std::exception& ex) {
    msg_error(std::string("the factorization failed: ") + ex.what());
    worker_->factorized = false;
    return;
  }
  // A failed factorization is reported and not swapped in: solves keep the last good one.
  if (report(outcome, *worker_)) std::swap(factor_, worker_);
}

void AsyncSparseLDLSolver::prepare() {
  if (pending_.valid() && step_ > pending_step_) finish_pending();
  MatrixLinearSystem* sys = system();
  if (!sys || !sys->matrix_changed()) return;
  finish_pending();  // its buffer is reused by the launch below
  launch(sys->matrix());
  sys->clear_matrix_changed();
  if (wait_for_first_) {
    wait_for_first_ = false;
    finish_pending();
  }
}

void AsyncSparseLDLSolver::invert(const BlockCsrMatrix& A) {
  // Synchronous path (direct calls): factorize now and use it.
  finish_pending();
  launch(A);
  finish_pending();
}

void AsyncSparseLDLSolver::solve_global(Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  prepare();
  solve_with(*factor_, x, b);
}

void AsyncSparseLDLSolver::add_jminvjt(Eigen::MatrixXd& result,
                                       const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J, double fact) {
  if (!system()) return;
  prepare();
  const Eigen::Index m = J.rows();
  if (result.rows() < m || result.cols() < m) result.conservativeResize(m, m);
  if (!factor_->factorized || J.cols() != factor_->n) return MatrixLinearSolver::add_jminvjt(result, J, fact);
  ldl_add_jminvjt(*factor_, jminvjt_, result, J, fact);
}

void register_async_sparse_ldl_solver(Registry& r) {
  ComponentInfo info;
  info.name = "AsyncSparseLDLSolver";
  info.category = "LinearSolver/Direct";
  info.description = "direct LDLᵀ solver whose factorization runs on another thread, one step behind";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<AsyncSparseLDLSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
