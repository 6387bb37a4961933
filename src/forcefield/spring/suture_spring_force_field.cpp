#include "forcefield/spring/suture_spring_force_field.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/matrix_sink.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

// The thread's force on the vertex at x from the anchor a, and its 3×3 Jacobian
// ∂f/∂x (row-major): zero while the thread is slack (l ≤ L).
bool thread_force(const Vec3& x, const Vec3& a, double k, double L, Vec3& f, double K[9]) {
  const Vec3 d = a - x;
  const double l = d.norm();
  if (!(l > L) || l == 0.0) {
    f = Vec3::Zero();
    for (int i = 0; i < 9; ++i) K[i] = 0.0;
    return false;
  }
  const Vec3 u = d / l;
  f = k * (l - L) * u;
  // f = k (l − L) u;  ∂f/∂x = −k [ u uᵀ + (1 − L/l)(I − u uᵀ) ]
  const double s = 1.0 - L / l;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) K[3 * r + c] = -k * (u[r] * u[c] + s * ((r == c ? 1.0 : 0.0) - u[r] * u[c]));
  return true;
}

}  // namespace

SutureSpringForceField::SutureSpringForceField() { follow_.owner = this; }

void SutureSpringForceField::init() {
  ForceField::init();
  if (!mstate || mstate->state_type() != StateType::vec3) {
    msg_error("the body's state must be Vec3d");
    set_state(ComponentState::invalid);
    return;
  }
  if (!needle || needle->state_type() != StateType::vec3) {
    msg_error(needle ? "needle: the state must be Vec3d" : "needle: no state linked (the needle's points)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!(capture_distance.value() > 0) || !(stiffness.value() >= 0)) {
    msg_error("captureDistance must be > 0 and stiffness >= 0");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& s = springs.value();
  if (s.size() % 2 != 0) {
    msg_error("springs: pairs of (vertex, rest length) expected, got " + std::to_string(s.size()) + " numbers");
    set_state(ComponentState::invalid);
    return;
  }
  const std::size_t n = mstate->size();
  pierced_.assign(n, 0);
  linked_.assign(n, 0);
  list_.clear();
  for (std::size_t i = 0; i < s.size(); i += 2) {
    const double v = s[i];
    if (!(v >= 0) || v >= static_cast<double>(n) || v != std::floor(v) || !(s[i + 1] >= 0)) {
      msg_error("springs: entry " + std::to_string(i / 2) + " (" + std::to_string(v) + ", " +
                std::to_string(s[i + 1]) + ") is not a vertex of the body with a rest length >= 0");
      set_state(ComponentState::invalid);
      return;
    }
    list_.push_back({static_cast<unsigned>(v), s[i + 1]});
    linked_[static_cast<std::size_t>(v)] = 1;
  }
  if (MeshTopologyBase* t = node() ? node()->get_mesh_topology_link() : nullptr) follow_.attach(t);
}

// The needle's points exist once every component is initialised (its node may come later).
void SutureSpringForceField::bwd_init() {
  if (state() != ComponentState::valid || !needle) return;
  const int n_needle = static_cast<int>(needle->size());
  for (auto [name, v] : {std::pair{"frontIndex", front_index.value()}, std::pair{"backIndex", back_index.value()}})
    if (v < 0 || v >= n_needle) {
      msg_error(std::string(name) + " = " + std::to_string(v) + " is not a point of the needle state (" +
                std::to_string(n_needle) + " points)");
      set_state(ComponentState::invalid);
      return;
    }
}

bool SutureSpringForceField::ready() const {
  return state() == ComponentState::valid && mstate && needle && pierced_.size() == mstate->size();
}

Vec3 SutureSpringForceField::needle_point(int index) const {
  const std::vector<double>& x = needle->read(kPosition);
  const std::size_t i = static_cast<std::size_t>(index) * 3;
  return Vec3(x[i], x[i + 1], x[i + 2]);
}

void SutureSpringForceField::handle_event(Event& e) {
  if (e.kind == Event::Kind::animate_end && ready()) update_springs();
}

void SutureSpringForceField::update_springs() {
  if (static_cast<int>(needle->size()) <= std::max(front_index.value(), back_index.value())) return;
  const auto x = as_vec3(mstate->read(kPosition));
  const Vec3 front = needle_point(front_index.value());
  const Vec3 back = needle_point(back_index.value());
  const double r2 = capture_distance.value() * capture_distance.value();
  int pierced = pierced_count.value();
  std::size_t best = x.size();
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!pierced_[i] && (x[i] - front).squaredNorm() < r2) {
      pierced_[i] = 1;
      ++pierced;
    }
    if (pierced_[i] && !linked_[i]) {
      const double d2 = (x[i] - back).squaredNorm();
      if (d2 < r2 && d2 < best_d2) {
        best = i;
        best_d2 = d2;
      }
    }
  }
  if (pierced != pierced_count.value()) pierced_count.set(pierced);
  const int cap = max_springs.value();
  if (best < x.size() && (cap <= 0 || static_cast<int>(list_.size()) < cap)) {
    list_.push_back({static_cast<unsigned>(best), std::sqrt(best_d2)});
    linked_[best] = 1;
    publish();
  }
}

void SutureSpringForceField::publish() {
  std::vector<double> s;
  s.reserve(2 * list_.size());
  for (const Spring& sp : list_) {
    s.push_back(sp.vertex);
    s.push_back(sp.rest);
  }
  springs.set(std::move(s));
}

void SutureSpringForceField::add_force(const MechParams& p) {
  if (!ready() || list_.empty()) return;
  const auto x = as_vec3(mstate->read(p.x));
  auto f = as_vec3(mstate->write(p.f));
  const Vec3 a = needle_point(back_index.value());
  const double k = stiffness.value();
  double K[9];
  for (const Spring& s : list_) {
    Vec3 fi;
    thread_force(x[s.vertex], a, k, s.rest, fi, K);
    f[s.vertex] += fi;
  }
}

void SutureSpringForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!ready() || list_.empty()) return;
  const auto x = as_vec3(mstate->read(p.x));
  const auto dx = as_vec3(mstate->read(p.dx));
  auto df = as_vec3(mstate->write(p.df));
  const Vec3 a = needle_point(back_index.value());
  const double k = stiffness.value();
  double K[9];
  for (const Spring& s : list_) {
    Vec3 fi;
    if (!thread_force(x[s.vertex], a, k, s.rest, fi, K)) continue;
    const Vec3& d = dx[s.vertex];
    for (int r = 0; r < 3; ++r) df[s.vertex][r] += kfactor * (K[3 * r] * d[0] + K[3 * r + 1] * d[1] + K[3 * r + 2] * d[2]);
  }
}

bool SutureSpringForceField::build_stiffness(MatrixSink& M) {
  if (!ready()) return true;
  const auto x = as_vec3(mstate->read(kPosition));
  const Vec3 a = needle_point(back_index.value());
  const double k = stiffness.value();
  double K[9];
  for (const Spring& s : list_) {
    Vec3 fi;
    thread_force(x[s.vertex], a, k, s.rest, fi, K);  // zeros while slack: the pattern stays
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) M.add(mstate.get(), 3 * s.vertex + r, mstate.get(), 3 * s.vertex + c, K[3 * r + c]);
  }
  return true;
}

std::optional<double> SutureSpringForceField::potential_energy() const {
  if (!ready()) return std::nullopt;
  const auto x = as_vec3(mstate->read(kPosition));
  const Vec3 a = needle_point(back_index.value());
  double e = 0;
  for (const Spring& s : list_) {
    const double l = (a - x[s.vertex]).norm();
    if (l > s.rest) e += 0.5 * stiffness.value() * (l - s.rest) * (l - s.rest);
  }
  return e;
}

void SutureSpringForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::points_removed) return;
  SutureSpringForceField& o = *owner;
  std::size_t n = t.nb_points();
  bool changed = false;
  for (unsigned r : c.indices) {
    if (r >= n) continue;
    const auto last = static_cast<unsigned>(n - 1);
    for (std::size_t i = 0; i < o.list_.size();) {
      if (o.list_[i].vertex == r) {
        o.list_.erase(o.list_.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        continue;
      }
      if (o.list_[i].vertex == last) {
        o.list_[i].vertex = r;
        changed = true;
      }
      ++i;
    }
    --n;
  }
  remove_swap_last(o.pierced_, c.indices);
  remove_swap_last(o.linked_, c.indices);
  if (changed) o.publish();
}

void register_suture_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SutureSpringForceField";
  info.category = "ForceField";
  info.description =
      "Sinew: suture threads created where a needle's back point passes through vertices its front pierced";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SutureSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
