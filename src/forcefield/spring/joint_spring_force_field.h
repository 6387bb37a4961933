// JointSpringForceField: 6-D springs between frames of two Rigid3d states
// (object1, object2; both default to the node's state). Each spring holds the
// second frame at a rest offset from the first, with a stiffness per local
// axis of the first frame: hard on held axes, soft on free ones, plus angular
// limits on free rotations. Springs, parameters and defaults: joint_spring.h.
//
// As SOFA's: the stiffness used by add_dforce is the diagonal per-axis
// stiffness of the last add_force (the rotation-dependent terms of the exact
// tangent are left out), the damping kd is applied in add_force only (no
// damping matrix), and no potential energy is computed.
// build_stiffness assembles the same K as add_dforce (SOFA has no matrix for
// this component: with a direct solver it adds nothing and logs an error).
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/joint_spring.h"

namespace sinew {

class JointSpringForceField : public ForceField {
 public:
  JointSpringForceField();

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::string> spring{this, "spring", "",
                            "springs: BEGIN_SPRING i j [FREE_AXIS ..] [KS_T ..] [KS_R ..] [KS_B ..] [KD ..] "
                            "[R_LIM_X|Y|Z min max] [REST_T x y z] [REST_R qx qy qz qw] END_SPRING ...",
                            "Spring"};
  Field<std::string> infile{this, "infile", "",
                            "file of constant joint forces: one line (6 numbers, first frame's axes) read per "
                            "spring and force evaluation, from the start again at its end",
                            "Spring"};
  Field<std::string> outfile{this, "outfile", "", "file receiving the relative position, velocity and forces",
                             "Spring"};
  Field<double> period{this, "period", 0.0, "time between two outputs to outfile", "Spring", "time"};
  Field<bool> reinit_file{this, "reinit", false, "rewrite outfile from its start at each output", "Spring"};
  Field<bool> show_lawful_torsion{this, "showLawfulTorsion", false, "display the lawful part of the joint rotation",
                                  "Visualization"};
  Field<bool> show_extra_torsion{this, "showExtraTorsion", false, "display the illicit part of the joint rotation",
                                 "Visualization"};
  Field<double> show_factor_size{this, "showFactorSize", 1.0, "size factor of the debug drawings",
                                 "Visualization"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override;
  MechanicalState* single_state() const override { return s1_ && s1_ == s2_ ? s1_ : nullptr; }
  bool build_stiffness(MatrixSink& K) override;
  // potential_energy(): not provided (SOFA's getPotentialEnergy returns 0, it never sums one).

  const std::vector<joints::JointSpring>& springs() const { return springs_; }
  const std::vector<joints::JointWork>& work() const { return work_; }

 private:
  void write_output(const joints::JointSpring& s, const joints::JointWork& w, const double* x1, const double* x2,
                    const double* v1, const double* v2, const double* constant);

  std::vector<joints::JointSpring> springs_;
  std::vector<joints::JointWork> work_;
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  // False (component invalid, springs dropped) when a resized state no longer holds every spring end.
  bool sizes_ok();
  std::size_t n1_ = 0, n2_ = 0;  // state sizes the indices were checked against
  std::unique_ptr<std::ifstream> in_;
  std::unique_ptr<std::ofstream> out_;
  double last_time_ = 0;
  bool ready_ = false;  // bwd_init checked the indices against the states
};

}  // namespace sinew
