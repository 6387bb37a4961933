#include "forcefield/load/ellipsoid_force_field.h"

#include <string>

#include "core/registry.h"

namespace sinew {

void EllipsoidForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  dim_ = static_cast<unsigned>(mstate->info().deriv_width);
  const std::vector<double>& c = center.value();
  const std::vector<double>& r = vradius.value();
  const auto fail = [this](const std::string& why) {
    msg_error(why);
    set_state(ComponentState::invalid);
  };
  if (!c.empty() && c.size() != dim_)
    return fail("center must hold " + std::to_string(dim_) + " coordinates (it holds " + std::to_string(c.size()) +
                ")");
  if (r.size() != dim_)
    return fail("vradius must hold " + std::to_string(dim_) + " radii (it holds " + std::to_string(r.size()) + ")");
  for (unsigned j = 0; j < dim_; ++j) {
    if (!(r[j] != 0.0) || !std::isfinite(r[j]))
      return fail("vradius " + std::to_string(j) + " is " + parse::format_double(r[j]) + ": radii must be non-zero");
    c_[j] = c.empty() ? 0.0 : c[j];
    inv_r2_[j] = 1 / (r[j] * r[j]);
  }
}

void EllipsoidForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  contacts_.clear();
  const double k = stiffness.value(), kd = damping.value();
  const unsigned n = static_cast<unsigned>(x.size() / dim_);
  for (unsigned i = 0; i < n; ++i) {
    double dp[3] = {0, 0, 0};
    for (unsigned j = 0; j < dim_; ++j) dp[j] = x[dim_ * i + j] - c_[j];
    EllipsoidPenalty pen;
    if (!ellipsoid_penalty(dp, inv_r2_, dim_, k, kd, &v[dim_ * i], pen)) continue;
    for (unsigned j = 0; j < dim_; ++j) f[dim_ * i + j] += pen.force[j];
    Contact c{i, {}};
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) c.m[a][b] = pen.m[a][b];
    contacts_.push_back(c);
  }
}

void EllipsoidForceField::add_dforce(const MechParams& p, double kfactor) {
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  for (const Contact& c : contacts_) {
    const double* du = &dx[dim_ * c.index];
    for (unsigned a = 0; a < dim_; ++a) {
      double s = 0;
      for (unsigned b = 0; b < dim_; ++b) s += c.m[a][b] * du[b];
      df[dim_ * c.index + a] += s * kfactor;
    }
  }
}

bool EllipsoidForceField::build_stiffness(MatrixSink& K) {
  // SOFA's buildStiffnessMatrix adds nothing (its loop body is empty) while its
  // addDForce uses the tangent: the assembled matrix here is the tangent, so that
  // assembled and matrix-free solvers agree.
  const MechanicalState* s = mstate.get();
  for (const Contact& c : contacts_)
    for (unsigned a = 0; a < dim_; ++a)
      for (unsigned b = 0; b < dim_; ++b) K.add(s, dim_ * c.index + a, s, dim_ * c.index + b, c.m[a][b]);
  return true;
}

void register_ellipsoid_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "EllipsoidForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "penalty force keeping points out of (or inside) an ellipsoid";
  info.templates = {"Vec3d", "Vec2d", "Vec1d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<EllipsoidForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
