// BilateralLagrangianConstraint (ex BilateralInteractionConstraint,
// spec/interaction.md §5.6): point first_point[i] of object1 and
// second_point[i] of object2 are held together (at rest_vector[i] apart).
//
// Vec3d: three rows per pair, J = −e_x, −e_y, −e_z on object1's point and +e
// on object2's; violation x2 − x1 − rest at the free positions (velocity
// order: (v2 − v1) + (x2 − x1 + rest)/dt, SOFA's sign). Each pair is one 3×3
// bilateral block scaled by `load` and warm-started with the previous forces.
//
// Rigid3d: six rows per pair (translations, then rotations, J = ∓e on the
// linear then the angular part); violation: centre difference and the
// rotation vector from orientation 1 to orientation 2 expressed by frame 1
// (SOFA's dof1.rotate(angularDisplacement(q2, q1))), minus rest_vector[i]
// (six numbers). With keepOrientationDifference, frame 1 is first moved by
// the difference measured at init (rest_vector is then ignored). As in SOFA,
// the Rigid3d variant always uses position violations, ignores `activate`
// and `load`, and its two 3×3 blocks per pair start from zero force.
//
// StickContactConstraint creates one and fills it with add_contact().
#pragma once

#include <array>
#include <vector>

#include "core/constraint_problem.h"

namespace sinew {

class BilateralLagrangianConstraint final : public LagrangianConstraint {
 public:
  explicit BilateralLagrangianConstraint(StateType type = StateType::vec3);

  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::vector<unsigned>> first_point{this, "first_point", {}, "indices of the constrained points on object1",
                                           "Constraint"};
  Field<std::vector<unsigned>> second_point{this, "second_point", {},
                                            "indices of the constrained points on object2", "Constraint"};
  // One derivative per pair: 3 numbers (Vec3d) or 6 (Rigid3d: translation, rotation vector).
  Field<FlatVec> rest_vector;
  Field<bool> activate{this, "activate", true, "whether the constraint is active (Vec3d)", "Constraint"};
  Field<bool> keep_orientation_difference{this, "keepOrientationDifference", false,
                                          "keep the initial orientation difference (Rigid3d only)", "Constraint"};
  Field<double> load{this, "load", 1.0, "factor on the constraint force, in [0, 1] (incremental loading, Vec3d)",
                     "Constraint"};
  // When set, a point removed from that topology drops the pairs naming it (the first one found
  // per removed point, rest vector included), and the list of that side follows the renumbering.
  Link<MeshTopologyBase> topology1{this, "topology1", "topology of object1 (point removals drop pairs)"};
  Link<MeshTopologyBase> topology2{this, "topology2", "topology of object2 (point removals drop pairs)"};

  // For responses: the two states, set before init.
  void set_states(MechanicalState& s1, MechanicalState& s2) {
    object1.set(&s1);
    object2.set(&s2);
  }
  // Appends the pair (m1, m2) with its rest vector (Vec3d; SOFA's addContact
  // with rest = Q − P).
  void add_contact(unsigned m1, unsigned m2, const Vec3& rest);
  // Drops every pair (and the rest vectors).
  void clear_pairs();

  void init() override;
  void bwd_init() override;
  void reinit() override { prev_forces_.clear(); }

  void build_constraint_matrix(const ConstraintParams& p, int& row) override;
  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override;
  void constraint_resolutions(const ConstraintParams& p, std::vector<ConstraintBlock>& out) override;

 private:
  std::size_t pairs() const { return std::min(first_point.value().size(), second_point.value().size()); }
  // SOFA's Rigid3d variant never checks `activate`.
  std::size_t active_pairs() const { return activate.value() || rigid_ ? pairs() : 0; }
  void violation_vec3(const ConstraintParams& p, std::vector<double>& dfree);
  void violation_rigid3(const ConstraintParams& p, std::vector<double>& dfree);

  // Point removals on topology1 / topology2 (SOFA's removeContact callback, then the
  // TopologySubsetIndices default on that side's list).
  void on_points_removed(int side, const MeshTopologyBase& t, const std::vector<unsigned>& decreasing);
  struct Follow final : TopologyHandler {
    BilateralLagrangianConstraint* owner = nullptr;
    int side = 0;
    void apply(const MeshTopologyBase& t, const TopologyChange& c) override;
  } follow1_, follow2_;

  bool rigid_;
  int width_;                                       // rows per pair: 3 or 6
  std::vector<int> rows_;                           // first row of each pair this step
  std::vector<std::array<double, 3>> prev_forces_;  // warm start, per pair (Vec3d)
  std::vector<std::array<double, 7>> initial_difference_;  // Rigid3d keepOrientationDifference
};

}  // namespace sinew
