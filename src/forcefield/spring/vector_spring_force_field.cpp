#include "forcefield/spring/vector_spring_force_field.h"

#include "core/node.h"
#include "core/registry.h"
#include "forcefield/spring/spring_force_field.h"

namespace sinew {

VectorSpringForceField::VectorSpringForceField() {
  filename.set_file(true, false);
}

std::vector<MechanicalState*> VectorSpringForceField::states() const {
  if (s1_ && s1_ == s2_) return {s1_};
  return {s1_, s2_};
}

void VectorSpringForceField::init() {
  if (!bind_interaction_states(*this, object1, object2, s1_, s2_)) return;
  if (s1_->state_type() != StateType::vec3) {
    msg_error(std::string("object1/object2 are ") + s1_->info().name + " states; only Vec3d is supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (use_topology.value()) {
    topo_ = topology ? topology.get() : (node() ? node()->get_mesh_topology_link() : nullptr);
    if (!topo_) {
      msg_error("useTopology is set but no topology is linked (topology) nor found in the node");
      set_state(ComponentState::invalid);
      return;
    }
  }
  if (springs.is_set() && !springs.value().empty())
    msg_warning("'springs' is an output: the value given in the scene is ignored (as SOFA does)");
}

// SOFA's bwdInit: default springs once every state is initialised.
void VectorSpringForceField::bwd_init() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  list_.clear();
  if (!filename.value().empty()) {
    msg_error("filename: spring files (" + filename.value() + ") are not supported yet");
    set_state(ComponentState::invalid);
    return;
  }
  const double ks = stiffness.value(), kd = viscosity.value();
  n1_ = s1_->size();
  n2_ = s2_->size();
  if (topo_) {
    const auto& x0 = s1_->read(kRestPosition);
    const auto& edges = topo_->edges();
    list_.reserve(edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const unsigned a = edges[e][0], b = edges[e][1];
      if (a >= n1_ || b >= n1_ || b >= n2_) {
        msg_error("edge " + std::to_string(e) + " (" + std::to_string(a) + ", " + std::to_string(b) +
                  ") refers to a point out of range (object1 has " + std::to_string(n1_) + " points, object2 " +
                  std::to_string(n2_) + ")");
        set_state(ComponentState::invalid);
        list_.clear();
        return;
      }
      Spring s{a, b, ks, kd, {}};
      for (int k = 0; k < 3; ++k) s.rest[k] = x0[3 * b + k] - x0[3 * a + k];
      list_.push_back(s);
    }
  } else {
    if (n2_ < n1_) {
      msg_error("object1 has " + std::to_string(n1_) + " points but object2 only " + std::to_string(n2_) +
                ": the default springs pair point i of object1 with point i of object2");
      set_state(ComponentState::invalid);
      return;
    }
    list_.reserve(n1_);
    for (unsigned i = 0; i < n1_; ++i) list_.push_back(Spring{i, i, ks, kd, {}});
  }
  springs_set();
}

// The states' sizes the springs were checked against, and the `springs` output.
void VectorSpringForceField::springs_set() {
  n1_ = s1_ ? s1_->size() : 0;
  n2_ = s2_ ? s2_->size() : 0;
  std::vector<double>& out = springs.edit();
  out.clear();
  for (const auto& s : list_) out.insert(out.end(), {s.ks, s.kd, s.rest[0], s.rest[1], s.rest[2]});
}

bool VectorSpringForceField::ready() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return false;
  if (s1_->size() == n1_ && s2_->size() == n2_) return true;
  msg_error("the states were resized (object1 " + std::to_string(n1_) + " → " + std::to_string(s1_->size()) +
            ", object2 " + std::to_string(n2_) + " → " + std::to_string(s2_->size()) +
            " points): topological changes are not followed, the force field stops");
  set_state(ComponentState::invalid);
  return false;
}

void VectorSpringForceField::add_force(const MechParams& p) {
  energy_ = 0;
  if (!ready()) return;
  const auto [x1, v1, f1, x2, v2, f2] = pair_force_vectors(*s1_, *s2_, p);
  for (const auto& s : list_) {
    const std::size_t i = 3 * std::size_t(s.m1), j = 3 * std::size_t(s.m2);
    double sq = 0;
    for (int k = 0; k < 3; ++k) {
      const double stretch = x2[j + k] - x1[i + k] - s.rest[k];
      const double f = stretch * s.ks + (v2[j + k] - v1[i + k]) * s.kd;
      f1[i + k] += f;
      f2[j + k] -= f;
      sq += stretch * stretch;
    }
    energy_ += 0.5 * s.ks * sq;
  }
}

// SOFA: df1 += k·ks·(dx2 − dx1), df2 −= the same (no damping term).
void VectorSpringForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!ready()) return;
  const auto [dx1, df1, dx2, df2] = pair_dforce_vectors(*s1_, *s2_, p);
  for (const auto& s : list_) {
    const std::size_t i = 3 * std::size_t(s.m1), j = 3 * std::size_t(s.m2);
    const double c = s.ks * kfactor;
    for (int k = 0; k < 3; ++k) {
      const double d = (dx2[j + k] - dx1[i + k]) * c;
      df1[i + k] += d;
      df2[j + k] -= d;
    }
  }
}

// Not in SOFA (no buildStiffnessMatrix): the exact blocks of add_dforce.
bool VectorSpringForceField::build_stiffness(MatrixSink& K) {
  if (!s1_ || !s2_) return false;
  for (const auto& s : list_) {
    const std::size_t i = 3 * std::size_t(s.m1), j = 3 * std::size_t(s.m2);
    for (std::size_t k = 0; k < 3; ++k) {
      K.add(s1_, i + k, s1_, i + k, -s.ks);
      K.add(s1_, i + k, s2_, j + k, s.ks);
      K.add(s2_, j + k, s1_, i + k, s.ks);
      K.add(s2_, j + k, s2_, j + k, -s.ks);
    }
  }
  return true;
}

void register_vector_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "VectorSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "springs towards a rest vector between the points of one or two states";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::none;
  info.create = creator<VectorSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
