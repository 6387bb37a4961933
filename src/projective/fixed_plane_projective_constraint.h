// FixedPlaneProjectiveConstraint (alias FixedPlaneConstraint): selects the DoFs
// whose position along `direction` lies strictly between dmin and dmax (added
// at init to the explicit `indices`) and removes the component of their
// velocity increments along `direction` (as SOFA's component of that name;
// spec/mechanics.md §4 covers the other projective constraints).
//
// SOFA quirks kept on purpose, since results are compared with SOFA's:
// - `direction` is used as written, not normalised (dx − d(d·dx));
// - the selection is strict (dmin < x·d < dmax) and only happens when
//   dmin ≠ dmax; selected DoFs are appended after the explicit indices;
// - assembled systems clear the rows/columns of every component where the
//   direction is non-zero, which matches the projection only for directions
//   along a coordinate axis;
// - positions and velocities are not projected (the DoFs stay put because their
//   increments along `direction` are removed and they start at rest);
// - Rigid3d: only the translation is projected; its direction is a Rigid
//   coordinate (centre, then quaternion) whose first 6 entries flag the
//   assembled rows.
// `indices` (with the selected points appended) follows point removals, as
// SOFA's TopologySubsetIndices.
#pragma once

#include <vector>

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class FixedPlaneProjectiveConstraint final : public ProjectiveConstraint {
 public:
  Field<std::vector<double>> direction{this, "direction", {}, "normal direction of the plane (default: 0)",
                                       "Constraint"};
  Field<double> dmin{this, "dmin", 0.0, "minimum plane distance from the origin", "Constraint", "length"};
  Field<double> dmax{this, "dmax", 0.0, "maximum plane distance from the origin", "Constraint", "length"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the fixed points", "Constraint"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int, double) override {}
  void project_position(int, double) override {}
  bool dirichlet_indices(std::vector<std::size_t>& out) override;

  // The DoFs actually constrained (explicit indices in the state, then the selected ones).
  const std::vector<unsigned>& constrained() const { return active_; }

 private:
  std::vector<double> dir_;   // direction padded to the coordinate width
  int projected_ = 0;         // leading derivative components projected (3 for rigids)
  std::vector<unsigned> active_;
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
