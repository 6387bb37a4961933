// AMDOrderingMethod: approximate minimum degree ordering (Eigen AMDOrdering) (spec/solvers.md §3.5).
#pragma once

#include "solver/linear/ordering_method.h"

namespace sinew {

class AMDOrderingMethod final : public OrderingMethod {
 public:
  std::string method_name() const override { return "AMD"; }
  void compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) override;
};

}  // namespace sinew
