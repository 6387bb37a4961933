// Helpers of the Lagrangian solver tests: solvers with their problem exposed
// (to solve hand-written problems), a correction holding a dense compliance
// (to drive the unbuilt solvers without a body), and contacts of points on
// planes with persistent ids (to drive the LCP solver's warm start).
#pragma once

#include <cstdint>
#include <vector>

#include "core/constraint_problem.h"
#include "core/roles.h"

namespace sinew::test {

// A solver of type S whose problem can be written and solved directly.
template <class S>
struct Exposed : S {
  ConstraintProblem& prob() { return this->problem_; }
  ConstraintScope& scope() { return this->scope_; }
  void build(const ConstraintParams& p) { this->build_system(p); }
  void solve() { this->solve_system(); }
  int iterations() const { return this->iterations_; }
  double error() const { return this->error_; }
  bool converged() const { return this->converged_; }
};

// problem.clear(n) with W (row-major) and dfree, and the given blocks.
inline void set_problem(ConstraintProblem& P, int n, const std::vector<double>& W, const std::vector<double>& dfree,
                        const std::vector<ConstraintBlock>& blocks) {
  P.clear(n);
  P.W = W;
  P.dfree = dfree;
  P.blocks = blocks;
}

inline ConstraintBlock block(ConstraintBlock::Kind kind, int first, int rows, double mu = 0.0) {
  ConstraintBlock b;
  b.kind = kind;
  b.first = first;
  b.rows = rows;
  b.mu = mu;
  return b;
}

// Owns every row; its compliance is the dense matrix W. Unbuilt: the force
// accumulated so far acts through W on every row (what a body whose
// compliance is W would do).
class DenseCorrection final : public ConstraintCorrection {
 public:
  int n = 0;
  std::vector<double> W;
  std::vector<double> acc;  // accumulated constraint force per row
  int displacement_calls = 0, dforce_calls = 0;

  void add_compliance(const ConstraintParams&, ConstraintProblem& P) override {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) P.w(i, j) += W[i * n + j];
  }
  void apply_correction(const ConstraintParams&, const std::vector<double>&, int, int, int) override {}
  bool has_constraint_row(int row) const override { return row >= 0 && row < n; }
  bool supports_unbuilt() const override { return true; }
  void reset_for_unbuilt(const ConstraintParams&, const std::vector<double>&, std::vector<int>&) override {
    acc.assign(n, 0.0);
  }
  void add_block_diagonal_compliance(ConstraintProblem& P, int begin, int end) override {
    for (int i = begin; i < end; ++i)
      for (int j = begin; j < end; ++j) P.w(i, j) += W[i * n + j];
  }
  void add_constraint_displacement(std::vector<double>& d, int begin, int end) override {
    ++displacement_calls;
    for (int i = begin; i < end; ++i)
      for (int k = 0; k < n; ++k) d[i] += W[i * n + k] * acc[k];
  }
  void set_constraint_dforce(const std::vector<double>& df, int begin, int end) override {
    ++dforce_calls;
    for (int i = begin; i < end; ++i) acc[i] += df[i];
  }
};

// Points of one Vec3d state kept above planes n·x ≥ h, each contact with a
// persistent id (1 row per contact, or 3 with friction: n, t, s), like
// UnilateralLagrangianConstraint on a single body. The contact list can be
// edited between steps.
class PlaneContacts final : public LagrangianConstraint {
 public:
  struct Contact {
    int dof = 0;
    Vec3 n{0, 0, 1}, t{1, 0, 0}, s{0, 1, 0};
    double h = 0;
    std::int64_t id = 0;
    int row = 0;
  };
  MechanicalState* state = nullptr;
  std::vector<Contact> contacts;
  bool friction = false;
  double mu = 0.5;
  bool yet_integrated = false;

  int rows_per_contact() const { return friction ? 3 : 1; }
  void build_constraint_matrix(const ConstraintParams&, int& row) override {
    ConstraintMatrix& J = state->constraint_jacobian();
    for (Contact& c : contacts) {
      c.row = row;
      const Vec3* dirs[3] = {&c.n, &c.t, &c.s};
      for (int k = 0; k < rows_per_contact(); ++k) J.add(row + k, c.dof, dirs[k]->data());
      row += rows_per_contact();
    }
  }
  void constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) override {
    const auto x = as_vec3(state->read(p.x));
    for (const Contact& c : contacts) {
      dfree[c.row] = c.n.dot(x[c.dof]) - c.h;
      if (friction) dfree[c.row + 1] = dfree[c.row + 2] = 0.0;
    }
  }
  void constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) override {
    for (const Contact& c : contacts) {
      ConstraintBlock b;
      b.first = c.row;
      b.rows = rows_per_contact();
      b.kind = friction ? ConstraintBlock::Kind::unilateral_friction : ConstraintBlock::Kind::unilateral;
      b.mu = mu;
      out.push_back(b);
    }
  }
  void constraint_info(std::vector<BlockInfo>& blocks, std::vector<std::int64_t>& ids) override {
    if (contacts.empty()) return;
    BlockInfo info;
    info.parent = this;
    info.first_row = contacts[0].row;
    info.lines = rows_per_contact();
    info.groups = static_cast<int>(contacts.size());
    info.has_id = true;
    info.offset = static_cast<int>(ids.size());
    for (const Contact& c : contacts) ids.push_back(yet_integrated ? c.id : -c.id);
    yet_integrated = true;
    blocks.push_back(info);
  }
};

}  // namespace sinew::test
