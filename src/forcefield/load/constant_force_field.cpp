#include "forcefield/load/constant_force_field.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

ConstantForceField::ConstantForceField() { indices.add_alias("points"); }

void ConstantForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("only Vec3d states are supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (!topology) topology.set(node()->get_mesh_topology_link());
  const std::size_t system = topology ? topology->nb_points() : mstate->size();
  idx_ = indices.get();
  if (!indices.is_set() || idx_.empty()) {
    idx_.resize(system);
    for (std::size_t i = 0; i < system; ++i) idx_[i] = static_cast<unsigned>(i);
  }
  const std::size_t n_state = mstate->size();
  for (std::size_t i = 0; i < idx_.size(); ++i)
    if (idx_[i] >= n_state) {
      msg_error("index " + std::to_string(i) + " (" + std::to_string(idx_[i]) + ") exceeds the state size " +
                std::to_string(n_state));
      set_state(ComponentState::invalid);
      return;
    }
  auto finite = [](const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); };
  applied_.clear();
  if (forces.is_set() && !forces.get().empty()) {
    const auto& fs = forces.get();
    if (force.is_set() || total_force.is_set()) msg_warning("'forces' is set: 'force' and 'totalForce' are ignored");
    if (fs.size() == 1) {
      applied_.assign(idx_.size(), fs[0]);
    } else if (fs.size() == idx_.size()) {
      applied_ = fs;
    } else {
      msg_error("'forces' has " + std::to_string(fs.size()) + " entries but there are " +
                std::to_string(idx_.size()) + " indices");
      set_state(ComponentState::invalid);
      return;
    }
  } else if (force.is_set()) {
    applied_.assign(idx_.size(), force.get());
  } else if (total_force.is_set()) {
    if (idx_.empty()) {
      msg_error("cannot distribute totalForce: there are no indices");
      set_state(ComponentState::invalid);
      return;
    }
    const double n = static_cast<double>(idx_.size());
    const Vec3 t = total_force.get();
    applied_.assign(idx_.size(), Vec3(t[0] / n, t[1] / n, t[2] / n));
  } else {
    msg_warning("no force is set (forces, force or totalForce): the force is zero");
    applied_.assign(idx_.size(), Vec3::Zero());
  }
  for (std::size_t i = 0; i < applied_.size(); ++i)
    if (!finite(applied_[i])) {
      msg_error("the force of index " + std::to_string(i) + " is not a finite number");
      set_state(ComponentState::invalid);
      return;
    }
}

void ConstantForceField::add_force(const MechParams& p) {
  std::vector<double>& f = mstate->write(p.f);
  const std::size_t n = f.size() / 3;
  const bool from_end = index_from_end.value();
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const std::size_t k = from_end ? n - idx_[i] - 1 : idx_[i];
    if (k >= n) continue;
    for (int c = 0; c < 3; ++c) f[3 * k + c] += applied_[i][c];
  }
}

std::optional<double> ConstantForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const std::size_t n = x.size() / 3;
  const bool from_end = index_from_end.value();
  double e = 0;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const std::size_t k = from_end ? n - idx_[i] - 1 : idx_[i];
    if (k >= n) continue;
    for (int c = 0; c < 3; ++c) e -= applied_[i][c] * x[3 * k + c];
  }
  return e;
}

void register_constant_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "ConstantForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "constant force applied on a set of points";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ConstantForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
