#include "collision/response/penalty_contact.h"

#include "collision/intersection.h"
#include "collision/response/outputs_by_id.h"
#include "core/node.h"

namespace sinew {

// ------------------------------------------------------------------ force field

void PenaltyContactForceField::add_force(const MechParams& p) {
  // An obstacle's positions are its `position` (solver vectors do not exist there).
  const auto x1 = as_vec3(s1_->read(fixed1_ ? kPosition : vec_for(*s1_, p.x, kPosition)));
  const auto x2 = as_vec3(s2_->read(fixed2_ ? kPosition : vec_for(*s2_, p.x, kPosition)));
  // externalForce is empty between steps: sized here, like SOFA's f.resize(x.size()).
  auto forces = [&](MechanicalState& s) {
    std::vector<double>& f = s.write(vec_for(s, p.f, kForce));
    if (f.size() < 3 * s.size()) f.resize(3 * s.size(), 0.0);
    return as_vec3(f);
  };
  std::span<Vec3> f1, f2;
  if (!fixed1_) f1 = forces(*s1_);
  if (!fixed2_) f2 = forces(*s2_);
  for (Point& c : points_) {
    const Vec3 u = x2[c.m2] - x1[c.m1];
    c.pen = c.dist - u.dot(c.normal);
    if (c.pen > 0) {
      const Vec3 force = -c.normal * (c.ks * c.pen);
      if (!fixed1_) f1[c.m1] += force;
      if (!fixed2_) f2[c.m2] -= force;
    }
  }
}

void PenaltyContactForceField::add_dforce(const MechParams& p, double kfactor) {
  std::span<const Vec3> dx1, dx2;
  std::span<Vec3> df1, df2;
  if (!fixed1_) {
    dx1 = as_vec3(s1_->read(vec_for(*s1_, p.dx, kDx)));
    df1 = as_vec3(s1_->write(vec_for(*s1_, p.df, kDforce)));
  }
  if (!fixed2_) {
    dx2 = as_vec3(s2_->read(vec_for(*s2_, p.dx, kDx)));
    df2 = as_vec3(s2_->write(vec_for(*s2_, p.df, kDforce)));
  }
  for (const Point& c : points_) {
    if (c.pen <= 0) continue;  // active set of the last add_force
    Vec3 du = Vec3::Zero();
    if (!fixed2_) du += dx2[c.m2];
    if (!fixed1_) du -= dx1[c.m1];
    const double dpen = -du.dot(c.normal);
    const Vec3 dforce = -c.normal * (c.ks * dpen * kfactor);
    if (!fixed1_) df1[c.m1] += dforce;
    if (!fixed2_) df2[c.m2] -= dforce;
  }
}

// All four blocks, even on an obstacle's side, as SOFA: the system decides what
// lands where (an obstacle outside it still adds coupling terms, see MappedAssembly).
bool PenaltyContactForceField::build_stiffness(MatrixSink& K) {
  for (const Point& c : points_) {
    if (c.pen <= 0) continue;
    const Mat3 block = c.ks * c.normal * c.normal.transpose();
    const std::size_t i1 = 3 * c.m1, i2 = 3 * c.m2;
    K.add_block(s1_, i1, s1_, i1, -block);
    K.add_block(s1_, i1, s2_, i2, block);
    K.add_block(s2_, i2, s1_, i1, block);
    K.add_block(s2_, i2, s2_, i2, -block);
  }
  return true;
}

std::optional<double> PenaltyContactForceField::potential_energy() const {
  double e = 0;
  for (const Point& c : points_)
    if (c.pen > 0) e += 0.5 * c.ks * c.pen * c.pen;
  return e;
}

// ------------------------------------------------------------------ contact

PenaltyContact::PenaltyContact(CollisionModelBase& m1, CollisionModelBase& m2, const Intersection& method)
    : Contact(m1, m2, method),
      mapper1_(m1, m1.name.value() + "-contacts"),
      mapper2_(m2, m2.name.value() + "-contacts") {}

PenaltyContact::~PenaltyContact() = default;

bool PenaltyContact::set_param(const std::string& name, const std::string&, std::string& error) {
  // Penalty contacts have no parameter (friction coefficients are not used by their force law).
  error = "PenalityContactForceField has no parameter '" + name + "'";
  return false;
}

void PenaltyContact::set_detection_outputs(std::vector<DetectionOutput>& outputs) {
  if (!ff_ && !detached_) {
    MechanicalState* s1 = mapper1_.state();
    MechanicalState* s2 = mapper2_.state();
    detached_ = std::make_unique<PenaltyContactForceField>(*s1, *s2, !m1_->simulated.value(), !m2_->simulated.value());
    detached_->name.set(m1_->name.value() + "-" + m2_->name.value());
    detached_->set_type("PenalityContactForceField", "Vec3d");
    detached_->mark_initialised();
  }
  PenaltyContactForceField& ff = ff_ ? *ff_ : *detached_;

  // One contact per id: the first output of smallest value (SOFA keeps the
  // winner at its own place in the output order).
  keep_smallest_per_id(outputs, by_id_, kept_);

  ff.clear(kept_.size());
  mapper1_.resize(kept_.size());
  mapper2_.resize(kept_.size());
  const double d0 = method_->contact_distance() + m1_->contact_distance.value() + m2_->contact_distance.value();
  const double k12 = m1_->contact_stiffness.value() * m2_->contact_stiffness.value();
  for (std::size_t i : kept_) {
    const DetectionOutput& o = outputs[i];
    double r1 = 0, r2 = 0;
    const unsigned i1 = mapper1_.add_point(o.point1, o.elem1, r1);
    const unsigned i2 = mapper2_.add_point(o.point2, o.elem2, r2);
    const double dist = d0 + r1 + r2;
    double ks = k12;
    if (dist != 0.0) ks /= dist;
    ff.add_contact({i1, i2, o.normal, dist, ks});
  }
  mapper1_.update();
  mapper2_.update();
}

void PenaltyContact::create_response(Node& where) {
  ff_ = attach_response(where, ff_, detached_);
}

void PenaltyContact::cleanup() {
  if (ff_ && ff_->node()) ff_->node()->remove_object(ff_);  // destroyed here
  ff_ = nullptr;
  detached_.reset();
  mapper1_.cleanup();
  mapper2_.cleanup();
}

}  // namespace sinew
