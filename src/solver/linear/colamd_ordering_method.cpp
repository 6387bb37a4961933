#include "solver/linear/colamd_ordering_method.h"

#include <Eigen/OrderingMethods>

#include "core/registry.h"

namespace sinew {

void COLAMDOrderingMethod::compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) {
  auto m = ordering_pattern(n, colptr, rowind);
  m.makeCompressed();
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  Eigen::COLAMDOrdering<int> ordering;
  ordering(m, P);
  permutation_indices(P, perm);
}

void register_colamd_ordering_method(Registry& r) {
  ComponentInfo info;
  info.name = "COLAMDOrderingMethod";
  info.category = "LinearSolver/Ordering";
  info.description = "column approximate minimum degree fill-reducing ordering";
  
  info.create = creator<COLAMDOrderingMethod>();
  r.add(std::move(info));
}

}  // namespace sinew
