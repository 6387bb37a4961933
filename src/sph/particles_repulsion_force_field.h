// ParticlesRepulsionForceField (SofaSphFluid): a spring pushing apart every
// pair of particles closer than `distance` (rest length `distance`, no
// attraction), damped along the relative velocity. Pairs come from the node's
// SpatialGridContainer when there is one, else from a brute-force search;
// add_dforce uses the pairs of the last add_force with SOFA's simplified
// stiffness ks·(n·dx)·n/|d|² (no geometric term).
#pragma once

#include <cstdint>
#include <vector>

#include "core/roles.h"

namespace sinew {

class ParticlesRepulsionForceField final : public ForceField {
 public:
  Field<double> distance{this, "distance", 1.0, "distance to keep between particles", "Repulsion", "length"};
  Field<double> stiffness{this, "stiffness", 100.0, "repulsion stiffness", "Repulsion", "force/length"};
  Field<double> damping{this, "damping", 0.1, "damping along the relative velocity", "Repulsion"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  // SOFA's addKToMatrix adds nothing.
  bool build_stiffness(MatrixSink&) override { return true; }

  std::size_t pair_count() const { return nb_j_.size(); }

 private:
  std::vector<std::uint32_t> pair_i_, pair_j_, row_start_, nb_j_;
};

}  // namespace sinew
