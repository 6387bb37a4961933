// PlaneForceField: penalty force pushing points to the positive side of the
// plane x·n = d (n not normalised), with damping along the velocity; the
// stiffness −k·n·nᵀ acts on the points found in contact by the last
// add_force (spec/mechanics.md §3.9). Rigid3d: on the frame centres, no torque.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class PlaneForceField final : public ForceField {
 public:
  Field<Vec3> normal{this, "normal", Vec3(0, 1, 0), "normal of the plane", "Plane"};
  Field<double> d{this, "d", 0.0, "plane offset d (plane: normal·x = d)", "Plane"};
  Field<double> stiffness{this, "stiffness", 500.0, "penalty stiffness", "Plane", "force/length"};
  Field<double> damping{this, "damping", 5.0, "penalty damping", "Plane", "force·time/length"};
  Field<double> max_force{this, "maxForce", 0.0, "force magnitude cap per point (0: no cap)", "Plane"};
  Field<bool> bilateral{this, "bilateral", false, "push points toward the plane from both sides", "Plane"};
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1),
                              "[first, last] DoF range the plane acts on (-1: open end)", "Plane"};
  Field<bool> show_plane{this, "showPlane", false, "draw the plane (viewer)", "Visualization"};
  Field<std::vector<double>> plane_color{this, "planeColor", {0.0, 0.5, 0.2, 1.0}, "plane colour (viewer)",
                                         "Visualization"};
  Field<double> show_plane_size{this, "showPlaneSize", 10.0, "plane display size (viewer)", "Visualization"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  // ½·k·d² per point on the wrong side of the plane (either side when bilateral), d its
  // distance; none with maxForce, whose capped force derives from no such energy.
  // (SOFA does not implement it.)
  std::optional<double> potential_energy() const override;

  const std::vector<unsigned>& contacts() const { return contacts_; }

 private:
  double k_ = 500, c_ = 5, max_ = 0;
  unsigned cw_ = 3, dw_ = 3;  // coord and deriv widths (Rigid3d: 7, 6; the centre is the first 3)
  unsigned dim_ = 3;          // spatial dimension: components of the normal used
  std::vector<unsigned> contacts_;
};

}  // namespace sinew
