// What the Lagrangian constraint models share: finding their states and
// reading the vectors a constraint step names.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "core/constraint_problem.h"

namespace sinew {

// The state type a component was created for (its template), `fallback`
// when it has none or an unknown one.
StateType template_state_type(const Component& c, StateType fallback);

// A single-state constraint's `mstate` (default: the node's state, searched
// upwards), checked against `want`. False after an error (the component is
// then invalid).
bool resolve_constraint_state(Component& c, Link<MechanicalState>& mstate, StateType want);

// A pair constraint's object1 / object2 (default: the node's state), both of
// type `want`. False after an error (the component is then invalid).
bool resolve_pair_states(Component& c, Link<MechanicalState>& object1, Link<MechanicalState>& object2, StateType want);

// Vector `id` of a constraint step (free positions, free velocities) on `s`,
// falling back to the standard vector of `role` on mapped states.
inline const std::vector<double>& step_vec(const MechanicalState& s, int id, int role) {
  return s.read(vec_for(s, id, role));
}

}  // namespace sinew
