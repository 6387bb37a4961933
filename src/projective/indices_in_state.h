// How projective constraints read their `indices` against the state's size.
// Fixed and PartialFixed: an index past the end of the state is skipped with a
// warning (SOFA would write out of bounds), the others are kept in order.
// AffineMovement and Direction: SOFA reports such an index and removes it from
// the list itself (drop_indices_beyond_state). init_state_of_type: the state check of the
// templated ones.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/component.h"
#include "core/field.h"
#include "core/roles.h"

namespace sinew {

// Replaces `active` with the entries of `indices` below `n_dofs`.
inline void keep_indices_in_state(const Component& c, const std::vector<unsigned>& indices, std::size_t n_dofs,
                                  std::vector<unsigned>& active) {
  active.clear();
  for (unsigned i : indices) {
    if (i >= n_dofs) {
      c.msg_warning("index " + std::to_string(i) + " is out of range (the state has " + std::to_string(n_dofs) +
                    " DoFs); ignored");
      continue;
    }
    active.push_back(i);
  }
}

// Removes from `indices` (unlinking it) the entries not below `n_dofs`, each with an error, as
// SOFA's removeConstraint at init; the others keep their order.
inline void drop_indices_beyond_state(const Component& c, Field<std::vector<unsigned>>& indices, std::size_t n_dofs) {
  std::vector<unsigned> kept;
  bool dropped = false;
  for (unsigned i : indices.get()) {
    if (i < n_dofs) {
      kept.push_back(i);
      continue;
    }
    c.msg_error("index " + std::to_string(i) + " is not valid (the state has " + std::to_string(n_dofs) +
                " DoFs); it is removed");
    dropped = true;
  }
  if (!dropped) return;
  if (indices.parent()) indices.set_parent(nullptr);
  indices.set(std::move(kept));
}

}  // namespace sinew

namespace sinew {

// ProjectiveConstraint::init for a templated constraint: then the state must be of type `t`;
// false, with the component invalid and the mismatch reported, otherwise.
inline bool init_state_of_type(ProjectiveConstraint& c, StateType t) {
  c.ProjectiveConstraint::init();
  if (c.state() != ComponentState::valid) return false;
  if (c.mstate->state_type() != t) {
    c.msg_error(std::string("the mechanical state is ") + c.mstate->info().name + ", not " + state_type_info(t).name);
    c.set_state(ComponentState::invalid);
    return false;
  }
  return true;
}

}  // namespace sinew
