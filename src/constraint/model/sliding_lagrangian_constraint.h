// SlidingLagrangianConstraint's picture (its class is private to its .cpp): what SOFA's draw()
// shows of it.
#pragma once

#include "math/types.h"

namespace sinew {

class Component;

struct SlidingPicture {
  Vec3 point = Vec3::Zero();    // sliding_point of object1
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();  // the axis ends on object2
  bool tied = false;            // the last build had three directions (A and B coincide)
};

// The picture of `c` when it is a valid SlidingLagrangianConstraint (false otherwise).
bool sliding_picture(const Component& c, SlidingPicture& out);

}  // namespace sinew
