// Projective constraints in pictures, as SOFA's draw() of each, under showBehaviorModels:
// FixedProjectiveConstraint shows its fixed DoFs (every DoF with fixAll) when `showObject`,
// as 10-pixel points in (1, 0.5, 0.5) when drawSize is 0, else as lit spheres of radius
// drawSize in (1, 0.35, 0.35); FixedPlaneProjectiveConstraint its points (`indices`) as
// 10-pixel points in (1, 1, 0.5); LinearMovementProjectiveConstraint (when it has key times)
// its DoFs as 10-pixel points in (1, 0.5, 0.5), or with showMovement the path between
// consecutive key movements of each DoF as 10-pixel lines (from its first position with
// relativeMovements, once it has one).
#include "core/node.h"
#include "projective/fixed_plane_projective_constraint.h"
#include "projective/fixed_projective_constraint.h"
#include "projective/linear_movement_projective_constraint.h"
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

// SOFA's drawPoints(points, 10, color) without lighting: a batch for `source`.
Batch& points_batch(DrawList& list, const Component* source, const Rgba& color) {
  Batch& b = fresh_batch(list, source, Batch::Kind::points);
  b.shading = Shading{{0, 0, 0, 0}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  b.point_size = 10.f;
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

void add_fixed(DrawList& list, const FixedProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.show_object.get() || !c.mstate) return;
  const StatePoints x(*c.mstate);
  const bool all = c.fix_all.get();
  const double size = c.draw_size.get();
  if (size == 0) {
    if (!all) return add_state_points(list, &c, x, c.fixed(), kFixed);
    Batch& b = points_batch(list, &c, kFixed);
    for (std::size_t i = 0; i < x.size(); ++i) push_point(b, x[i]);
    close_batch(list, b);
    return;
  }
  Batch& b = fresh_batch(list, &c, Batch::Kind::triangles);
  const Rgba color{1.f, 0.35f, 0.35f, 1.f};
  b.shading = Shading{{0.2f * color[0], 0.2f * color[1], 0.2f * color[2], 1.f}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  const std::size_t count = all ? x.size() : c.fixed().size();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = all ? k : c.fixed()[k];
    if (i < x.size()) append_sphere(b, x[i], size);
  }
  close_batch(list, b);
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
  Batch& b = fresh_batch(list, &c, Batch::Kind::lines);
  b.shading = Shading{{0, 0, 0, 0}, kFixed, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  b.line_width = 10.f;
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
  if (!flags.shown(DisplayFlags::behavior_models)) return;
  for (const auto& o : node.objects()) {
    if (const auto* c = dynamic_cast<const FixedProjectiveConstraint*>(o.get())) {
      add_fixed(list, *c);
    } else if (const auto* p = dynamic_cast<const FixedPlaneProjectiveConstraint*>(o.get())) {
      // SOFA's draw: its points, whatever its state (an invalid one has none).
      if (p->state() == ComponentState::valid && p->mstate)
        add_state_points(list, p, StatePoints(*p->mstate), p->indices.get(), {1.f, 1.f, 0.5f, 1.f});
    } else if (const auto* m = dynamic_cast<const LinearMovementProjectiveConstraint*>(o.get())) {
      add_linear_movement(list, *m);
    }
  }
}

}  // namespace sinew::render
