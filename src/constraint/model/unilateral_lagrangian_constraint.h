// UnilateralLagrangianConstraint (ex UnilateralInteractionConstraint,
// spec/interaction.md §5.6): frictional contacts between points of two Vec3d
// states (the same state for self-collision), what the FrictionContact
// response creates.
//
// Per contact: one row along the normal (mu = 0) or three (normal, t, s) with
// J = −n/−t/−s on object1's point and +n/+t/+s on object2's. Violation at the
// free positions, with SOFA's rule for the tangential part (the motion since
// the collision, cut at the moment of first contact).
//
// With `augmented` set it is SOFA's AugmentedLagrangianConstraint (what the
// AugmentedLagrangianResponseConstraint response creates): the same rows, the
// frictional blocks solved by augmented Lagrangian steps of factor epsilon
// (frictionless blocks are solved as unilateral ones, as SOFA does).
#pragma once

#include <cstdint>
#include <vector>

#include "core/constraint_problem.h"

namespace sinew {

class UnilateralLagrangianConstraint final : public LagrangianConstraint {
 public:
  struct Contact {
    int m1 = 0, m2 = 0;     // point indices in object1 / object2
    Vec3 P, Q;              // positions of object2's and object1's points when detected
    Vec3 n, t, s;           // normal (1 → 2) and tangent frame
    double distance = 0;    // distance to keep along n
    double mu = 0;          // friction coefficient (0: one row)
    double epsilon = 0;     // augmented Lagrangian penalty factor (augmented only)
    std::int64_t id = 0;    // persistent id (LCP warm start)
    std::int64_t local_id = 0;
    int row = 0;            // first row this step
    double dfree = 0;       // last normal violation
    bool active = false;    // whether it pushed in the last solve (written by the solver)
  };

  UnilateralLagrangianConstraint(MechanicalState& s1, MechanicalState& s2) : s1_(&s1), s2_(&s2) {}

  // Tolerance of each contact's block (0: the solver's).
  double custom_tolerance = 0.0;
  // Augmented Lagrangian law for the frictional blocks.
  bool augmented = false;

  void clear(std::size_t reserve);
  // A contact at the current positions of points m1 (object1) and m2 (object2).
  void add_contact(double mu, const Vec3& normal, double distance, int m1, int m2, std::int64_t id,
                   std::int64_t local_id, double epsilon = 0.0);
  const std::vector<Contact>& contacts() const { return contacts_; }
  // LCP warm start: false during the first solve after the constraint was made.
  bool yet_integrated = false;

  MechanicalState* state1() const { return s1_; }
  MechanicalState* state2() const { return s2_; }

  void build_constraint_matrix(const ConstraintParams& p, int& row) override;
  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override;
  void constraint_resolutions(const ConstraintParams& p, std::vector<ConstraintBlock>& out) override;
  // One group per contact (3 rows if the first contact has friction, else
  // 1), ids negated until the first call has passed (yet_integrated).
  void constraint_info(std::vector<BlockInfo>& blocks, std::vector<std::int64_t>& ids) override;

 private:
  MechanicalState* s1_;
  MechanicalState* s2_;
  std::vector<Contact> contacts_;
};

}  // namespace sinew
