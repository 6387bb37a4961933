// The solvers a compliance-from-the-system correction works with
// (LinearSolverConstraintCorrection, GenericConstraintCorrection), found as
// SOFA finds them: the linked linear solver, else the first of the owner's
// node, which must assemble its matrix (A⁻¹ comes from its factorisation);
// the linked ODE solver, else the node's, else the first from the root (its
// integration factors scale the compliance and the correction).
#pragma once

#include "core/component.h"
#include "core/roles.h"

namespace sinew {

class MatrixLinearSolver;

// Sets unset links to their defaults and returns the matrix solver; nullptr
// after msg_error on `owner` when a solver is missing or assembles nothing.
MatrixLinearSolver* resolve_correction_solvers(Component& owner, Link<LinearSolver>& linear, Link<OdeSolver>& ode);

}  // namespace sinew
