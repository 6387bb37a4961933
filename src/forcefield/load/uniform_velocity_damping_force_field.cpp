#include "forcefield/load/uniform_velocity_damping_force_field.h"

#include "core/registry.h"

namespace sinew {

void UniformVelocityDampingForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  const StateType t = mstate->state_type();
  if (t == StateType::rigid3 || t == StateType::rigid2) {
    msg_error("rigid states are not supported");
    set_state(ComponentState::invalid);
  }
}

void UniformVelocityDampingForceField::add_force(const MechParams& p) {
  const std::vector<double>& v = mstate->read(p.v);
  std::vector<double>& f = mstate->write(p.f);
  const double c = damping_coefficient.value();
  for (std::size_t i = 0; i < f.size() && i < v.size(); ++i) f[i] -= v[i] * c;
}

void UniformVelocityDampingForceField::add_dforce(const MechParams& p, double) {
  if (!implicit.value() || p.b == 0.0) return;
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  const double bc = p.b * damping_coefficient.value();
  for (std::size_t i = 0; i < df.size() && i < dx.size(); ++i) df[i] -= dx[i] * bc;
}

bool UniformVelocityDampingForceField::build_damping(MatrixSink& B) {
  if (!implicit.value()) return true;
  const MechanicalState* s = mstate.get();
  const std::size_t n = mstate->size() * static_cast<std::size_t>(mstate->info().deriv_width);
  const double c = damping_coefficient.value();
  for (std::size_t i = 0; i < n; ++i) B.add(s, i, s, i, -c);
  return true;
}

void register_uniform_velocity_damping_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "UniformVelocityDampingForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "velocity damping force −c·v on every degree of freedom";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<UniformVelocityDampingForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
