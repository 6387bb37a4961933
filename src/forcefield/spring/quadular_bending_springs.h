// QuadularBendingSprings: for each edge shared by exactly two quads, two
// springs crossing the edge between the quads' vertices (rest lengths from the
// rest positions), forces as SpringForceField, inactive below 1e-4.
// Edge j of a quad is (q[j], q[j+1]); the first quad (in order) holding an
// edge builds its springs (SOFA's QuadularBendingSprings).
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew {

class QuadularBendingSprings final : public ForceField {
 public:
  Field<double> stiffness{this, "stiffness", 100000.0, "stiffness shared by all springs", "Spring", "force/length"};
  Field<double> damping{this, "damping", 1.0, "damping shared by all springs", "Spring", "force·time/length"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the quads (default: the node's)"};

  struct Spring {
    unsigned e0 = 0, e1 = 0;
    double rest_length = 0;
    std::array<double, 9> dfdx{};
  };

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<Spring>& springs() const { return springs_; }

 private:
  bool rebuild();
  std::vector<Spring> springs_;  // two per active edge, in edge order
  std::uint64_t quads_version_ = 0;  // of the list the elements were built from
  double ks_ = 100000.0, kd_ = 1.0;
};

}  // namespace sinew
