// EigenDirectSolver: base of EigenSimplicialLDLT, EigenSimplicialLLT,
// EigenSparseLU and EigenSparseQR (spec/solvers.md §3.6).
// invert: non-zero filtered scalar copy of A (row-major, converted to Eigen's
// column-major SparseMatrix), analyzePattern when the pattern changed, then
// factorize; failures are reported ("Solver cannot factorize: ...") and the
// solve returns 0. The ordering comes from the OrderingMethod component
// (Natural, AMD, COLAMD, Metis).
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "solver/linear/matrix_linear_solver.h"
#include "solver/linear/ordering_method.h"

namespace sinew {

// Type-erased Eigen sparse solver.
class EigenFactorization {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  virtual ~EigenFactorization() = default;
  virtual void analyze(const Matrix& A) = 0;
  virtual void factorize(const Matrix& A) = 0;
  virtual Eigen::ComputationInfo info() const = 0;
  virtual void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
};

template <class S>
class EigenFactorizationOf final : public EigenFactorization {
 public:
  void analyze(const Matrix& A) override { s_.analyzePattern(A); }
  void factorize(const Matrix& A) override { s_.factorize(A); }
  Eigen::ComputationInfo info() const override { return s_.info(); }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override { x = s_.solve(b); }

 private:
  S s_;
};

class EigenDirectSolver : public MatrixLinearSolver {
 public:
  Link<OrderingMethod> ordering_method{this, "orderingMethod", "fill-reducing ordering (default: AMD)"};

  void init() override;
  bool factorized() const { return factorized_; }

 protected:
  // The Eigen solver for an ordering name; nullptr when not supported.
  virtual std::unique_ptr<EigenFactorization> make(const std::string& ordering) const = 0;
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  std::unique_ptr<EigenFactorization> factor_;
  std::string ordering_name_;
  std::vector<int> rb_, ci_, prev_rb_, prev_ci_;
  std::vector<double> vals_;
  EigenFactorization::Matrix matrix_;
  bool factorized_ = false, analyzed_ = false;
  bool input_reported_ = false;
  // Why the filtered matrix cannot be given to Eigen (zero, non-finite, zero rows); empty when it can.
  std::string check_input(int n) const;
};

// Builds a factorization for one of the orderings Natural, AMD, COLAMD, Metis.
template <template <class> class Solver>
std::unique_ptr<EigenFactorization> make_eigen_factorization(const std::string& ordering);

}  // namespace sinew
