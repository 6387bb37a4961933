// Projective constraints in pictures, as SOFA's draw() of each, under showBehaviorModels:
// FixedProjectiveConstraint shows its fixed DoFs (every DoF with fixAll) when `showObject`,
// as 10-pixel points in (1, 0.5, 0.5) when drawSize is 0, else as lit spheres of radius
// drawSize in (1, 0.35, 0.35); FixedPlaneProjectiveConstraint its points (`indices`) as
// 10-pixel points in (1, 1, 0.5).
#include "core/node.h"
#include "projective/fixed_plane_projective_constraint.h"
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

}  // namespace

void add_constraints(DrawList& list, Node& node, const DisplayFlags& flags) {
  if (!flags.shown(DisplayFlags::behavior_models)) return;
  for (const auto& o : node.objects())
    if (const auto* c = dynamic_cast<const FixedProjectiveConstraint*>(o.get())) add_fixed(list, *c);
    else if (const auto* p = dynamic_cast<const FixedPlaneProjectiveConstraint*>(o.get())) add_fixed_plane(list, *p);
}

}  // namespace sinew::render
