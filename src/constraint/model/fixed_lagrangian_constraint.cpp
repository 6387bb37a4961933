// FixedLagrangianConstraint (spec/interaction.md §5.6): DOFs held at their
// rest position by Lagrangian rows instead of a projection.
//
// One row per scalar of the derivative of each fixed DOF (`indices`, or every
// DOF with fixAll): J = e_k on that DOF. Violation at the free positions:
// x_free − x_rest; Rigid3d: centre difference, then the roll/pitch/yaw angles
// of q_free·q_rest⁻¹ (SOFA's toEulerVector). The order of the step does not
// matter (SOFA reads the free positions in every order).
// Blocks: Vec3d one 3-row bilateral block per DOF, warm-started with the
// previous step's forces; Rigid3d two such blocks (translation, rotation);
// Vec1d/Vec2d/Vec6d one block of 1/2/6 rows solved with an LDLᵀ of its W
// block, without warm start.
#include <array>
#include <memory>
#include <string>

#include "constraint/model/constraint_states.h"
#include "constraint/solver/resolution.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

namespace {

class FixedLagrangianConstraint final : public LagrangianConstraint {
 public:
  Link<MechanicalState> mstate{this, "mstate", "state whose DOFs are fixed (default: the node's)"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the DOFs to fix", "Constraint"};
  Field<bool> fix_all{this, "fixAll", false, "fix every DOF of the state", "Constraint"};

  void init() override {
    type_ = template_state_type(*this, StateType::vec3);
    if (!resolve_constraint_state(*this, mstate, type_)) return;
    width_ = mstate->info().deriv_width;
    warm_.clear();
  }

  void bwd_init() override {
    if (state() != ComponentState::valid || fix_all.value()) return;
    for (std::size_t i = 0; i < indices.value().size(); ++i)
      if (indices.value()[i] >= mstate->size()) {
        msg_error("index " + std::to_string(indices.value()[i]) + " (entry " + std::to_string(i) +
                  ") is out of range: " + mstate->describe() + " has " + std::to_string(mstate->size()) + " DOFs");
        set_state(ComponentState::invalid);
        return;
      }
  }

  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    constraint_index.set(static_cast<unsigned>(row));
    const std::size_t n = count();
    rows_.resize(n);
    ConstraintMatrix& c = mstate->constraint_jacobian();
    for (std::size_t i = 0; i < n; ++i) {
      rows_[i] = row;
      const int dof = static_cast<int>(dof_of(i));
      for (int k = 0; k < width_; ++k) c.add_component(row + k, dof, k, 1.0);
      row += width_;
    }
  }

  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    const std::size_t n = count();
    const std::vector<double>& x = step_vec(*mstate, p.x, kPosition);
    const std::vector<double>& x0 = mstate->read(kRestPosition);
    const int cw = mstate->info().coord_width;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t dof = dof_of(i);
      const double* xf = &x[dof * cw];
      const double* xr = &x0[dof * cw];
      double* out = &dfree[rows_[i]];
      if (type_ == StateType::rigid3) {
        for (int k = 0; k < 3; ++k) out[k] = xf[k] - xr[k];
        const Vec3 e = quat_to_euler_vector(quat_mul(Quat::from(xf + 3), quat_inverse(Quat::from(xr + 3))));
        for (int k = 0; k < 3; ++k) out[3 + k] = e[k];
      } else {
        for (int k = 0; k < cw; ++k) out[k] = xf[k] - xr[k];
      }
    }
  }

  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    const std::size_t n = count();
    // SOFA resizes its previous forces without clearing them: DOFs keep theirs while the count holds.
    warm_.resize(n, {0, 0, 0, 0, 0, 0});
    if (type_ != StateType::vec3 && type_ != StateType::rigid3)
      while (factors_.size() < n) factors_.push_back(std::make_unique<BlockFactor>());
    for (std::size_t i = 0; i < n; ++i) {
      ConstraintBlock b;
      b.first = rows_[i];
      if (type_ == StateType::vec3 || type_ == StateType::rigid3) {
        b.kind = ConstraintBlock::Kind::bilateral3;
        b.rows = 3;
        b.warm = warm_[i].data();
        out.push_back(b);
        if (type_ == StateType::rigid3) {
          b.first += 3;
          b.warm = warm_[i].data() + 3;
          out.push_back(b);
        }
      } else {
        b.kind = ConstraintBlock::Kind::bilateral_n;
        b.rows = width_;
        b.factor = factors_[i].get();
        out.push_back(b);
      }
    }
  }

 private:
  std::size_t count() const { return fix_all.value() ? mstate->size() : indices.value().size(); }
  std::size_t dof_of(std::size_t i) const { return fix_all.value() ? i : indices.value()[i]; }

  StateType type_ = StateType::vec3;
  int width_ = 3;
  std::vector<int> rows_;                           // first row of each fixed DOF this step
  std::vector<std::array<double, 6>> warm_;         // previous forces (Vec3d, Rigid3d)
  std::vector<std::unique_ptr<BlockFactor>> factors_;  // Vec1d, Vec2d, Vec6d blocks
};

}  // namespace

void register_fixed_lagrangian_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "FixedLagrangianConstraint";
  info.category = "Constraint/Lagrangian/Model";
  info.description = "holds DOFs at their rest position with Lagrangian rows";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<FixedLagrangianConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
