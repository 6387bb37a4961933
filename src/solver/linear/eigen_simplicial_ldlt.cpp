#include "solver/linear/eigen_simplicial_ldlt.h"

#include <Eigen/Sparse>

#include "core/registry.h"
#include "solver/linear/eigen_direct_solver_impl.h"

namespace sinew {

// A name unique to this file: GCC gives make_eigen_factorization<alias> weak
// linkage even for an alias in an anonymous namespace, so four files each
// naming theirs `Impl` made one symbol, and the linker kept one of the four
// factorizations for every solver wherever the call was not inlined (-O1).
namespace {
template <class O>
using SimplicialLdltOf = Eigen::SimplicialLDLT<EigenFactorization::Matrix, Eigen::Lower, O>;
}  // namespace

std::unique_ptr<EigenFactorization> EigenSimplicialLDLT::make(const std::string& ordering) const {
  return make_eigen_factorization<SimplicialLdltOf>(ordering);
}

void register_eigen_simplicial_ldlt(Registry& r) {
  ComponentInfo info;
  info.name = "EigenSimplicialLDLT";
  info.category = "LinearSolver/Direct";
  info.description = "Eigen's simplicial LDLᵀ direct solver (lower triangle)";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<EigenSimplicialLDLT>();
  r.add(std::move(info));
}

}  // namespace sinew
