// BeamLinearMapping: points attached to a chain of rigid beam frames
// (spec/mechanics.md §6.8). Rigid3d → Vec3d.
//
// Beam lengths L_i = |X_i − X_{i+1}| from the initial input positions (the
// last one repeats the previous). Local point p: x = beam index + fraction,
// y and z in beam-length units (localCoord, default), or converted from world
// coordinates by walking along the beam. With j = clamp(⌊p.x⌋, 0, n−2),
// t = p.x − j, h = 3t² − 2t³:
//   r0 = R_j·(t, p.y, p.z)·L_j, r1 = R_{j+1}·(t−1, p.y, p.z)·L_j,
//   out = (c_j + r0)(1−h) + (c_{j+1} + r1)h, J: v ↦ (v_j − r0×ω_j)(1−h) + (v_{j+1} − r1×ω_{j+1})h.
#pragma once

#include "mapping/mapping_base.h"

namespace sinew {

class BeamLinearMapping final : public MappingBase {
 public:
  BeamLinearMapping() : MappingBase(StateType::rigid3, StateType::vec3) {}

  Field<bool> local_coord{
      this, "localCoord", true,
      "initial points are in beam coordinates (x = beam index + fraction) instead of world coordinates", "Mapping"};

  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;

 protected:
  bool init_mapping() override;

 private:
  std::vector<double> points_;  // local coordinates, 3 per point
  std::vector<double> length_;  // per input frame
  std::vector<double> r0_, r1_; // rotated offsets at the last apply, 3 per point
};

}  // namespace sinew
