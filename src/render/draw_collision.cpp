#include "render/draw_collision.h"

#include <cmath>

#include <Eigen/Geometry>

#include "collision/model/line_collision_model.h"
#include "collision/model/obb_collision_model.h"
#include "collision/model/sphere_collision_model.h"
#include "render/draw_shapes.h"
#include "collision/model/tetrahedron_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/node.h"
#include "render/material.h"
#include "visual/visual_style.h"

namespace sinew::render {

std::array<float, 4> collision_color(bool color_set, const std::array<float, 4>& color, bool simulated, bool moving,
                                     bool active) {
  if (color_set) return color;
  if (simulated) {
    if (moving) return active ? std::array<float, 4>{1, 0.5f, 0, 1} : std::array<float, 4>{0.5f, 0.25f, 0, 1};
    return active ? std::array<float, 4>{1, 0, 0, 1} : std::array<float, 4>{0.5f, 0, 0, 1};
  }
  if (moving) return active ? std::array<float, 4>{0, 1, 0.5f, 1} : std::array<float, 4>{0, 0.5f, 0.25f, 1};
  return active ? std::array<float, 4>{0.5f, 0.5f, 0.5f, 1} : std::array<float, 4>{0.25f, 0.25f, 0.25f, 1};
}

namespace {

// Point i of the model's state (Vec3d, or a Rigid3d frame's centre); false when out of range.
bool point(const MechanicalState& s, unsigned i, float out[3]) {
  const int w = s.info().coord_width;
  if (s.info().spatial_dim != 3 || w < 3) return false;
  const std::vector<double>& x = s.read(kPosition);
  if (std::size_t(i) * w + 2 >= x.size()) return false;
  for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(x[std::size_t(i) * w + c]);
  return true;
}

void push(std::vector<float>& v, const float p[3]) { v.insert(v.end(), p, p + 3); }

Shading flat_color(const std::array<float, 4>& c, bool lit) {
  Shading s{};
  s.diffuse = c;
  if (lit) s.ambient = {0.2f * c[0], 0.2f * c[1], 0.2f * c[2], 1};
  s.shininess = 1.f;
  return s;
}

void triangles(DrawList& list, const TriangleCollisionModel& m, const std::array<float, 4>& color, bool wireframe) {
  Batch& b = fresh_batch(list, &m, Batch::Kind::triangles);
  const MechanicalState& s = *m.mstate();
  for (unsigned i = 0; i < m.size(); ++i) {
    const Triangle& t = m.triangle(i);
    float p[3][3];
    if (!point(s, t[0], p[0]) || !point(s, t[1], p[1]) || !point(s, t[2], p[2])) continue;
    const Vec3 a(p[0][0], p[0][1], p[0][2]), e1 = Vec3(p[1][0], p[1][1], p[1][2]) - a,
               e2 = Vec3(p[2][0], p[2][1], p[2][2]) - a;
    Vec3 n = e1.cross(e2);
    if (n.norm() > 0) n.normalize();
    const float nf[3] = {float(n[0]), float(n[1]), float(n[2])};
    for (auto& q : p) push(b.positions, q), push(b.normals, nf);
  }
  b.shading = flat_color(color, true);
  b.wireframe = wireframe;
  close_batch(list, b);
}

void lines_of(DrawList& list, const CollisionModelBase& m, const std::array<float, 4>& color) {
  Batch& b = fresh_batch(list, &m, Batch::Kind::lines);
  const MechanicalState& s = *m.mstate();
  float p[4][3];
  if (m.kind() == CollisionModelBase::Kind::line) {
    const auto& lm = static_cast<const LineCollisionModel&>(m);
    for (unsigned i = 0; i < lm.size(); ++i) {
      const Edge& e = lm.edge(i);
      if (point(s, e[0], p[0]) && point(s, e[1], p[1])) push(b.positions, p[0]), push(b.positions, p[1]);
    }
  } else {  // tetrahedra: their six edges
    const auto& tm = static_cast<const TetrahedronCollisionModel&>(m);
    static const int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (unsigned i = 0; i < tm.size(); ++i) {
      const Tetra& t = tm.tetrahedron(i);
      bool ok = true;
      for (int k = 0; k < 4; ++k) ok &= point(s, t[k], p[k]);
      if (!ok) continue;
      for (const auto& e : kEdges) push(b.positions, p[e[0]]), push(b.positions, p[e[1]]);
    }
  }
  b.shading = flat_color(color, false);
  close_batch(list, b);
}

void points_of(DrawList& list, const CollisionModelBase& m, const std::array<float, 4>& color) {
  Batch& b = fresh_batch(list, &m, Batch::Kind::points);
  const MechanicalState& s = *m.mstate();
  float p[3];
  for (unsigned i = 0; i < s.size(); ++i)
    if (point(s, i, p)) push(b.positions, p);
  b.shading = flat_color(color, false);
  b.point_size = 3.f;
  close_batch(list, b);
}

// Each sphere as a latitude–longitude mesh (SOFA's drawSpheres tessellates too).
void spheres(DrawList& list, const SphereCollisionModel& m, const std::array<float, 4>& color, bool wireframe) {
  Batch& b = fresh_batch(list, &m, Batch::Kind::triangles);
  for (unsigned i = 0; i < m.size(); ++i) {
    const SphereElem e = m.elem(i);
    if (!(e.r > 0) || !e.c.allFinite()) continue;
    append_sphere(b, e.c, e.r);
  }
  b.shading = flat_color(color, true);
  b.wireframe = wireframe;
  close_batch(list, b);
}

// Each oriented box by its six faces, two triangles each, lit by the face normals.
void boxes(DrawList& list, const ObbCollisionModel& m, const std::array<float, 4>& color, bool wireframe) {
  // Faces as corner numbers of obb_vertices (0–3 on +axis 0, 4–7 on −axis 0), with their normal: ±axis k.
  static const int kFaces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {1, 5, 6, 2}, {0, 3, 7, 4}, {2, 6, 7, 3}, {0, 4, 5, 1}};
  static const int kNormal[6][2] = {{0, 1}, {0, -1}, {1, 1}, {1, -1}, {2, 1}, {2, -1}};
  Batch& b = fresh_batch(list, &m, Batch::Kind::triangles);
  for (unsigned i = 0; i < m.size(); ++i) {
    const ObbElem& e = m.elem(i);
    const auto v = obb_vertices(e);
    bool finite = true;
    for (const Vec3& p : v) finite &= p.allFinite();
    if (!finite) continue;
    for (int f = 0; f < 6; ++f) {
      const Vec3 n = e.axis[kNormal[f][0]] * kNormal[f][1];
      const float nf[3] = {float(n[0]), float(n[1]), float(n[2])};
      for (int k : {0, 1, 2, 0, 2, 3}) {
        const Vec3& p = v[kFaces[f][k]];
        const float pf[3] = {float(p[0]), float(p[1]), float(p[2])};
        push(b.positions, pf), push(b.normals, nf);
      }
    }
  }
  b.shading = flat_color(color, true);
  b.wireframe = wireframe;
  close_batch(list, b);
}

// The cubes of every level of the bounding tree by their twelve edges, the root white and
// the deeper levels bluer.
void bounding_tree(DrawList& list, const CollisionModelBase& m) {
  const CubeTree& t = m.tree();
  if (!t.built()) return;
  Batch& b = fresh_batch(list, &m, Batch::Kind::lines);
  const auto& levels = t.levels();
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const float f = levels.size() > 1 ? float(l) / float(levels.size() - 1) : 0.f;
    const float rgba[4] = {1 - f, 1 - f, 1, 1};
    for (const CubeTree::Cube& c : levels[l]) {
      append_box_edges(b, c.box.min, c.box.max);
      for (int k = 0; k < 24; ++k) b.colors.insert(b.colors.end(), rgba, rgba + 4);
    }
  }
  close_batch(list, b);
}

}  // namespace

void add_collision_models(DrawList& list, Node& node, const DisplayFlags& flags) {
  const bool wire = flags.shown(DisplayFlags::wireframe);
  for (const auto& o : node.objects()) {
    const auto* m = dynamic_cast<const CollisionModelBase*>(o.get());
    if (!m || m->state() != ComponentState::valid || !m->mstate()) continue;
    if (flags.shown(DisplayFlags::collision_models)) {
      std::array<float, 4> c{1, 0, 0, 1};
      if (auto parsed = parse_color(m->color.get())) c = *parsed;
      const auto color = collision_color(m->color.is_set(), c, m->simulated.get(), m->moving.get(), m->active.get());
      switch (m->kind()) {
        case CollisionModelBase::Kind::triangle:
          triangles(list, static_cast<const TriangleCollisionModel&>(*m), color, wire);
          break;
        case CollisionModelBase::Kind::line:
        case CollisionModelBase::Kind::tetrahedron: lines_of(list, *m, color); break;
        case CollisionModelBase::Kind::point: points_of(list, *m, color); break;
        case CollisionModelBase::Kind::sphere:
          spheres(list, static_cast<const SphereCollisionModel&>(*m), color, wire);
          break;
        case CollisionModelBase::Kind::obb:
          boxes(list, static_cast<const ObbCollisionModel&>(*m), color, wire);
          break;
      }
    }
    if (flags.shown(DisplayFlags::bounding_collision_models)) bounding_tree(list, *m);
  }
}

}  // namespace sinew::render
