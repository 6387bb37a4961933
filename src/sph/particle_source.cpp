#include "sph/particle_source.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "projective/subset_indices.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

void ParticleSource::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (!(delay.value() > 0))
    diag.error(where, describe() + ": delay must be positive (got " + parse::format_double(delay.value()) + ")");
  if (scale.value() == 0) diag.error(where, describe() + ": scale must not be 0");
}

void ParticleSource::init() {
  ProjectiveConstraint::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d state (got " + std::string(mstate->info().name) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  number_ = center.get().size();
  last_time_ = start.get() - delay.get();
  if (last_time_ < 0.0) last_time_ = 0.0;
  max_dist_ = 0;
  last_pos_.resize(number_);
  follow_.owner = this;
  follow_.attach(node()->get_mesh_topology_link());
}

void ParticleSource::reset() {
  if (mstate) mstate->resize(1);
  last_time_ = start.get() - delay.get();
  if (last_time_ < 0.0) last_time_ = 0.0;
  max_dist_ = 0;
  last_particles.set({});
  last_pos_.clear();
}

void ParticleSource::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::points_removed) return;
  std::vector<unsigned> last = owner->last_particles.get();
  std::vector<Vec3>& pos = owner->last_pos_;
  // SOFA's destruction callback moves the last emission point into the removed entry's slot.
  follow_subset_removal(last, c.indices, t.nb_points(), [&](std::size_t k) {
    if (k < pos.size()) {
      pos[k] = pos.back();
      pos.pop_back();
    }
  });
  owner->last_particles.set(std::move(last));
}

void ParticleSource::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid) return;
  animate_begin(node()->time.value());
}

void ParticleSource::animate_begin(double time) {
  MechanicalState& s = *mstate;
  if (!active_at(time)) return;
  std::size_t i0 = s.size();
  if (i0 == 1) {  // a lone DoF is the MechanicalObject's default one: overwrite it
    i0 = 0;
    if (auto* con = node()->find_up<PointSetTopologyContainer>()) con->set_nb_points(1);
  }
  const double dl = delay.value();
  std::size_t layers = static_cast<std::size_t>(static_cast<int>((time - last_time_) / dl));
  if (layers == 0) return;

  std::vector<unsigned> last = last_particles.get();
  new_x_.clear();
  new_v_.clear();
  const Vec3 v0 = velocity.value();
  const std::vector<Vec3>& c = center.value();
  const double sc = scale.value();
  const Vec3 tr = translation.value();
  const Vec3 rad = radius.value();
  const bool noise = add_noise.value();
  const double vnorm = std::sqrt(v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2]);
  for (std::size_t l = 0; l < layers; ++l) {
    last_time_ += dl;
    max_dist_ += dl * vnorm / sc;
    // Keep the newer half of the driven particles (the previous layer), advanced by one delay.
    const std::size_t lp0 = last.empty() ? 0 : last.size() / 2;
    if (lp0 > 0) {
      const std::size_t shift = last.size() - lp0;
      for (std::size_t k = 0; k < lp0; ++k) {
        last[k] = last[k + shift];
        for (int d = 0; d < 3; ++d) last_pos_[k][d] = last_pos_[k + shift][d] + v0[d] * dl;
      }
    }
    last.resize(lp0);
    last_pos_.resize(lp0);
    for (std::size_t k = 0; k < number_; ++k) {
      Vec3 p;
      for (int d = 0; d < 3; ++d) p[d] = c[k][d] * sc + tr[d];
      if (noise) {
        for (int d = 0; d < 3; ++d) p[d] += rad[d] * (std::rand() * 1.0 / RAND_MAX);
      } else {
        for (int d = 0; d < 3; ++d) p[d] += rad[d];
      }
      last_pos_.push_back(p);
      last.push_back(static_cast<unsigned>(i0 + new_x_.size()));
      Vec3 q;
      for (int d = 0; d < 3; ++d) q[d] = p[d] + v0[d] * (time - last_time_);
      new_x_.push_back(q);
      new_v_.push_back(v0);
    }
  }
  last_particles.set(std::move(last));
  const std::size_t created = new_x_.size();
  if (created == 0) return;

  if (auto* mod = node()->find_up<PointSetTopologyModifier>()) {
    std::size_t n = i0 + created;
    if (n < s.size()) {
      msg_error("fewer particles to create (" + std::to_string(n) + ") than DoFs in the state (" +
                std::to_string(s.size()) + ")");
      n = 0;
    } else {
      n -= s.size();
    }
    mod->add_points(static_cast<unsigned>(n));
    if (s.size() < i0 + created) {
      // The modifier edits another container than the state's topology (a node with two point
      // containers): the state would not follow, so it is resized directly, as without a modifier.
      if (!warned_growth_)
        msg_warning("the PointSetTopologyModifier's container is not this state's topology: the state is resized "
                    "directly");
      warned_growth_ = true;
      s.resize(i0 + created);
    }
  } else {
    s.resize(i0 + created);
  }
  std::vector<double>& x = s.write(kPosition);
  std::vector<double>& v = s.write(kVelocity);
  for (std::size_t k = 0; k < created; ++k)
    for (int d = 0; d < 3; ++d) {
      x[3 * (i0 + k) + d] = new_x_[k][d];
      v[3 * (i0 + k) + d] = new_v_[k][d];
    }
  emitted_ += created;
}

void ParticleSource::project_response(int dx) {
  const std::vector<unsigned>& last = last_particles.value();
  if (last.empty() || !active_at(node()->time.value())) return;
  std::vector<double>& d = mstate->write(dx);
  for (unsigned i : last)
    if (3 * i + 2 < d.size()) d[3 * i] = d[3 * i + 1] = d[3 * i + 2] = 0;
}

// SOFA reads the context time (the step's start time) whatever time the caller projects at.
void ParticleSource::project_velocity(int v, double) {
  const std::vector<unsigned>& last = last_particles.value();
  if (last.empty() || !active_at(node()->time.value())) return;
  std::vector<double>& vel = mstate->write(v);
  const Vec3 v0 = velocity.value();
  for (unsigned i : last)
    if (3 * i + 2 < vel.size())
      for (int d = 0; d < 3; ++d) vel[3 * i + d] = v0[d];
}

void ParticleSource::project_position(int x, double) {
  const std::vector<unsigned>& last = last_particles.value();
  const double time = node()->time.value();
  if (last.empty() || !active_at(time)) return;
  std::vector<double>& pos = mstate->write(x);
  const Vec3 v0 = velocity.value();
  Vec3 dpos;
  for (int d = 0; d < 3; ++d) dpos[d] = v0[d] * (time - last_time_);
  for (std::size_t k = 0; k < last.size() && k < last_pos_.size(); ++k) {
    const unsigned i = last[k];
    if (3 * i + 2 >= pos.size()) continue;
    for (int d = 0; d < 3; ++d) {
      pos[3 * i + d] = last_pos_[k][d];
      pos[3 * i + d] += dpos[d];
    }
  }
}

void register_particle_source(Registry& r) {
  ComponentInfo info;
  info.name = "ParticleSource";
  info.category = "SPH";
  info.description = "emits particles in layers while the simulation runs (SofaSphFluid)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ParticleSource>();
  r.add(std::move(info));
}

}  // namespace sinew
