#include "forcefield/load/sphere_force_field.h"

#include <cmath>
#include <string>

#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

void SphereForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (radius.value() < 0)
    diag.error(where, describe() + ": radius must not be negative (got " + parse::format_double(radius.value()) + ")");
}

void SphereForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d state (got " + std::string(mstate->info().name) + ")");
    set_state(ComponentState::invalid);
  }
}

void SphereForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  contacts_.clear();
  const Vec3 c = center.value();
  const double r = radius.value(), r2 = r * r;
  const double k = stiffness.value(), kd = damping.value();
  unsigned ibegin = 0, iend = static_cast<unsigned>(x.size() / 3);
  const VecNi<2> range = local_range.value();
  if (range[0] >= 0) ibegin = static_cast<unsigned>(range[0]);
  if (range[1] >= 0 && static_cast<unsigned>(range[1]) + 1 < iend) iend = static_cast<unsigned>(range[1]) + 1;
  for (unsigned i = ibegin; i < iend; ++i) {
    const double dp[3] = {x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]};
    const double norm2 = dp[0] * dp[0] + dp[1] * dp[1] + dp[2] * dp[2];
    if (!(norm2 < r2) && !bilateral.value()) continue;
    const double norm = std::sqrt(norm2);
    const double d = norm - r;
    const double fi = -k * d, di = -kd * d;
    for (int a = 0; a < 3; ++a) f[3 * i + a] += dp[a] * (fi / norm) - v[3 * i + a] * di;
    contacts_.push_back({i, Vec3(dp[0] / norm, dp[1] / norm, dp[2] / norm), r / norm});
  }
}

void SphereForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  const double fact = -stiffness.value() * kfactor;
  for (const Contact& c : contacts_) {
    const double* du = &dx[3 * c.index];
    const double dot = du[0] * c.normal[0] + du[1] * c.normal[1] + du[2] * c.normal[2];
    for (int a = 0; a < 3; ++a) df[3 * c.index + a] += (c.normal[a] * (dot * c.fact) + du[a] * (1 - c.fact)) * fact;
  }
}

bool SphereForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  const double fact = -stiffness.value();
  for (const Contact& c : contacts_) {
    Mat3 m;
    for (int l = 0; l < 3; ++l)
      for (int k = 0; k < 3; ++k) m(l, k) = (c.normal[l] * c.normal[k] * c.fact + (l == k ? 1 - c.fact : 0.0)) * fact;
    K.add_block(s, 3 * c.index, s, 3 * c.index, m);
  }
  return true;
}

void register_sphere_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SphereForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "penalty force keeping points out of a sphere";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SphereForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
