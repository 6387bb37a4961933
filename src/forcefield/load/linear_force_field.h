// LinearForceField: a force on chosen points, linearly interpolated between
// key forces at key times, SOFA's LinearForceField (templates Vec1d, Vec2d,
// Vec3d, Vec6d, Rigid3d).
//
// At time t (the context time when forces are computed):
//   t < times[0] (or no key): no force;
//   times[k] ≤ t < times[k+1]: force·(F_k + (F_{k+1} − F_k)·(t − times[k])/(times[k+1] − times[k]));
//   t ≥ last time: the last key force, *not* scaled by `force` (SOFA's rule).
// Key times must increase (SOFA assumes it; Sinew checks it). No stiffness.
#pragma once

#include <optional>
#include <vector>

#include "core/roles.h"

namespace sinew {

class MeshTopologyBase;

class LinearForceField final : public ForceField {
 public:
  Field<std::vector<unsigned>> points{this, "points", {}, "indices of the points the force is applied to", "Load"};
  Field<double> force{this, "force", 1.0, "scale of the interpolated key forces", "Load"};
  Field<std::vector<double>> times{this, "times", {}, "key times, increasing", "Load", "time"};
  Field<std::vector<double>> forces{this, "forces", {}, "key forces, one derivative-sized vector per key time",
                                    "Load", "force"};
  Field<double> arrow_size_coef{this, "arrowSizeCoef", 0.0, "size of the drawn arrows (viewer; 0: none)",
                                "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the points (accepted)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams&, double) override {}
  bool build_stiffness(MatrixSink&) override { return true; }
  // −Σ F(t)·x_i over the loaded points (Vec templates; SOFA's sums over the
  // first points instead of the loaded ones).
  std::optional<double> potential_energy() const override;

  // The force applied to each loaded point at time t (false: none).
  bool force_at(double t, double* out) const;

 private:
  unsigned w_ = 3;
};

}  // namespace sinew
