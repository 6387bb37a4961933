#include "core/mechanical_ops.h"

#include <atomic>
#include <cmath>

#include "core/assert.h"
#include "core/node.h"

namespace sinew {

MechanicalOps::MechanicalOps(Node& node) : node_(&node) { rebuild(); }

double MechanicalOps::context_dt() const { return node_->dt.value(); }

int MechanicalOps::alloc_vec() {
  static std::atomic<int> next{kFirstDynamicVec};
  return next++;
}

int MechanicalOps::alloc_coord_vec() {
  static std::atomic<int> next{kFirstDynamicCoordVec};
  return next++;
}

void MechanicalOps::sync() {
  if (built_version_ != node_->structure_version()) rebuild();
}

void MechanicalOps::rebuild() {
  built_version_ = node_->structure_version();
  states_.clear();
  independent_.clear();
  mapped_.clear();
  force_fields_.clear();
  masses_.clear();
  mappings_.clear();
  all_mappings_.clear();
  constraints_.clear();
  // Top-down over the subtree, skipping inactive and sleeping nodes.
  // A node below a mechanical mapping with mapForces=false is "pruned": its
  // mappings are still propagated, but force and dx visitors skip it (§3.5).
  // In a DAG a node is pruned only when all of its parents are (traverse()).
  std::vector<std::pair<Node*, bool>> order;
  traverse(*node_, [&](Node& n, bool pruned) {
    if (!n.activated.value() || n.sleeping.value()) return Visit::skip;
    if (Mapping* m = n.mechanical_mapping; m && !m->map_forces.value()) pruned = true;
    order.emplace_back(&n, pruned);
    return pruned ? Visit::prune : Visit::descend;
  });
  for (auto [n, pruned] : order) {
    // Every mapping is propagated (positions, velocities); only mechanical ones carry forces and dx.
    if (Mapping* m = n->mechanical_mapping) {
      if (m->state() == ComponentState::valid) {
        all_mappings_.push_back(m);
        if (m->is_mechanical() && !pruned) mappings_.push_back(m);
      }
    }
    if (pruned) continue;
    if (MechanicalState* s = n->mechanical_state) {
      states_.push_back(s);
      (s->independent() ? independent_ : mapped_).push_back(s);
    }
    if (n->mass && n->mass->state() == ComponentState::valid) masses_.push_back(n->mass);
    for (ForceField* ff : n->force_fields)
      if (ff->state() == ComponentState::valid) force_fields_.push_back(ff);
    for (ForceField* ff : n->interaction_force_fields)
      if (ff->state() == ComponentState::valid) force_fields_.push_back(ff);
    for (ProjectiveConstraint* c : n->projective_constraints)
      if (c->state() == ComponentState::valid) constraints_.push_back(c);
  }
}

// ------------------------------------------------------------------ vectors

void MechanicalOps::v_clear(int r) {
  for (MechanicalState* s : independent_) {
    auto& v = s->write(r);
    std::fill(v.begin(), v.end(), 0.0);
  }
}

void MechanicalOps::v_eq(int r, int a) {
  for (MechanicalState* s : independent_) s->write(r) = s->read(a);
}

void MechanicalOps::v_peq(int r, int a, double f) {
  for (MechanicalState* s : independent_) {
    auto& rv = s->write(r);
    const auto& av = s->read(a);
    SINEW_ASSERT(av.size() == rv.size(), "v_peq: vectors of one state have the same layout");
    for (std::size_t i = 0; i < rv.size(); ++i) rv[i] += av[i] * f;
  }
}

void MechanicalOps::v_teq(int r, double f) {
  for (MechanicalState* s : independent_)
    for (double& x : s->write(r)) x *= f;
}

void MechanicalOps::v_op(int r, int a, int b, double f) {
  for (MechanicalState* s : independent_) {
    auto& rv = s->write(r);
    const auto& av = s->read(a);
    const auto& bv = s->read(b);
    SINEW_ASSERT(av.size() == bv.size(), "v_op: vectors of one state have the same layout");
    rv.resize(av.size());
    for (std::size_t i = 0; i < rv.size(); ++i) rv[i] = av[i] + bv[i] * f;
  }
}

void MechanicalOps::v_scale_add(int p, double beta, int r) {
  for (MechanicalState* s : independent_) {
    auto& pv = s->write(p);
    const auto& rv = s->read(r);
    SINEW_ASSERT(rv.size() == pv.size(), "v_scale_add: vectors of one state have the same layout");
    for (std::size_t i = 0; i < pv.size(); ++i) pv[i] = pv[i] * beta + rv[i];
  }
}

double MechanicalOps::v_dot(int a, int b) const {
  double total = 0;
  for (MechanicalState* s : independent_) {
    const auto& av = s->read(a);
    const auto& bv = s->read(b);
    const int w = s->info().deriv_width;
    const std::size_t n = std::min(av.size(), bv.size()) / static_cast<std::size_t>(w);
    if (w == 3) {  // the same sums with the component loop unrolled (CG calls this twice per iteration)
      const double* pa = av.data();
      const double* pb = bv.data();
      for (std::size_t i = 0; i < n; ++i) {
        double d = 0;
        d += pa[3 * i] * pb[3 * i];
        d += pa[3 * i + 1] * pb[3 * i + 1];
        d += pa[3 * i + 2] * pb[3 * i + 2];
        total += d;
      }
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      double d = 0;  // per-DOF partial sum first, as SOFA's Vec dot product
      for (int c = 0; c < w; ++c) d += av[i * w + c] * bv[i * w + c];
      total += d;
    }
  }
  return total;
}

void MechanicalOps::v_integrate(int v, int a, double fa, int x_out, int x_in, double fx) {
  for (MechanicalState* s : independent_) {
    auto& vv = s->write(v);
    const auto& av = s->read(a);
    const StateType t = s->state_type();
    if (t == StateType::rigid3 || t == StateType::rigid2) {
      for (std::size_t i = 0; i < vv.size(); ++i) vv[i] += av[i] * fa;
      s->add_deriv_to_coord(x_out, x_in, v, fx);
    } else {
      // Fused loop: v_i += a_i·fa; x_i += v_i·fx (the updated v), one DOF at a time.
      auto& xo = s->write(x_out);
      const auto& xi = s->read(x_in);
      SINEW_ASSERT(av.size() == vv.size() && xo.size() == vv.size() && xi.size() == vv.size(),
                   "v_integrate: point states have equal coordinate and derivative widths");
      for (std::size_t i = 0; i < vv.size(); ++i) {
        vv[i] += av[i] * fa;
        xo[i] = xi[i] + vv[i] * fx;
      }
    }
  }
}

std::size_t MechanicalOps::independent_dofs() const {
  std::size_t n = 0;
  for (MechanicalState* s : independent_) n += s->size() * s->info().deriv_width;
  return n;
}

bool MechanicalOps::all_finite(int id) const {
  for (MechanicalState* s : independent_)
    for (double x : s->read(id))
      if (!std::isfinite(x)) return false;
  return true;
}

// ------------------------------------------------------------------ mechanics

namespace {
// Ids as seen by a single-state component (dynamic ids only exist on independent states).
MechParams resolved(const MechParams& p, const MechanicalState* state) {
  if (!state) return p;  // multi-state components resolve per state
  const MechanicalState& s = *state;
  MechParams q = p;
  q.x = vec_for(s, p.x, kPosition);
  q.v = vec_for(s, p.v, kVelocity);
  q.f = vec_for(s, p.f, kForce);
  q.dx = vec_for(s, p.dx, kDx);
  q.df = vec_for(s, p.df, kDforce);
  return q;
}
}  // namespace

void MechanicalOps::compute_force(int f, bool clear, bool accumulate, int x, int v) {
  MechParams p;
  p.f = f;
  p.x = x;
  p.v = v;
  for (MechanicalState* s : states_) {
    auto& fv = s->write(vec_for(*s, f, kForce));
    if (clear) std::fill(fv.begin(), fv.end(), 0.0);
    const auto& ext = s->read(kExternalForce);
    for (std::size_t i = 0; i < std::min(ext.size(), fv.size()); ++i) fv[i] += ext[i];
  }
  for (ForceField* ff : force_fields_) ff->add_force(resolved(p, ff->single_state()));
  if (accumulate)
    for (auto it = mappings_.rbegin(); it != mappings_.rend(); ++it)
      if ((*it)->map_forces.value()) (*it)->apply_jt(f, kForce);
}

void MechanicalOps::add_mbk_dx(int df, double m, double b, double k, int dx, bool clear, bool accumulate) {
  MechParams p;
  p.dx = dx;
  p.df = df;
  p.m = m;
  p.b = b;
  p.k = k;
  if (clear)
    for (MechanicalState* s : mapped_) {
      auto& v = s->write(vec_for(*s, df, kDforce));
      std::fill(v.begin(), v.end(), 0.0);
    }
  for (ForceField* ff : force_fields_) {
    const MechParams q = resolved(p, ff->single_state());
    const double kf = ff->k_factor(q);
    if (kf != 0.0 || q.b != 0.0) ff->add_dforce(q, kf);
    if (auto* mass = dynamic_cast<Mass*>(ff)) {
      const double mf = q.m - q.b * mass->rayleigh_mass.value();
      if (mf != 0.0) mass->add_mdx(q, q.df, q.dx, mf);
    }
  }
  if (accumulate)
    for (auto it = mappings_.rbegin(); it != mappings_.rend(); ++it) {
      Mapping* mp = *it;
      if (!mp->map_forces.value()) continue;
      mp->apply_jt(df, kDforce);
      if (k != 0.0) mp->apply_djt(df, dx, k);
    }
}

void MechanicalOps::add_mbk_v(int df, double m, double b, double k, bool clear, bool accumulate) {
  add_mbk_dx(df, m, b, k, kVelocity, clear, accumulate);
}

void MechanicalOps::add_mdx(int res, int dx, double factor) {
  MechParams p;
  for (Mass* m : masses_) m->add_mdx(p, res, dx, factor);
}

void MechanicalOps::acc_from_f(int a, int f) {
  MechParams p;
  for (Mass* m : masses_) m->acc_from_f(p, a, f);
}

void MechanicalOps::add_separate_gravity(double dt, int v) {
  for (Mass* m : masses_)
    if (m->separate_gravity.value()) m->add_gravity_to_v(v, dt);
}

void MechanicalOps::propagate_dx_and_reset_df(int dx, int df) {
  for (MechanicalState* s : states_) {
    auto& v = s->write(vec_for(*s, df, kDforce));
    std::fill(v.begin(), v.end(), 0.0);
  }
  propagate_dx(dx);
}

void MechanicalOps::propagate_dx(int dx) {
  for (Mapping* m : mappings_)
    if (m->map_forces.value()) m->apply_j(dx, kDx);
}

void MechanicalOps::propagate_x_and_v(int x, int v) {
  for (Mapping* m : all_mappings_) {
    m->apply(x);
    m->apply_j(v, kVelocity);
  }
}

void MechanicalOps::project_response(int dx) {
  for (ProjectiveConstraint* c : constraints_) c->project_response(vec_for(*c->mstate, dx, kDx));
}

void MechanicalOps::project_position(int x, double t) {
  for (ProjectiveConstraint* c : constraints_) c->project_position(vec_for(*c->mstate, x, kPosition), t);
}

void MechanicalOps::project_velocity(int v, double t) {
  for (ProjectiveConstraint* c : constraints_) c->project_velocity(vec_for(*c->mstate, v, kVelocity), t);
}

}  // namespace sinew
