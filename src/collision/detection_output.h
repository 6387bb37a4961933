// DetectionOutput: one contact candidate found by an intersection method
// between an element of model 1 and an element of model 2
// (spec/interaction.md §2.1).
#pragma once

#include <cstdint>

#include "math/types.h"

namespace sinew {

struct DetectionOutput {
  unsigned elem1 = 0, elem2 = 0;  // element indices in model 1 and model 2
  // Identifier of the contact within its model pair: penalty contacts keep the
  // output of smallest value per id; constraint contacts use it for persistence.
  std::int64_t id = 0;
  Vec3 point1 = Vec3::Zero();  // world point on element 1
  Vec3 point2 = Vec3::Zero();  // world point on element 2
  Vec3 normal = Vec3::Zero();  // unit, from model 1 towards model 2
  double value = 0;            // distance minus the effective contact distance (< 0: penetration) [length]
};

}  // namespace sinew
