// MetisOrderingMethod: nested dissection ordering from METIS (Eigen MetisOrdering) (spec/solvers.md §3.5).
#pragma once

#include "solver/linear/ordering_method.h"

namespace sinew {

class MetisOrderingMethod final : public OrderingMethod {
 public:
  std::string method_name() const override { return "Metis"; }
  void compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) override;
};

}  // namespace sinew
