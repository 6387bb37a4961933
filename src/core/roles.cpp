#include "core/roles.h"

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/value_text.h"

namespace sinew {

const StateTypeInfo& state_type_info(StateType t) {
  static const StateTypeInfo infos[] = {
      {"Vec1d", 1, 1, 1}, {"Vec2d", 2, 2, 2}, {"Vec3d", 3, 3, 3},
      {"Vec6d", 6, 6, 6}, {"Rigid2d", 3, 3, 2}, {"Rigid3d", 7, 6, 3},
  };
  return infos[static_cast<int>(t)];
}

bool state_type_from_name(std::string_view name, StateType& out) {
  for (int i = 0; i <= static_cast<int>(StateType::rigid3); ++i) {
    if (name == state_type_info(static_cast<StateType>(i)).name) {
      out = static_cast<StateType>(i);
      return true;
    }
  }
  return false;
}

bool MechanicalState::independent() const { return !node() || node()->mechanical_mapping == nullptr; }

OdeSolver::OdeSolver() = default;
OdeSolver::~OdeSolver() = default;

MechanicalOps& OdeSolver::scope() {
  if (!scope_) scope_ = std::make_unique<MechanicalOps>(*node());
  scope_->sync();
  return *scope_;
}

void ForceField::init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

void ProjectiveConstraint::init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

void Mapping::parse(AttributeMap& attrs, Diagnostics& diag) {
  if (const std::string* v = attrs.take("isMechanical")) {
    if (!map_forces.read(*v) && !v->empty())
      diag.warning(where, describe() + ": could not read value for field 'isMechanical': " + quote_value(*v));
    map_masses.read(*v);
  }
  Component::parse(attrs, diag);
}

}  // namespace sinew
