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
#include "projective/linear_movement_projective_constraint.h"
#include "projective/fixed_projective_constraint.h"
#include "render/draw_collision.h"
#include "render/draw_shapes.h"
#include "visual/visual_style.h"

namespace sinew::render {

namespace {

void add_fixed(DrawList& list, const FixedProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.show_object.get() || !c.mstate) return;
  const MechanicalState& s = *c.mstate;
  const int w = s.info().coord_width, dim = std::min(3, s.info().spatial_dim);
  const std::vector<double>& x = s.read(kPosition);
  const std::size_t n = w > 0 ? x.size() / static_cast<std::size_t>(w) : 0;
  auto point = [&](std::size_t i) {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < dim; ++k) p[k] = x[i * static_cast<std::size_t>(w) + static_cast<std::size_t>(k)];
    return p;
  };
  const bool all = c.fix_all.get();
  const std::size_t count = all ? n : c.fixed().size();
  if (count == 0) return;
  const double size = c.draw_size.get();
  if (size == 0) {
    Batch& b = fresh_batch(list, &c, Batch::Kind::points);
    b.shading = Shading{{0, 0, 0, 0}, {1.f, 0.5f, 0.5f, 1.f}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    b.shading_parsed = false;
    b.lit = false;
    b.point_size = 10.f;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = all ? k : c.fixed()[k];
      if (i >= n) continue;
      const Vec3 p = point(i);
      for (int d = 0; d < 3; ++d) b.positions.push_back(static_cast<float>(p[d]));
    }
    close_batch(list, b);
    return;
  }
  Batch& b = fresh_batch(list, &c, Batch::Kind::triangles);
  const Rgba color{1.f, 0.35f, 0.35f, 1.f};
  b.shading = Shading{{0.2f * color[0], 0.2f * color[1], 0.2f * color[2], 1.f}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = all ? k : c.fixed()[k];
    if (i < n) append_sphere(b, point(i), size);
  }
  close_batch(list, b);
}

void add_fixed_plane(DrawList& list, const FixedPlaneProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.mstate || c.indices.get().empty()) return;
  const MechanicalState& s = *c.mstate;
  const int w = s.info().coord_width, dim = std::min(3, s.info().spatial_dim);
  const std::vector<double>& x = s.read(kPosition);
  const std::size_t n = w > 0 ? x.size() / static_cast<std::size_t>(w) : 0;
  Batch& b = fresh_batch(list, &c, Batch::Kind::points);
  b.shading = Shading{{0, 0, 0, 0}, {1.f, 1.f, 0.5f, 1.f}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  b.point_size = 10.f;
  for (unsigned i : c.indices.get()) {
    if (i >= n) continue;
    for (int k = 0; k < 3; ++k)
      b.positions.push_back(k < dim ? static_cast<float>(x[std::size_t(i) * w + static_cast<std::size_t>(k)]) : 0.f);
  }
  close_batch(list, b);
}

void add_linear_movement(DrawList& list, const LinearMovementProjectiveConstraint& c) {
  if (c.state() != ComponentState::valid || !c.mstate || c.key_times.get().empty()) return;
  const MechanicalState& s = *c.mstate;
  const int dim = std::min(3, s.info().spatial_dim);
  const Rgba color{1.f, 0.5f, 0.5f, 1.f};
  if (!c.show_movement.get()) {
    const int w = s.info().coord_width;
    const std::vector<double>& x = s.read(kPosition);
    const std::size_t n = w > 0 ? x.size() / static_cast<std::size_t>(w) : 0;
    Batch& b = fresh_batch(list, &c, Batch::Kind::points);
    b.shading = Shading{{0, 0, 0, 0}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    b.shading_parsed = false;
    b.lit = false;
    b.point_size = 10.f;
    for (unsigned i : c.indices.get()) {
      if (i >= n) continue;
      for (int k = 0; k < 3; ++k)
        b.positions.push_back(k < dim ? static_cast<float>(x[std::size_t(i) * w + static_cast<std::size_t>(k)]) : 0.f);
    }
    close_batch(list, b);
    return;
  }
  const std::vector<double>& km = c.key_movements();
  const int dw = c.deriv_width(), cw = c.coord_width();
  const std::size_t keys = dw > 0 ? km.size() / static_cast<std::size_t>(dw) : 0;
  const bool relative = c.relative_movements.get();
  const std::vector<double>* x0 = c.initial_positions();
  if (keys < 2 || (relative && !x0)) return;
  Batch& b = fresh_batch(list, &c, Batch::Kind::lines);
  b.shading = Shading{{0, 0, 0, 0}, color, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  b.line_width = 10.f;
  for (std::size_t key = 0; key + 1 < keys; ++key)
    for (unsigned i : c.indices.get()) {
      if (relative && (std::size_t(i) + 1) * cw > x0->size()) continue;
      for (std::size_t end : {key, key + 1})
        for (int k = 0; k < 3; ++k) {
          double v = 0;
          if (k < dim) {
            v = km[end * dw + static_cast<std::size_t>(k)];
            if (relative) v += (*x0)[std::size_t(i) * cw + static_cast<std::size_t>(k)];
          }
          b.positions.push_back(static_cast<float>(v));
        }
    }
  close_batch(list, b);
}

}  // namespace

void add_constraints(DrawList& list, Node& node, const DisplayFlags& flags) {
  if (!flags.shown(DisplayFlags::behavior_models)) return;
  for (const auto& o : node.objects())
    if (const auto* c = dynamic_cast<const FixedProjectiveConstraint*>(o.get())) add_fixed(list, *c);
    else if (const auto* p = dynamic_cast<const FixedPlaneProjectiveConstraint*>(o.get())) add_fixed_plane(list, *p);
    else if (const auto* m = dynamic_cast<const LinearMovementProjectiveConstraint*>(o.get()))
      add_linear_movement(list, *m);
}

}  // namespace sinew::render
