#include "viewer/picking.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "collision/model/sphere_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/node.h"
#include "render/draw_list.h"

namespace sinew::viewer {

double ray_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = ray.dir.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14 * e1.norm() * e2.norm()) return -1;  // parallel or degenerate
  const double inv = 1.0 / det;
  const Vec3 s = ray.origin - a;
  const double u = s.dot(p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3 q = s.cross(e1);
  const double v = ray.dir.dot(q) * inv;
  if (v < 0 || u + v > 1) return -1;
  return e2.dot(q) * inv;
}

double ray_sphere(const Ray& ray, const Vec3& centre, double radius) {
  const Vec3 oc = ray.origin - centre;
  const double b = oc.dot(ray.dir), c = oc.squaredNorm() - radius * radius;
  const double disc = b * b - c;
  if (disc < 0) return -1;
  const double s = std::sqrt(disc);
  const double t0 = -b - s, t1 = -b + s;
  return t0 >= 0 ? t0 : t1;  // from inside: the exit point
}

namespace {

bool simulated_model(const CollisionModelBase& m) {
  return m.is_active() && m.simulated.get() && m.mstate() && m.state() == ComponentState::valid;
}

// Closest hit among the triangle and sphere collision models.
void pick_collision(Node& root, const Ray& ray, Pick& best) {
  std::vector<CollisionModelBase*> models;
  root.collect_down(models);
  for (CollisionModelBase* m : models) {
    if (!simulated_model(*m)) continue;
    if (m->kind() == CollisionModelBase::Kind::triangle) {
      auto* t = static_cast<TriangleCollisionModel*>(m);
      if (t->mstate()->state_type() != StateType::vec3) continue;
      const std::vector<double>& x = t->mstate()->read(kPosition);
      const std::size_t n = x.size() / 3;
      for (unsigned i = 0; i < t->size(); ++i) {
        const Triangle& tri = t->triangle(i);
        if (tri[0] >= n || tri[1] >= n || tri[2] >= n) continue;
        const double d = ray_triangle(ray, Vec3(&x[3 * tri[0]]), Vec3(&x[3 * tri[1]]), Vec3(&x[3 * tri[2]]));
        if (d >= 0 && (!best || d < best.distance)) {
          best.on = Pick::On::collision_element;
          best.model = m, best.element = i, best.distance = d;
          best.point = ray.origin + d * ray.dir;
        }
      }
    } else if (m->kind() == CollisionModelBase::Kind::sphere) {
      auto* s = static_cast<SphereCollisionModel*>(m);
      for (unsigned i = 0; i < s->size(); ++i) {
        const SphereElem e = s->elem(i);
        const double d = ray_sphere(ray, e.c, e.r);
        if (d >= 0 && (!best || d < best.distance)) {
          best.on = Pick::On::collision_element;
          best.model = m, best.element = i, best.distance = d;
          best.point = ray.origin + d * ray.dir;
        }
      }
    }
  }
}

// Vec3d states the mouse may pull: every state of that type that a solver moves, mapped or not.
void pullable_states(Node& root, std::vector<MechanicalState*>& out) {
  for_each_node(root, [&](Node& n) {
    MechanicalState* s = n.mechanical_state;
    if (s && s->state_type() == StateType::vec3 && s->size() > 0) out.push_back(s);
  });
}

}  // namespace

Pick pick(Node& root, const render::DrawList& visible, const Ray& ray, double tolerance) {
  Pick best;
  pick_collision(root, ray, best);
  if (best) return best;

  std::vector<MechanicalState*> states;
  pullable_states(root, states);
  if (states.empty()) return best;

  // The visible surface: the triangles of the drawn visual models.
  double hit = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < visible.used; ++k) {
    const render::Batch& b = visible.batches[k];
    if (b.kind != render::Batch::Kind::triangles) continue;
    const auto vertex = [&](unsigned i) { return Vec3(b.positions[3 * i], b.positions[3 * i + 1], b.positions[3 * i + 2]); };
    const std::size_t corners = b.indices.empty() ? b.vertex_count() : b.indices.size();
    for (std::size_t c = 0; c + 2 < corners; c += 3) {
      const unsigned i0 = b.indices.empty() ? unsigned(c) : b.indices[c];
      const unsigned i1 = b.indices.empty() ? unsigned(c + 1) : b.indices[c + 1];
      const unsigned i2 = b.indices.empty() ? unsigned(c + 2) : b.indices[c + 2];
      const double d = ray_triangle(ray, vertex(i0), vertex(i1), vertex(i2));
      if (d >= 0 && d < hit) hit = d;
    }
  }
  if (std::isfinite(hit)) {
    // The particle nearest to the point seen.
    const Vec3 p = ray.origin + hit * ray.dir;
    double nearest = std::numeric_limits<double>::infinity();
    for (MechanicalState* s : states) {
      const std::vector<double>& x = s->read(kPosition);
      for (unsigned i = 0; 3 * i + 2 < x.size(); ++i) {
        const double d = (Vec3(&x[3 * i]) - p).squaredNorm();
        if (d < nearest) {
          nearest = d;
          best.on = Pick::On::particle;
          best.state = s, best.index = i;
        }
      }
    }
    best.point = p, best.distance = hit;
    return best;
  }

  // Last resort: of the particles within `tolerance` of the ray, in front of the camera,
  // the one nearest to the camera (SOFA's particle picking sorts them along the ray).
  for (MechanicalState* s : states) {
    const std::vector<double>& x = s->read(kPosition);
    for (unsigned i = 0; 3 * i + 2 < x.size(); ++i) {
      const Vec3 q(&x[3 * i]);
      const double along = (q - ray.origin).dot(ray.dir);
      if (along <= 0 || (best && along >= best.distance)) continue;
      if ((q - ray.origin - along * ray.dir).norm() > tolerance) continue;
      best.on = Pick::On::particle;
      best.state = s, best.index = i;
      best.point = q, best.distance = along;
    }
  }
  return best;
}

}  // namespace sinew::viewer
