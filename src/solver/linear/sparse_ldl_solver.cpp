#include "solver/linear/sparse_ldl_solver.h"

#include <string>

#include "core/registry.h"

namespace sinew {

void SparseLDLSolver::init() {
  if (saving_matrix_to_file.is_set())
    msg_warning("'savingMatrixToFile' is deprecated and has no effect");
  MatrixLinearSolver::init();
  find_or_create_ordering(*this, ordering_method);
}

void SparseLDLSolver::invert(const BlockCsrMatrix& A) {
  ldl_load(*factor_, A);
  OrderingMethod* ordering = factor_->n > 0 ? find_or_create_ordering(*this, ordering_method) : nullptr;
  report(ldl_factorize(*factor_, ordering, precompute_symbolic_decomposition.value()), *factor_);
}

bool SparseLDLSolver::report(const LdlOutcome& outcome, const LdlFactorization& f) {
  switch (outcome.status) {
    case LdlStatus::empty:
      msg_warning("Invalid Linear System to solve (null size). Please ensure that there are DoFs to solve.");
      return false;
    case LdlStatus::zero_pivot:
      msg_error("Failed to factorize, D(k,k) is zero (k = " + std::to_string(outcome.row) +
                "): the system matrix is singular (are there fixed points?)");
      return false;
    case LdlStatus::non_finite_pivot:
      msg_error("Failed to factorize: non-finite pivot at row " + std::to_string(outcome.row) +
                " (the system matrix has NaNs)");
      return false;
    case LdlStatus::ok:
      break;
  }
  l_nnz.set(f.lp.empty() ? 0 : f.lp.back());
  if (outcome.negative_pivot && !warned_indefinite_) {
    warned_indefinite_ = true;
    msg_warning("the system matrix is not positive definite (negative pivots in LDLᵀ); check for negative stiffness");
  }
  return true;
}

void SparseLDLSolver::solve_with(LdlFactorization& f, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.setZero(n);
  if (!f.factorized || n != f.n) {
    x.setZero();
    return;
  }
  ldl_solve(f, x.data(), b.data());
}

void SparseLDLSolver::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  solve_with(*factor_, x, b);
}

void SparseLDLSolver::add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                                  double fact) {
  MatrixLinearSystem* sys = system();
  if (!sys) return;
  if (sys->matrix_changed()) {
    invert(sys->matrix());
    sys->clear_matrix_changed();
  }
  const Eigen::Index m = J.rows();
  if (result.rows() < m || result.cols() < m) result.conservativeResize(m, m);
  if (!factor_->factorized || J.cols() != factor_->n) return MatrixLinearSolver::add_jminvjt(result, J, fact);
  ldl_add_jminvjt(*factor_, jminvjt_, result, J, fact);
}

void register_sparse_ldl_solver(Registry& r) {
  ComponentInfo info;
  info.name = "SparseLDLSolver";
  info.category = "LinearSolver/Direct";
  info.description = "direct LDLᵀ solver on the assembled sparse system";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<SparseLDLSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
