#include "forcefield/load/plane_force_field.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void PlaneForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() == StateType::vec6) {
    msg_error("Vec6d states are not supported (Vec1d, Vec2d, Vec3d, Rigid2d, Rigid3d)");
    set_state(ComponentState::invalid);
    return;
  }
  // Rigid frames: the plane acts on the centres; no torque (SOFA's DPos is the translation).
  // 1D and 2D states use the first components of the normal.
  dim_ = static_cast<unsigned>(mstate->info().spatial_dim);
  cw_ = mstate->info().coord_width;
  dw_ = mstate->info().deriv_width;
  k_ = stiffness.get();
  c_ = damping.get();
  max_ = max_force.get();
  if (k_ < 0) {
    msg_warning("stiffness " + parse::format_double(k_) + " is negative: using 500");
    k_ = 500;
  }
  if (c_ < 0) {
    msg_warning("damping " + parse::format_double(c_) + " is negative: using 5");
    c_ = 5;
  }
  if (max_ < 0) {
    msg_warning("maxForce " + parse::format_double(max_) + " is negative: using 0 (no limit)");
    max_ = 0;
  }
  const VecNi<2> r = local_range.get();
  if (local_range.is_set() && (r[0] < 0 || r[1] < 0 || r[0] > r[1])) {
    msg_warning("localRange must hold two indices in increasing order: ignored");
    local_range.set(VecNi<2>(-1, -1));
  }
}

void PlaneForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  contacts_.clear();
  unsigned ibegin = 0, iend = static_cast<unsigned>(x.size() / cw_);
  const VecNi<2> r = local_range.value();
  if (r[0] >= 0) ibegin = static_cast<unsigned>(r[0]);
  if (r[1] >= 0 && static_cast<unsigned>(r[1]) + 1 < iend) iend = static_cast<unsigned>(r[1]) + 1;
  const double limit = max_ * max_;
  const Vec3 n = normal.value();
  const double pd = d.value();
  const bool both_sides = bilateral.value();
  if (dim_ == 3 && cw_ == 3 && limit == 0) {
    // Vec3d without a force limit (SPH tanks: thousands of particles, five
    // planes): the general loop below with its component loops unrolled.
    const double n0 = n[0], n1 = n[1], n2 = n[2], k = k_, c = c_;
    for (unsigned i = ibegin; i < iend; i++) {
      const double* xi = &x[3 * i];
      double dist = 0.0;
      dist += xi[0] * n0;
      dist += xi[1] * n1;
      dist += xi[2] * n2;
      dist -= pd;
      if (both_sides || dist < 0) {
        const double fi = -k * dist;
        const double di = -c * dist;
        const double* vi = &v[3 * i];
        double* fo = &f[3 * i];
        fo[0] += n0 * fi - vi[0] * di;
        fo[1] += n1 * fi - vi[1] * di;
        fo[2] += n2 * fi - vi[2] * di;
        contacts_.push_back(i);
      }
    }
    return;
  }
  for (unsigned i = ibegin; i < iend; i++) {
    const double* xi = &x[cw_ * i];
    double dist = 0.0;
    for (unsigned c = 0; c < dim_; ++c) dist += xi[c] * n[c];
    dist -= pd;
    if (both_sides || dist < 0) {
      const double fi = -k_ * dist;
      const double di = -c_ * dist;
      double F[3] = {0, 0, 0};
      for (unsigned c = 0; c < dim_; ++c) F[c] = n[c] * fi - v[dw_ * i + c] * di;
      const double amp = F[0] * F[0] + F[1] * F[1] + F[2] * F[2];
      if (limit > 0 && amp > limit) {
        const double sc = std::sqrt(limit / amp);
        for (double& c : F) c *= sc;
      }
      for (unsigned c = 0; c < dim_; ++c) f[dw_ * i + c] += F[c];
      contacts_.push_back(i);
    }
  }
}

std::optional<double> PlaneForceField::potential_energy() const {
  if (state() != ComponentState::valid || max_ > 0) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  unsigned ibegin = 0, iend = static_cast<unsigned>(x.size() / cw_);
  const VecNi<2> r = local_range.value();
  if (r[0] >= 0) ibegin = static_cast<unsigned>(r[0]);
  if (r[1] >= 0 && static_cast<unsigned>(r[1]) + 1 < iend) iend = static_cast<unsigned>(r[1]) + 1;
  const Vec3 n = normal.value();
  double e = 0;
  for (unsigned i = ibegin; i < iend; i++) {
    const double* xi = &x[cw_ * i];
    double dist = 0.0;
    for (unsigned c = 0; c < dim_; ++c) dist += xi[c] * n[c];
    dist -= d.value();
    if (bilateral.value() || dist < 0) e += 0.5 * k_ * dist * dist;
  }
  return e;
}

void PlaneForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  const double fact = -k_ * kfactor;
  const Vec3 n = normal.value();
  if (dim_ == 3) {
    const double n0 = n[0], n1 = n[1], n2 = n[2];
    const unsigned w = dw_;
    for (unsigned i : contacts_) {
      const double* dxi = &dx[w * i];
      double dot = 0.0;
      dot += dxi[0] * n0;
      dot += dxi[1] * n1;
      dot += dxi[2] * n2;
      const double t = fact * dot;
      double* dfi = &df[w * i];
      dfi[0] += n0 * t;
      dfi[1] += n1 * t;
      dfi[2] += n2 * t;
    }
    return;
  }
  for (unsigned i : contacts_) {
    const double* dxi = &dx[dw_ * i];
    double dot = 0.0;
    for (unsigned c = 0; c < dim_; ++c) dot += dxi[c] * n[c];
    const double t = fact * dot;
    for (unsigned c = 0; c < dim_; ++c) df[dw_ * i + c] += n[c] * t;
  }
}

bool PlaneForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  const Vec3 n = normal.value();
  if (dim_ == 3) {
    Mat3 m;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) m(a, b) = -k_ * (n[a] * n[b]);
    for (unsigned i : contacts_) K.add_block(s, dw_ * i, s, dw_ * i, m);
    return true;
  }
  for (unsigned i : contacts_)
    for (unsigned a = 0; a < dim_; ++a)
      for (unsigned b = 0; b < dim_; ++b) K.add(s, dw_ * i + a, s, dw_ * i + b, -k_ * (n[a] * n[b]));
  return true;
}

void register_plane_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "PlaneForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "penalty force keeping points on one side of a plane";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<PlaneForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
