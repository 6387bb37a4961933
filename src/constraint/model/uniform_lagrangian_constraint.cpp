// UniformLagrangianConstraint (spec/interaction.md §5.6): every scalar of a
// Vec1d state is held at zero (or at its rest value with constrainToRestPos),
// typically the output of a mapping such as DistanceMapping, which makes the
// mapped quantity a hard constraint (InextensiblePendulum).
//
// One row per DOF: J = 1 on it. Violation: position orders x_free (− x_rest);
// velocity order v_free + (x − x_rest)/dt with x the current position.
// Blocks: one bilateral row each (iterative), or all rows in one block solved
// exactly with an LDLᵀ of its W block (iterative = false).
#include <string>

#include "constraint/model/constraint_states.h"
#include "constraint/solver/resolution.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

class UniformLagrangianConstraint final : public LagrangianConstraint {
 public:
  Link<MechanicalState> mstate{this, "mstate", "constrained state (default: the node's)"};
  Field<bool> iterative{this, "iterative", true,
                        "one row at a time in the Gauss-Seidel sweep; false: all rows solved together", "Constraint"};
  Field<bool> constrain_to_rest_pos{this, "constrainToRestPos", false,
                                    "hold the values at the rest position instead of zero", "Constraint"};

  void init() override { resolve_constraint_state(*this, mstate, StateType::vec1); }

  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    constraint_index.set(static_cast<unsigned>(row));
    first_ = row;
    n_ = static_cast<int>(mstate->size());
    ConstraintMatrix& c = mstate->constraint_jacobian();
    for (int i = 0; i < n_; ++i) c.add_component(row++, i, 0, 1.0);
  }

  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    const bool rest = constrain_to_rest_pos.value();
    const std::vector<double>& x0 = mstate->read(kRestPosition);
    if (p.order == ConstraintOrder::vel) {
      const std::vector<double>& v = step_vec(*mstate, p.v, kVelocity);
      const std::vector<double>& x = mstate->read(kPosition);
      const double inv_dt = 1.0 / p.dt;
      for (int i = 0; i < n_; ++i) dfree[first_ + i] = v[i] + inv_dt * (rest ? x[i] - x0[i] : x[i]);
      return;
    }
    const std::vector<double>& x = step_vec(*mstate, p.x, kPosition);
    for (int i = 0; i < n_; ++i) dfree[first_ + i] = rest ? x[i] - x0[i] : x[i];
  }

  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    if (n_ == 0) return;
    ConstraintBlock b;
    if (iterative.value()) {
      b.kind = ConstraintBlock::Kind::bilateral;
      for (int i = 0; i < n_; ++i) {
        b.first = first_ + i;
        out.push_back(b);
      }
      return;
    }
    b.kind = ConstraintBlock::Kind::bilateral_n;
    b.first = first_;
    b.rows = n_;
    b.factor = &factor_;
    out.push_back(b);
  }

 private:
  int first_ = 0, n_ = 0;
  BlockFactor factor_;
};

}  // namespace

void register_uniform_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "UniformLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "holds every value of a Vec1d state at zero (or its rest value) with Lagrangian rows";
  info.templates = {"Vec1d"};
  info.default_template = "Vec1d";
  info.requirement = Requirement::state;
  info.create = creator<UniformLagrangianConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
