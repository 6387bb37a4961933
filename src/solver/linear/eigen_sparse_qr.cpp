#include "solver/linear/eigen_sparse_qr.h"

#include <Eigen/Sparse>

#include "core/registry.h"
#include "solver/linear/eigen_direct_solver_impl.h"

namespace sinew {

namespace {
template <class O>
using Impl = Eigen::SparseQR<EigenFactorization::Matrix, O>;
}  // namespace

std::unique_ptr<EigenFactorization> EigenSparseQR::make(const std::string& ordering) const {
  return make_eigen_factorization<Impl>(ordering);
}

void register_eigen_sparse_qr(Registry& r) {
  ComponentInfo info;
  info.name = "EigenSparseQR";
  info.category = "LinearSolver/Direct";
  info.description = "Eigen's sparse QR direct solver";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<EigenSparseQR>();
  r.add(std::move(info));
}

}  // namespace sinew
