#include "forcefield/spring/rest_shape_springs_force_field.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void RestShapeSpringsForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  if (const std::string* s = attrs.peek("external_rest_shape"); s && !s->empty() && (*s)[0] != '@')
    diag.error(where, describe() + ": 'external_rest_shape' is a link since SOFA 17.06: write it with a leading '@'");
  ForceField::parse(attrs, diag);
}

void RestShapeSpringsForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  const StateType t = mstate->state_type();
  if (t == StateType::vec1) dim_ = 1;
  else if (t == StateType::vec2) dim_ = 2;
  else if (t == StateType::vec3) dim_ = 3;
  else if (t == StateType::rigid3) {
    dim_ = 3;
    rigid_ = true;
  } else {
    msg_error(std::string("states of type ") + mstate->info().name +
              " are not supported (Vec1d, Vec2d, Vec3d, Rigid3d)");
    set_state(ComponentState::invalid);
    return;
  }
  if (external_rest_shape && external_rest_shape->state_type() != t) {
    msg_error("external_rest_shape has another type than the state");
    set_state(ComponentState::invalid);
    return;
  }
  k_ = stiffness.get();
  if (k_.empty()) k_.push_back(100.0);
  const auto& ad = active_directions.get();
  const int nd = rigid_ ? 6 : dim_;
  active_.assign(nd, 1);
  for (int c = 0; c < nd && c < static_cast<int>(ad.size()); ++c) active_[c] = ad[c] != 0;
  if (rigid_) {
    // One angular stiffness per stiffness: missing ones are 100, extra ones dropped (SOFA).
    ka_ = angular_stiffness.get();
    ka_.resize(k_.size(), 100.0);
    angular_stiffness.set(ka_);
  }
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!compute_indices()) set_state(ComponentState::invalid);
}

const std::vector<double>* RestShapeSpringsForceField::rest() const {
  if (external_rest_shape) return &external_rest_shape->read(kPosition);
  return &mstate->read(kRestPosition);
}

bool RestShapeSpringsForceField::compute_indices() {
  idx_ = points.get();
  ext_idx_ = external_points.get();
  state_size_ = mstate->size();
  if (idx_.empty())
    for (unsigned i = 0; i < state_size_; ++i) idx_.push_back(i);
  const std::size_t n_rest = rest()->size() / static_cast<std::size_t>(rigid_ ? 7 : dim_);
  if (ext_idx_.empty()) {
    if (external_rest_shape)
      for (unsigned i = 0; i < n_rest; ++i) ext_idx_.push_back(i);
    else
      ext_idx_ = idx_;
  }
  for (std::size_t i = 0; i < idx_.size(); ++i)
    if (idx_[i] >= state_size_) {
      msg_error("point " + std::to_string(i) + " (" + std::to_string(idx_[i]) + ") is out of range (the state has " +
                std::to_string(state_size_) + " points)");
      idx_.clear();
      ext_idx_.clear();
      return false;
    }
  for (std::size_t i = 0; i < ext_idx_.size(); ++i)
    if (ext_idx_[i] >= n_rest) {
      msg_error("external point " + std::to_string(i) + " (" + std::to_string(ext_idx_[i]) +
                ") is out of range (the rest shape has " + std::to_string(n_rest) + " points)");
      idx_.clear();
      ext_idx_.clear();
      return false;
    }
  if (idx_.size() != ext_idx_.size()) {
    msg_error("points has " + std::to_string(idx_.size()) + " entries but external_points " +
              std::to_string(ext_idx_.size()));
    idx_.clear();
    ext_idx_.clear();
    return false;
  }
  return true;
}

void RestShapeSpringsForceField::add_force(const MechParams& p) {
  if (recompute_indices.value() && mstate->size() != state_size_ && !compute_indices()) {
    set_state(ComponentState::invalid);
    return;
  }
  if (rigid_) return add_force_rigid(p);
  const std::vector<double>& x = mstate->read(p.x);
  const std::vector<double>& x0 = *rest();
  std::vector<double>& f = mstate->write(p.f);
  const int N = dim_;
  const bool use_ext = external_rest_shape.get() != nullptr;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const unsigned b = use_ext ? ext_idx_[i] : idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    for (int c = 0; c < N; ++c) {
      const double d = active_[c] ? x[a * N + c] - x0[b * N + c] : 0.0;
      f[a * N + c] -= d * k;
    }
  }
}

std::optional<double> RestShapeSpringsForceField::potential_energy() const {
  if (state() != ComponentState::valid || rigid_) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const std::vector<double>& x0 = *rest();
  const int N = dim_;
  const bool use_ext = external_rest_shape.get() != nullptr;
  double e = 0;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const unsigned b = use_ext ? ext_idx_[i] : idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    for (int c = 0; c < N; ++c) {
      const double d = active_[c] ? x[a * N + c] - x0[b * N + c] : 0.0;
      e += 0.5 * k * d * d;
    }
  }
  return e;
}

void RestShapeSpringsForceField::add_force_rigid(const MechParams& p) {
  const std::vector<double>& x = mstate->read(p.x);
  const std::vector<double>& x0 = *rest();
  std::vector<double>& f = mstate->write(p.f);
  const bool use_ext = external_rest_shape.get() != nullptr;
  const auto& pivots = pivot_points.get();
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const unsigned b = use_ext ? ext_idx_[i] : idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    const double ka = ka_[i < ka_.size() ? i : 0];
    const Vec3 c1(x[7 * a], x[7 * a + 1], x[7 * a + 2]);
    const Vec3 c0(x0[7 * b], x0[7 * b + 1], x0[7 * b + 2]);
    const Eigen::Quaterniond q1(x[7 * a + 6], x[7 * a + 3], x[7 * a + 4], x[7 * a + 5]);
    const Eigen::Quaterniond q0(x0[7 * b + 6], x0[7 * b + 3], x0[7 * b + 4], x0[7 * b + 5]);
    double* fa = &f[6 * a];
    Vec3 dx;
    if (i < pivots.size()) {
      // The pivot, carried from the rest frame to the current one, is pulled back to its place.
      const Vec3 local = q0.conjugate() * (pivots[i] - c0);
      dx = c1 + q1 * local - pivots[i];
    } else {
      dx = c1 - c0;
      for (int c = 0; c < 3; ++c)
        if (!active_[c]) dx[c] = 0.0;
    }
    for (int c = 0; c < 3; ++c) fa[c] -= dx[c] * k;
    // Rotation from the rest orientation, as axis·angle with the angle in [0, π].
    Eigen::Quaterniond dq = q1 * q0.conjugate();
    dq.normalize();
    if (dq.w() < 0.0) dq.coeffs() *= -1.0;
    Vec3 dir(0, 0, 0);
    double angle = 0.0;
    if (dq.w() < 1.0) {
      double sin_half;
      if (dq.w() > 0.999) {  // small angles: asin is accurate where acos is not
        sin_half = dq.vec().norm();
        angle = 2.0 * std::asin(sin_half);
      } else {
        const double half = std::acos(dq.w());
        sin_half = std::sin(half);
        angle = 2 * half;
      }
      dir = sin_half < std::numeric_limits<double>::epsilon() ? Vec3(0, 1, 0) : Vec3(dq.vec() / sin_half);
    }
    for (int c = 0; c < 3; ++c)
      if (!active_[3 + c]) dir[c] = 0.0;
    for (int c = 0; c < 3; ++c) fa[3 + c] -= dir[c] * angle * ka;
  }
}

void RestShapeSpringsForceField::add_dforce_rigid(const MechParams& p, double kfactor) {
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    const double ka = ka_[i < ka_.size() ? i : 0];
    for (int c = 0; c < 3; ++c) df[6 * a + c] -= (active_[c] ? dx[6 * a + c] : 0.0) * k * kfactor;
    for (int c = 0; c < 3; ++c) df[6 * a + 3 + c] -= (active_[3 + c] ? dx[6 * a + 3 + c] : 0.0) * ka * kfactor;
  }
}

void RestShapeSpringsForceField::add_dforce(const MechParams& p, double kfactor) {
  if (rigid_) return add_dforce_rigid(p, kfactor);
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  const int N = dim_;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    for (int c = 0; c < N; ++c) {
      const double d = active_[c] ? dx[a * N + c] : 0.0;
      df[a * N + c] -= d * k * kfactor;
    }
  }
}

bool RestShapeSpringsForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  if (rigid_) {
    // SOFA's buildStiffnessMatrix for rigids: stiffnesses indexed by the DoF, every
    // translation entry, rotation entries only in active directions.
    for (const unsigned a : idx_) {
      const double k = k_[a < k_.size() ? a : 0];
      const double ka = ka_[a < ka_.size() ? a : 0];
      for (int c = 0; c < 3; ++c) K.add(s, 6 * a + c, s, 6 * a + c, -k);
      for (int c = 0; c < 3; ++c)
        if (active_[3 + c]) K.add(s, 6 * a + 3 + c, s, 6 * a + 3 + c, -ka);
    }
    return true;
  }
  const int N = dim_;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const unsigned a = idx_[i];
    const double k = k_[i < k_.size() ? i : 0];
    for (int c = 0; c < N; ++c)
      if (active_[c]) K.add(s, a * N + c, s, a * N + c, -k);
  }
  return true;
}

void register_rest_shape_springs_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "RestShapeSpringsForceField";
  info.category = "ForceField/Spring";
  info.description = "springs pulling points back to their rest position";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<RestShapeSpringsForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
