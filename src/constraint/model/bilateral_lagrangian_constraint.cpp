#include "constraint/model/bilateral_lagrangian_constraint.h"

#include <algorithm>
#include <string>

#include "constraint/model/constraint_states.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

BilateralLagrangianConstraint::BilateralLagrangianConstraint(StateType type)
    : rest_vector{this,
                  "rest_vector",
                  FlatVec{type == StateType::rigid3 ? 6 : 3, {}},
                  "relative position to keep between the points of each pair (optional)",
                  "Constraint",
                  "length"},
      rigid_(type == StateType::rigid3),
      width_(rigid_ ? 6 : 3) {}

void BilateralLagrangianConstraint::add_contact(unsigned m1, unsigned m2, const Vec3& rest) {
  first_point.edit().push_back(m1);
  second_point.edit().push_back(m2);
  std::vector<double>& r = rest_vector.edit().data;
  r.insert(r.end(), rest.data(), rest.data() + 3);
}

void BilateralLagrangianConstraint::clear_pairs() {
  first_point.edit().clear();
  second_point.edit().clear();
  rest_vector.edit().data.clear();
}

void BilateralLagrangianConstraint::init() {
  if (!resolve_pair_states(*this, object1, object2, rigid_ ? StateType::rigid3 : StateType::vec3)) return;
  if (load.value() < 0.0 || load.value() > 1.0) {
    msg_warning("load " + std::to_string(load.value()) + " is outside [0, 1]: clamped");
    load.set(std::clamp(load.value(), 0.0, 1.0));
  }
  prev_forces_.clear();
  follow1_.owner = follow2_.owner = this;
  follow1_.side = 0;
  follow2_.side = 1;
  follow1_.attach(topology1.get());
  follow2_.attach(topology2.get());
}

void BilateralLagrangianConstraint::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type == TopologyChangeType::points_removed) owner->on_points_removed(side, t, c.indices);
}

void BilateralLagrangianConstraint::on_points_removed(int side, const MeshTopologyBase& t,
                                                      const std::vector<unsigned>& decreasing) {
  std::vector<unsigned> m1 = first_point.value(), m2 = second_point.value();
  std::vector<double> rest = rest_vector.value().data;
  const std::size_t w = static_cast<std::size_t>(width_);
  // SOFA's removeContact: per removed point, the first pair naming it on this side goes (order kept).
  for (unsigned id : decreasing) {
    std::vector<unsigned>& mine = side == 0 ? m1 : m2;
    const auto it = std::find(mine.begin(), mine.end(), id);
    if (it == mine.end()) continue;
    const std::size_t pos = static_cast<std::size_t>(it - mine.begin());
    if (rest.size() == m1.size() * w) rest.erase(rest.begin() + pos * w, rest.begin() + (pos + 1) * w);
    if (pos < m1.size()) m1.erase(m1.begin() + pos);
    if (pos < m2.size()) m2.erase(m2.begin() + pos);
  }
  // Then the subset list of this side (TopologySubsetIndices::remove): remaining entries naming a
  // removed point are erased, and the entries naming the point that moves into the freed slot
  // (the last one) are renumbered.
  std::vector<unsigned>& mine = side == 0 ? m1 : m2;
  std::size_t n = t.nb_points();
  for (unsigned id : decreasing) {
    if (mine.empty()) break;
    for (std::size_t k = mine.size(); k-- > 0;)
      if (mine[k] == id) mine.erase(mine.begin() + static_cast<std::ptrdiff_t>(k));
    if (n == 0) continue;
    for (unsigned& v : mine)
      if (v == n - 1) v = id;
    --n;
  }
  if (first_point.parent()) first_point.set_parent(nullptr);
  if (second_point.parent()) second_point.set_parent(nullptr);
  first_point.set(std::move(m1));
  second_point.set(std::move(m2));
  rest_vector.edit().data = std::move(rest);
}

void BilateralLagrangianConstraint::bwd_init() {
  if (state() != ComponentState::valid) return;
  // Indices are checked once both states are sized.
  const std::size_t n = pairs();
  for (std::size_t i = 0; i < n; ++i) {
    if (first_point.value()[i] >= object1->size() || second_point.value()[i] >= object2->size()) {
      msg_error("pair " + std::to_string(i) + " (" + std::to_string(first_point.value()[i]) + ", " +
                std::to_string(second_point.value()[i]) + ") refers to a point out of range (object1 has " +
                std::to_string(object1->size()) + " points, object2 " + std::to_string(object2->size()) + ")");
      set_state(ComponentState::invalid);
      return;
    }
  }
  if (!rigid_ || !keep_orientation_difference.value()) return;
  if (!rest_vector.value().data.empty()) {
    msg_warning("keepOrientationDifference is set: rest_vector is ignored");
    rest_vector.edit().data.clear();
  }
  // Frame 2 seen from frame 1 at init: centre offset (world axes) and relative orientation.
  const std::vector<double>& x1 = object1->read(kPosition);
  const std::vector<double>& x2 = object2->read(kPosition);
  initial_difference_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* P = &x1[first_point.value()[i] * 7];
    const double* Q = &x2[second_point.value()[i] * 7];
    const Quat qp = quat_normalized(Quat::from(P + 3));
    const Quat qq = quat_normalized(Quat::from(Q + 3));
    const Quat dq = quat_normalized(quat_diff(qq, qp));
    std::array<double, 7>& d = initial_difference_[i];
    for (int k = 0; k < 3; ++k) d[k] = Q[k] - P[k];
    dq.store(&d[3]);
  }
}

void BilateralLagrangianConstraint::build_constraint_matrix(const ConstraintParams&, int& row) {
  constraint_index.set(static_cast<unsigned>(row));
  const std::size_t n = active_pairs();
  rows_.resize(n);
  ConstraintMatrix& c1 = object1->constraint_jacobian();
  ConstraintMatrix& c2 = object2->constraint_jacobian();
  for (std::size_t i = 0; i < n; ++i) {
    const int m1 = static_cast<int>(first_point.value()[i]);
    const int m2 = static_cast<int>(second_point.value()[i]);
    rows_[i] = row;
    // Row k moves component k of the derivative (Rigid3d: 0-2 translation, 3-5 rotation).
    for (int k = 0; k < width_; ++k) {
      c1.add_component(row + k, m1, k, -1.0);
      c2.add_component(row + k, m2, k, 1.0);
    }
    row += width_;
  }
}

void BilateralLagrangianConstraint::constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) {
  if (rigid_)
    violation_rigid3(p, dfree);
  else
    violation_vec3(p, dfree);
}

void BilateralLagrangianConstraint::violation_vec3(const ConstraintParams& p, std::vector<double>& dfree) {
  const std::size_t n = active_pairs();
  const std::vector<double>& rest = rest_vector.value().data;
  const std::size_t nrest = rest.size() / 3;
  if (p.order == ConstraintOrder::vel) {
    auto x1 = as_vec3(object1->read(kPosition));
    auto x2 = as_vec3(object2->read(kPosition));
    auto v1 = as_vec3(step_vec(*object1, p.v, kVelocity));
    auto v2 = as_vec3(step_vec(*object2, p.v, kVelocity));
    const double inv_dt = 1.0 / p.dt;
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned m1 = first_point.value()[i], m2 = second_point.value()[i];
      Vec3 dpos = x2[m2] - x1[m1];
      if (i < nrest) dpos -= -Vec3(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]);  // SOFA's sign
      dpos *= inv_dt;
      const Vec3 dv = v2[m2] - v1[m1];
      for (int k = 0; k < 3; ++k) dfree[rows_[i] + k] = dv[k] + dpos[k];
    }
    return;
  }
  auto x1 = as_vec3(step_vec(*object1, p.x, kPosition));
  auto x2 = as_vec3(step_vec(*object2, p.x, kPosition));
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 d = x2[second_point.value()[i]] - x1[first_point.value()[i]];
    if (i < nrest) d -= Vec3(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]);
    for (int k = 0; k < 3; ++k) dfree[rows_[i] + k] = d[k];
  }
}

void BilateralLagrangianConstraint::violation_rigid3(const ConstraintParams& p, std::vector<double>& dfree) {
  // Position violation in every order (SOFA's Rigid3d variant has no velocity form).
  const std::size_t n = active_pairs();
  const std::vector<double>& rest = rest_vector.value().data;
  const std::size_t nrest = rest.size() / 6;
  const std::vector<double>& x1 = step_vec(*object1, p.x, kPosition);
  const std::vector<double>& x2 = step_vec(*object2, p.x, kPosition);
  const bool keep = keep_orientation_difference.value() && initial_difference_.size() >= n;
  for (std::size_t i = 0; i < n; ++i) {
    const double* a = &x1[first_point.value()[i] * 7];
    const double* b = &x2[second_point.value()[i] * 7];
    Vec3 c1(a[0], a[1], a[2]);
    Quat q1 = Quat::from(a + 3);
    if (keep) {
      // Frame 1 carried by the initial difference: centre offset in world axes, orientation q1·dq.
      const std::array<double, 7>& d = initial_difference_[i];
      c1 = Vec3(a[0] + d[0], a[1] + d[1], a[2] + d[2]);
      q1 = quat_mul(q1, Quat::from(&d[3]));
    }
    const Vec3 dc = Vec3(b[0], b[1], b[2]) - c1;
    const Vec3 rot = quat_rotate(q1, quat_angular_displacement(Quat::from(b + 3), q1));
    double* out = &dfree[rows_[i]];
    for (int k = 0; k < 3; ++k) out[k] = dc[k], out[3 + k] = rot[k];
    if (i < nrest)
      for (int k = 0; k < 6; ++k) out[k] -= rest[6 * i + k];
  }
}

void BilateralLagrangianConstraint::constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) {
  const std::size_t n = active_pairs();
  if (!rigid_) prev_forces_.resize(n, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < n; ++i) {
    ConstraintBlock b;
    b.kind = ConstraintBlock::Kind::bilateral3;
    b.first = rows_[i];
    b.rows = 3;
    if (rigid_) {
      out.push_back(b);  // translation: no load, no warm start (SOFA)
      b.first += 3;
      out.push_back(b);  // rotation
      continue;
    }
    b.load = load.value();
    b.warm = prev_forces_[i].data();
    out.push_back(b);
  }
}

void register_bilateral_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "BilateralLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "holds pairs of points (or frames) of two states together with Lagrangian rows";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    return std::make_unique<BilateralLagrangianConstraint>(t == "Rigid3d" ? StateType::rigid3 : StateType::vec3);
  };
  r.add(std::move(info));
}

}  // namespace sinew
