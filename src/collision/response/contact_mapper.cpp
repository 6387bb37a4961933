#include "collision/response/contact_mapper.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "collision/model/line_collision_model.h"
#include "collision/model/sphere_collision_model.h"
#include "collision/model/tetrahedron_collision_model.h"
#include "collision/model/triangle_collision_model.h"
#include "core/node.h"
#include "mapping/nonlinear/rigid_mapping.h"
#include "math/quat.h"
#include "state/mechanical_object.h"

namespace sinew {

// The graph owns the child node: destroying the mapper (at graph teardown) leaves it alone.
ContactMapper::~ContactMapper() = default;

bool ContactMapper::identity() const {
  switch (model_->kind()) {
    case CollisionModelBase::Kind::point:
      return true;
    case CollisionModelBase::Kind::sphere:
      return !static_cast<const SphereCollisionModel*>(model_)->rigid();
    default:
      return false;
  }
}

MechanicalState* ContactMapper::state() {
  if (identity()) return model_->mstate();
  if (!child_) {
    Node& parent = *model_->node();
    auto node = std::make_unique<Node>(name_);
    node->name.set(name_);
    child_ = parent.add_child(std::move(node));
    auto mo = std::make_unique<MechanicalObject>(StateType::vec3);
    mo->name.set("contactPoints");
    mo->use_topology.set(false);
    mo->set_type("MechanicalObject", "Vec3d");
    mapped_ = static_cast<MechanicalState*>(child_->add_object(std::move(mo)));
    mapped_->init();
    mapped_->resize(0);
    mapped_->mark_initialised();
    if (model_->mstate()->state_type() == StateType::rigid3) {
      auto map = std::make_unique<RigidMapping>(StateType::rigid3, StateType::vec3);
      map->name.set("contactMapping");
      map->set_type("RigidMapping", "Rigid3d,Vec3d");
      rigid_mapping_ = static_cast<RigidMapping*>(child_->add_object(std::move(map)));
      rigid_mapping_->bind_contact_states(*model_->mstate(), *mapped_);
      map_ = rigid_mapping_;
    } else {
      auto map = std::make_unique<ContactMapping>(*model_->mstate(), *mapped_);
      map->name.set("contactMapping");
      map->set_type("BarycentricMapping", "Vec3d,Vec3d");
      mapping_ = static_cast<ContactMapping*>(child_->add_object(std::move(map)));
      map_ = mapping_;
    }
    map_->mark_initialised();
    child_->initialised = true;
  }
  return mapped_;
}

void ContactMapper::resize(std::size_t n) {
  if (identity()) return;
  state();
  if (mapping_) mapping_->clear();
  if (rigid_mapping_) rigid_mapping_->clear_points();
  mapped_->resize(n);
}

unsigned ContactMapper::add_point(const Vec3& P, unsigned elem, double& r) {
  r = 0;
  switch (model_->kind()) {
    case CollisionModelBase::Kind::point:
      return elem;
    case CollisionModelBase::Kind::sphere: {
      const auto& sphere = *static_cast<SphereCollisionModel*>(model_);
      r = sphere.radius_of(elem);
      if (!sphere.rigid()) return elem;
      // The point in the frame of its rigid: q⁻¹·(P − c).
      const double* c = &model_->mstate()->read(kPosition)[elem * 7];
      const Vec3 local = quat_inverse_rotate(Quat::from(c + 3), P - Vec3(c[0], c[1], c[2]));
      return rigid_mapping_->add_point(local, elem);
    }
    case CollisionModelBase::Kind::obb: {
      // The point in the frame of its box (SOFA's OBB contact mapper).
      const double* c = &model_->mstate()->read(kPosition)[elem * 7];
      const Vec3 local = quat_inverse_rotate(Quat::from(c + 3), P - Vec3(c[0], c[1], c[2]));
      return rigid_mapping_->add_point(local, elem);
    }
    case CollisionModelBase::Kind::line: {
      // Parameter along the edge, not clamped (SOFA's line contact mapper).
      const auto& line = *static_cast<LineCollisionModel*>(model_);
      const LineElem e = line.elem(elem);
      const Vec3 ab = e.b - e.a;
      const double l2 = ab.dot(ab);
      const double fx = l2 < std::numeric_limits<double>::epsilon() ? 0.0 : (P - e.a).dot(ab) / l2;
      ContactMapping::Point p;
      p.n = 2;
      p.v = {e.v[0], e.v[1], 0, 0};
      p.w = {1.0 - fx, fx, 0, 0};
      return mapping_->add(p);
    }
    case CollisionModelBase::Kind::tetrahedron: {
      // Barycentric coordinates of P in the tetrahedron (SOFA's Tetrahedron::getBary).
      const TetrahedronElem t = static_cast<TetrahedronCollisionModel*>(model_)->elem(elem);
      Mat3 m;
      m.col(0) = t.p[1] - t.p[0];
      m.col(1) = t.p[2] - t.p[0];
      m.col(2) = t.p[3] - t.p[0];
      const Vec3 b = m.inverse() * (P - t.p[0]);
      ContactMapping::Point p;
      p.n = 4;
      p.v = t.v;
      p.w = {1.0 - b[0] - b[1] - b[2], b[0], b[1], b[2]};
      return mapping_->add(p);
    }
    case CollisionModelBase::Kind::triangle: {
      const auto& tri = *static_cast<TriangleCollisionModel*>(model_);
      const auto x = as_vec3(model_->mstate()->read(kPosition));
      ContactMapping::Point p;
      if (elem < tri.topology_triangles()) {
        // Closest point of the triangle (SOFA's createPointInTriangle).
        const Triangle& t = tri.triangle(elem);
        const Vec3 ab = x[t[1]] - x[t[0]], ac = x[t[2]] - x[t[0]], aq = P - x[t[0]];
        const double a00 = ab.dot(ab), a11 = ac.dot(ac), a01 = ab.dot(ac);
        const double b0 = aq.dot(ab), b1 = aq.dot(ac);
        const double det = a00 * a11 - a01 * a01;
        double fx = (b0 * a11 - b1 * a01) / det;
        double fy = (b1 * a00 - b0 * a01) / det;
        if (fx < 0 || fy < 0 || fx + fy > 1) {
          const double pab = b0 / a00, pac = b1 / a11;
          if (pab < 0 && pac < 0) {
            fx = 0;
            fy = 0;
          } else if (pab < 1 && fy < 0) {
            fx = pab;
            fy = 0;
          } else if (pac < 1 && fx < 0) {
            fx = 0;
            fy = pac;
          } else {
            const double pbc = (b1 - b0 + a00 - a01) / (a00 + a11 - 2 * a01);
            if (pbc < 0) {
              fx = 1;
              fy = 0;
            } else if (pbc > 1) {
              fx = 0;
              fy = 1;
            } else {
              fx = 1.0 - pbc;
              fy = pbc;
            }
          }
        }
        p.n = 3;
        p.v = {t[0], t[1], t[2], 0};
        p.w = {1.0 - fx - fy, fx, fy, 0};
      } else {
        // Triangle split from a quad: bilinear coordinates in the quad (SOFA's createPointInQuad).
        const unsigned qi = static_cast<unsigned>((elem - tri.topology_triangles()) / 2);
        const Quad& q = tri.mesh()->quads()[qi];
        const Vec3 pa = x[q[1]] - x[q[0]], pb = x[q[3]] - x[q[0]], pos = P - x[q[0]];
        Mat3 m;
        m.col(0) = pa;
        m.col(1) = pb;
        m.col(2) = pa.cross(pb);
        const Mat3 base = m.inverse();
        const double fx = base.row(0).dot(pos), fy = base.row(1).dot(pos);
        p.n = 4;
        p.v = {q[0], q[1], q[3], q[2]};
        p.w = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
      }
      return mapping_->add(p);
    }
  }
  return elem;
}

void ContactMapper::update() {
  if (identity() || !map_) return;
  map_->apply(kPosition);
  map_->apply_j(kVelocity, kVelocity);
}

void ContactMapper::update_xfree() {
  if (identity() || !map_) return;
  map_->apply(kFreePosition);
  map_->apply_j(kFreeVelocity, kFreeVelocity);
}

void ContactMapper::cleanup() {
  if (!child_) return;
  if (Node* parent = child_->parent()) parent->remove_child(child_);
  child_ = nullptr;
  mapped_ = nullptr;
  map_ = nullptr;
  mapping_ = nullptr;
  rigid_mapping_ = nullptr;
}

}  // namespace sinew
