#include "solver/linear/eigen_sparse_lu.h"

#include <Eigen/Sparse>

#include "core/registry.h"
#include "solver/linear/eigen_direct_solver_impl.h"

namespace sinew {

namespace {
template <class O>
using Impl = Eigen::SparseLU<EigenFactorization::Matrix, O>;
}  // namespace

std::unique_ptr<EigenFactorization> EigenSparseLU::make(const std::string& ordering) const {
  return make_eigen_factorization<Impl>(ordering);
}

void register_eigen_sparse_lu(Registry& r) {
  ComponentInfo info;
  info.name = "EigenSparseLU";
  info.category = "LinearSolver/Direct";
  info.description = "Eigen's supernodal sparse LU direct solver";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<EigenSparseLU>();
  r.add(std::move(info));
}

}  // namespace sinew
