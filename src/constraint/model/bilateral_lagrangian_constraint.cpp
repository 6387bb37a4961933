// BilateralLagrangianConstraint (ex BilateralInteractionConstraint,
// spec/interaction.md §5.6): point first_point[i] of object1 and
// second_point[i] of object2 are held together (at rest_vector[i] apart).
//
// Three rows per pair: J = −e_x, −e_y, −e_z on object1's point and +e on
// object2's; violation x2 − x1 − rest at the free positions (velocity order:
// (v2 − v1) + (x2 − x1 + rest)/dt, SOFA's sign). Each pair is one 3×3
// bilateral block warm-started with the forces of the previous step.
#include <algorithm>
#include <array>
#include <string>

#include "core/constraint_problem.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

class BilateralLagrangianConstraint final : public LagrangianConstraint {
 public:
  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::vector<unsigned>> first_point{this, "first_point", {}, "indices of the constrained points on object1",
                                           "Constraint"};
  Field<std::vector<unsigned>> second_point{this, "second_point", {},
                                            "indices of the constrained points on object2", "Constraint"};
  Field<std::vector<Vec3>> rest_vector{this, "rest_vector", {},
                                       "relative position to keep between the points of each pair (optional)",
                                       "Constraint", "length"};
  Field<bool> activate{this, "activate", true, "whether the constraint is active", "Constraint"};
  Field<bool> keep_orientation_difference{this, "keepOrientationDifference", false,
                                          "keep the initial orientation difference (Rigid3d only)", "Constraint"};
  Field<double> load{this, "load", 1.0, "factor on the constraint force, in [0, 1] (incremental loading)",
                     "Constraint"};
  Link<MeshTopologyBase> topology1{this, "topology1", "topology of object1 (point removals drop pairs)"};
  Link<MeshTopologyBase> topology2{this, "topology2", "topology of object2 (point removals drop pairs)"};

  void init() override {
    MechanicalState* local = node() ? node()->get_mechanical_state() : nullptr;
    if (!object1) object1.set(local);
    if (!object2) object2.set(local);
    if (!object1 || !object2) {
      msg_error("no mechanical state found (object1/object2 or the node's state)");
      set_state(ComponentState::invalid);
      return;
    }
    for (const Link<MechanicalState>* o : {&object1, &object2})
      if ((*o)->state_type() != StateType::vec3) {
        msg_error(std::string((*o)->describe()) + " is " + (*o)->info().name +
                  ": this constraint takes Vec3d states (Rigid3d is not supported yet)");
        set_state(ComponentState::invalid);
        return;
      }
    if (load.value() < 0.0 || load.value() > 1.0) {
      msg_warning("load " + std::to_string(load.value()) + " is outside [0, 1]: clamped");
      load.set(std::clamp(load.value(), 0.0, 1.0));
    }
    prev_forces_.clear();
  }

  void bwd_init() override {
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
  }

  void reinit() override { prev_forces_.clear(); }

  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    const std::size_t n = active_pairs();
    rows_.resize(n);
    ConstraintMatrix& c1 = object1->constraint_jacobian();
    ConstraintMatrix& c2 = object2->constraint_jacobian();
    for (std::size_t i = 0; i < n; ++i) {
      const int m1 = static_cast<int>(first_point.value()[i]);
      const int m2 = static_cast<int>(second_point.value()[i]);
      rows_[i] = row;
      for (int k = 0; k < 3; ++k) {
        c1.add_component(row + k, m1, k, -1.0);
        c2.add_component(row + k, m2, k, 1.0);
      }
      row += 3;
    }
  }

  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    const std::size_t n = active_pairs();
    const auto& rest = rest_vector.value();
    if (p.order == ConstraintOrder::vel) {
      auto x1 = as_vec3(object1->read(kPosition));
      auto x2 = as_vec3(object2->read(kPosition));
      auto v1 = as_vec3(object1->read(vec_for(*object1, p.v, kVelocity)));
      auto v2 = as_vec3(object2->read(vec_for(*object2, p.v, kVelocity)));
      const double inv_dt = 1.0 / p.dt;
      for (std::size_t i = 0; i < n; ++i) {
        const unsigned m1 = first_point.value()[i], m2 = second_point.value()[i];
        Vec3 dpos = x2[m2] - x1[m1];
        if (i < rest.size()) dpos -= -rest[i];  // SOFA's sign
        dpos *= inv_dt;
        const Vec3 dv = v2[m2] - v1[m1];
        for (int k = 0; k < 3; ++k) dfree[rows_[i] + k] = dv[k] + dpos[k];
      }
      return;
    }
    auto x1 = as_vec3(object1->read(vec_for(*object1, p.x, kPosition)));
    auto x2 = as_vec3(object2->read(vec_for(*object2, p.x, kPosition)));
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 d = x2[second_point.value()[i]] - x1[first_point.value()[i]];
      if (i < rest.size()) d -= rest[i];
      for (int k = 0; k < 3; ++k) dfree[rows_[i] + k] = d[k];
    }
  }

  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    const std::size_t n = active_pairs();
    prev_forces_.resize(n, {0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < n; ++i) {
      ConstraintBlock b;
      b.kind = ConstraintBlock::Kind::bilateral3;
      b.first = rows_[i];
      b.rows = 3;
      b.load = load.value();
      b.warm = prev_forces_[i].data();
      out.push_back(b);
    }
  }

 private:
  std::size_t pairs() const { return std::min(first_point.value().size(), second_point.value().size()); }
  std::size_t active_pairs() const { return activate.value() ? pairs() : 0; }

  std::vector<int> rows_;                          // first row of each pair this step
  std::vector<std::array<double, 3>> prev_forces_;  // warm start, per pair
};

}  // namespace

void register_bilateral_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "BilateralLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "holds pairs of points of two states together (three Lagrangian rows per pair)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<BilateralLagrangianConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
