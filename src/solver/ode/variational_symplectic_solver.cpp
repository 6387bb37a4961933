#include "solver/ode/variational_symplectic_solver.h"

#include <cmath>

#include "core/node.h"
#include "core/profile.h"
#include "core/registry.h"

namespace sinew {

void VariationalSymplecticSolver::init() {
  if (!linear_solver) linear_solver.set(node()->find_down<LinearSolver>());
  if (!linear_solver) {
    msg_error("no linear solver found in this node or below it");
    set_state(ComponentState::invalid);
    return;
  }
  for (int* id : {&p_, &newp_, &acc_, &b_, &res_, &tmp_}) *id = MechanicalOps::alloc_vec();
  for (int* id : {&oldpos_, &x0_, &resi_}) *id = MechanicalOps::alloc_coord_vec();  // resi_: x1 - x0 per coordinate
  // SOFA opens (and empties) the file at init, whether or not the energies are saved.
  if (!file.value().empty()) {
    energies_.open(file.value(), std::ios::out);
    if (!energies_ && save_energy_in_file.value()) msg_warning("cannot open '" + file.value() + "' for writing");
  }
}

// Σ |x_i|² of a coordinate vector, summed per DOF, then per state, then over states (SOFA's vNorm²).
static double coord_norm2(const MechanicalOps& ops, int id) {
  double total = 0.0;
  for (MechanicalState* st : ops.independent_states()) {
    const auto& x = st->read(id);
    const std::size_t w = static_cast<std::size_t>(st->info().coord_width);
    double sum = 0.0;
    for (std::size_t i = 0; i + w <= x.size(); i += w) {
      double d = 0.0;
      for (std::size_t c = 0; c < w; ++c) d += x[i + c] * x[i + c];
      sum += d;
    }
    total += sum;
  }
  return total;
}

double VariationalSymplecticSolver::potential_energy(MechanicalOps& ops) const {
  double e = 0.0;
  for (ForceField* ff : ops.force_fields()) e += ff->potential_energy().value_or(0.0);
  return e;
}

void VariationalSymplecticSolver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  StepProfile& profile = node()->root()->profile();
  LinearSolver& ls = *linear_solver;
  const double h = dt, rM = rayleigh_mass.value(), rK = rayleigh_stiffness.value();
  const int pos = kPosition;

  // Momentum of the first step (or of a step starting at time 0): p = M·v.
  if (steps_done_ == 0 || node()->time.value() == 0.0) {
    ops.v_clear(p_);
    ops.add_mdx(p_, v_result, 1.0);
    const double pe = potential_energy(ops);
    if (compute_hamiltonian.value() && use_incremental_potential_energy.value()) incremental_potential_ = pe;
    if (save_energy_in_file.value()) energies_ << "time,kinetic energy,potential energy, hamiltonian energy" << std::endl;
  }
  ++steps_done_;

  if (explicit_integration.value()) {
    {
      SINEW_TIMED(profile, "solve/forces");
      ops.compute_force(kForce);
    }
    ops.v_peq(kForce, p_, 1.0 / h);
    ops.acc_from_f(acc_, kForce);
    if (rM > 0) ops.v_peq(acc_, kVelocity, -rM);
    ops.project_response(acc_);
    ops.v_eq(v_result, acc_);
    ops.v_teq(v_result, h);
    for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(x_result, pos, v_result, h);
    ops.v_clear(newp_);
    ops.add_mdx(newp_, v_result, 1.0);
    ops.v_eq(p_, newp_);
    return;
  }

  // Implicit: Newton iterations on the midpoint position q = x + res.
  ops.v_eq(oldpos_, pos);
  const double position_norm = std::sqrt(coord_norm2(ops, oldpos_));
  ops.v_eq(x0_, pos);
  ops.v_clear(res_);
  const unsigned max_iter = steps.value();
  unsigned iter = 0;
  double err = 0.0;
  while ((iter < max_iter && err > newton_error.value()) || iter == 0) {
    {
      SINEW_TIMED(profile, "solve/forces");
      ops.compute_force(kForce);
    }
    ops.v_op(b_, kForce, p_, 2.0 / h);  // b = f(q_i) + (2/h)·p
    ops.propagate_dx(res_);
    ops.add_mbk_dx(b_, 0.0, 0.0, -1.0, res_);  // b −= K·res
    ops.project_response(b_);
    {
      SINEW_TIMED(profile, "solve/build system");
      ls.build_system(ops, 4.0 / (h * h) + 4.0 * rM / h, 0.0, -1.0 - 4.0 * rK / h);
    }
    {
      SINEW_TIMED(profile, "solve/linear solve");
      ls.solve_system(ops, res_, b_);
    }
    // q_{i+1} = x + res; the change since q_i is the stopping measure.
    for (MechanicalState* st : ops.independent_states()) {
      st->add_deriv_to_coord(x_result, oldpos_, res_, 1.0);
      const auto& x1 = st->read(x_result);
      auto& x0 = st->write(x0_);
      auto& r = st->write(resi_);
      r.resize(x1.size());
      for (std::size_t i = 0; i < x1.size(); ++i) r[i] = x1[i] - x0[i];
      x0 = x1;
    }
    ops.propagate_x_and_v(x_result, kVelocity);
    err = std::sqrt(coord_norm2(ops, resi_)) / position_norm;
    ++iter;
  }

  if (compute_hamiltonian.value() && use_incremental_potential_energy.value())
    incremental_potential_ += -2.0 * ops.v_dot(kForce, res_);

  ops.v_eq(v_result, res_);
  ops.v_teq(v_result, 2.0 / h);
  // Momentum from the force at x + h/2·v₁, then x₁ = x + h/2·v₁ + h/2·v₁.
  for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(x_result, oldpos_, v_result, h / 2);
  ops.compute_force(kForce);
  ops.project_response(kForce);
  ops.v_eq(newp_, kForce);
  ops.v_teq(newp_, h / 2.0);
  ops.add_mdx(newp_, v_result, 1.0);
  for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(x_result, x_result, v_result, h / 2);

  if (compute_hamiltonian.value()) {
    // Kinetic energy ½ p·M⁻¹p with the linear solver.
    ops.v_clear(tmp_);
    ls.build_system(ops, 1.0, 0.0, 0.0);
    ls.solve_system(ops, tmp_, newp_);
    const double kinetic = 0.5 * ops.v_dot(newp_, tmp_);
    const double potential =
        use_incremental_potential_energy.value() ? incremental_potential_ : potential_energy(ops);
    hamiltonian_energy.set(kinetic + potential);
    if (save_energy_in_file.value())
      energies_ << node()->time.value() << "," << kinetic << "," << potential << "," << kinetic + potential
                << std::endl;
  }

  ops.v_eq(p_, newp_);
}

void register_variational_symplectic_solver(Registry& r) {
  ComponentInfo info;
  info.name = "VariationalSymplecticSolver";
  info.category = "Solver/ODE";
  info.description = "variational (momentum-conserving) implicit midpoint time integration, or its explicit variant";
  info.create = creator<VariationalSymplecticSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
