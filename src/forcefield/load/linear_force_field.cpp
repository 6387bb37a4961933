#include "forcefield/load/linear_force_field.h"

#include <string>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void LinearForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  w_ = static_cast<unsigned>(mstate->info().deriv_width);
  const auto fail = [this](const std::string& why) {
    msg_error(why);
    set_state(ComponentState::invalid);
  };
  const std::vector<double>& kt = times.value();
  const std::vector<double>& kf = forces.value();
  if (kf.size() != kt.size() * w_)
    return fail("forces holds " + std::to_string(kf.size()) + " values: expected " + std::to_string(w_) + " per key time (" +
                std::to_string(kt.size()) + " key times)");
  for (std::size_t k = 1; k < kt.size(); ++k)
    if (!(kt[k] > kt[k - 1]))
      return fail("times must increase (key " + std::to_string(k) + ": " + parse::format_double(kt[k]) + " after " +
                  parse::format_double(kt[k - 1]) + ")");
  const std::size_t n = mstate->size();
  for (unsigned i : points.value())
    if (i >= n) return fail("point index " + std::to_string(i) + " is out of range (the state has " + std::to_string(n) + " points)");
}

bool LinearForceField::force_at(double t, double* out) const {
  const std::vector<double>& kt = times.value();
  const std::vector<double>& kf = forces.value();
  if (kt.empty() || t < kt.front()) return false;
  if (t >= kt.back()) {
    for (unsigned j = 0; j < w_; ++j) out[j] = kf[(kt.size() - 1) * w_ + j];
    return true;
  }
  std::size_t k = 0;
  while (k + 1 < kt.size() && kt[k + 1] <= t) ++k;
  const double* f0 = &kf[k * w_];
  const double* f1 = &kf[(k + 1) * w_];
  const double inv = 1.0 / (kt[k + 1] - kt[k]);
  for (unsigned j = 0; j < w_; ++j) out[j] = (((f1[j] - f0[j]) * inv) * (t - kt[k]) + f0[j]) * force.value();
  return true;
}

void LinearForceField::add_force(const MechParams& p) {
  double F[6] = {};
  if (!force_at(node()->time.value(), F)) return;
  std::vector<double>& f = mstate->write(p.f);
  for (unsigned i : points.value())
    for (unsigned j = 0; j < w_; ++j) f[w_ * i + j] += F[j];
}

std::optional<double> LinearForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const unsigned cw = static_cast<unsigned>(mstate->info().coord_width);
  if (cw != w_) return std::nullopt;  // rigid: no position-force pairing
  double F[6] = {};
  if (!force_at(node()->time.value(), F)) return 0.0;
  const std::vector<double>& x = mstate->read(kPosition);
  double e = 0;
  for (unsigned i : points.value())
    for (unsigned j = 0; j < w_; ++j) e -= F[j] * x[w_ * i + j];
  return e;
}

void register_linear_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "LinearForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "force on chosen points interpolated linearly between key forces at key times";
  info.templates = {"Vec3d", "Vec2d", "Vec1d", "Vec6d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<LinearForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
