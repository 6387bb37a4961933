// GearSpringForceField: gear couplings between the frames of two Rigid3d
// states (object1, object2; both default to the node's state). Each spring
// holds two gears on their pivots and ties their rotations about their free
// axes by a gear ratio. Springs, parameters and kernels: gear_spring.h.
//
// As SOFA's: the angles are accumulated in add_force (one call per force
// evaluation), the damping kd is applied in add_force only, the stiffness of
// add_dforce is SOFA's (hard stiffnesses in the pivot's frame and the gear
// coupling; not the exact derivative of the force), and no potential energy
// is computed. build_stiffness assembles the same K as add_dforce (SOFA has
// none for this component).
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/gear_spring.h"

namespace sinew {

class GearSpringForceField final : public ForceField {
 public:
  GearSpringForceField();

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::string> spring{this, "spring", "",
                            "springs: BEGIN_SPRING pivot1 gear1 pivot2 gear2 [AXIS a1 a2] [KS_T hard] "
                            "[KS_R soft hard] [KD kd] [RATIO r] END_SPRING ...",
                            "Spring"};
  Field<std::string> filename{this, "filename", "", "file receiving the angles and the gear force", "Spring"};
  Field<double> period{this, "period", 0.0, "time between two outputs to the file", "Spring", "time"};
  Field<bool> reinit_file{this, "reinit", false, "rewrite the file from its start at each output", "Spring"};
  Field<double> show_factor_size{this, "showFactorSize", 1.0, "size of the drawn gear axes", "Visualization"};

  void init() override;
  void bwd_init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override;
  MechanicalState* single_state() const override { return s1_ && s1_ == s2_ ? s1_ : nullptr; }
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<gears::GearSpring>& springs() const { return springs_; }
  const std::vector<gears::GearWork>& work() const { return work_; }

 private:
  bool indices_ok();
  void write_output(const gears::GearWork& w);

  std::vector<gears::GearSpring> springs_;
  std::vector<gears::GearWork> work_;
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  std::unique_ptr<std::ofstream> out_;
  double last_time_ = 0;
  bool ready_ = false;  // bwd_init checked the indices against the states
};

}  // namespace sinew
