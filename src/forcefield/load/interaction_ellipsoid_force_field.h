// InteractionEllipsoidForceField: points of a Vec3 state (object1) kept
// outside (stiffness > 0) or inside (< 0) ellipsoids attached to a frame of
// a Rigid3 state (object2), with damping along the point velocity; the
// reaction goes to the frame's linear part only when object2_forces
// (spec/mechanics.md §3.12). Template "Vec3d,Rigid3d".
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class InteractionEllipsoidForceField final : public ForceField {
 public:
  Link<MechanicalState> object1{this, "object1", "Vec3 state of the points (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "Rigid3 state carrying the ellipsoids"};
  Field<std::vector<Vec3>> center{this, "center", {}, "ellipsoid centers (in the frame of object2)", "Ellipsoid"};
  Field<std::vector<Vec3>> vradius{this, "vradius", {}, "ellipsoid radii", "Ellipsoid"};
  Field<double> stiffness{this, "stiffness", 500.0,
                          "penalty stiffness; > 0 pushes points out of the ellipsoids, < 0 keeps them inside",
                          "Ellipsoid", "force/length"};
  Field<double> damping{this, "damping", 5.0, "penalty damping", "Ellipsoid", "force·time/length"};
  Field<std::vector<double>> color{this, "color", {0.0, 0.5, 1.0, 1.0}, "ellipsoid colour (viewer)",
                                   "Visualization"};
  Field<bool> draw{this, "draw", true, "draw the ellipsoids (viewer)", "Visualization"};
  Field<int> object2_dof_index{this, "object2_dof_index", 0, "index of the object2 frame carrying the ellipsoids",
                               "Ellipsoid"};
  Field<bool> object2_forces{this, "object2_forces", true, "apply the reaction forces to object2", "Ellipsoid"};
  Field<bool> object2_invert{this, "object2_invert", false, "use object2 as the rest configuration (unsupported)",
                             "Ellipsoid"};

  struct Contact {
    unsigned index = 0;
    double m[3][3] = {};  // local ∂f/∂p (frame of object2)
  };

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override { return {s1_, s2_}; }
  MechanicalState* single_state() const override { return nullptr; }
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  std::vector<Vec3> c_, inv_r2_;
  double q_[4] = {0, 0, 0, 1};  // frame orientation of the last add_force
  std::vector<Contact> contacts_;
};

}  // namespace sinew
