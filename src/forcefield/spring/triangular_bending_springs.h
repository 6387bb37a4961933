// TriangularBendingSprings: one linear spring per edge shared by exactly two
// triangles, between the two vertices opposite the edge; rest length from
// the rest positions; forces as SpringForceField but inactive below 1e-4
// (spec/mechanics.md §3.5).
#pragma once

#include <vector>

#include "core/roles.h"
#include "forcefield/spring/spring_kernel.h"

namespace sinew {

class TriangularBendingSprings final : public ForceField {
 public:
  Field<double> stiffness{this, "stiffness", 100000.0, "stiffness shared by all springs", "Spring", "force/length"};
  Field<double> damping{this, "damping", 1.0, "damping shared by all springs", "Spring", "force·time/length"};
  Field<bool> show_springs{this, "showSprings", true, "draw the springs (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the triangles (default: the node's)"};

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<springs::LinearSpring>& spring_list() const { return springs_; }
  // Σ ½·ks·(d − L0)² of the last add_force (SOFA computes it there but does not return it).
  std::optional<double> potential_energy() const override { return energy_; }

 private:
  bool rebuild();
  std::vector<springs::LinearSpring> springs_;  // active edges only, in edge order
  std::vector<springs::Block> dfdx_;
  // Versions of the lists the springs/elements were built from (topology changes).
  std::uint64_t triangles_version_ = 0, edges_version_ = 0;
  double ks_ = 100000.0, kd_ = 1.0;
  double energy_ = 0;
};

}  // namespace sinew
