#include "solver/ode/damp_velocity_solver.h"

#include <cmath>

#include "core/registry.h"

namespace sinew {

void DampVelocitySolver::solve(double dt, int /*x_result*/, int v_result) {
  MechanicalOps& ops = scope();
  ops.v_teq(v_result, std::exp(-rate.value() * dt));
  const double t = threshold.value();
  if (t == 0.0) return;
  const double t2 = t * t;
  for (MechanicalState* st : ops.independent_states()) {
    auto& v = st->write(v_result);
    const std::size_t w = static_cast<std::size_t>(st->info().deriv_width);
    for (std::size_t i = 0; i + w <= v.size(); i += w) {
      double n2 = 0.0;
      for (std::size_t c = 0; c < w; ++c) n2 += v[i + c] * v[i + c];
      if (n2 < t2)
        for (std::size_t c = 0; c < w; ++c) v[i + c] = 0.0;
    }
  }
}

void register_damp_velocity_solver(Registry& r) {
  ComponentInfo info;
  info.name = "DampVelocitySolver";
  info.category = "Solver/ODE";
  info.description = "reduces the velocities: v *= exp(-rate·dt), zeroed below a threshold";
  info.create = creator<DampVelocitySolver>();
  r.add(std::move(info));
}

}  // namespace sinew
