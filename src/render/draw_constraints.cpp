// Constraints in pictures, as SOFA's draw() of each.
//
// Projective constraints, under showBehaviorModels, in (1, 0.5, 0.5) unless said:
// - FixedProjectiveConstraint (when `showObject`), Point, Line, Plane and Direction: their
//   DoFs (every DoF with fixAll) as 10-pixel points when drawSize is 0, else as lit spheres of
//   radius drawSize in (1, 0.35, 0.35); FixedPlaneProjectiveConstraint its points in (1, 1, 0.5).
// - LinearMovementProjectiveConstraint (when it has key times) its DoFs as 10-pixel points, or
//   with showMovement the path between consecutive key movements of each DoF as 10-pixel lines
//   (from its first position with relativeMovements, once it has one);
//   LinearVelocityProjectiveConstraint the segments first position + key velocity k to first
//   position + key velocity k + 1 (SOFA adds the velocities to the positions as they are), 1 px.
// - AttachProjectiveConstraint: the attached points of object2 (10 px) and 1-pixel lines from
//   each source point to its attached point, active pairs only.
// - HermiteSplineProjectiveConstraint: the spline as a 2-pixel line strip sampled every dt over
//   EndTime − BeginTime, its ends as 5-pixel red points and its tangents (·0.1) as red lines.
//   SOFA's draw passes X0 for both ends (X1 unused: a slip); the curve drawn here is the one
//   the DoFs follow.
// - ParabolicProjectiveConstraint: the parabola as 1-pixel segments, one per time step between
//   BeginTime and EndTime, and P1, P2, P3 as 5-pixel points.
// AffineMovement and PatchTestMovement draw their DoFs (10 px) when drawConstrainedPoints, whatever
// the display flags, as SOFA's do.
//
// Lagrangian constraints, under showInteractionForceFields: BilateralLagrangianConstraint both
// points of each pair as 10-pixel points, magenta when active, green when not; the contacts
// of a collision response (UnilateralLagrangianConstraint) as 3-pixel lines from object2's
// point along the normal (white) and from object1's point against it (0, 0.5, 0.5), one unit
// long; SlidingLagrangianConstraint its sliding point (10 px: yellow when the last build tied it
// in three directions, the axis ends coinciding, else green) and its axis as a blue line.
#include "constraint/model/bilateral_lagrangian_constraint.h"
#include "constraint/model/sliding_lagrangian_constraint.h"
#include "constraint/model/unilateral_lagrangian_constraint.h"
#include "core/node.h"
#include "projective/attach_projective_constraint.h"
#include "projective/direction_projective_constraint.h"
#include "projective/fixed_plane_projective_constraint.h"
#include "projective/fixed_projective_constraint.h"
#include "projective/hermite_spline_projective_constraint.h"
#include "projective/indexed_projections.h"
#include "projective/linear_movement_projective_constraint.h"
#include "projective/linear_velocity_projective_constraint.h"
#include "projective/movement_to_final_positions.h"
#include "projective/parabolic_projective_constraint.h"
#include "render/draw_collision.h"
#include "render/draw_shapes.h"
#include "visual/visual_style.h"

namespace sinew::render {

namespace {

constexpr Rgba kFixed{1.f, 0.5f, 0.5f, 1.f};

// The positions of a constraint's state: point i (its first three coordinates, missing ones 0).
struct StatePoints {
  explicit StatePoints(const MechanicalState& s)
      : x(s.read(kPosition)), w(s.info().coord_width), dim(std::min(3, s.info().spatial_dim)) {}
  std::size_t size() const { return w > 0 ? x.size() / static_cast<std::size_t>(w) : 0; }
  Vec3 operator[](std::size_t i) const {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < dim; ++k) p[k] = x[i * static_cast<std::size_t>(w) + static_cast<std::size_t>(k)];
    return p;
  }
  const std::vector<double>& x;
  int w, dim;
};

// An unlit batch of `kind` in `color` for `source` (SOFA's draw tool with lighting disabled).
Batch& unlit_batch(DrawList& list, const Component* source, Batch::Kind kind, const Rgba& color) {
  Batch& b = fresh_batch(list, source, kind);
  b.shading = Shading{{0, 0, 0, 0}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  return b;
}

// SOFA's drawPoints(points, 10, color).
Batch& points_batch(DrawList& list, const Component* source, const Rgba& color) {
  Batch& b = unlit_batch(list, source, Batch::Kind::points, color);
  b.point_size = 10.f;
  return b;
}

// SOFA's drawLines(points, width, color).
Batch& lines_batch(DrawList& list, const Component* source, const Rgba& color, float width) {
  Batch& b = unlit_batch(list, source, Batch::Kind::lines, color);
  b.line_width = width;
  return b;
}

// Points `indices` of the state (those that exist in it) as 10-pixel points.
template <class Indices>
void add_state_points(DrawList& list, const Component* source, const StatePoints& x, const Indices& indices,
                      const Rgba& color) {
  Batch& b = points_batch(list, source, color);
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) < x.size()) push_point(b, x[static_cast<std::size_t>(i)]);
  close_batch(list, b);
}

// SOFA's drawPoints(points, 10, (1, 0.5, 0.5)) when drawSize is 0, else drawSpheres(points,
// drawSize, (1, 0.35, 0.35)) (lit); points `indices` of the state, or all of them.
void add_marks(DrawList& list, const Component* source, const StatePoints& x, const std::vector<unsigned>* indices,
               double size) {
  if (size == 0) {
    if (indices) return add_state_points(list, source, x, *indices, kFixed);
    Batch& b = points_batch(list, source, kFixed);
    for (std::size_t i = 0; i < x.size(); ++i) push_point(b, x[i]);
    close_batch(list, b);
    return;
  }
  Batch& b = fresh_batch(list, source, Batch::Kind::triangles);
  const Rgba color{1.f, 0.35f, 0.35f, 1.f};
  b.shading = Shading{{0.2f * color[0], 0.2f * color[1], 0.2f * color[2], 1.f}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  const std::size_t count = indices ? indices->size() : x.size();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = indices ? (*indices)[k] : k;
    if (i < x.size()) append_sphere(b, x[i], size);
  }
  close_batch(list, b);
}

void add_fixed(DrawList& list, const FixedProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.show_object.get() || !c.mstate) return;
  const std::vector<unsigned>& fixed = c.fixed();
  add_marks(list, &c, StatePoints(*c.mstate), c.fix_all.get() ? nullptr : &fixed, c.draw_size.get());
}

void add_attach(DrawList& list, const AttachProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.state1() || !c.state2()) return;
  const StatePoints x1(*c.state1()), x2(*c.state2());
  const auto& i1 = c.indices1.get();
  const auto& i2 = c.indices2.get();
  const std::vector<char>& active = c.active_pairs();
  const std::size_t n = std::min(i1.size(), i2.size());
  auto shown = [&](std::size_t i) {
    return (i >= active.size() || active[i]) && i1[i] < x1.size() && i2[i] < x2.size();
  };
  Batch& p = points_batch(list, &c, kFixed);
  for (std::size_t i = 0; i < n; ++i)
    if (shown(i)) push_point(p, x2[i2[i]]);
  close_batch(list, p);
  Batch& l = lines_batch(list, &c, kFixed, 1.f);
  for (std::size_t i = 0; i < n; ++i)
    if (shown(i)) push_point(l, x1[i1[i]]), push_point(l, x2[i2[i]]);
  close_batch(list, l);
}

void add_linear_velocity(DrawList& list, const LinearVelocityProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.mstate || c.key_times.get().empty()) return;
  const std::vector<double>& x0 = c.initial_positions();
  const std::vector<double>& kv = c.velocities.get();
  const int cw = c.coord_width(), dw = c.deriv_width();
  const int dim = std::min({3, c.mstate->info().spatial_dim, dw});
  const std::size_t keys = kv.size() / static_cast<std::size_t>(dw);
  if (x0.empty() || keys < 2) return;
  Batch& b = lines_batch(list, &c, kFixed, 1.f);
  for (std::size_t key = 0; key + 1 < keys; ++key)
    for (unsigned i : c.indices.get()) {
      if ((std::size_t(i) + 1) * cw > x0.size()) continue;
      for (std::size_t end : {key, key + 1}) {
        Vec3 p = Vec3::Zero();
        for (int k = 0; k < dim; ++k) p[k] = x0[std::size_t(i) * cw + k] + kv[end * dw + k];
        push_point(b, p);
      }
    }
  close_batch(list, b);
}

// The time step of `c`'s node (0 without one).
double dt_of(const Component& c) { return c.node() ? c.node()->dt.value() : 0.0; }

// Time steps over `duration` (SOFA's draws loop over them), bounded so that a tiny dt cannot
// make a picture of millions of segments.
std::size_t steps_over(double duration, double dt) {
  if (!(dt > 0) || !(duration > 0)) return 0;
  return static_cast<std::size_t>(std::min(std::ceil(duration / dt), 100000.0));
}

void add_hermite(DrawList& list, const HermiteSplineProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid) return;
  const double duration = c.t_end.get() - c.t_begin.get(), dt = dt_of(c);
  const std::size_t n = steps_over(duration, dt);
  Batch& curve = lines_batch(list, &c, kFixed, 2.f);
  // The strip through the samples at t = 0, dt, ... < duration, as segments.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    push_point(curve, c.curve_point(static_cast<double>(k) * dt / duration));
    push_point(curve, c.curve_point(static_cast<double>(k + 1) * dt / duration));
  }
  close_batch(list, curve);
  const Rgba red{1.f, 0.f, 0.f, 1.f};
  Batch& ends = points_batch(list, &c, red);
  ends.point_size = 5.f;
  push_point(ends, c.x0.get());
  push_point(ends, c.x1.get());
  close_batch(list, ends);
  Batch& tangents = lines_batch(list, &c, red, 1.f);
  push_point(tangents, c.x0.get());
  push_point(tangents, c.x0.get() + c.dx0.get() * 0.1);
  push_point(tangents, c.x1.get());
  push_point(tangents, c.x1.get() + c.dx1.get() * 0.1);
  close_batch(list, tangents);
}

void add_parabolic(DrawList& list, const ParabolicProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid) return;
  const double duration = c.t_end.get() - c.t_begin.get(), dt = dt_of(c);
  const std::size_t n = steps_over(duration, dt);  // segment i from i/steps to (i + 1)/steps
  const double steps = duration / dt;
  Batch& b = lines_batch(list, &c, kFixed, 1.f);
  for (std::size_t i = 0; i < n; ++i) {
    push_point(b, c.path_point(static_cast<double>(i) / steps));
    push_point(b, c.path_point(static_cast<double>(i + 1) / steps));
  }
  close_batch(list, b);
  Batch& p = points_batch(list, &c, kFixed);
  p.point_size = 5.f;
  for (const Field<Vec3>* f : {&c.p1, &c.p2, &c.p3}) push_point(p, f->get());
  close_batch(list, p);
}

void add_bilateral(DrawList& list, const BilateralLagrangianConstraint& c) {
  if (c.state() != ComponentState::valid || !c.object1.get() || !c.object2.get()) return;
  const StatePoints x1(*c.object1.get()), x2(*c.object2.get());
  const auto& m1 = c.first_point.get();
  const auto& m2 = c.second_point.get();
  const Rgba color = c.activate.get() ? Rgba{1.f, 0.f, 1.f, 1.f} : Rgba{0.f, 1.f, 0.f, 1.f};
  Batch& b = points_batch(list, &c, color);
  for (std::size_t i = 0; i < std::min(m1.size(), m2.size()); ++i) {
    if (m1[i] >= x1.size() || m2[i] >= x2.size()) continue;
    push_point(b, x1[m1[i]]);
    push_point(b, x2[m2[i]]);
  }
  close_batch(list, b);
}

void add_sliding(DrawList& list, const Component& c, const SlidingPicture& s) {
  Batch& p = points_batch(list, &c, s.tied ? Rgba{1.f, 1.f, 0.f, 1.f} : Rgba{0.f, 1.f, 0.f, 1.f});
  push_point(p, s.point);
  close_batch(list, p);
  Batch& axis = lines_batch(list, &c, {0.f, 0.f, 1.f, 1.f}, 1.f);
  push_point(axis, s.a), push_point(axis, s.b);
  close_batch(list, axis);
}

void add_contacts(DrawList& list, const UnilateralLagrangianConstraint& c) {
  const auto& contacts = c.contacts();
  if (contacts.empty()) return;
  Batch& out = lines_batch(list, &c, {1.f, 1.f, 1.f, 1.f}, 3.f);
  for (const auto& k : contacts) push_point(out, k.P), push_point(out, k.P + k.n);
  close_batch(list, out);
  Batch& in = lines_batch(list, &c, {0.f, 0.5f, 0.5f, 1.f}, 3.f);
  for (const auto& k : contacts) push_point(in, k.Q), push_point(in, k.Q - k.n);
  close_batch(list, in);
}

void add_linear_movement(DrawList& list, const LinearMovementProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.mstate || c.key_times.get().empty()) return;
  const StatePoints x(*c.mstate);
  if (!c.show_movement.get()) return add_state_points(list, &c, x, c.indices.get(), kFixed);
  const std::vector<double>& km = c.key_movements();
  const int dw = c.deriv_width(), cw = c.coord_width();
  const std::size_t keys = dw > 0 ? km.size() / static_cast<std::size_t>(dw) : 0;
  const bool relative = c.relative_movements.get();
  const std::vector<double>* x0 = c.initial_positions();
  if (keys < 2 || (relative && !x0)) return;
  Batch& b = lines_batch(list, &c, kFixed, 10.f);
  for (std::size_t key = 0; key + 1 < keys; ++key)
    for (unsigned i : c.indices.get()) {
      if (relative && (std::size_t(i) + 1) * cw > x0->size()) continue;
      for (std::size_t end : {key, key + 1}) {
        Vec3 p = Vec3::Zero();
        for (int k = 0; k < x.dim; ++k) {
          p[k] = km[end * dw + static_cast<std::size_t>(k)];
          if (relative) p[k] += (*x0)[std::size_t(i) * cw + static_cast<std::size_t>(k)];
        }
        push_point(b, p);
      }
    }
  close_batch(list, b);
}

}  // namespace

void add_constraints(DrawList& list, Node& node, const DisplayFlags& flags) {
  const bool behavior = flags.shown(DisplayFlags::behavior_models);
  const bool interaction = flags.shown(DisplayFlags::interaction_force_fields);
  for (const auto& o : node.objects()) {
    const Component* c = o.get();
    if (const auto* m = dynamic_cast<const MovementToFinalPositions*>(c)) {
      if (m->state() == ComponentState::valid && m->mstate && m->draw_constrained_points.get())
        add_state_points(list, m, StatePoints(*m->mstate), m->indices.get(), kFixed);
      continue;
    }
    if (interaction) {
      if (const auto* b = dynamic_cast<const BilateralLagrangianConstraint*>(c)) add_bilateral(list, *b);
      else if (const auto* u = dynamic_cast<const UnilateralLagrangianConstraint*>(c)) add_contacts(list, *u);
      else if (SlidingPicture s; sliding_picture(*c, s)) add_sliding(list, *c, s);
    }
    if (!behavior || !dynamic_cast<const ProjectiveConstraint*>(c)) continue;
    if (const auto* f = dynamic_cast<const FixedProjectiveConstraint*>(c)) {
      add_fixed(list, *f);
    } else if (const auto* p = dynamic_cast<const FixedPlaneProjectiveConstraint*>(c)) {
      // SOFA's draw: its points, whatever its state (an invalid one has none).
      if (p->state() == ComponentState::valid && p->mstate)
        add_state_points(list, p, StatePoints(*p->mstate), p->indices.get(), {1.f, 1.f, 0.5f, 1.f});
    } else if (const auto* point = dynamic_cast<const PointProjectiveConstraint*>(c)) {
      if (point->state() == ComponentState::valid && point->mstate)
        add_marks(list, point, StatePoints(*point->mstate), point->fix_all.get() ? nullptr : &point->indices.get(),
                  point->draw_size.get());
    } else if (const auto* ip = dynamic_cast<const IndexedProjection*>(c)) {  // line, plane
      if (ip->state() == ComponentState::valid && ip->mstate)
        add_marks(list, ip, StatePoints(*ip->mstate), &ip->indices.get(), ip->draw_size.get());
    } else if (const auto* d = dynamic_cast<const DirectionProjectiveConstraint*>(c)) {
      if (d->state() == ComponentState::valid && d->mstate)
        add_marks(list, d, StatePoints(*d->mstate), &d->indices.get(), d->draw_size.get());
    } else if (const auto* m = dynamic_cast<const LinearMovementProjectiveConstraint*>(c)) {
      add_linear_movement(list, *m);
    } else if (const auto* v = dynamic_cast<const LinearVelocityProjectiveConstraint*>(c)) {
      add_linear_velocity(list, *v);
    } else if (const auto* a = dynamic_cast<const AttachProjectiveConstraint*>(c)) {
      add_attach(list, *a);
    } else if (const auto* h = dynamic_cast<const HermiteSplineProjectiveConstraint*>(c)) {
      add_hermite(list, *h);
    } else if (const auto* q = dynamic_cast<const ParabolicProjectiveConstraint*>(c)) {
      add_parabolic(list, *q);
    }
  }
}

}  // namespace sinew::render
