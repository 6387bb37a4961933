#include "constraint/model/constraint_states.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

StateType template_state_type(const Component& c, StateType fallback) {
  StateType t;
  if (!c.template_name().empty() && state_type_from_name(resolve_template_alias(c.template_name()), t)) return t;
  return fallback;
}

namespace {

bool check_type(Component& c, const MechanicalState& s, StateType want) {
  if (s.state_type() == want) return true;
  c.msg_error(s.describe() + " is " + s.info().name + " but this constraint was created for " +
              state_type_info(want).name + " states");
  c.set_state(ComponentState::invalid);
  return false;
}

}  // namespace

bool resolve_constraint_state(Component& c, Link<MechanicalState>& mstate, StateType want) {
  if (!mstate && c.node()) mstate.set(c.node()->get_mechanical_state());
  if (!mstate) {
    c.msg_error("no mechanical state found (mstate, or in this node or above)");
    c.set_state(ComponentState::invalid);
    return false;
  }
  return check_type(c, *mstate, want);
}

bool resolve_pair_states(Component& c, Link<MechanicalState>& object1, Link<MechanicalState>& object2,
                         StateType want) {
  MechanicalState* local = c.node() ? c.node()->get_mechanical_state() : nullptr;
  if (!object1) object1.set(local);
  if (!object2) object2.set(local);
  if (!object1 || !object2) {
    c.msg_error("no mechanical state found (object1/object2 or the node's state)");
    c.set_state(ComponentState::invalid);
    return false;
  }
  return check_type(c, *object1, want) && check_type(c, *object2, want);
}

}  // namespace sinew
