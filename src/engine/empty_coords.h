// An empty position list of a state type (width: its coord_width), the
// default of the engines' coordinate fields.
#pragma once

#include "core/roles.h"

namespace sinew {

inline FlatVec empty_coords(StateType t) {
  FlatVec v;
  v.width = state_type_info(t).coord_width;
  return v;
}

}  // namespace sinew
