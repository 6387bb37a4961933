#include "solver/system/precomputed_matrix_system.h"

#include "core/registry.h"

namespace sinew {

void register_precomputed_matrix_system(Registry& r) {
  ComponentInfo info;
  info.name = "PrecomputedMatrixSystem";
  info.category = "LinearSystem";
  info.description = "linear system without assembly (matrix stays empty): vectors only, for precomputed preconditioners";
  info.templates = {"CompressedRowSparseMatrixd"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<PrecomputedMatrixSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
