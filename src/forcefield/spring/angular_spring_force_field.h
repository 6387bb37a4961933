// AngularSpringForceField (SOFA SolidMechanics/Spring, Rigid3d): angular springs
// between consecutive frames of a chain.
//
// For the listed points i = indices[j], j ≥ 1, the rotation from frame i − 1 to
// frame i, dq = q_i · q_{i−1}⁻¹ (normalised, no hemisphere flip: its angle is in
// [0, 2π)), pulls frame i back with the torque
//   τ_i −= axis(dq) · angle(dq) · k_j          (k_j = angularStiffness[j], else [0])
// Only frame i receives it: the previous frame gets no reaction (SOFA's force).
// Its tangent is −k_j on the three rotational diagonal entries of every listed
// point, the first included (SOFA's addDForce and stiffness matrix): not the
// derivative of the force above. Neighbours are i − 1 in the state, whatever
// the list says. `limit` is read by nothing in SOFA and has no effect here.
// No potential energy (SOFA does not compute it).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class AngularSpringForceField final : public ForceField {
 public:
  Field<std::vector<unsigned>> indices{this, "indices", {}, "points held by the angular springs", "Spring"};
  Field<std::vector<double>> angular_stiffness{
      this, "angularStiffness", {}, "angular stiffness per listed point (or one for all; default 100)", "Spring",
      "torque/rad"};
  Field<std::vector<double>> limit{this, "limit", {},
                                   "angular limits (max; min): read by nothing in SOFA, no effect", "Spring"};
  Field<bool> draw_spring{this, "drawSpring", false, "draw the springs (viewer)", "Visualization"};
  Field<std::vector<double>> spring_color{this, "springColor", {0.0, 1.0, 0.0, 1.0}, "spring colour (viewer)",
                                          "Visualization"};

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

 private:
  bool indices_fit(std::size_t points);
  std::vector<double> k_;        // angularStiffness, or {100}
  unsigned max_index_ = 0;       // largest listed point, checked against the state's size
  bool warned_size_ = false;
};

}  // namespace sinew
