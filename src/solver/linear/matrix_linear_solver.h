// MatrixLinearSolver: base of the linear solvers working on an assembled
// system (spec/solvers.md §0.2, §2.2, §3.0).
//
// init: link `linearSystem`, else the first unused MatrixLinearSystem of
// exactly the solver's template in this node or an ancestor, else create one
// (warning when other linear systems exist, info otherwise).
// build_system → the system assembles A; solve_system → copy the initial
// guess and the RHS into global vectors, invert A when the system changed
// since the last factorization, solve, copy the solution back.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/roles.h"
#include "solver/system/matrix_linear_system.h"

namespace sinew {

class MatrixLinearSolver : public LinearSolver {
 public:
  Link<MatrixLinearSystem> linear_system{this, "linearSystem", "linear system assembled for this solver"};
  Field<bool> parallel_inverse_product{this, "parallelInverseProduct", false, "compute J·A⁻¹·Jᵀ products in parallel",
                                       "LinearSolver"};

  void init() override;
  void build_system(MechanicalOps& ops, double m, double b, double k) override;
  void solve_system(MechanicalOps& ops, int x, int rhs) override;

  // LU and QR solve non-symmetric systems.
  virtual bool supports_non_symmetric() const { return false; }

  // Global-vector interface (preconditioners, constraint corrections):
  // factorizes if the system changed, then solves A·x = b.
  // (AsyncSparseLDLSolver decides itself which factorization solves.)
  virtual void solve_global(Eigen::VectorXd& x, const Eigen::VectorXd& b);
  MatrixLinearSystem* system() const { return linear_system.get(); }
  // Constraint corrections (§3.0): result += fact·J·A⁻¹·Jᵀ, J with system-size
  // columns; one solve A·y = J_rowᵀ per non-empty row of J, then
  // result(r2, row) += fact·J_r2·y for every row r2.
  virtual void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                           double fact);

 protected:
  // Factorizes / prepares A (called once per assembly).
  virtual void invert(const BlockCsrMatrix& A) = 0;
  // x = A⁻¹·b (x holds the initial guess on entry).
  virtual void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) = 0;
  // The matrix template of the system this solver needs (default: its own template).
  virtual std::string system_template() const;
};

}  // namespace sinew
