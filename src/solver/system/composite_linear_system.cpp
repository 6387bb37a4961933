#include "solver/system/composite_linear_system.h"

#include <algorithm>

#include "core/registry.h"

namespace sinew {

void CompositeLinearSystem::init() {
  MatrixLinearSystem::init();
  systems_ = linear_systems.targets();
  if (std::find(systems_.begin(), systems_.end(), this) != systems_.end()) {
    msg_error("the composite linear system cannot contain itself");
    set_state(ComponentState::invalid);
    return;
  }
  if (systems_.empty()) {
    if (!solver_linear_system) {
      msg_error("no linear system given: set 'linearSystems' and/or 'solverLinearSystem'");
      set_state(ComponentState::invalid);
      return;
    }
    systems_.push_back(solver_linear_system.get());
  } else if (solver_linear_system) {
    if (std::find(systems_.begin(), systems_.end(), solver_linear_system.get()) == systems_.end()) {
      msg_info("the solver linear system is not in the list of linear systems: it is added");
      systems_.push_back(solver_linear_system.get());
    }
  } else {
    const std::string mine = template_name().empty() ? "CompressedRowSparseMatrixd" : template_name();
    for (MatrixLinearSystem* s : systems_) {
      const std::string t = s->template_name().empty() ? "CompressedRowSparseMatrixd" : s->template_name();
      if (t == mine) {
        solver_linear_system.set(s);
        break;
      }
    }
    if (!solver_linear_system) {
      msg_error("no linear system of type " + mine + " in 'linearSystems' to be used by the linear solver");
      set_state(ComponentState::invalid);
      return;
    }
  }
  // The solver system's storage decides the composite's (same matrix type).
  const std::string t = solver_linear_system->template_name().empty() ? "CompressedRowSparseMatrixd"
                                                                      : solver_linear_system->template_name();
  assembler_.configure(block_size_of(t), structure_of(t));
  configured_ = true;
}

void CompositeLinearSystem::build_system_matrix(MechanicalOps& ops, double m, double b, double k) {
  if (state() == ComponentState::invalid || !enable_assembly.value()) return;
  for (MatrixLinearSystem* s : systems_) s->build_system_matrix(ops, m, b, k);
  MatrixLinearSystem& solver = *solver_linear_system;
  // The linear solver works on the solver system's matrix; the composite holds a copy
  // with the same global layout, so its vectors are gathered and scattered the same way.
  assembler_.update_layout(ops);
  matrix() = solver.matrix();
  const int n = static_cast<int>(assembler_.size());
  if (matrix_size.value() != VecNi<2>(n, n)) matrix_size.set(VecNi<2>(n, n));
  rhs_.setZero(n);
  solution_.setZero(n);
  factorization_invalidation.set(true);
  assembled_once_ = solver.assembled();
}

void register_composite_linear_system(Registry& r) {
  ComponentInfo info;
  info.name = "CompositeLinearSystem";
  info.category = "LinearSystem";
  info.description = "builds several linear systems together; the linear solver uses one of them";
  info.templates = MatrixLinearSystem::matrix_templates();
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<CompositeLinearSystem>();
  r.add(std::move(info));
}

}  // namespace sinew
