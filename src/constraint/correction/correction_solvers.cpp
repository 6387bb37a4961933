#include "constraint/correction/correction_solvers.h"

#include "core/node.h"
#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

MatrixLinearSolver* resolve_correction_solvers(Component& owner, Link<LinearSolver>& linear, Link<OdeSolver>& ode) {
  Node& node = *owner.node();
  if (!linear) linear.set(node.find_local<LinearSolver>());
  if (!linear) {
    owner.msg_error("no linear solver linked (linearSolver) nor in this node");
    return nullptr;
  }
  auto* solver = dynamic_cast<MatrixLinearSolver*>(linear.get());
  if (!solver) {
    owner.msg_error(linear->describe() +
                    " does not assemble its matrix (SOFA refuses GraphScattered solvers here): link a direct solver "
                    "such as SparseLDLSolver or EigenSimplicialLDLT");
    return nullptr;
  }
  if (!ode) ode.set(node.find_local<OdeSolver>());
  if (!ode) ode.set(node.root()->find_down<OdeSolver>());
  if (!ode) {
    owner.msg_error("no ODE solver linked (ODESolver), in this node or anywhere from the root");
    return nullptr;
  }
  return solver;
}

}  // namespace sinew
