#include "forcefield/load/constant_force_field.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

ConstantForceField::ConstantForceField() { indices.add_alias("points"); }

bool ConstantForceField::read_one(const Field<std::vector<double>>& f, std::vector<double>& out) {
  out = f.get();
  if (out.size() == static_cast<std::size_t>(w_)) return true;
  msg_error("field '" + f.name() + "': expected " + std::to_string(w_) + " values (" + mstate->info().name +
            "), got " + std::to_string(out.size()));
  set_state(ComponentState::invalid);
  return false;
}

void ConstantForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  w_ = mstate->info().deriv_width;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  const std::size_t system = topology ? topology->nb_points() : mstate->size();
  idx_ = indices.get();
  if (!indices.is_set() || idx_.empty()) {
    idx_.resize(system);
    for (std::size_t i = 0; i < system; ++i) idx_[i] = static_cast<unsigned>(i);
  }
  const std::size_t w = static_cast<std::size_t>(w_);
  applied_.clear();
  std::vector<double> one;
  if (forces.is_set() && !forces.get().empty()) {
    const auto& fs = forces.get();
    if (force.is_set() || total_force.is_set()) msg_warning("'forces' is set: 'force' and 'totalForce' are ignored");
    if (fs.size() % w != 0) {
      msg_warning("field 'forces': expected a multiple of " + std::to_string(w) + " values (" +
                  mstate->info().name + "), got " + std::to_string(fs.size()) + "; the incomplete force is dropped");
    }
    const std::size_t count = fs.size() / w;
    if (count == 1) {
      for (std::size_t i = 0; i < idx_.size(); ++i) applied_.insert(applied_.end(), fs.begin(), fs.begin() + w);
    } else if (count == idx_.size()) {
      applied_.assign(fs.begin(), fs.begin() + count * w);
    } else {
      msg_error("'forces' has " + std::to_string(count) + " entries but there are " + std::to_string(idx_.size()) +
                " indices");
      set_state(ComponentState::invalid);
      return;
    }
  } else if (force.is_set()) {
    if (!read_one(force, one)) return;
    for (std::size_t i = 0; i < idx_.size(); ++i) applied_.insert(applied_.end(), one.begin(), one.end());
  } else if (total_force.is_set()) {
    if (!read_one(total_force, one)) return;
    if (idx_.empty()) {
      msg_error("cannot distribute totalForce: there are no indices");
      set_state(ComponentState::invalid);
      return;
    }
    const double n = static_cast<double>(idx_.size());
    for (double& v : one) v = v / n;
    for (std::size_t i = 0; i < idx_.size(); ++i) applied_.insert(applied_.end(), one.begin(), one.end());
  } else {
    msg_warning("no force is set (forces, force or totalForce): the force is zero");
    applied_.assign(idx_.size() * w, 0.0);
  }
  for (std::size_t k = 0; k < applied_.size(); ++k)
    if (!std::isfinite(applied_[k])) {
      msg_error("the force of index " + std::to_string(k / w) + " is not a finite number");
      set_state(ComponentState::invalid);
      return;
    }
}

// The indices are checked once the whole graph is initialised: a state under a mapping gets its
// size from the mapping's init, which may come after this one (SOFA's MatrixLinearSystem.scn: a
// Rigid3d state of one default frame, pushed by this force field, then sized by an IdentityMapping).
void ConstantForceField::bwd_init() {
  if (state() != ComponentState::valid) return;
  const std::size_t n_state = mstate->size();
  for (std::size_t i = 0; i < idx_.size(); ++i)
    if (idx_[i] >= n_state) {
      msg_error("index " + std::to_string(i) + " (" + std::to_string(idx_[i]) + ") exceeds the state size " +
                std::to_string(n_state));
      set_state(ComponentState::invalid);
      return;
    }
}

void ConstantForceField::add_force(const MechParams& p) {
  std::vector<double>& f = mstate->write(p.f);
  const std::size_t w = static_cast<std::size_t>(w_);
  const std::size_t n = f.size() / w;
  const bool from_end = index_from_end.value();
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const std::size_t k = from_end ? n - idx_[i] - 1 : idx_[i];
    if (k >= n) continue;
    for (std::size_t c = 0; c < w; ++c) f[w * k + c] += applied_[w * i + c];
  }
}

// −Σ f·x over the translational part (the centre of rigid frames).
std::optional<double> ConstantForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::vector<double>& x = mstate->read(kPosition);
  const std::size_t cw = static_cast<std::size_t>(mstate->info().coord_width);
  const std::size_t w = static_cast<std::size_t>(w_);
  const std::size_t dim = static_cast<std::size_t>(mstate->info().spatial_dim);
  const bool rigid = cw != w || mstate->state_type() == StateType::rigid2;
  const std::size_t comps = rigid ? dim : w;
  const std::size_t n = x.size() / cw;
  const bool from_end = index_from_end.value();
  double e = 0;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const std::size_t k = from_end ? n - idx_[i] - 1 : idx_[i];
    if (k >= n) continue;
    for (std::size_t c = 0; c < comps; ++c) e -= applied_[w * i + c] * x[cw * k + c];
  }
  return e;
}

void register_constant_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "ConstantForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "constant force applied on a set of points";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ConstantForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
