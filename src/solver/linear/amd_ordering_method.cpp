#include "solver/linear/amd_ordering_method.h"

#include <Eigen/OrderingMethods>

#include "core/registry.h"

namespace sinew {

void AMDOrderingMethod::compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) {
  const auto m = ordering_pattern(n, colptr, rowind);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  Eigen::AMDOrdering<int> ordering;
  ordering(m, P);
  permutation_indices(P, perm);
}

void register_amd_ordering_method(Registry& r) {
  ComponentInfo info;
  info.name = "AMDOrderingMethod";
  info.category = "LinearSolver/Ordering";
  info.description = "approximate minimum degree fill-reducing ordering";
  
  info.create = creator<AMDOrderingMethod>();
  r.add(std::move(info));
}

}  // namespace sinew
