#include "solver/linear/natural_ordering_method.h"

#include "core/registry.h"

namespace sinew {

void NaturalOrderingMethod::compute_permutation(int n, const int*, const int*, std::vector<int>& perm) {
  perm.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) perm[static_cast<std::size_t>(i)] = i;
}

void register_natural_ordering_method(Registry& r) {
  ComponentInfo info;
  info.name = "NaturalOrderingMethod";
  info.category = "LinearSolver/Ordering";
  info.description = "identity permutation (no reordering)";
  
  info.create = creator<NaturalOrderingMethod>();
  r.add(std::move(info));
}

}  // namespace sinew
