#include "core/constraint_problem.h"

#include "core/node.h"

namespace sinew {

void ConstraintCorrection::init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

bool ConstraintCorrection::has_constraint_row(int row) const {
  return mstate && mstate->constraint_jacobian().find_row(row) != nullptr;
}

}  // namespace sinew
