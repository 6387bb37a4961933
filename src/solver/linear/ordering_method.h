// OrderingMethod: fill-reducing permutation for the direct solvers
// (spec/solvers.md §3.5). Components: NaturalOrderingMethod ("Natural"),
// AMDOrderingMethod ("AMD"), COLAMDOrderingMethod ("COLAMD"),
// MetisOrderingMethod ("Metis"); no Data.
#pragma once

#include <string>
#include <vector>

#include "core/component.h"
#include "core/field.h"

namespace sinew {

class OrderingMethod : public Component {
 public:
  // Name used to pick the Eigen ordering type ("Natural", "AMD", "COLAMD", "Metis").
  virtual std::string method_name() const = 0;
  // perm[j] for the pattern of a symmetric n×n matrix given in compressed form
  // (outer index `colptr`, inner indices `rowind`): the Eigen ordering's P.indices().
  virtual void compute_permutation(int n, const int* colptr, const int* rowind, std::vector<int>& perm) = 0;
};

// The ordering of a direct solver: its link if set, else the first
// OrderingMethod of its node, else an AMDOrderingMethod created in its node
// (our framework's default, §3.5).
OrderingMethod* find_or_create_ordering(Component& solver, Link<OrderingMethod>& link);

}  // namespace sinew

#include <Eigen/SparseCore>

namespace sinew {
// Pattern of (n, colptr, rowind) as an Eigen column-major matrix of ones (for the Eigen orderings).
Eigen::SparseMatrix<double, Eigen::ColMajor, int> ordering_pattern(int n, const int* colptr, const int* rowind);
// perm[j] = P.indices()(j)
template <class Perm>
void permutation_indices(const Perm& P, std::vector<int>& perm) {
  perm.resize(static_cast<std::size_t>(P.indices().size()));
  for (Eigen::Index j = 0; j < P.indices().size(); ++j) perm[static_cast<std::size_t>(j)] = P.indices()(j);
}
}  // namespace sinew
