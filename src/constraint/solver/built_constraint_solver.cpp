#include "constraint/solver/built_constraint_solver.h"

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/SVD>

namespace sinew {

void BuiltConstraintSolver::build_system(const ConstraintParams& p) {
  if (!use_svd_for_regularization.value()) return GenericConstraintSolver::build_system(p);
  add_compliances(scope_, p, problem_, 0.0);
  const double reg = regularization_term.value();
  const int n = problem_.n;
  if (n == 0 || reg <= std::numeric_limits<double>::epsilon()) return;
  // Only the rows that take part in the numerical null space of W get the
  // regularisation: those with a large component in a singular vector whose
  // singular value is small next to the largest one.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> W(problem_.W.data(), n, n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(W), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  int begin = -1;
  for (int i = 0; i < n; ++i)
    if (std::fabs(sv(i)) < std::fabs(sv(0)) * svd_value_factor.value()) {
      begin = i;
      break;
    }
  std::vector<bool> in_null_space(n, false);
  for (int i = begin; i != -1 && i < n; ++i)
    for (int j = 0; j < n; ++j)
      in_null_space[j] = in_null_space[j] || std::fabs(svd.matrixV()(j, i)) > svd_vector_factor.value();
  for (int i = 0; i < n; ++i) W(i, i) += in_null_space[i] * reg;
}

}  // namespace sinew
