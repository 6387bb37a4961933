// RotationFinder: components that know a rotation per point of their state
// (corotational FEM), SOFA's BaseRotationFinder. Used by RotationMatrixSystem,
// WarpPreconditioner and PrecomputedWarpPreconditioner.
#pragma once

#include <span>

#include "math/types.h"

namespace sinew {

class MechanicalState;

class RotationFinder {
 public:
  virtual ~RotationFinder() = default;
  // One rotation per point of rotation_state(); out.size() = its number of points.
  virtual void node_rotations(std::span<Mat3> out) const = 0;
  // The state whose points the rotations belong to.
  virtual MechanicalState* rotation_state() const = 0;
};

}  // namespace sinew
