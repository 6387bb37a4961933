// Fixed and PartialFixed projective constraints read their `indices` the same
// way: an index past the end of the state is skipped with a warning (SOFA
// would write out of bounds), the others are kept in order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/component.h"

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

}  // namespace sinew
