#include "forcefield/load/diagonal_velocity_damping_force_field.h"

#include <algorithm>
#include <string>

#include "core/registry.h"

namespace sinew {

void DiagonalVelocityDampingForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  w_ = static_cast<unsigned>(mstate->info().deriv_width);
  const std::size_t n = damping_coefficient.value().size();
  if (n % w_ != 0) {
    msg_error("dampingCoefficient holds " + std::to_string(n) + " values: expected a multiple of " +
              std::to_string(w_) + " (one " + std::to_string(w_) + "-component vector per DoF)");
    set_state(ComponentState::invalid);
    return;
  }
  count_ = n / w_;
}

double DiagonalVelocityDampingForceField::coef(std::size_t i, unsigned j) const {
  return damping_coefficient.value()[std::min(i, count_ - 1) * w_ + j];
}

void DiagonalVelocityDampingForceField::add_force(const MechParams& p) {
  if (count_ == 0) return;
  const std::vector<double>& v = mstate->read(p.v);
  std::vector<double>& f = mstate->write(p.f);
  const std::size_t n = v.size() / w_;
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < w_; ++j) f[w_ * i + j] -= v[w_ * i + j] * coef(i, j);
}

void DiagonalVelocityDampingForceField::add_dforce(const MechParams& p, double) {
  if (count_ == 0 || p.b == 0.0) return;
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  const std::size_t n = dx.size() / w_;
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < w_; ++j) df[w_ * i + j] -= dx[w_ * i + j] * coef(i, j) * p.b;
}

bool DiagonalVelocityDampingForceField::build_damping(MatrixSink& B) {
  if (count_ == 0) return true;
  const MechanicalState* s = mstate.get();
  const std::size_t n = mstate->size();
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < w_; ++j) B.add(s, w_ * i + j, s, w_ * i + j, -coef(i, j));
  return true;
}

void register_diagonal_velocity_damping_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "DiagonalVelocityDampingForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "velocity damping with a coefficient per DoF component";
  info.templates = {"Vec3d", "Vec2d", "Vec1d", "Vec6d", "Rigid3d", "Rigid2d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<DiagonalVelocityDampingForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
