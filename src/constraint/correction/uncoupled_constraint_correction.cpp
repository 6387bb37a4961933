// UncoupledConstraintCorrection (spec/interaction.md §5.3): a diagonal
// compliance per DOF, so constraint rows couple only through shared DOFs.
//
// Vec1d/2d/3d: one compliance per DOF (`compliance`, else `defaultCompliance`).
// Rigid3d: 7 numbers (translation compliance, then the upper triangle of the
// 3×3 rotational compliance), used for every rigid of the state as SOFA does;
// derived from the node's UniformMass when not given. With
// useOdeSolverIntegrationFactors the compliance is scaled by the ODE solver's
// position factor (dt for implicit Euler) and the correction moves x by the
// position factor and v by the velocity factor.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/constraint_problem.h"
#include "core/node.h"
#include "core/registry.h"
#include "mass/uniform_mass.h"
#include "math/rigid.h"

namespace sinew {

namespace {

class UncoupledConstraintCorrection final : public ConstraintCorrection {
 public:
  Field<std::vector<double>> compliance{
      this, "compliance", {},
      "compliance per DoF; Rigid3d: 7 values (translation, then the upper triangle of the rotational compliance)",
      "Correction"};
  Field<double> default_compliance{this, "defaultCompliance", 1e-5,
                                   "compliance of DoFs without a value in 'compliance'", "Correction"};
  Field<bool> verbose{this, "verbose", false, "print the constraint rows (debug)", "Correction"};
  Field<double> correction_velocity_factor{this, "correctionVelocityFactor", 1.0,
                                           "factor on velocity corrections without ODE factors", "Correction"};
  Field<double> correction_position_factor{this, "correctionPositionFactor", 1.0,
                                           "factor on position corrections without ODE factors", "Correction"};
  Field<bool> use_ode_factors{this, "useOdeSolverIntegrationFactors", true,
                              "scale by the ODE solver's integration factors instead of the two factors above",
                              "Correction"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the per-DoF compliance (unused in batch runs)"};

  void init() override {
    ConstraintCorrection::init();
    if (state() != ComponentState::valid) return;
    rigid_ = mstate->state_type() == StateType::rigid3;
    if (!rigid_ && mstate->state_type() != StateType::vec1 && mstate->state_type() != StateType::vec2 &&
        mstate->state_type() != StateType::vec3) {
      msg_error(std::string("template ") + mstate->info().name + " is not supported (Vec1d, Vec2d, Vec3d, Rigid3d)");
      set_state(ComponentState::invalid);
      return;
    }
    ode_ = node()->find_up<OdeSolver>();
    if (!ode_ && use_ode_factors.value()) {
      msg_error("no ODE solver found in this node or above: useOdeSolverIntegrationFactors is set to false");
      use_ode_factors.set(false);
    }
    if (default_compliance.value() == 0.0) {
      msg_error("defaultCompliance is zero: the constraint resolution would diverge");
      set_state(ComponentState::invalid);
      return;
    }
    if (rigid_ ? !init_rigid() : !init_vec()) set_state(ComponentState::invalid);
  }

  void add_compliance(const ConstraintParams& p, ConstraintProblem& problem) override {
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    if (J.empty()) return;
    const double factor = use_ode_factors.value() ? correction_factor(p) : 1.0;
    scaled_.assign(comp_.begin(), comp_.end());
    for (double& c : scaled_) c *= factor;
    const double c0 = default_compliance.value() * factor;
    const auto rows = J.rows();
    const auto entries = J.entries();
    for (std::size_t a = 0; a < rows.size(); ++a) {
      const ConstraintMatrix::Row& ra = rows[a];
      {
        double w = 0.0;
        for (int e = ra.begin; e < ra.end; ++e) w += pair(scaled_, entries[e].dof, J.value(e), J.value(e), c0);
        problem.w(ra.id, ra.id) += w;
      }
      // Rows sorted by DOF: the shared DOFs of two rows in one pass.
      for (std::size_t b = a + 1; b < rows.size(); ++b) {
        const ConstraintMatrix::Row& rb = rows[b];
        double w = 0.0;
        int i = ra.begin, k = rb.begin;
        while (i < ra.end && k < rb.end) {
          if (entries[i].dof < entries[k].dof) ++i;
          else if (entries[k].dof < entries[i].dof) ++k;
          else {
            w += pair(scaled_, entries[i].dof, J.value(i), J.value(k), c0);
            ++i;
            ++k;
          }
        }
        if (w != 0.0) {
          problem.w(ra.id, rb.id) += w;
          problem.w(rb.id, ra.id) += w;
        }
      }
    }
  }

  void apply_correction(const ConstraintParams& p, const std::vector<double>& lambda, int x_out, int v_out,
                        int dx_out) override {
    const std::size_t n = mstate->size();
    const int w = mstate->info().deriv_width;
    // force = Jᵀλ on this state, then dx = C·force per DoF (no integration factor).
    force_.assign(n * w, 0.0);
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    for (const ConstraintMatrix::Row& r : J.rows()) {
      const double l = lambda[r.id];
      for (int e = r.begin; e < r.end; ++e) {
        const double* v = J.value(e);
        double* f = &force_[static_cast<std::size_t>(J.entries()[e].dof) * w];
        for (int c = 0; c < w; ++c) f[c] += v[c] * l;
      }
    }
    corr_.assign(n * w, 0.0);
    const double c0 = default_compliance.value();
    for (std::size_t i = 0; i < n; ++i) dof_dx(i, &force_[i * w], c0, &corr_[i * w]);

    const bool ode = use_ode_factors.value();
    const double dt = p.dt;
    std::vector<double>& dx = mstate->write(dx_out);
    dx.resize(n * w);
    if (p.order == ConstraintOrder::vel) {
      const double vf = ode ? ode_->velocity_integration_factor(dt) : correction_velocity_factor.value();
      const std::vector<double>& vfree = mstate->read(p.v);
      std::vector<double>& v = mstate->write(v_out);
      for (std::size_t k = 0; k < n * w; ++k) {
        dx[k] = corr_[k] * vf;
        v[k] = vfree[k] + dx[k];
      }
      return;
    }
    const double xf = ode ? ode_->position_integration_factor(dt) : correction_position_factor.value();
    for (std::size_t k = 0; k < n * w; ++k) dx[k] = corr_[k] * xf;
    add_to_coords(p.x, dx_out, x_out);
    if (p.order == ConstraintOrder::pos_and_vel) {
      const double vf = ode ? ode_->velocity_integration_factor(dt) : correction_velocity_factor.value() / dt;
      const std::vector<double>& vfree = mstate->read(p.v);
      std::vector<double>& v = mstate->write(v_out);
      for (std::size_t k = 0; k < n * w; ++k) v[k] = vfree[k] + corr_[k] * vf;
    }
  }

  // ---- unbuilt resolution (UnbuiltGaussSeidel, unbuilt LCP): the DoFs keep
  // the constraint force accumulated so far and the displacement it causes.
  bool supports_unbuilt() const override { return true; }

  void reset_for_unbuilt(const ConstraintParams&, const std::vector<double>& f, std::vector<int>&) override {
    const std::size_t n = mstate->size() * mstate->info().deriv_width;
    cforce_.assign(n, 0.0);
    // SOFA starts the displacements at zero even when the initial forces
    // are not: an initial guess is only seen once a DoF's force changes.
    cdisp_.assign(n, 0.0);
    add_jt(f, cforce_);
  }

  // Without the integration factor, unlike add_compliance: with
  // useOdeSolverIntegrationFactors the unbuilt solvers see a compliance dt
  // times too large while the correction still scales by dt (SOFA's quirk,
  // reproduced: BilateralLagrangianConstraint_UGS's reference encodes it).
  void add_block_diagonal_compliance(ConstraintProblem& problem, int begin, int end) override {
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const auto entries = J.entries();
    const double c0 = default_compliance.value();
    for (int id1 = begin; id1 < end; ++id1) {
      const ConstraintMatrix::Row* ra = J.find_row(id1);
      if (!ra) continue;
      double self = 0.0;
      for (int e = ra->begin; e < ra->end; ++e) self += pair(comp_, entries[e].dof, J.value(e), J.value(e), c0);
      problem.w(id1, id1) += self;
      for (int id2 = id1 + 1; id2 < end; ++id2) {
        const ConstraintMatrix::Row* rb = J.find_row(id2);
        if (!rb) continue;
        double w = 0.0;
        int i = ra->begin, k = rb->begin;
        while (i < ra->end && k < rb->end) {
          if (entries[i].dof < entries[k].dof) ++i;
          else if (entries[k].dof < entries[i].dof) ++k;
          else {
            w += pair(comp_, entries[i].dof, J.value(i), J.value(k), c0);
            ++i;
            ++k;
          }
        }
        if (w != 0.0) {
          problem.w(id1, id2) += w;
          problem.w(id2, id1) += w;
        }
      }
    }
  }

  void add_constraint_displacement(std::vector<double>& d, int begin, int end) override {
    if (state() != ComponentState::valid || cdisp_.empty()) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    for (int id = begin; id < end; ++id) {
      const ConstraintMatrix::Row* r = J.find_row(id);
      if (!r) continue;
      for (int e = r->begin; e < r->end; ++e) {
        const double* v = J.value(e);
        const double* disp = &cdisp_[static_cast<std::size_t>(J.entries()[e].dof) * w];
        double s = 0.0;
        for (int c = 0; c < w; ++c) s += v[c] * disp[c];
        d[id] += s;
      }
    }
  }

  void set_constraint_dforce(const std::vector<double>& df, int begin, int end) override {
    if (cforce_.empty()) return;
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    const double c0 = default_compliance.value();
    for (int id = begin; id < end; ++id) {
      const ConstraintMatrix::Row* r = J.find_row(id);
      if (!r) continue;
      for (int e = r->begin; e < r->end; ++e) {
        const double* v = J.value(e);
        const std::size_t dof = static_cast<std::size_t>(J.entries()[e].dof);
        double* cf = &cforce_[dof * w];
        for (int c = 0; c < w; ++c) cf[c] += v[c] * df[id];
        dof_dx(dof, cf, c0, &cdisp_[dof * w]);  // no integration factor
      }
    }
  }

  // ---- LCP path: the contact force goes through externalForce.
  void reset_contact_force() override {
    std::vector<double>& ext = mstate->write(kExternalForce);
    std::fill(ext.begin(), ext.end(), 0.0);
  }

  void apply_contact_force(const ConstraintParams& p, const std::vector<double>& f) override {
    if (state() != ComponentState::valid) return;
    const std::size_t n = mstate->size();
    const int w = mstate->info().deriv_width;
    std::vector<double>& ext = mstate->write(kExternalForce);
    ext.resize(n * w, 0.0);
    add_jt(f, ext);
    corr_.assign(n * w, 0.0);
    const double c0 = default_compliance.value();
    for (std::size_t i = 0; i < n; ++i) dof_dx(i, &ext[i * w], c0, &corr_[i * w]);
    const bool ode = use_ode_factors.value();
    const double xf = ode ? ode_->position_integration_factor(p.dt) : correction_position_factor.value();
    const double vf = ode ? ode_->velocity_integration_factor(p.dt) : correction_velocity_factor.value() / p.dt;
    std::vector<double>& dx = mstate->write(kDx);
    dx.resize(n * w);
    for (std::size_t k = 0; k < n * w; ++k) dx[k] = corr_[k] * xf;
    add_to_coords(kFreePosition, kDx, kPosition);
    const std::vector<double>& vfree = mstate->read(kFreeVelocity);
    std::vector<double>& v = mstate->write(kVelocity);
    for (std::size_t k = 0; k < n * w; ++k) v[k] = vfree[k] + corr_[k] * vf;
  }

 private:
  // out += Jᵀf over the rows whose force is not zero.
  void add_jt(const std::vector<double>& f, std::vector<double>& out) const {
    const ConstraintMatrix& J = mstate->constraint_jacobian();
    const int w = mstate->info().deriv_width;
    for (const ConstraintMatrix::Row& r : J.rows()) {
      const double l = static_cast<std::size_t>(r.id) < f.size() ? f[r.id] : 0.0;
      if (l == 0.0) continue;
      for (int e = r.begin; e < r.end; ++e) {
        const double* v = J.value(e);
        double* o = &out[static_cast<std::size_t>(J.entries()[e].dof) * w];
        for (int c = 0; c < w; ++c) o[c] += v[c] * l;
      }
    }
  }

  // SOFA's correctionFactor: the ODE solver's position factor for position
  // orders, its velocity factor for velocity ones.
  double correction_factor(const ConstraintParams& p) const {
    if (!ode_) return 1.0;
    return p.order == ConstraintOrder::pos || p.order == ConstraintOrder::pos_and_vel
               ? ode_->position_integration_factor(p.dt)
               : ode_->velocity_integration_factor(p.dt);
  }

  // Compliance between two Jacobian entries on DoF `dof`, with the per-DoF
  // compliances `comp` (scaled_ or comp_) and `c0` for DoFs beyond them.
  double pair(const std::vector<double>& comp, int dof, const double* a, const double* b, double c0) const {
    if (rigid_) {
      const double* c = comp.data();
      double w = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * c[0];
      w += (a[3] * c[1] + a[4] * c[2] + a[5] * c[3]) * b[3];
      w += (a[3] * c[2] + a[4] * c[4] + a[5] * c[5]) * b[4];
      w += (a[3] * c[3] + a[4] * c[5] + a[5] * c[6]) * b[5];
      return w;
    }
    const int width = mstate->info().deriv_width;
    double dot = 0.0;
    for (int k = 0; k < width; ++k) dot += a[k] * b[k];
    return dot * (static_cast<std::size_t>(dof) < comp.size() ? comp[dof] : c0);
  }

  // dx of one DoF from its constraint force (unscaled compliance).
  void dof_dx(std::size_t i, const double* f, double c0, double* out) const {
    if (rigid_) {
      const double* c = comp_.data();
      for (int k = 0; k < 3; ++k) out[k] = f[k] * c[0];
      out[3] = f[3] * c[1] + f[4] * c[2] + f[5] * c[3];
      out[4] = f[3] * c[2] + f[4] * c[4] + f[5] * c[5];
      out[5] = f[3] * c[3] + f[4] * c[5] + f[5] * c[6];
      return;
    }
    const int width = mstate->info().deriv_width;
    const double c = i < comp_.size() ? comp_[i] : c0;
    for (int k = 0; k < width; ++k) out[k] = f[k] * c;
  }

  // x_out = x_free + dx per DoF (the exponential map for rigids, as SOFA's RigidCoord +=).
  void add_to_coords(int x_free, int dx, int x_out) {
    const std::vector<double>& d = mstate->read(dx);
    const std::vector<double>& xf = mstate->read(x_free);  // x_free is never x_out (free vs current positions)
    std::vector<double>& x = mstate->write(x_out);
    const std::size_t n = mstate->size();
    if (rigid_) {
      for (std::size_t i = 0; i < n; ++i) rigid3_add_deriv(&xf[i * 7], &d[i * 6], 1.0, &x[i * 7]);
    } else {
      for (std::size_t k = 0; k < x.size() && k < xf.size(); ++k) x[k] = xf[k] + d[k];
    }
  }

  bool init_vec() {
    if (!default_compliance.is_set() && !compliance.is_set())
      msg_warning("neither 'defaultCompliance' nor 'compliance' is set: defaultCompliance " +
                  std::to_string(default_compliance.value()) + " is used");
    std::vector<double> comp = compliance.value();
    if (std::any_of(comp.begin(), comp.end(), [](double c) { return c == 0.0; })) {
      msg_error("a compliance value is zero: the constraint resolution would diverge");
      return false;
    }
    // The same single value in both: keep only the default (SOFA).
    if (comp.size() == 1 && default_compliance.is_set() && default_compliance.value() == comp[0]) comp.clear();
    const std::size_t n = mstate->size();
    if (!comp.empty() && comp.size() != n) {
      if (comp.size() > 1)
        msg_warning("'compliance' has " + std::to_string(comp.size()) + " values for " + std::to_string(n) +
                    " DoFs: a single value is used for all");
      if (!default_compliance.is_set()) default_compliance.set(comp[0]);
      comp.assign(n, default_compliance.value());
    }
    comp_ = comp;
    return true;
  }

  bool init_rigid() {
    std::vector<double> comp = compliance.value();
    if (comp.size() == 7) {
      if (comp[0] == 0.0 || comp[1] == 0.0 || comp[4] == 0.0 || comp[6] == 0.0) {
        msg_error("zero translational or rotational compliance: the constraint resolution would diverge");
        return false;
      }
      comp_ = comp;
      return true;
    }
    if (!comp.empty())
      msg_warning("'compliance' of a Rigid3d state needs 7 values (it has " + std::to_string(comp.size()) +
                  "): derived from the mass instead");
    // W = h²·J·M⁻¹·Jᵀ when the compliance is not scaled by the solver (SOFA).
    double ode_factor = 1.0;
    if (ode_ && !use_ode_factors.value()) {
      const double dt = node()->root()->dt.value();
      ode_factor = dt * dt;
    }
    Mat3 inv_inertia = Mat3::Identity();
    comp.clear();
    if (default_compliance.is_set()) {
      comp.push_back(default_compliance.value());
    } else if (auto* um = dynamic_cast<UniformMass*>(node()->mass)) {
      comp.push_back(ode_factor / um->mass());
      inv_inertia = um->inv_inertia_mass();
    } else {
      msg_warning("neither a compliance nor a UniformMass in this node: unit mass and inertia are assumed");
      comp.push_back(ode_factor);  // SOFA's default Rigid3Mass: mass 1
    }
    comp.push_back(ode_factor * inv_inertia(0, 0));
    comp.push_back(ode_factor * inv_inertia(0, 1));
    comp.push_back(ode_factor * inv_inertia(0, 2));
    comp.push_back(ode_factor * inv_inertia(1, 1));
    comp.push_back(ode_factor * inv_inertia(1, 2));
    comp.push_back(ode_factor * inv_inertia(2, 2));
    compliance.set(comp);
    comp_ = comp;
    return true;
  }

  bool rigid_ = false;
  OdeSolver* ode_ = nullptr;
  std::vector<double> comp_;    // compliance as used (per DoF, or the 7 rigid numbers)
  std::vector<double> scaled_;  // comp_ × integration factor (add_compliance scratch)
  std::vector<double> force_, corr_;
  std::vector<double> cforce_, cdisp_;  // unbuilt resolution: force and displacement per DoF
};

}  // namespace

void register_uncoupled_constraint_correction(Registry& r) {
  ComponentInfo info;
  info.name = "UncoupledConstraintCorrection";
  info.category = "Constraint/Lagrangian/Correction";
  info.description = "diagonal compliance per DoF (Rigid3d: from the mass) for Lagrangian constraints";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<UncoupledConstraintCorrection>();
  r.add(std::move(info));
}

}  // namespace sinew
