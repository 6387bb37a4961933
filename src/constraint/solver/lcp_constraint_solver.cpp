#include "constraint/solver/lcp_constraint_solver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "core/value_text.h"

namespace sinew {

namespace {

bool usable(const Component& c) { return c.state() == ComponentState::valid; }

bool entry_less(const LagrangianConstraint* pa, std::int64_t ia, const LagrangianConstraint* pb, std::int64_t ib) {
  if (pa != pb) return std::less<const LagrangianConstraint*>()(pa, pb);
  return ia < ib;
}

}  // namespace

void LCPConstraintSolver::init() {
  if (max_it.value() < 0) {
    msg_error("maxIt must be >= 0");
    set_state(ComponentState::invalid);
  }
}

bool LCPConstraintSolver::active(const ConstraintCorrection& cc) const { return usable(cc); }

void LCPConstraintSolver::solve_constraint(const ConstraintParams& p, int /*x_out*/, int /*v_out*/) {
  sync_constraint_scope(*node(), scope_);
  // prepareStates: the state's dx is zeroed everywhere (mapped states too),
  // then each correction clears the force it applies through.
  for (MechanicalState* st : scope_.ops->all_states()) {
    std::vector<double>& dx = st->write(kDx);
    std::fill(dx.begin(), dx.end(), 0.0);
  }
  for (ConstraintCorrection* cc : scope_.corrections)
    if (active(*cc)) cc->reset_contact_force();

  // buildSystem, with the solver's own parameters (SOFA builds a fresh
  // ConstraintParams: free position and velocity, position-and-velocity
  // order), whatever the animation loop asked.
  params_ = ConstraintParams{};
  params_.dt = p.dt;
  const int n = build_constraint_jacobian(scope_, params_, /*project=*/false);
  problem_.clear(n);
  for (LagrangianConstraint* c : scope_.constraints)
    if (usable(*c)) c->constraint_violation(params_, problem_.dfree);
  if (build_lcp.value()) add_compliances(scope_, params_, problem_, regularization_term.value());
  infos_.clear();
  ids_.clear();
  if (initial_guess.value() && n > 0) {
    for (LagrangianConstraint* c : scope_.constraints)
      if (usable(*c)) c->constraint_info(infos_, ids_);
    compute_initial_guess();
  }
  initial_forces_.assign(problem_.f.begin(), problem_.f.end());
  Event built{Event::Kind::build_constraint_system_end};  // SOFA's postBuildSystem
  propagate_event(*node(), built);

  // solveSystem: the solver's mu picks the algorithm.
  result_ = LcpResult{};
  const double m = mu.value();
  const bool friction = m > 0.0;
  if (n > 0 && friction && n % 3 != 0 && !warned_rows_) {
    warned_rows_ = true;
    msg_error("mu = " + parse::format_double(m) + " solves contacts of 3 rows (normal and friction) but there are " +
              std::to_string(n) +
              " rows: nothing is solved (set the contacts' friction mu > 0, or this solver's mu = 0 for "
              "frictionless contacts)");
  }
  if (n > 0) {
    if (build_lcp.value()) {
      if (friction)
        result_ = nlcp_gauss_seidel(n, problem_.dfree.data(), problem_.W.data(), problem_.f.data(), m,
                                    tolerance.value(), max_it.value(), initial_guess.value(), min_w.value(),
                                    max_f.value());
      else
        result_ = gauss_seidel_lcp1(n, problem_.dfree.data(), problem_.W.data(), problem_.f.data(), tolerance.value(),
                                    max_it.value(), min_w.value(), max_f.value(), lcp_work_);
    } else if (friction) {
      solve_unbuilt_nlcp();
    } else {
      solve_unbuilt_lcp();
    }
  } else {
    result_.converged = true;
  }
  if (compute_constraint_forces.value()) constraint_forces.set(problem_.f);
  bool finite = true;
  for (double v : problem_.f) finite = finite && std::isfinite(v);
  if (!finite) {
    msg_error("the constraint forces are not finite (" + std::to_string(n) +
              " rows): no force applied this step; check the compliance of the constraint corrections");
    std::fill(problem_.f.begin(), problem_.f.end(), 0.0);
  } else if (n > 0 && !result_.converged && (!friction || n % 3 == 0) && !warned_divergence_) {
    warned_divergence_ = true;
    msg_warning("no convergence after " + std::to_string(result_.iterations) + " iterations: residual " +
                parse::format_double(result_.error) + " (tolerance " + parse::format_double(tolerance.value()) +
                ", " + std::to_string(n) + " rows); the contacts may contradict each other (warned once)");
  }

  Event solved{Event::Kind::solve_constraint_system_end};  // SOFA's postSolveSystem
  propagate_event(*node(), solved);

  // applyCorrection
  if (initial_guess.value()) keep_contact_forces();
  for (ConstraintCorrection* cc : scope_.corrections)
    if (active(*cc) && !cc->node()->sleeping.value()) cc->apply_contact_force(params_, problem_.f);
}

// Zero forces, then each group of a constraint that existed last step takes
// last step's forces of the group with the same persistent id. SOFA copies
// min(lines now, lines then) rows and strides groups by that number.
void LCPConstraintSolver::compute_initial_guess() {
  const int n = problem_.n;
  const int contacts = mu.value() > 0.0 ? n / 3 : n;
  const int zeroed = mu.value() > 0.0 ? 3 * contacts : contacts;
  std::fill(problem_.f.begin(), problem_.f.begin() + zeroed, 0.0);
  for (const LagrangianConstraint::BlockInfo& info : infos_) {
    if (!info.has_id) continue;
    auto lines = std::find_if(prev_lines_.begin(), prev_lines_.end(),
                              [&](const PrevLines& l) { return l.parent == info.parent; });
    if (lines == prev_lines_.end()) continue;
    const int nbl = std::min(info.lines, lines->lines);
    for (int c = 0; c < info.groups; ++c) {
      const std::int64_t id = ids_[info.offset + c];
      auto it = std::lower_bound(prev_entries_.begin(), prev_entries_.end(), PrevEntry{info.parent, id, 0, 0},
                                 [](const PrevEntry& a, const PrevEntry& b) {
                                   return entry_less(a.parent, a.id, b.parent, b.id);
                                 });
      if (it == prev_entries_.end() || it->parent != info.parent || it->id != id) continue;
      const int prev = it->row;
      if (prev < 0 || prev + nbl > static_cast<int>(prev_forces_.size())) continue;
      for (int l = 0; l < nbl; ++l) {
        const int row = info.first_row + c * nbl + l;
        if (row >= 0 && row < n) problem_.f[row] = prev_forces_[prev + l];
      }
    }
  }
}

// Remembers this step's forces and, per constraint, the first row of each
// persistent id (a later group with the same id wins, as in SOFA's map).
void LCPConstraintSolver::keep_contact_forces() {
  prev_forces_.assign(problem_.f.begin(), problem_.f.end());
  prev_entries_.clear();
  prev_lines_.clear();
  for (const LagrangianConstraint::BlockInfo& info : infos_) {
    if (!info.parent || !info.has_id) continue;
    prev_lines_.push_back({info.parent, info.lines});
    for (int c = 0; c < info.groups; ++c)
      prev_entries_.push_back({info.parent, ids_[info.offset + c], info.first_row + c * info.lines,
                               static_cast<int>(prev_entries_.size())});
  }
  std::sort(prev_entries_.begin(), prev_entries_.end(), [](const PrevEntry& a, const PrevEntry& b) {
    if (a.parent != b.parent || a.id != b.id) return entry_less(a.parent, a.id, b.parent, b.id);
    return a.order < b.order;
  });
  // Keep the last of equal keys.
  std::size_t out = 0;
  for (std::size_t i = 0; i < prev_entries_.size(); ++i) {
    if (out > 0 && prev_entries_[out - 1].parent == prev_entries_[i].parent &&
        prev_entries_[out - 1].id == prev_entries_[i].id)
      prev_entries_[out - 1] = prev_entries_[i];
    else
      prev_entries_[out++] = prev_entries_[i];
  }
  prev_entries_.resize(out);
}

bool LCPConstraintSolver::find_owners(int row, ConstraintCorrection*& a, ConstraintCorrection*& b) const {
  a = b = nullptr;
  for (ConstraintCorrection* cc : scope_.corrections) {
    if (!active(*cc) || !cc->supports_unbuilt() || !cc->has_constraint_row(row)) continue;
    if (!a) a = cc;
    else if (!b) b = cc;
  }
  return a != nullptr;
}

// Unbuilt NLCP (mu > 0): contacts of 3 rows, each with the (up to two)
// corrections of its bodies; W holds only the 3×3 diagonal blocks.
void LCPConstraintSolver::solve_unbuilt_nlcp() {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  if (n % 3 != 0) return;
  const int contacts = n / 3;
  sequence_.resize(n);
  std::iota(sequence_.begin(), sequence_.end(), 0);
  // The corrections start from the initial guess (but see reset_for_unbuilt).
  for (ConstraintCorrection* cc : scope_.corrections)
    if (active(*cc) && cc->supports_unbuilt()) cc->reset_for_unbuilt(params_, P.f, sequence_);
  owner1_.assign(contacts, nullptr);
  owner2_.assign(contacts, nullptr);
  int missing = 0, first_missing = -1;
  for (int c = 0; c < contacts; ++c)
    if (!find_owners(3 * c, owner1_[c], owner2_[c])) {
      if (missing++ == 0) first_missing = c;
    }
  if (missing > 0 && !warned_owner_) {
    warned_owner_ = true;
    msg_error(std::to_string(missing) + " contact(s) (first: " + std::to_string(first_missing) +
              ") have no constraint correction on either body" +
              (missing == contacts ? std::string(": no contact force is computed") : std::string()));
  }
  if (missing == contacts) return;
  for (int c = 0; c < contacts; ++c) {
    if (owner1_[c]) owner1_[c]->add_block_diagonal_compliance(P, 3 * c, 3 * c + 3);
    if (owner2_[c]) owner2_[c]->add_block_diagonal_compliance(P, 3 * c, 3 * c + 3);
  }
  const double reg = regularization_term.value();
  if (reg > std::numeric_limits<double>::epsilon())
    for (int i = 0; i < n; ++i) P.w(i, i) += reg;
  w33_.resize(contacts);
  for (int c = 0; c < contacts; ++c) {
    const int j = 3 * c;
    double* w = w33_[c].w;
    w[0] = P.w(j, j);
    w[1] = P.w(j, j + 1);
    w[2] = P.w(j, j + 2);
    w[3] = P.w(j + 1, j + 1);
    w[4] = P.w(j + 1, j + 2);
    w[5] = P.w(j + 2, j + 2);
  }
  d_.assign(n, 0.0);
  df_.assign(n, 0.0);
  double* f = P.f.data();
  const double m = mu.value();
  const double tol = tolerance.value();
  int it = 0;
  double error = 0.0;
  for (it = 0; it < max_it.value(); ++it) {
    error = 0.0;
    for (std::size_t k = 0; k < sequence_.size(); k += 3) {
      const int c = sequence_[k] / 3;
      const int j = 3 * c;
      for (int l = 0; l < 3; ++l) d_[j + l] = P.dfree[j + l];
      double fn = f[j], ft = f[j + 1], fs = f[j + 2];
      const double fn0 = fn;
      if (owner1_[c]) owner1_[c]->add_constraint_displacement(d_, j, j + 3);
      if (owner2_[c]) owner2_[c]->add_constraint_displacement(d_, j, j + 3);
      double dn = d_[j], dt = d_[j + 1], ds = d_[j + 2];
      contact_new_gs_state(w33_[c], m, dn, dt, ds, fn, ft, fs);
      error += std::sqrt((d_[j] - dn) * (d_[j] - dn) + (d_[j + 1] - dt) * (d_[j + 1] - dt) +
                         (d_[j + 2] - ds) * (d_[j + 2] - ds));
      if (!(fn0 == 0.0 && fn == 0.0)) {
        df_[j] = fn - f[j];
        df_[j + 1] = ft - f[j + 1];
        df_[j + 2] = fs - f[j + 2];
        if (owner1_[c]) owner1_[c]->set_constraint_dforce(df_, j, j + 3);
        if (owner2_[c]) owner2_[c]->set_constraint_dforce(df_, j, j + 3);
      }
      f[j] = fn;
      f[j + 1] = ft;
      f[j + 2] = fs;
    }
    if (error < tol * (contacts + 1)) {
      result_ = {it + 1, error, true};
      return;
    }
  }
  result_ = {it, error, false};
}

// Unbuilt LCP (mu = 0): one row per contact.
void LCPConstraintSolver::solve_unbuilt_lcp() {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  sequence_.resize(n);
  std::iota(sequence_.begin(), sequence_.end(), 0);
  for (ConstraintCorrection* cc : scope_.corrections)
    if (active(*cc) && cc->supports_unbuilt()) cc->reset_for_unbuilt(params_, P.f, sequence_);
  owner1_.assign(n, nullptr);
  owner2_.assign(n, nullptr);
  int missing = 0, first_missing = -1;
  for (int c = 0; c < n; ++c)
    if (!find_owners(c, owner1_[c], owner2_[c])) {
      if (missing++ == 0) first_missing = c;
    }
  if (missing > 0 && !warned_owner_) {
    warned_owner_ = true;
    msg_error(std::to_string(missing) + " constraint(s) (first: row " + std::to_string(first_missing) +
              ") have no constraint correction on either body" +
              (missing == n ? std::string(": no contact force is computed") : std::string()));
  }
  if (missing == n) return;
  for (int c = 0; c < n; ++c) {
    if (owner1_[c]) owner1_[c]->add_block_diagonal_compliance(P, c, c + 1);
    if (owner2_[c]) owner2_[c]->add_block_diagonal_compliance(P, c, c + 1);
  }
  const double reg = regularization_term.value();
  if (reg > std::numeric_limits<double>::epsilon())
    for (int i = 0; i < n; ++i) P.w(i, i) += reg;
  d_.assign(n, 0.0);
  df_.assign(n, 0.0);
  double* f = P.f.data();
  const double tol = tolerance.value();
  int it = 0;
  double error = 0.0;
  for (it = 0; it < max_it.value(); ++it) {
    error = 0.0;
    for (int c : sequence_) {
      d_[c] = P.dfree[c];
      const double fn0 = f[c];
      if (owner1_[c]) owner1_[c]->add_constraint_displacement(d_, c, c + 1);
      if (owner2_[c]) owner2_[c]->add_constraint_displacement(d_, c, c + 1);
      const double w11 = P.w(c, c);
      double fn = fn0 - d_[c] / w11;
      if (fn < 0) fn = 0.0;
      error += std::fabs(w11 * (fn - fn0));
      if (fn0 != 0.0 || fn != 0.0) {
        df_[c] = fn - fn0;
        if (owner1_[c]) owner1_[c]->set_constraint_dforce(df_, c, c + 1);
        if (owner2_[c]) owner2_[c]->set_constraint_dforce(df_, c, c + 1);
      }
      f[c] = fn;
    }
    if (error < tol * (n + 1)) {
      result_ = {it + 1, error, true};
      return;
    }
  }
  result_ = {it, error, false};
}

void register_lcp_constraint_solver(Registry& r) {
  ComponentInfo info;
  info.name = "LCPConstraintSolver";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "contacts as a (nonlinear) complementarity problem by Gauss-Seidel, built or unbuilt, with a "
                     "warm start by persistent contact id";
  info.create = creator<LCPConstraintSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
