// TransformEngine: output_position = transformed input_position
// (spec/mechanics.md §7.8): scale, Euler rotation (degrees), quaternion
// rotation, translation, each applied only when not neutral, in that order
// (reversed and inverted when `inverse`). Rigid coordinates: the centre is
// transformed and the orientation pre-multiplied by the rotation.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class TransformEngine final : public Engine {
 public:
  explicit TransformEngine(StateType type);

  Field<FlatVec> input_position;
  Field<FlatVec> output_position;
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation vector (x, y, z)", "Transformation", "length"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation (Euler angles in degrees)", "Transformation", "degrees"};
  Field<VecN<4>> quaternion{this, "quaternion", VecN<4>(0, 0, 0, 1), "rotation quaternion (qx qy qz qw)",
                            "Transformation"};
  Field<Vec3> scale{this, "scale", Vec3::Ones(), "scale factors", "Transformation"};
  Field<bool> inverse{this, "inverse", false, "apply the inverse transformation", "Transformation"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  StateType type_;
};

}  // namespace sinew
