#include "forcefield/spring/angular_spring_force_field.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/matrix_sink.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

void AngularSpringForceField::reinit() {
  // SOFA's default, written into the field as SOFA does (with an info message there).
  if (angular_stiffness.get().empty()) angular_stiffness.set({100.0});
  k_ = angular_stiffness.get();
}

void AngularSpringForceField::init() {
  ForceField::init();
  if (!mstate) {
    msg_error("no mechanical state to act on");
    set_state(ComponentState::invalid);
    return;
  }
  reinit();
  const std::vector<unsigned>& idx = indices.get();
  max_index_ = 0;
  for (std::size_t j = 0; j < idx.size(); ++j) {
    // Frame indices[j] is pulled towards frame indices[j] − 1 (j ≥ 1): there must be one.
    if (j >= 1 && idx[j] == 0) {
      msg_error("indices[" + std::to_string(j) +
                "] is 0: the spring of a listed point (after the first) ties it to the previous point of the "
                "state, and point 0 has none");
      set_state(ComponentState::invalid);
      return;
    }
    max_index_ = std::max(max_index_, idx[j]);
  }
  if (!indices_fit(mstate->size())) {
    set_state(ComponentState::invalid);
    return;
  }
  if (!limit.get().empty())
    msg_warning("limit is read by nothing in SOFA's AngularSpringForceField: it has no effect");
}

bool AngularSpringForceField::indices_fit(std::size_t points) {
  if (indices.get().empty() || max_index_ < points) return true;
  if (!warned_size_) {
    warned_size_ = true;
    msg_error("indices name point " + std::to_string(max_index_) + " but the state has " + std::to_string(points) +
              " points: the springs are skipped");
  }
  return false;
}

void AngularSpringForceField::add_force(const MechParams& p) {
  const std::vector<double>& x = mstate->read(p.x);
  std::vector<double>& f = mstate->write(p.f);
  if (!indices_fit(x.size() / 7)) return;
  const std::vector<unsigned>& idx = indices.get();
  for (std::size_t j = 1; j < idx.size(); ++j) {
    const unsigned i = idx[j];
    const Quat qi = Quat::from(&x[7 * i + 3]), previous = Quat::from(&x[7 * (i - 1) + 3]);
    const Quat dq = quat_normalized(quat_mul(qi, quat_inverse(previous)));
    // No hemisphere flip: the angle is in [0, 2π). SOFA takes asin above w = 0.999999.
    const QuatAngle a = quat_angle(dq, 0.999999);
    const double angle = a.angle, sin_half = a.sin_half;
    double axis[3] = {0.0, 1.0, 0.0};  // SOFA's choice for a null rotation
    if (sin_half >= std::numeric_limits<double>::epsilon()) {
      axis[0] = dq.x / sin_half;
      axis[1] = dq.y / sin_half;
      axis[2] = dq.z / sin_half;
    }
    const double k = k_[j < k_.size() ? j : 0];
    for (int c = 0; c < 3; ++c) f[6 * i + 3 + c] -= axis[c] * angle * k;
  }
}

void AngularSpringForceField::add_dforce(const MechParams& p, double kfactor) {
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  if (!indices_fit(dx.size() / 6)) return;
  const std::vector<unsigned>& idx = indices.get();
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const std::size_t at = 6 * static_cast<std::size_t>(idx[j]) + 3;
    const double k = k_[j < k_.size() ? j : 0];
    for (int c = 0; c < 3; ++c) df[at + c] -= dx[at + c] * k * kfactor;
  }
}

bool AngularSpringForceField::build_stiffness(MatrixSink& K) {
  if (!indices_fit(mstate->size())) return true;
  const MechanicalState* s = mstate.get();
  const std::vector<unsigned>& idx = indices.get();
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const std::size_t at = 6 * static_cast<std::size_t>(idx[j]) + 3;
    const double k = k_[j < k_.size() ? j : 0];
    for (int c = 0; c < 3; ++c) K.add(s, at + c, s, at + c, -k);
  }
  return true;
}

void register_angular_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "AngularSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "angular springs between consecutive frames of a chain (rotational degrees of freedom)";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.requirement = Requirement::state;
  info.create = creator<AngularSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
