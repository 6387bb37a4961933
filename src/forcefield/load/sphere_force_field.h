// SphereForceField: penalty force pushing points out of a sphere (or onto
// its surface from both sides when `bilateral`), SOFA's SphereForceField
// (templates Vec1d, Vec2d, Vec3d).
//
// For a point at distance ρ = |x − c| < r from the centre, with penetration
// d = ρ − r < 0:
//     f = −k·d·(x − c)/ρ − (−c_d·d)·v
// (the damping is proportional to the penetration depth, as SOFA's). The
// tangent, kept for the points in contact at the last add_force, is the
// exact ∂f/∂x = −k·(n·nᵀ·r/ρ + (1 − r/ρ)·I), n = (x − c)/ρ.
#pragma once

#include <optional>
#include <vector>

#include "core/roles.h"

namespace sinew {

class SphereForceField final : public ForceField {
 public:
  Field<std::vector<double>> center{this, "center", {}, "sphere centre (one coordinate per dimension; default 0)",
                                    "Sphere", "length"};
  Field<double> radius{this, "radius", 1.0, "sphere radius", "Sphere", "length"};
  Field<double> stiffness{this, "stiffness", 500.0, "penalty stiffness", "Sphere", "force/length"};
  Field<double> damping{this, "damping", 5.0, "damping per unit of penetration", "Sphere", "force·time/length²"};
  Field<std::vector<double>> color{this, "color", {0.0, 0.0, 1.0, 1.0}, "sphere colour (viewer)", "Visualization"};
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1),
                              "[first, last] DoF range the sphere acts on (-1: open end)", "Sphere"};
  Field<bool> bilateral{this, "bilateral", false, "also act on the points outside the sphere", "Sphere"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  // ½·k·d² per point in contact (SOFA does not implement it).
  std::optional<double> potential_energy() const override;

  struct Contact {
    unsigned index;
    double normal[3];
    double fact;  // r/ρ
  };
  const std::vector<Contact>& contacts() const { return contacts_; }

 private:
  unsigned dim_ = 3;
  double c_[3] = {0, 0, 0};
  std::vector<Contact> contacts_;
};

}  // namespace sinew
