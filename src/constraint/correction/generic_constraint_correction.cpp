// GenericConstraintCorrection (spec/interaction.md §5.3): the compliance of
// everything a linear solver solves for, from the matrix that solver
// assembled and factorised during the free motion. Not tied to one state:
// every independent state of the solver's system takes part, at its offset
// in the system (SOFA builds J over the solver's subtree in the same order).
//
// Compliance: W += f·J·A⁻¹·Jᵀ, f = the ODE solver's correction factor (dt for
// implicit Euler in position orders, 1 for velocity) × complianceFactor, then
// regularizationTerm on the diagonal of every row J touches.
// Correction: A·dx = Jᵀλ with the same factorisation, then on every state
// x = xf + pf·dx, v = vf + vf'·dx and the stored dx scaled by the factor of
// the order, with pf, vf' the ODE factors × complianceFactor (velocity order:
// v only, and SOFA leaves complianceFactor out there).
#include <limits>
#include <string>

#include <Eigen/SparseCore>

#include "constraint/correction/correction_solvers.h"
#include "core/constraint_problem.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/rigid.h"
#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

namespace {

class GenericConstraintCorrection final : public ConstraintCorrection {
 public:
  Link<LinearSolver> linear_solver{this, "linearSolver",
                                   "linear solver whose factorisation gives A⁻¹ (default: the first in this node)"};
  Link<OdeSolver> ode_solver{this, "ODESolver",
                             "ODE solver giving the integration factors (default: this node's, else the first from "
                             "the root)"};
  Field<double> compliance_factor{this, "complianceFactor", 1.0,
                                  "factor on the integration factors used for the compliance and the correction",
                                  "Correction"};
  Field<double> regularization_term{this, "regularizationTerm", 0.0,
                                    "added to the diagonal of W on the rows this correction touches", "Correction"};

  void init() override {
    // No state of its own: `mstate` only names the node's state when there is one.
    if (!mstate && node()) mstate.set(node()->get_mechanical_state());
    if (!linear_solver) msg_info("linearSolver is not set: the first linear solver of this node is used");
    solver_ = resolve_correction_solvers(*this, linear_solver, ode_solver);
    if (!solver_) set_state(ComponentState::invalid);
  }

  void add_compliance(const ConstraintParams& p, ConstraintProblem& problem) override {
    if (!system_ready() || problem.n == 0) return;
    if (!build_jacobian(problem.n)) return;
    const double factor = correction_factor(p) * compliance_factor.value();
    w_.setZero(problem.n, problem.n);
    solver_->add_jminvjt(w_, j_, factor);
    for (int r = 0; r < problem.n; ++r)
      for (int c = 0; c < problem.n; ++c) problem.w(r, c) += w_(r, c);
    const double reg = regularization_term.value();
    if (reg > std::numeric_limits<double>::epsilon())
      for (int r = 0; r < problem.n; ++r)
        if (row_used_[r]) problem.w(r, r) += reg;
  }

  void apply_correction(const ConstraintParams& p, const std::vector<double>& lambda, int x_out, int v_out,
                        int dx_out) override {
    if (!system_ready()) return;
    solve_correction(lambda);
    const double cf = compliance_factor.value();
    const double pf = ode_solver->position_integration_factor(p.dt);
    const double vf = ode_solver->velocity_integration_factor(p.dt);
    switch (p.order) {
      case ConstraintOrder::vel:
      case ConstraintOrder::acc:
        integrate(p.x, p.v, x_out, v_out, dx_out, 0.0, vf, vf);
        return;
      case ConstraintOrder::pos:
        integrate(p.x, p.v, x_out, v_out, dx_out, pf * cf, 0.0, pf * cf);
        return;
      case ConstraintOrder::pos_and_vel:
        integrate(p.x, p.v, x_out, v_out, dx_out, pf * cf, vf * cf, pf * cf);
        return;
    }
  }

  // LCP path: the correction of the contact forces f, from the current
  // positions and velocities (SOFA's default constraint parameters).
  void apply_contact_force(const ConstraintParams& p, const std::vector<double>& f) override {
    if (!system_ready()) return;
    solve_correction(f);
    const double cf = compliance_factor.value();
    const double pf = ode_solver->position_integration_factor(p.dt) * cf;
    const double vf = ode_solver->velocity_integration_factor(p.dt) * cf;
    integrate(kPosition, kVelocity, kPosition, kVelocity, kDx, pf, vf, pf);
  }

 private:
  double correction_factor(const ConstraintParams& p) const {
    return p.order == ConstraintOrder::vel || p.order == ConstraintOrder::acc
               ? ode_solver->velocity_integration_factor(p.dt)
               : ode_solver->position_integration_factor(p.dt);
  }

  // False (with one error) while the solver has no assembled system.
  bool system_ready() {
    MatrixLinearSystem* sys = solver_ ? solver_->system() : nullptr;
    if (sys && sys->assembled()) return true;
    if (!warned_) {
      warned_ = true;
      msg_error("the system of " + linear_solver->describe() +
                " was never assembled (is it the linear solver of an implicit ODE solver?): no constraint "
                "correction from it");
    }
    return false;
  }

  // J over the solver's unknowns: each state's rows at its offset in the system.
  bool build_jacobian(int rows) {
    const MatrixLinearSystem& sys = *solver_->system();
    triplets_.clear();
    row_used_.assign(rows, 0);
    for (const SystemAssembler::StateBlock& b : sys.assembler().layout()) {
      const ConstraintMatrix& J = b.state->constraint_jacobian();
      const int w = b.state->info().deriv_width;
      for (const ConstraintMatrix::Row& r : J.rows()) {
        if (r.end > r.begin && r.id < rows) row_used_[r.id] = 1;
        for (int e = r.begin; e < r.end; ++e) {
          const double* v = J.value(e);
          const std::size_t base = b.offset + static_cast<std::size_t>(J.entries()[e].dof) * w;
          for (int c = 0; c < w; ++c)
            if (v[c] != 0.0) triplets_.emplace_back(r.id, static_cast<int>(base + c), v[c]);
        }
      }
    }
    if (triplets_.empty()) return false;
    j_.resize(rows, static_cast<Eigen::Index>(sys.size()));
    j_.setFromTriplets(triplets_.begin(), triplets_.end());
    return true;
  }

  // sol_ = A⁻¹·Jᵀλ over the whole system.
  void solve_correction(const std::vector<double>& lambda) {
    const MatrixLinearSystem& sys = *solver_->system();
    rhs_.setZero(static_cast<Eigen::Index>(sys.size()));
    for (const SystemAssembler::StateBlock& b : sys.assembler().layout()) {
      const ConstraintMatrix& J = b.state->constraint_jacobian();
      const int w = b.state->info().deriv_width;
      for (const ConstraintMatrix::Row& r : J.rows()) {
        if (r.id >= static_cast<int>(lambda.size())) continue;
        const double l = lambda[r.id];
        if (l == 0.0) continue;
        for (int e = r.begin; e < r.end; ++e) {
          const double* v = J.value(e);
          const std::size_t base = b.offset + static_cast<std::size_t>(J.entries()[e].dof) * w;
          for (int c = 0; c < w; ++c) rhs_[base + c] += v[c] * l;
        }
      }
    }
    sol_.setZero(rhs_.size());
    solver_->solve_global(sol_, rhs_);
  }

  // On every state of the system: x = x_base + pf·dx (pf ≠ 0), v = v_base +
  // vf·dx (vf ≠ 0), stored dx = df·dx (SOFA's MechanicalIntegrateConstraintsVisitor).
  void integrate(int x_base, int v_base, int x_out, int v_out, int dx_out, double pf, double vf, double df) {
    for (const SystemAssembler::StateBlock& b : solver_->system()->assembler().layout()) {
      MechanicalState& s = *b.state;
      const int w = s.info().deriv_width;
      const std::size_t n = s.size() * static_cast<std::size_t>(w);
      const double* dx = sol_.data() + b.offset;
      if (pf != 0.0) {
        const std::vector<double>& xb = s.read(x_base);
        std::vector<double>& x = s.write(x_out);
        if (s.state_type() == StateType::rigid3) {
          for (std::size_t i = 0; i < s.size(); ++i) rigid3_add_deriv(&xb[i * 7], dx + i * 6, pf, &x[i * 7]);
        } else {
          for (std::size_t k = 0; k < n; ++k) x[k] = xb[k] + dx[k] * pf;
        }
      }
      if (vf != 0.0) {
        const std::vector<double>& vb = s.read(v_base);
        std::vector<double>& v = s.write(v_out);
        for (std::size_t k = 0; k < n; ++k) v[k] = vb[k] + dx[k] * vf;
      }
      std::vector<double>& d = s.write(dx_out);
      d.resize(n);
      for (std::size_t k = 0; k < n; ++k) d[k] = dx[k] * df;
    }
  }

  MatrixLinearSolver* solver_ = nullptr;
  bool warned_ = false;
  std::vector<Eigen::Triplet<double>> triplets_;
  std::vector<char> row_used_;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> j_;
  Eigen::MatrixXd w_;
  Eigen::VectorXd rhs_, sol_;
};

}  // namespace

void register_generic_constraint_correction(Registry& r) {
  ComponentInfo info;
  info.name = "GenericConstraintCorrection";
  info.category = "Constraint/Lagrangian/Correction";
  info.description = "compliance J·A⁻¹·Jᵀ of everything a linear solver solves for, from its factorised matrix";
  info.create = creator<GenericConstraintCorrection>();
  r.add(std::move(info));
}

}  // namespace sinew
