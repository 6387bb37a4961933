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

}  // namespace sinew
