// FixedProjectiveConstraint: keeps listed DoFs still by zeroing their
// velocity increments (spec/mechanics.md §4). Positions are not projected:
// the DoFs stay put because they start at rest and never get a Δv.
#pragma once

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class FixedProjectiveConstraint final : public ProjectiveConstraint {
 public:
  FixedProjectiveConstraint();
  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the fixed DoFs (default: 0)", "Constraint"};
  Field<bool> fix_all{this, "fixAll", false, "fix every DoF", "Constraint"};
  Field<bool> activate_project_velocity{this, "activate_projectVelocity", false,
                                        "also zero the velocity of fixed DoFs after each step", "Constraint"};
  Field<bool> show_object{this, "showObject", true, "draw the fixed DoFs (viewer)", "Visualization"};
  Field<double> draw_size{this, "drawSize", 0.0, "point size (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override {}
  bool dirichlet_indices(std::vector<std::size_t>& out) override;
  // The fixed DoFs that exist in the state (indices filtered at init and on topology changes).
  const std::vector<unsigned>& fixed() const { return active_; }

 private:
  void zero(int id);
  std::vector<unsigned> active_;
  // Point removals (SOFA's TopologySubsetIndices): `indices` and the in-state subset follow.
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
