#include "sph/particle_sink.h"

#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "projective/subset_indices.h"
#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

void ParticleSink::init() {
  ProjectiveConstraint::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d state (got " + std::string(mstate->info().name) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (MeshTopologyBase* t = topology.get()) {
    modifier_ = t->node() ? t->node()->find_up<PointSetTopologyModifier>() : nullptr;
    if (!modifier_) {
      msg_error("topology '" + t->name.value() +
                "' is not dynamic (no PointSetTopologyModifier beside it): particles cannot be removed");
      set_state(ComponentState::invalid);
      return;
    }
    follow_.owner = this;
    follow_.attach(t);
  }
}

void ParticleSink::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::points_removed) return;
  std::vector<unsigned> f = owner->fixed.get();
  follow_point_removal(f, c.indices, t.nb_points());
  owner->fixed.set(std::move(f));
}

void ParticleSink::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(kPosition);
  const Vec3 n = normal.value();
  const double d = d1.value();
  remove_.clear();
  for (std::size_t i = s.size(); i-- > 0;) {
    const double* xi = &x[3 * i];
    if (xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2] - d < 0) remove_.push_back(static_cast<unsigned>(i));
  }
  if (remove_.empty()) return;
  removed_ += remove_.size();
  if (modifier_) {
    modifier_->remove_points(remove_, true);
  } else {
    // No topology: the state moves its last DoF into each freed slot (SOFA's replaceValue).
    s.remove_points(remove_);
  }
}

void ParticleSink::project_position(int x, double) {
  const std::vector<double>& pos = mstate->read(x);
  const Vec3 n = normal.value();
  const double d = d0.value();
  std::vector<unsigned> f;
  f.reserve(fixed.value().capacity());
  const std::size_t np = pos.size() / 3;
  for (std::size_t i = 0; i < np; ++i) {
    const double* xi = &pos[3 * i];
    if (xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2] - d < 0) f.push_back(static_cast<unsigned>(i));
  }
  fixed.set(std::move(f));
}

void ParticleSink::project_velocity(int v, double) {
  std::vector<double>& vel = mstate->write(v);
  for (unsigned i : fixed.value())
    if (3 * i + 2 < vel.size()) vel[3 * i] = vel[3 * i + 1] = vel[3 * i + 2] = 0;
}

void register_particle_sink(Registry& r) {
  ComponentInfo info;
  info.name = "ParticleSink";
  info.category = "SPH";
  info.description = "removes the particles that crossed a plane (SofaSphFluid)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ParticleSink>();
  r.add(std::move(info));
}

}  // namespace sinew
