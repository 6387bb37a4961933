#include "forcefield/spring/spring_force_field.h"

#include <algorithm>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

SpringForceField::SpringForceField() {
  springs_indices1.add_alias("indices1");
  springs_indices2.add_alias("indices2");
  lengths.add_alias("length");
  file_springs.add_alias("fileSprings");
  file_springs.set_file(true);
}

std::vector<MechanicalState*> SpringForceField::states() const {
  if (s1_ && s1_ == s2_) return {s1_};
  return {s1_, s2_};
}

bool bind_interaction_states(ForceField& self, Link<MechanicalState>& object1, Link<MechanicalState>& object2,
                             MechanicalState*& s1, MechanicalState*& s2) {
  MechanicalState* local = self.node() ? self.node()->get_mechanical_state() : nullptr;
  s1 = object1 ? object1.get() : local;
  s2 = object2 ? object2.get() : local;
  if (!s1 || !s2) {
    self.msg_error("no mechanical state found (object1/object2 or the node's state)");
    self.set_state(ComponentState::invalid);
    return false;
  }
  if (!self.mstate) self.mstate.set(s1);
  if (s1->state_type() != s2->state_type()) {
    self.msg_error(std::string("object1 is ") + s1->info().name + " but object2 is " + s2->info().name);
    self.set_state(ComponentState::invalid);
    return false;
  }
  return true;
}

PairForceVectors pair_force_vectors(MechanicalState& a, MechanicalState& b, const MechParams& p) {
  // A braced list evaluates left to right.
  return {a.read(vec_for(a, p.x, kPosition)).data(), a.read(vec_for(a, p.v, kVelocity)).data(),
          a.write(vec_for(a, p.f, kForce)).data(),   b.read(vec_for(b, p.x, kPosition)).data(),
          b.read(vec_for(b, p.v, kVelocity)).data(), b.write(vec_for(b, p.f, kForce)).data()};
}

PairDforceVectors pair_dforce_vectors(MechanicalState& a, MechanicalState& b, const MechParams& p) {
  return {a.read(vec_for(a, p.dx, kDx)).data(), a.write(vec_for(a, p.df, kDforce)).data(),
          b.read(vec_for(b, p.dx, kDx)).data(), b.write(vec_for(b, p.df, kDforce)).data()};
}

bool SpringForceField::bind_states() {
  if (!bind_interaction_states(*this, object1, object2, s1_, s2_)) return false;
  const StateType t1 = s1_->state_type();
  if (t1 == StateType::vec1) dim_ = 1;
  else if (t1 == StateType::vec2) dim_ = 2;
  else if (t1 == StateType::vec3) dim_ = 3;
  else if (t1 == StateType::rigid3) dim_ = 3;  // on the frames' centres (SOFA's getCPos/getDPos)
  else {
    msg_error(std::string("states of type ") + s1_->info().name +
              " are not supported (Vec1d, Vec2d, Vec3d, Rigid3d only)");
    set_state(ComponentState::invalid);
    return false;
  }
  return true;
}

void SpringForceField::init() {
  if (!bind_states()) return;
  // SOFA attaches one handler per state, to the topology of the state's context.
  MechanicalState* sides[2] = {s1_, s2_};
  for (int k = 0; k < 2; ++k) {
    follow_[k].owner = this;
    follow_[k].side = k;
    follow_[k].attach(sides[k]->node() ? sides[k]->node()->get_mesh_topology_link() : nullptr);
  }
  if (!file_springs.value().empty()) {
    msg_error("spring files (filename=" + file_springs.value() + ") are not supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (!generated_) {
    springs_.clear();
    if (spring.is_set()) {
      // Authoritative "i j ks kd L0" list; the split lists are rewritten from it.
      const auto& v = spring.get();
      if (v.size() % 5 != 0) {
        msg_error("'spring' must hold 5 numbers per spring (index1 index2 stiffness damping restLength); got " +
                  std::to_string(v.size()) + " numbers");
        set_state(ComponentState::invalid);
        return;
      }
      for (std::size_t i = 0; i + 4 < v.size(); i += 5) {
        if (v[i] < 0 || v[i + 1] < 0 || v[i] != std::floor(v[i]) || v[i + 1] != std::floor(v[i + 1])) {
          msg_error("spring " + std::to_string(i / 5) + ": the indices must be non-negative integers");
          set_state(ComponentState::invalid);
          return;
        }
        springs::LinearSpring s;
        s.m1 = static_cast<unsigned>(v[i]);
        s.m2 = static_cast<unsigned>(v[i + 1]);
        s.ks = v[i + 2];
        s.kd = v[i + 3];
        s.l0 = v[i + 4];
        springs_.push_back(s);
      }
    } else {
      const auto& i1 = springs_indices1.get();
      const auto& i2 = springs_indices2.get();
      if (i1.size() != i2.size()) {
        msg_error("indices1 has " + std::to_string(i1.size()) + " entries but indices2 has " +
                  std::to_string(i2.size()) + ": no spring is created");
      } else if (!i1.empty()) {
        // Per-spring lists resized to the number of springs with their last value (SOFA's rule).
        auto fit = [&](auto list, auto fill) {
          if (list.empty()) list.push_back(fill);
          if (list.size() != i1.size()) list.resize(i1.size(), list.back());
          return list;
        };
        const auto L = fit(lengths.get(), 0.0);
        const auto KS = fit(stiffness.get(), 100.0);
        const auto KD = fit(damping.get(), 5.0);
        const auto EO = fit(elongation_only.get(), 0);
        const auto EN = fit(enabled.get(), 1);
        for (std::size_t i = 0; i < i1.size(); ++i)
          springs_.push_back({i1[i], i2[i], KS[i], KD[i], L[i], EO[i] != 0, EN[i] != 0});
      }
    }
  }
  for (std::size_t i = 0; i < springs_.size(); ++i)
    if (springs_[i].ks < 0) {
      msg_warning("spring " + std::to_string(i) + " has a negative stiffness (" +
                  parse::format_double(springs_[i].ks) + "): the motion may be unstable and the system indefinite");
      break;
    }
}

void SpringForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::points_removed || c.indices.empty()) return;
  // Received before the container changes: its count is the one before the removal.
  auto n = static_cast<unsigned>(t.nb_points());
  std::vector<springs::LinearSpring>& list = owner->springs_;
  auto end_of = [&](springs::LinearSpring& s) -> unsigned& { return side == 0 ? s.m1 : s.m2; };
  for (unsigned removed : c.indices) {
    if (n == 0) break;
    --n;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](springs::LinearSpring& s) { return end_of(s) == removed; }),
               list.end());
    if (removed == n) continue;
    for (auto& s : list)
      if (end_of(s) == n) end_of(s) = removed;
  }
  owner->dfdx_.assign(list.size() + owner->grid_springs_.size(), springs::Block{});
}

// The ends are checked once every state is initialised: object1/object2 may be
// states of child nodes, which SOFA (and Sinew) initialise after this node's
// objects.
void SpringForceField::bwd_init() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  // Bad indices are refused with the spring named, never read out of range.
  const std::size_t n1 = s1_->size(), n2 = s2_->size();
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const auto& s = springs_[i];
    if (s.m1 >= n1 || s.m2 >= n2) {
      msg_error("spring " + std::to_string(i) + " (" + std::to_string(s.m1) + ", " + std::to_string(s.m2) +
                ") refers to a point out of range (object1 has " + std::to_string(n1) + " points, object2 " +
                std::to_string(n2) + ")");
      set_state(ComponentState::invalid);
      return;
    }
  }
  for (const auto& s : grid_springs_)
    if (s.m1 >= n1 || s.m2 >= n2) {
      msg_error("a generated spring refers to a point out of range (" + std::to_string(s.m1) + ", " +
                std::to_string(s.m2) + ")");
      set_state(ComponentState::invalid);
      return;
    }
  dfdx_.assign(springs_.size() + grid_springs_.size(), springs::Block{});
  n1_ = n1;
  n2_ = n2;
}

bool SpringForceField::sizes_ok() {
  if (s1_->size() == n1_ && s2_->size() == n2_) return true;
  // The states were resized (topological change): keep going only if every spring still fits.
  n1_ = s1_->size();
  n2_ = s2_->size();
  auto fits = [&](const springs::LinearSpring& s) { return s.m1 < n1_ && s.m2 < n2_; };
  for (std::size_t i = 0; i < springs_.size() + grid_springs_.size(); ++i) {
    const auto& s = i < springs_.size() ? springs_[i] : grid_springs_[i - springs_.size()];
    if (!fits(s)) {
      msg_error("spring " + std::to_string(i) + " (" + std::to_string(s.m1) + ", " + std::to_string(s.m2) +
                ") refers to a point removed from the state at step " + std::to_string(node()->root()->step_index) +
                ": the force field stops");
      set_state(ComponentState::invalid);
      springs_.clear();
      grid_springs_.clear();
      return false;
    }
  }
  return true;
}

template <int N, int CS, int DS>
void SpringForceField::add_force_n(const MechParams& p) {
  const auto [x1, v1, f1, x2, v2, f2] = pair_force_vectors(*s1_, *s2_, p);
  energy_ = 0;
  std::size_t k = 0;
  for (const auto& s : springs_) springs::add_spring_force<N, CS, DS>(s, x1, v1, f1, x2, v2, f2, dfdx_[k++], energy_);
  for (const auto& s : grid_springs_) springs::add_spring_force<N, CS, DS>(s, x1, v1, f1, x2, v2, f2, dfdx_[k++], energy_);
}

template <int N, int DS>
void SpringForceField::add_dforce_n(const MechParams& p, double kfactor) {
  const auto [dx1, df1, dx2, df2] = pair_dforce_vectors(*s1_, *s2_, p);
  std::size_t k = 0;
  for (const auto& s : springs_) springs::add_spring_dforce<N, DS>(s, dfdx_[k++], dx1, df1, dx2, df2, kfactor);
  for (const auto& s : grid_springs_) springs::add_spring_dforce<N, DS>(s, dfdx_[k++], dx1, df1, dx2, df2, kfactor);
}

void SpringForceField::add_force(const MechParams& p) {
  if (!sizes_ok()) return;
  if (s1_->state_type() == StateType::rigid3) return add_force_n<3, 7, 6>(p);
  switch (dim_) {
    case 1: add_force_n<1, 1, 1>(p); break;
    case 2: add_force_n<2, 2, 2>(p); break;
    default: add_force_n<3, 3, 3>(p); break;
  }
}

void SpringForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!sizes_ok()) return;
  if (s1_->state_type() == StateType::rigid3) return add_dforce_n<3, 6>(p, kfactor);
  switch (dim_) {
    case 1: add_dforce_n<1, 1>(p, kfactor); break;
    case 2: add_dforce_n<2, 2>(p, kfactor); break;
    default: add_dforce_n<3, 3>(p, kfactor); break;
  }
}

std::string SpringForceField::set_springs(std::vector<springs::LinearSpring> list) {
  if (s1_ && s2_)
    for (std::size_t i = 0; i < list.size(); ++i)
      if (list[i].m1 >= s1_->size() || list[i].m2 >= s2_->size())
        return "spring " + std::to_string(i) + " (" + std::to_string(list[i].m1) + ", " +
               std::to_string(list[i].m2) + ") refers to a point out of range (object1 has " +
               std::to_string(s1_->size()) + " points, object2 " + std::to_string(s2_->size()) + ")";
  springs_ = std::move(list);
  dfdx_.assign(springs_.size() + grid_springs_.size(), springs::Block{});
  if (generated_) return "";  // the Data describe the generator, not a list
  std::vector<unsigned> i1, i2;
  std::vector<double> L, KS, KD, packed;
  std::vector<int> EO, EN;
  for (const auto& sp : springs_) {
    i1.push_back(sp.m1);
    i2.push_back(sp.m2);
    L.push_back(sp.l0);
    KS.push_back(sp.ks);
    KD.push_back(sp.kd);
    EO.push_back(sp.elongation_only ? 1 : 0);
    EN.push_back(sp.enabled ? 1 : 0);
    packed.insert(packed.end(), {double(sp.m1), double(sp.m2), sp.ks, sp.kd, sp.l0});
  }
  springs_indices1.set(std::move(i1));
  springs_indices2.set(std::move(i2));
  lengths.set(std::move(L));
  stiffness.set(std::move(KS));
  damping.set(std::move(KD));
  elongation_only.set(std::move(EO));
  enabled.set(std::move(EN));
  if (spring.is_set()) spring.set(std::move(packed));
  return "";
}

bool SpringForceField::build_stiffness(MatrixSink& K) {
  if (!s1_ || !s2_) return false;
  const int N = dim_;
  const std::size_t DS = static_cast<std::size_t>(s1_->info().deriv_width);  // Rigid3d: 6, translations first
  std::size_t e = 0;
  auto emit = [&](const springs::LinearSpring& s) {
    const springs::Block& m = dfdx_[e++];
    const std::size_t p1 = s.m1 * DS, p2 = s.m2 * DS;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const double k = m[i * N + j];
        K.add(s1_, p1 + i, s1_, p1 + j, -k);
        K.add(s1_, p1 + i, s2_, p2 + j, k);
        K.add(s2_, p2 + i, s1_, p1 + j, k);
        K.add(s2_, p2 + i, s2_, p2 + j, -k);
      }
  };
  for (const auto& s : springs_) emit(s);
  for (const auto& s : grid_springs_) emit(s);
  return true;
}

void register_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SpringForceField";
  info.category = "ForceField/Spring";
  info.description = "linear springs between the points of one or two states";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  // object1/object2 may live elsewhere than the node's state: the types are checked at init.
  info.requirement = Requirement::none;
  info.create = creator<SpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
