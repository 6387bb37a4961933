// ConicalForceField: penalty force keeping points inside a cone, SOFA's
// ConicalForceField (template Vec3d). The cone has its apex at `coneCenter`,
// its axis and height given by `coneHeight` (apex to base) and its half-angle
// `coneAngle` (degrees). A point outside it is pushed:
//   - beyond the base sphere (|x − apex| > |height|): towards the apex by
//     k·(|x − apex| − |height|), plus c_d·(penetration)·v (SOFA's sign: along the velocity);
//   - beside the cone (on the base side of the apex plane): to the nearest
//     point of the cone's side line in the plane of the axis and the point;
//   - behind the apex: to the apex;
// with force k·d·dir − c_d·(dir·v)·dir in the last two cases.
// The tangent is −k·dir·dirᵀ per point in contact (SOFA's: the curvature
// terms are dropped).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class ConicalForceField final : public ForceField {
 public:
  Field<Vec3> cone_center{this, "coneCenter", Vec3::Zero(), "apex of the cone", "Cone", "length"};
  Field<Vec3> cone_height{this, "coneHeight", Vec3::Zero(), "axis of the cone, apex to base (its length: the height)",
                          "Cone", "length"};
  Field<double> cone_angle{this, "coneAngle", 10.0, "half-angle of the cone", "Cone", "degrees"};
  Field<double> stiffness{this, "stiffness", 500.0, "penalty stiffness", "Cone", "force/length"};
  Field<double> damping{this, "damping", 5.0, "penalty damping", "Cone"};
  Field<std::vector<double>> color{this, "color", {0.0, 0.0, 1.0, 1.0}, "cone colour (viewer)", "Visualization"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  struct Contact {
    unsigned index;
    Vec3 normal;
  };
  const std::vector<Contact>& contacts() const { return contacts_; }
  // True when x is inside the cone (SOFA's isIn).
  bool is_in(const Vec3& x) const;

 private:
  std::vector<Contact> contacts_;
};

}  // namespace sinew
