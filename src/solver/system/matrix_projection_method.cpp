#include "solver/system/matrix_projection_method.h"

#include "core/registry.h"

namespace sinew {

void MatrixProjectionMethod::init() {
  const auto& s = mechanical_states.get();
  if (s.size() < 2) {
    msg_error("mechanicalStates names " + std::to_string(s.size()) +
              " state(s): a projection method is for a pair of states (rows, columns)");
    set_state(ComponentState::invalid);
    return;
  }
  if (s.size() > 2) msg_warning("mechanicalStates names more than two states: the first two are the pair");
}

bool MatrixProjectionMethod::has_pair(const MechanicalState* rows, const MechanicalState* cols) const {
  const auto& s = mechanical_states.get();
  return state() == ComponentState::valid && s.size() >= 2 && s[0] == rows && s[1] == cols;
}

void register_matrix_projection_method(Registry& r) {
  ComponentInfo info;
  info.name = "MatrixProjectionMethod";
  info.category = "LinearSystem";
  info.description = "projection of the matrix block of a pair of mapped states (Jᵀ·K·J), optionally with "
                     "Jacobians computed once";
  info.templates = {"CompressedRowSparseMatrixd"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<MatrixProjectionMethod>();
  r.add(std::move(info));
}

}  // namespace sinew
