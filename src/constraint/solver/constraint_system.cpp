#include "constraint/solver/constraint_system.h"

#include <limits>
#include <string>

#include "core/node.h"

namespace sinew {

namespace {

bool usable(const Component& c) { return c.state() == ComponentState::valid; }

void gather(Node& root, ConstraintScope& s) {
  traverse(root, [&](Node& n, bool) {
    if (!n.activated.value() || n.sleeping.value()) return Visit::skip;
    for (LagrangianConstraint* c : n.lagrangian_constraints) s.constraints.push_back(c);
    for (ConstraintCorrection* c : n.constraint_corrections) s.corrections.push_back(c);
    return Visit::descend;
  });
}

}  // namespace

void sync_constraint_scope(Node& node, ConstraintScope& s) {
  if (!s.ops) s.ops = std::make_unique<MechanicalOps>(node);
  s.ops->sync();
  if (s.version == node.structure_version()) return;
  s.version = node.structure_version();
  s.constraints.clear();
  s.corrections.clear();
  gather(node, s);
}

int build_constraint_jacobian(ConstraintScope& s, const ConstraintParams& p, bool project) {
  for (MechanicalState* st : s.ops->all_states()) st->constraint_jacobian().clear(st->info().deriv_width);
  int row = 0;
  for (LagrangianConstraint* c : s.constraints)
    if (usable(*c)) c->build_constraint_matrix(p, row);
  // Bottom-up: a mapping's output rows are complete once the mappings below it ran.
  const auto& maps = s.ops->mappings();
  for (auto it = maps.rbegin(); it != maps.rend(); ++it) {
    Mapping* m = *it;
    if (!m->map_constraints.value() || !usable(*m)) continue;
    if (!m->apply_jt_constraints()) {
      m->msg_error("cannot carry Lagrangian constraint rows to its input (no Jacobian): the constraints on " +
                   m->output()->describe() + " are ignored");
      m->set_state(ComponentState::invalid);
    }
  }
  for (MechanicalState* st : s.ops->all_states()) st->constraint_jacobian().compress();
  if (project)
    for (ProjectiveConstraint* pc : s.ops->projective_constraints())
      if (usable(*pc) && pc->mstate) pc->project_jacobian(pc->mstate->constraint_jacobian());
  return row;
}

bool fill_constraint_problem(ConstraintScope& s, const ConstraintParams& p, int n, ConstraintProblem& problem,
                             Component& owner) {
  problem.clear(n);
  for (LagrangianConstraint* c : s.constraints)
    if (usable(*c)) c->constraint_violation(p, problem.dfree);
  for (LagrangianConstraint* c : s.constraints)
    if (usable(*c)) c->constraint_resolutions(p, problem.blocks);
  int next = 0;
  for (const ConstraintBlock& b : problem.blocks) {
    if (b.first != next || b.rows < 1) break;
    next += b.rows;
  }
  if (next != n) {
    owner.msg_error("the constraint blocks cover " + std::to_string(next) + " of " + std::to_string(n) +
                    " rows: constraints disagree on their numbering; no constraint is solved this step");
    problem.clear(0);
    return false;
  }
  return true;
}

void add_compliances(ConstraintScope& s, const ConstraintParams& p, ConstraintProblem& problem, double regularization) {
  for (ConstraintCorrection* cc : s.corrections)
    if (usable(*cc) && !cc->node()->sleeping.value()) cc->add_compliance(p, problem);
  if (problem.n > 0 && regularization > std::numeric_limits<double>::epsilon())
    for (int i = 0; i < problem.n; ++i) problem.w(i, i) += regularization;
}

void apply_corrections(ConstraintScope& s, const ConstraintParams& p, const std::vector<double>& lambda, int x_out,
                       int v_out, int dx) {
  for (ConstraintCorrection* cc : s.corrections)
    if (usable(*cc) && !cc->node()->sleeping.value()) cc->apply_correction(p, lambda, x_out, v_out, dx);
}

}  // namespace sinew
