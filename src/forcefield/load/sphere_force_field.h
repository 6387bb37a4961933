// SphereForceField: penalty force pushing points out of a sphere (SOFA's
// Sofa.Component.MechanicalLoad): a point at distance d < r from the centre
// gets −k(d − r) along the radius, minus damping c(d − r)·v; with `bilateral`
// points outside are pulled back to the surface too. The stiffness acts on
// the points found in contact by the last add_force.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class SphereForceField final : public ForceField {
 public:
  Field<Vec3> center{this, "center", Vec3(0, 0, 0), "sphere centre", "Sphere", "length"};
  Field<double> radius{this, "radius", 1.0, "sphere radius", "Sphere", "length"};
  Field<double> stiffness{this, "stiffness", 500.0, "penalty stiffness", "Sphere", "force/length"};
  Field<double> damping{this, "damping", 5.0, "penalty damping", "Sphere"};
  Field<std::string> color{this, "color", "0 0 1 1", "sphere colour (viewer)", "Visualization"};
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1),
                              "[first, last] DoF range the sphere acts on (-1: open end)", "Sphere"};
  Field<bool> bilateral{this, "bilateral", false, "act on both sides of the sphere surface", "Sphere"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

 private:
  struct Contact {
    unsigned index;
    Vec3 normal;
    double fact;  // r / |x − c|
  };
  std::vector<Contact> contacts_;
};

}  // namespace sinew
