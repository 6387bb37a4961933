#include "solver/system/preconditioned_matrix_free_system.h"

#include "core/registry.h"

namespace sinew {

void PreconditionedMatrixFreeSystem::build_system_matrix(MechanicalOps& ops, double m, double b, double k) {
  m_ = m;
  b_ = b;
  k_ = k;
  ops.m_fact = m;
  ops.b_fact = b;
  ops.k_fact = k;
  const int n = static_cast<int>(ops.independent_dofs());
  if (matrix_size.value() != VecNi<2>(n, n)) matrix_size.set(VecNi<2>(n, n));
  if (!preconditioner_system) return;
  if (++counter_ >= assembling_rate.value()) {
    preconditioner_system->build_system_matrix(ops, m, b, k);
    counter_ = 0;
    ++builds_;
  }
}

void PreconditionedMatrixFreeSystem::product(MechanicalOps& ops, int p, int q) const {
  // As MatrixFreeSystem: reset q everywhere and propagate p down the mappings,
  // accumulate m·M + b·B + k·K products (mapped ones brought up with Jᵀ), project.
  ops.propagate_dx_and_reset_df(p, q);
  ops.add_mbk_dx(q, m_, b_, k_, p, /*clear=*/false);
  ops.project_response(q);
}

void register_preconditioned_matrix_free_system(Registry& r) {
  ComponentInfo info;
  info.name = "PreconditionedMatrixFreeSystem";
  info.category = "LinearSystem";
  info.description = "matrix-free linear system whose preconditioner's system is assembled every assemblingRate steps";
  info.templates = {"GraphScattered"};
  info.default_template = "GraphScattered";
  info.create = creator<PreconditionedMatrixFreeSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
