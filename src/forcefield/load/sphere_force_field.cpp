#include "forcefield/load/sphere_force_field.h"

#include <cmath>

#include "core/registry.h"

namespace sinew {

void SphereForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  dim_ = static_cast<unsigned>(mstate->info().deriv_width);
  const std::vector<double>& c = center.value();
  if (!c.empty() && c.size() != dim_) {
    msg_error("center must hold " + std::to_string(dim_) + " coordinates (it holds " + std::to_string(c.size()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  for (unsigned j = 0; j < 3; ++j) c_[j] = j < c.size() ? c[j] : 0.0;
  if (!(radius.value() >= 0)) {
    msg_error("radius must be positive or zero (it is " + parse::format_double(radius.value()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const VecNi<2> r = local_range.value();
  if (local_range.is_set() && (r[0] < 0 || r[1] < 0 || r[0] > r[1])) {
    msg_warning("localRange must hold two indices in increasing order: ignored");
    local_range.set(VecNi<2>(-1, -1));
  }
}

void SphereForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  contacts_.clear();
  const double r = radius.value(), r2 = r * r, k = stiffness.value(), kd = damping.value();
  const bool both = bilateral.value();
  unsigned ibegin = 0, iend = static_cast<unsigned>(x.size() / dim_);
  const VecNi<2> range = local_range.value();
  if (range[0] >= 0) ibegin = static_cast<unsigned>(range[0]);
  if (range[1] >= 0 && static_cast<unsigned>(range[1]) + 1 < iend) iend = static_cast<unsigned>(range[1]) + 1;
  for (unsigned i = ibegin; i < iend; ++i) {
    double dp[3] = {0, 0, 0}, norm2 = 0;
    for (unsigned j = 0; j < dim_; ++j) {
      dp[j] = x[dim_ * i + j] - c_[j];
      norm2 += dp[j] * dp[j];
    }
    if (!(norm2 < r2 || both)) continue;
    const double norm = std::sqrt(norm2);
    if (norm == 0.0) continue;  // at the centre: no direction to push along
    const double d = norm - r;
    const double fi = -k * d, di = -kd * d;
    Contact c{i, {0, 0, 0}, r / norm};
    for (unsigned j = 0; j < dim_; ++j) {
      f[dim_ * i + j] += dp[j] * (fi / norm) - v[dim_ * i + j] * di;
      c.normal[j] = dp[j] / norm;
    }
    contacts_.push_back(c);
  }
}

void SphereForceField::add_dforce(const MechParams& p, double kfactor) {
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  const double fact = -stiffness.value() * kfactor;
  for (const Contact& c : contacts_) {
    const double* du = &dx[dim_ * c.index];
    double dot = 0;
    for (unsigned j = 0; j < dim_; ++j) dot += du[j] * c.normal[j];
    for (unsigned j = 0; j < dim_; ++j)
      df[dim_ * c.index + j] += (c.normal[j] * (dot * c.fact) + du[j] * (1 - c.fact)) * fact;
  }
}

bool SphereForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  const double fact = -stiffness.value();
  for (const Contact& c : contacts_)
    for (unsigned l = 0; l < dim_; ++l)
      for (unsigned m = 0; m < dim_; ++m)
        K.add(s, dim_ * c.index + l, s, dim_ * c.index + m,
              (c.normal[l] * c.normal[m] * c.fact + (l == m ? 1 - c.fact : 0.0)) * fact);
  return true;
}

std::optional<double> SphereForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const double r = radius.value();
  unsigned ibegin = 0, iend = static_cast<unsigned>(x.size() / dim_);
  const VecNi<2> range = local_range.value();
  if (range[0] >= 0) ibegin = static_cast<unsigned>(range[0]);
  if (range[1] >= 0 && static_cast<unsigned>(range[1]) + 1 < iend) iend = static_cast<unsigned>(range[1]) + 1;
  double e = 0;
  for (unsigned i = ibegin; i < iend; ++i) {
    double norm2 = 0;
    for (unsigned j = 0; j < dim_; ++j) {
      const double d = x[dim_ * i + j] - c_[j];
      norm2 += d * d;
    }
    if (!(norm2 < r * r || bilateral.value()) || norm2 == 0.0) continue;
    const double d = std::sqrt(norm2) - r;
    e += 0.5 * stiffness.value() * d * d;
  }
  return e;
}

void register_sphere_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SphereForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "penalty force pushing points out of a sphere";
  info.templates = {"Vec3d", "Vec2d", "Vec1d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SphereForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
