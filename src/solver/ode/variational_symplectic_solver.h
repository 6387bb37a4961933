// VariationalSymplecticSolver: variational (momentum) integrator of SOFA
// (spec/solvers.md §1.5). The momentum p is kept between steps (p = M·v on the
// first step, or on a step starting at time 0).
// Implicit (default): midpoint position q found by Newton iterations on
//   (4/h²·M + 4rM/h·M − (1 + 4rK/h)·K)·res = f(q_i) + (2/h)·p − K·res_prev,  q_{i+1} = x + res
// until |q_{i+1} − q_i| / |x| ≤ newtonError (at least one, at most `steps`);
//   v₁ = (2/h)·res;  p₁ = (h/2)·P·f(x + h/2·v₁) + M·v₁;  x₁ = x + h/2·v₁ + h/2·v₁.
// Explicit: a = P·(M⁻¹(f + p/h) − rM·v);  v₁ = h·a;  x₁ = x + h·v₁;  p₁ = M·v₁.
// With computeHamiltonian, hamiltonianEnergy = ½ p₁·M⁻¹p₁ + potential energy (incremental:
// E₀ − Σ 2 f·res), appended to `file` when saveEnergyInFile.
#pragma once

#include <fstream>
#include <string>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class VariationalSymplecticSolver final : public OdeSolver {
 public:
  Field<double> newton_error{this, "newtonError", 0.01, "relative tolerance of the Newton iterations", "Solver"};
  Field<unsigned> steps{this, "steps", 5u, "maximum number of Newton iterations", "Solver"};
  Field<double> rayleigh_stiffness{this, "rayleighStiffness", 0.0, "Rayleigh damping related to stiffness (rK)",
                                   "Solver", "time"};
  Field<double> rayleigh_mass{this, "rayleighMass", 0.0, "Rayleigh damping related to mass (rM)", "Solver", "1/time"};
  Field<bool> save_energy_in_file{this, "saveEnergyInFile", false,
                                  "append time, kinetic, potential and Hamiltonian energies to `file` each step",
                                  "Solver"};
  Field<bool> explicit_integration{this, "explicitIntegration", false, "use the explicit scheme", "Solver"};
  Field<std::string> file{this, "file", "", "CSV file of the energies (opened, emptied, at init)", "Solver"};
  Field<bool> compute_hamiltonian{this, "computeHamiltonian", true, "compute the Hamiltonian energy", "Solver"};
  Field<double> hamiltonian_energy{this, "hamiltonianEnergy", 0.0, "Hamiltonian energy of the last step (output)",
                                   "Solver"};
  Field<bool> use_incremental_potential_energy{
      this, "useIncrementalPotentialEnergy", true,
      "potential energy accumulated from the work of the forces (else the force fields' own)", "Solver"};
  Field<bool> thread_safe_visitor{this, "threadSafeVisitor", false, "no effect (SOFA allocation detail)", "Solver"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver (default: first one below this node)"};

  void init() override;
  void solve(double dt, int x_result, int v_result) override;

 private:
  double potential_energy(MechanicalOps& ops) const;

  int p_ = -1, newp_ = -1, acc_ = -1, oldpos_ = -1, x0_ = -1, resi_ = -1, b_ = -1, res_ = -1, tmp_ = -1;
  long steps_done_ = 0;
  double incremental_potential_ = 0.0;
  std::ofstream energies_;
};

}  // namespace sinew
