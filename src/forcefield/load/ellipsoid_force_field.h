// EllipsoidForceField: penalty force keeping points out of (stiffness > 0)
// or inside (stiffness < 0) an axis-aligned ellipsoid, SOFA's
// EllipsoidForceField (templates Vec1d, Vec2d, Vec3d); the formula and
// SOFA's tangent are in ellipsoid_penalty.h. The tangent is kept for the
// points in contact at the last add_force.
#pragma once

#include <vector>

#include "core/roles.h"
#include "forcefield/load/ellipsoid_penalty.h"

namespace sinew {

class EllipsoidForceField final : public ForceField {
 public:
  Field<std::vector<double>> center{this, "center", {}, "ellipsoid centre (default 0)", "Ellipsoid", "length"};
  Field<std::vector<double>> vradius{this, "vradius", {}, "ellipsoid radii, one per dimension", "Ellipsoid",
                                     "length"};
  Field<double> stiffness{this, "stiffness", 500.0,
                          "penalty stiffness (positive: repulse outward, negative: keep inside)", "Ellipsoid",
                          "force/length"};
  Field<double> damping{this, "damping", 5.0, "damping per unit of normalised penetration", "Ellipsoid"};
  Field<std::vector<double>> color{this, "color", {0.0, 0.5, 1.0, 1.0}, "ellipsoid colour (viewer)",
                                   "Visualization"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  struct Contact {
    unsigned index;
    double m[3][3];
  };
  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  unsigned dim_ = 3;
  double c_[3] = {0, 0, 0}, inv_r2_[3] = {1, 1, 1};
  std::vector<Contact> contacts_;
};

}  // namespace sinew
