#include "solver/linear/metis_ordering_method.h"

#include <iostream>  // Eigen/MetisSupport uses std::cerr without including it
#include <Eigen/MetisSupport>

#include "core/registry.h"

namespace sinew {

void MetisOrderingMethod::compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) {
  const auto m = ordering_pattern(n, colptr, rowind);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P;
  Eigen::MetisOrdering<int> ordering;
  ordering(m, P);
  permutation_indices(P, perm);
}

void register_metis_ordering_method(Registry& r) {
  ComponentInfo info;
  info.name = "MetisOrderingMethod";
  info.category = "LinearSolver/Ordering";
  info.description = "nested dissection fill-reducing ordering (METIS)";
  info.aliases = {"METISOrderingMethod"};
  info.create = creator<MetisOrderingMethod>();
  r.add(std::move(info));
}

}  // namespace sinew
