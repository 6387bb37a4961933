#include "solver/linear/eigen_simplicial_llt.h"

#include <Eigen/Sparse>

#include "core/registry.h"
#include "solver/linear/eigen_direct_solver_impl.h"

namespace sinew {

namespace {
template <class O>
using Impl = Eigen::SimplicialLLT<EigenFactorization::Matrix, Eigen::Lower, O>;
}  // namespace

std::unique_ptr<EigenFactorization> EigenSimplicialLLT::make(const std::string& ordering) const {
  return make_eigen_factorization<Impl>(ordering);
}

void register_eigen_simplicial_llt(Registry& r) {
  ComponentInfo info;
  info.name = "EigenSimplicialLLT";
  info.category = "LinearSolver/Direct";
  info.description = "Eigen's simplicial LLᵀ (Cholesky) direct solver (lower triangle)";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<EigenSimplicialLLT>();
  r.add(std::move(info));
}

}  // namespace sinew
