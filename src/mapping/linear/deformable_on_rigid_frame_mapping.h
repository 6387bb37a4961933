// DeformableOnRigidFrameMapping (SOFA Mapping/Linear, template
// Vec3d,Rigid3d,Vec3d): points of a deformable state expressed in a rigid
// frame. Two inputs: `input1` the local (deformable) points p_i, `input2` the
// rigid frames; one output, the world points
//   out_i = R(q)·p_i + c          (frame `index`, or per `repartition`)
// with R the quaternion's matrix as SOFA writes it (not renormalised).
//
// Velocities use the frame `index` only, with r_i = R·p_i kept from the last
// apply and the orientation q of the last frame used there (SOFA's rootX):
//   out_i = ω × r_i + q·ṗ_i·q⁻¹ + v
// Forces: frame gets (Σ f_i, Σ r_i × f_i), point i gets q⁻¹·f_i·q. Constraint
// rows do the same per row, the frame's part scaled by
// rootLinearForceScaleFactor / rootAngularForceScaleFactor, and with
// indexFromEnd the frame is counted from the end of input1 (SOFA's quirk).
// No geometric stiffness (SOFA's applyDJT is empty). Without input2 the
// mapping copies input1 and carries no constraint row (SOFA).
#pragma once

#include <vector>

#include "mapping/mapping_base.h"

namespace sinew {

class DeformableOnRigidFrameMapping final : public Mapping {
 public:
  DeformableOnRigidFrameMapping();

  StateLink input1;
  StateLink input2;
  StateLink output_link;
  Field<unsigned> index{this, "index", 0u, "rigid frame of input2 the points are expressed in", "Mapping"};
  Field<bool> index_from_end{this, "indexFromEnd", false, "count `index` from the last frame", "Mapping"};
  Field<std::vector<unsigned>> repartition{
      this, "repartition", {},
      "output points per frame (one value: the same for every frame; empty: all on frame `index`)", "Mapping"};
  Field<bool> global_to_local_coords{this, "globalToLocalCoords", false,
                                     "whether the outputs start in world coordinates (read by nothing in SOFA)",
                                     "Mapping"};
  Field<double> root_angular_force_scale_factor{this, "rootAngularForceScaleFactor", 1.0,
                                                "factor on the torque constraint rows put on the frame", "Mapping"};
  Field<double> root_linear_force_scale_factor{this, "rootLinearForceScaleFactor", 1.0,
                                               "factor on the force constraint rows put on the frame", "Mapping"};

  std::vector<MechanicalState*> inputs() const override;
  MechanicalState* output() const override { return out_; }

  void init() override;
  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool jacobian(std::vector<JacobianEntry>& out) override;
  bool apply_jt_constraints() override;

 private:
  bool resolve_links();
  // Frame `index` among `frames` rigid DoFs (counted from the end with
  // indexFromEnd); −1, with one error, when out of range.
  long frame(std::size_t frames, std::size_t from_end_count);
  std::size_t points() const { return rotated_.size() / 3; }

  MechanicalState* in_ = nullptr;    // input1, Vec3d
  MechanicalState* root_ = nullptr;  // input2, Rigid3d (null: copy)
  MechanicalState* out_ = nullptr;
  std::vector<double> rotated_;      // R·p_i of the last apply
  double root_x_[7] = {0, 0, 0, 0, 0, 0, 1};  // last frame used by apply (SOFA's rootX)
  bool warned_range_ = false, warned_repartition_ = false, warned_no_root_ = false;
};

}  // namespace sinew
