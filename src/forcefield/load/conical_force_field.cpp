#include "forcefield/load/conical_force_field.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/registry.h"

namespace sinew {

void ConicalForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!(cone_height.value().norm() > 0)) {
    msg_error("coneHeight must be a non-zero vector (the cone's axis and height)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!(cone_angle.value() > 0 && cone_angle.value() < 180)) {
    msg_error("coneAngle must be between 0 and 180 degrees (it is " + parse::format_double(cone_angle.value()) + ")");
    set_state(ComponentState::invalid);
  }
}

bool ConicalForceField::is_in(const Vec3& p) const {
  const Vec3 c = cone_center.value(), height = cone_height.value();
  const double h = height.norm();
  const Vec3 vp = p - c;
  const double dist = vp.norm();
  if (dist > h) return false;
  // At the apex the angle is undefined (SOFA's acos(NaN) compares false: inside).
  return !(std::acos(vp.dot(height) / (h * dist)) * 180 / M_PI > cone_angle.value());
}

void ConicalForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  contacts_.clear();
  const Vec3 center = cone_center.value();
  const double hn = cone_height.value().norm();
  const Vec3 n = cone_height.value() / hn;
  const double k = stiffness.value(), kd = damping.value();
  const double angle = cone_angle.value() * M_PI / 180;
  const std::size_t count = x.size() / 3;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 pos(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    const Vec3 vel(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    if (is_in(pos)) continue;
    const Vec3 cp = pos - center;
    Vec3 force, dir;
    if (cp.norm() > hn) {  // beyond the base sphere
      const double norm = cp.norm();
      const double d = norm - hn;
      dir = cp / norm;
      force = cp * (-k * d / norm) - vel * (-kd * d);
    } else {
      double d;
      if (cp.dot(n) > 0) {  // beside the cone: rotate cp onto the side line
        const Vec3 n_cp = cp / cp.norm();
        const double alpha = std::acos(n_cp.dot(n)) - angle;
        Vec3 t = n.cross(cp);
        t /= t.norm();
        Vec3 cp_new = Eigen::AngleAxisd(-alpha, t) * cp;
        cp_new.normalize();
        const Vec3 pp_prime = cp_new * cp_new.dot(cp) - cp;
        d = pp_prime.norm();
        dir = pp_prime / d;
      } else {  // behind the apex
        d = cp.norm();
        dir = -cp / d;
      }
      force = dir * (k * d) + dir * (kd * (-dir.dot(vel)));
    }
    for (int j = 0; j < 3; ++j) f[3 * i + static_cast<std::size_t>(j)] += force[j];
    contacts_.push_back({static_cast<unsigned>(i), dir});
  }
}

void ConicalForceField::add_dforce(const MechParams& p, double kfactor) {
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  const double k = stiffness.value();
  for (const Contact& c : contacts_) {
    const Vec3 du(dx[3 * c.index], dx[3 * c.index + 1], dx[3 * c.index + 2]);
    const Vec3 dforce = c.normal * du.dot(c.normal) * (-k);
    for (int j = 0; j < 3; ++j) df[3 * c.index + static_cast<unsigned>(j)] += dforce[j] * kfactor;
  }
}

bool ConicalForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  const double k = stiffness.value();
  for (const Contact& c : contacts_) {
    const Mat3 m = -k * (c.normal * c.normal.transpose());
    K.add_block(s, 3 * c.index, s, 3 * c.index, m);
  }
  return true;
}

void register_conical_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "ConicalForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "penalty force keeping points inside a cone";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ConicalForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
