// PCGLinearSolver: preconditioned conjugate gradient, matrix-free
// (template GraphScattered only; spec/solvers.md §3.2). Old name
// ShewchukPCGLinearSolver (renamed table in core/registry.cpp).
//
// Always warm-started from the incoming x (the ODE's previous solution).
// Stops when rᵀz ≤ tolerance·bᵀb (squared, preconditioned) or after
// `iterations`. z = P⁻¹r is computed by the linked preconditioner (a matrix
// linear solver) on its own linear system, which the PCG's
// PreconditionedMatrixFreeSystem assembles every assemblingRate steps.
#pragma once

#include <vector>

#include "core/roles.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/preconditioned_matrix_free_system.h"

namespace sinew {

class PCGLinearSolver final : public LinearSolver {
 public:
  Field<unsigned> iterations{this, "iterations", 25u, "maximum number of PCG iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 1e-5, "stop when |r|²/|b|² falls below this value", "Solver"};
  Field<bool> use_precond{this, "use_precond", true, "apply the preconditioner", "Solver"};
  Field<unsigned> update_step{this, "update_step", 1u,
                              "deprecated: use the assemblingRate of the PreconditionedMatrixFreeSystem", "Solver"};
  Field<bool> build_precond{this, "build_precond", true, "deprecated: has no effect", "Solver"};
  Field<bool> parallel_inverse_product{this, "parallelInverseProduct", false, "no effect for PCG", "Solver"};
  Link<LinearSolver> preconditioner{this, "preconditioner", "linear solver acting as preconditioner"};
  Link<Component> linear_system{this, "linearSystem",
                                "linear system of this solver (a PreconditionedMatrixFreeSystem)"};

  void init() override;
  void bwd_init() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }
  void build_system(MechanicalOps& ops, double m, double b, double k) override;
  void solve_system(MechanicalOps& ops, int x, int rhs) override;

  PreconditionedMatrixFreeSystem* system() const { return system_; }
  // Iterations of the last solve (loop passes) and its rᵀz/bᵀb history.
  int last_iterations() const { return last_iterations_; }
  const std::vector<double>& last_errors() const { return errors_; }

 private:
  void apply_preconditioner(MechanicalOps& ops, int z, int r);

  PreconditionedMatrixFreeSystem* system_ = nullptr;
  MatrixLinearSolver* precond_ = nullptr;
  int r_ = -1, w_ = -1, s_ = -1;
  int newton_iter_ = 0;
  int last_iterations_ = 0;
  std::vector<double> errors_;
};

}  // namespace sinew
