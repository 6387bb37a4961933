// LinearSolverConstraintCorrection (spec/interaction.md §5.3): the exact
// compliance J·A⁻¹·Jᵀ of a body, A being the system matrix its linear solver
// assembled and factorised during the free motion.
//
// Compliance: W += factor·J·A⁻¹·Jᵀ (factor: the ODE solver's position factor,
// dt for implicit Euler), plus regularizationTerm on rows touching the state.
// Correction: A·dx = Jᵀλ with the same factorisation, x = xf + pf·dx,
// v = vf + vf·dx (the ODE solver's position and velocity factors).
#include <algorithm>
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

class LinearSolverConstraintCorrection final : public ConstraintCorrection {
 public:
  Field<bool> wire_optimization{this, "wire_optimization", false,
                                "order the rows of this body by their smallest DoF (wire-like bodies)", "Correction"};
  Field<double> regularization_term{this, "regularizationTerm", 0.0,
                                    "added to the diagonal of W on the rows touching this body", "Correction"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver whose factorisation gives A⁻¹"};
  Link<OdeSolver> ode_solver{this, "ODESolver", "ODE solver giving the integration factors"};

  void init() override {
    ConstraintCorrection::init();
    if (state() != ComponentState::valid) return;
    solver_ = resolve_correction_solvers(*this, linear_solver, ode_solver);
    if (!solver_) set_state(ComponentState::invalid);
  }

  void add_compliance(const ConstraintParams& p, ConstraintProblem& problem) override {
    if (!locate()) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    if (J.empty()) return;
    build_jacobian(J, problem.n);
    const double factor = p.order == ConstraintOrder::pos || p.order == ConstraintOrder::pos_and_vel
                              ? ode_solver->position_integration_factor(p.dt)
                              : ode_solver->velocity_integration_factor(p.dt);
    w_.setZero(problem.n, problem.n);
    solver_->add_jminvjt(w_, j_, factor);
    for (int r = 0; r < problem.n; ++r)
      for (int c = 0; c < problem.n; ++c) problem.w(r, c) += w_(r, c);
    const double reg = regularization_term.value();
    if (reg > std::numeric_limits<double>::epsilon())
      for (const ConstraintMatrix::Row& row : J.rows())
        if (row.end > row.begin) problem.w(row.id, row.id) += reg;
  }

  void apply_correction(const ConstraintParams& p, const std::vector<double>& lambda, int x_out, int v_out,
                        int dx_out) override {
    if (!locate()) return;
    const int w = mstate->info().deriv_width;
    const std::size_t n = mstate->size();
    // rhs = Jᵀλ in the solver's global layout (zero elsewhere), then A·dx = rhs.
    rhs_.setZero(static_cast<Eigen::Index>(solver_->system()->size()));
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    for (const ConstraintMatrix::Row& r : J.rows()) {
      const double l = lambda[r.id];
      if (l == 0.0) continue;
      for (int e = r.begin; e < r.end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c) rhs_[base + c] += v[c] * l;
      }
    }
    sol_.setZero(rhs_.size());
    solver_->solve_global(sol_, rhs_);
    const double pf = ode_solver->position_integration_factor(p.dt);
    const double vf = ode_solver->velocity_integration_factor(p.dt);
    std::vector<double>& dx = mstate->write(dx_out);
    dx.resize(n * w);
    if (p.order == ConstraintOrder::vel) {
      const std::vector<double>& vfree = mstate->read(p.v);
      std::vector<double>& v = mstate->write(v_out);
      for (std::size_t k = 0; k < n * w; ++k) {
        dx[k] = sol_[offset_ + k] * vf;
        v[k] = vfree[k] + dx[k];
      }
      return;
    }
    for (std::size_t k = 0; k < n * w; ++k) dx[k] = sol_[offset_ + k] * pf;
    const std::vector<double>& xfree = mstate->read(p.x);
    std::vector<double>& x = mstate->write(x_out);
    if (mstate->state_type() == StateType::rigid3) {
      for (std::size_t i = 0; i < n; ++i) rigid3_add_deriv(&xfree[i * 7], &dx[i * 6], 1.0, &x[i * 7]);
    } else {
      for (std::size_t k = 0; k < n * w; ++k) x[k] = xfree[k] + dx[k];
    }
    if (p.order == ConstraintOrder::pos_and_vel) {
      const std::vector<double>& vfree = mstate->read(p.v);
      std::vector<double>& v = mstate->write(v_out);
      for (std::size_t k = 0; k < n * w; ++k) v[k] = vfree[k] + sol_[offset_ + k] * vf;
    }
  }

  // ---- unbuilt resolution. SOFA asks the linear solver for partial solves
  // (only BTDLinearSolver implements them; the others leave the solution
  // untouched); here the accumulated constraint force is solved with the
  // full factorisation whenever it changed, which is what an exact partial
  // solve gives on the DoFs read.
  bool supports_unbuilt() const override { return true; }

  void reset_for_unbuilt(const ConstraintParams& p, const std::vector<double>& f, std::vector<int>& sequence) override {
    problem_dt_ = p.dt;  // the helpers below read the ODE factors at the step's dt
    if (!locate()) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    cforce_.setZero(static_cast<Eigen::Index>(solver_->system()->size()));
    for (const ConstraintMatrix::Row& r : J.rows()) {
      const double fc = static_cast<std::size_t>(r.id) < f.size() ? f[r.id] : 0.0;
      if (fc == 0.0) continue;
      for (int e = r.begin; e < r.end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c) cforce_[base + c] += v[c] * fc;
      }
    }
    disp_dirty_ = true;
    if (wire_optimization.value()) wire_order(sequence);
  }

  // J·A⁻¹·Jᵀ on the block, with the position factor (dt for implicit Euler),
  // plus the regularisation on its rows that touch this body.
  void add_block_diagonal_compliance(ConstraintProblem& problem, int begin, int end) override {
    if (!locate() || end <= begin) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    triplets_.clear();
    bool any = false;
    for (int id = begin; id < end; ++id) {
      const ConstraintMatrix::Row* r = J.find_row(id);
      if (!r) continue;
      any = true;
      for (int e = r->begin; e < r->end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c)
          if (v[c] != 0.0) triplets_.emplace_back(id - begin, static_cast<int>(base + c), v[c]);
      }
    }
    if (!any) return;
    const int nb = end - begin;
    j_.resize(nb, static_cast<Eigen::Index>(solver_->system()->size()));
    j_.setFromTriplets(triplets_.begin(), triplets_.end());
    w_.setZero(nb, nb);
    solver_->add_jminvjt(w_, j_, ode_solver->position_integration_factor(problem_dt_));
    for (int r = 0; r < nb; ++r)
      for (int c = 0; c < nb; ++c) problem.w(begin + r, begin + c) += w_(r, c);
    const double reg = regularization_term.value();
    if (reg > std::numeric_limits<double>::epsilon())
      for (int id = begin; id < end; ++id)
        if (const ConstraintMatrix::Row* r = J.find_row(id); r && r->end > r->begin) problem.w(id, id) += reg;
  }

  void add_constraint_displacement(std::vector<double>& d, int begin, int end) override {
    if (!locate() || cforce_.size() == 0) return;
    if (disp_dirty_) {
      disp_.setZero(cforce_.size());
      solver_->solve_global(disp_, cforce_);
      disp_dirty_ = false;
    }
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    const double pf = ode_solver->position_integration_factor(problem_dt_);
    for (int id = begin; id < end; ++id) {
      const ConstraintMatrix::Row* r = J.find_row(id);
      if (!r) continue;
      for (int e = r->begin; e < r->end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c) d[id] += v[c] * (disp_[base + c] * pf);
      }
    }
  }

  void set_constraint_dforce(const std::vector<double>& df, int begin, int end) override {
    if (!locate() || cforce_.size() == 0) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    for (int id = begin; id < end; ++id) {
      const ConstraintMatrix::Row* r = J.find_row(id);
      if (!r) continue;
      for (int e = r->begin; e < r->end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c) cforce_[base + c] += v[c] * df[id];
      }
      disp_dirty_ = true;
    }
  }

  // ---- LCP path. SOFA clears the state's force vector here (not
  // externalForce): nothing reads it before the next step recomputes it.
  void reset_contact_force() override {
    std::vector<double>& f = mstate->write(kForce);
    std::fill(f.begin(), f.end(), 0.0);
  }

  void apply_contact_force(const ConstraintParams& p, const std::vector<double>& f) override {
    ConstraintParams q = p;
    q.x = kFreePosition;
    q.v = kFreeVelocity;
    q.order = ConstraintOrder::pos_and_vel;
    apply_correction(q, f, kPosition, kVelocity, kDx);
  }

 private:
  // SOFA's wire optimisation: the rows of this body leave the sequence and
  // come back at its end, ordered by the smallest DoF each row touches
  // (rows of other bodies keep their order, in front).
  void wire_order(std::vector<int>& sequence) {
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const std::size_t n = mstate->size();
    per_dof_.resize(n + 2);
    for (std::vector<int>& rows : per_dof_) rows.clear();
    for (const ConstraintMatrix::Row& r : J.rows()) {
      std::size_t min_dof = n + 1;
      for (int e = r.begin; e < r.end; ++e)
        min_dof = std::min(min_dof, static_cast<std::size_t>(J.entries()[e].dof));
      per_dof_[min_dof].push_back(r.id);
      sequence.erase(std::remove(sequence.begin(), sequence.end(), r.id), sequence.end());
    }
    // SOFA appends only the DoFs 0..n-1: rows without entries are dropped.
    for (std::size_t dof = 0; dof < n; ++dof)
      for (int id : per_dof_[dof]) sequence.push_back(id);
  }

  // Offset of this state in the solver's system; false (with one error) when
  // the system was never assembled or does not hold this state.
  bool locate() {
    MatrixLinearSystem* sys = solver_ ? solver_->system() : nullptr;
    if (sys && sys->assembled()) {
      for (const SystemAssembler::StateBlock& b : sys->assembler().layout())
        if (b.state == mstate.get()) {
          offset_ = b.offset;
          return true;
        }
    }
    if (!warned_) {
      warned_ = true;
      msg_error("the system of " + linear_solver->describe() + " does not hold " + mstate->describe() +
                " (was it assembled during the free motion?): no constraint correction for this body");
    }
    return false;
  }

  // J as a sparse matrix over the solver's global unknowns.
  void build_jacobian(const ConstraintMatrix& J, int rows) {
    const int w = mstate->info().deriv_width;
    triplets_.clear();
    for (const ConstraintMatrix::Row& r : J.rows())
      for (int e = r.begin; e < r.end; ++e) {
        const double* v = J.value(e);
        const std::size_t base = offset_ + static_cast<std::size_t>(J.entries()[e].dof) * w;
        for (int c = 0; c < w; ++c)
          if (v[c] != 0.0) triplets_.emplace_back(r.id, static_cast<int>(base + c), v[c]);
      }
    j_.resize(rows, static_cast<Eigen::Index>(solver_->system()->size()));
    j_.setFromTriplets(triplets_.begin(), triplets_.end());
  }

  MatrixLinearSolver* solver_ = nullptr;
  std::size_t offset_ = 0;
  bool warned_ = false;
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> j_;
  Eigen::MatrixXd w_;
  Eigen::VectorXd rhs_, sol_;
  // unbuilt resolution
  Eigen::VectorXd cforce_, disp_;  // accumulated constraint force (system layout) and A⁻¹ of it
  bool disp_dirty_ = true;
  double problem_dt_ = 0.0;
  std::vector<std::vector<int>> per_dof_;
};

}  // namespace

void register_linear_solver_constraint_correction(Registry& r) {
  ComponentInfo info;
  info.name = "LinearSolverConstraintCorrection";
  info.category = "Constraint/Lagrangian/Correction";
  info.description = "exact compliance J·A⁻¹·Jᵀ from the body's factorised system matrix";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<LinearSolverConstraintCorrection>();
  r.add(std::move(info));
}

}  // namespace sinew
