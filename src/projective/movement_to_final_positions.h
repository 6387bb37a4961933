// What AffineMovementProjectiveConstraint and PatchTestMovementProjectiveConstraint share
// (SOFA's two components of those names have the same time law): listed DoFs move from
// their first positions x0 to final positions xf, linearly in time between
// beginConstraintTime and endConstraintTime; the subclass says how xf follows from x0.
//
//   begin < time ≤ end: x = ((xf − x0)·time + (x0·end − xf·begin)) / (end − begin)
//        (centres only for rigids); time > end: x = xf (whole coordinate);
//   velocities and responses of the listed DoFs are always zeroed.
// x0 and xf (and the same for `meshIndices`, kept as SOFA keeps them) are taken at the
// first position projection and never again: not on reset, not when points are removed —
// after a removal a renumbered DoF reads the x0/xf slot of its new index, as in SOFA.
// `indices` follows point removals. Assembled systems and constraint rows are not
// projected (SOFA implements neither; the rows report it).
#pragma once

#include <vector>

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class MovementToFinalPositions : public ProjectiveConstraint {
 public:
  explicit MovementToFinalPositions(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> mesh_indices{this, "meshIndices", {}, "indices of the mesh", "Constraint"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the constrained points", "Constraint"};
  Field<double> begin_time{this, "beginConstraintTime", 0.0, "time the movement starts", "Constraint", "time"};
  Field<double> end_time{this, "endConstraintTime", 20.0, "time the movement ends", "Constraint", "time"};
  Field<bool> draw_constrained_points{this, "drawConstrainedPoints", false, "draw the constrained points (viewer)",
                                      "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override;

  // Positions taken at the first projection and their images (coordinate width per DoF,
  // sized to the state at that time).
  const std::vector<double>& initial_positions() const { return x0_; }
  const std::vector<double>& final_positions() const { return xf_; }

 protected:
  // xf of the DoFs in idx (those below xf's size), from their first positions x0 and the
  // positions x being projected.
  virtual void final_of(const std::vector<unsigned>& idx, const std::vector<double>& x,
                        const std::vector<double>& x0, std::vector<double>& xf) const = 0;

  StateType type_;
  int cw_ = 3, w_ = 3;

 private:
  void zero(int id);
  void take_initial(const std::vector<unsigned>& idx, const std::vector<double>& x, std::vector<double>& x0) const;
  void take_final(const std::vector<unsigned>& idx, const std::vector<double>& x, std::vector<double>& x0,
                  std::vector<double>& xf) const;

  std::vector<double> x0_, xf_, mesh_x0_, mesh_xf_;
  bool warned_rows_ = false;
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
