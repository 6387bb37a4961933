// DirectionProjectiveConstraint (old name ProjectDirectionConstraint): listed
// DoFs may only move along `direction`, on the line through where they were at
// init (as SOFA's component of that name; Vec3d and Vec2d).
//
// As SOFA builds it at init (reinit): the direction is normalised and written
// back; the projection matrix is block diagonal over the DoFs of that time,
// n·nᵀ on the listed DoFs and the identity elsewhere, filled by walking the
// sorted indices alongside the DoFs (so a repeated index stops the walk: the
// DoFs listed after it stay free, as in SOFA); the line origins are the listed
// DoFs' positions, appended (never cleared) in list order.
//   response, velocity: v_i ← P_i·v_i (rows summed left to right);
//   position: x_k ← o_k + n·((x_k − o_k)·n) for the k-th listed DoF.
// `indices` follows point removals, the matrix and the origins do not (SOFA
// rebuilds neither): after a removal the matrix still acts on the DoF numbers
// of init, and the k-th listed DoF uses the k-th origin.
// Assembled systems and constraint rows are not projected (SOFA implements
// neither; both report it).
#pragma once

#include <vector>

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class DirectionProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit DirectionProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the projected DoFs (default: 0)",
                                       "Constraint"};
  Field<double> draw_size{this, "drawSize", 0.0, "size of the drawn DoFs: 0 points, > 0 sphere radius (viewer)",
                          "Visualization"};
  // A point of the state's dimension: missing values are 0, extra values are ignored.
  Field<std::vector<double>> direction{this, "direction", {}, "direction of the line (normalised at init)",
                                       "Constraint"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void reinit() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int v, double) override { project_response(v); }
  void project_position(int x, double) override;

  // The normalised direction and whether each DoF (as numbered at init) is projected.
  const std::vector<double>& unit_direction() const { return n_; }
  const std::vector<char>& projected() const { return projected_; }

 private:
  StateType type_;
  int d_ = 3;                    // spatial dimension (2 or 3)
  std::vector<double> n_;        // unit direction
  std::vector<double> P_;        // d×d block n·nᵀ, row-major
  std::vector<char> projected_;  // per DoF at init: the block is P_ (else the identity)
  std::vector<double> origin_;   // d per origin, appended at each reinit
  bool warned_rows_ = false;
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
