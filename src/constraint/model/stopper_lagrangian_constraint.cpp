// StopperLagrangianConstraint (spec/interaction.md §5.6): one value of a
// Vec1d state kept within [min, max] (a joint stop).
//
// One row, J = 1 on DOF `index`; violation x_free[index] in every order. Its
// block (kind stopper) starts from zero force each step and pushes the free
// value back onto the bound it crossed.
#include <string>

#include "constraint/model/constraint_states.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

class StopperLagrangianConstraint final : public LagrangianConstraint {
 public:
  Link<MechanicalState> mstate{this, "mstate", "constrained state (default: the node's)"};
  Field<int> index{this, "index", 0, "index of the stopped DOF", "Constraint"};
  Field<double> min{this, "min", -100.0, "smallest value accepted", "Constraint"};
  Field<double> max{this, "max", 100.0, "largest value accepted", "Constraint"};

  void init() override {
    if (!resolve_constraint_state(*this, mstate, StateType::vec1)) return;
    if (min.value() > max.value()) msg_warning("min is larger than max: the stop cannot be satisfied");
  }

  void bwd_init() override {
    if (state() != ComponentState::valid) return;
    if (index.value() < 0 || static_cast<std::size_t>(index.value()) >= mstate->size()) {
      msg_error("index " + std::to_string(index.value()) + " is out of range: " + mstate->describe() + " has " +
                std::to_string(mstate->size()) + " DOFs");
      set_state(ComponentState::invalid);
    }
  }

  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    constraint_index.set(static_cast<unsigned>(row));
    row_ = row;
    mstate->constraint_jacobian().add_component(row++, index.value(), 0, 1.0);
  }

  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    dfree[row_] = step_vec(*mstate, p.x, kPosition)[index.value()];
  }

  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    ConstraintBlock b;
    b.kind = ConstraintBlock::Kind::stopper;
    b.first = row_;
    b.lo = min.value();
    b.hi = max.value();
    out.push_back(b);
  }

 private:
  int row_ = 0;
};

}  // namespace

void register_stopper_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "StopperLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "keeps one value of a Vec1d state within [min, max] with a Lagrangian row";
  info.templates = {"Vec1d"};
  info.default_template = "Vec1d";
  info.requirement = Requirement::state;
  info.create = creator<StopperLagrangianConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
