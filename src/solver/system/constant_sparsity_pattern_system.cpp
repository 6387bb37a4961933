#include "solver/system/constant_sparsity_pattern_system.h"

#include "core/registry.h"

namespace sinew {

void register_constant_sparsity_pattern_system(Registry& r) {
  ComponentInfo info;
  info.name = "ConstantSparsityPatternSystem";
  info.category = "LinearSystem";
  info.description = "assembled linear system whose sparsity pattern is computed once and reused";
  info.templates = {"CompressedRowSparseMatrixd"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<ConstantSparsityPatternSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
