#include "forcefield/load/triangle_pressure_force_field.h"

#include <cmath>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void TrianglePressureForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (cauchy_stress.get().size() != 6) {
    msg_error("cauchyStress must hold 6 values (xx xy yy xz yz zz)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!rebuild(true)) set_state(ComponentState::invalid);
}

bool TrianglePressureForceField::rebuild(bool read_list) {
  if (read_list) {
    list_ = triangle_list.get();
    pressure_seen_ = pressure.get();
  }
  const auto& all = topology->triangles();
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  const std::size_t np = mstate->size();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  tris_.clear();
  force_.clear();
  for (std::size_t i = 0; i < list_.size(); ++i) {
    if (list_[i] >= all.size()) {
      msg_error("triangleList entry " + std::to_string(i) + " (" + std::to_string(list_[i]) +
                ") is out of range (the topology has " + std::to_string(all.size()) + " triangles)");
      return false;
    }
    const Triangle& t = all[list_[i]];
    if (t[0] >= np || t[1] >= np || t[2] >= np) {
      msg_error("triangle " + std::to_string(list_[i]) + " refers to a point out of the state (" +
                std::to_string(np) + " points)");
      return false;
    }
    const double* n0 = &x0[3 * t[0]];
    const double* n1 = &x0[3 * t[1]];
    const double* n2 = &x0[3 * t[2]];
    const double a[3] = {n1[0] - n0[0], n1[1] - n0[1], n1[2] - n0[2]};
    const double b[3] = {n2[0] - n0[0], n2[1] - n0[1], n2[2] - n0[2]};
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double area = 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    tris_.push_back(t);
    force_.push_back(Vec3(pressure_seen_[0] * area, pressure_seen_[1] * area, pressure_seen_[2] * area));
  }
  return true;
}

void TrianglePressureForceField::add_force(const MechParams& p) {
  // SOFA keeps the list and the forces computed at init, even when the list is
  // an engine output that changes later (its update callback does not run
  // during the simulation); only a change of the topology rebuilds them.
  if (topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ && !rebuild(false)) {
    set_state(ComponentState::invalid);
    tris_.clear();
    force_.clear();
    return;
  }
  std::vector<double>& f = mstate->write(p.f);
  if (use_constant_force.value()) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Vec3 fi(force_[i][0] / 3, force_[i][1] / 3, force_[i][2] / 3);
      for (unsigned v : tris_[i])
        for (int c = 0; c < 3; ++c) f[3 * v + c] += fi[c];
    }
    return;
  }
  const std::vector<double>& x = mstate->read(p.x);
  const auto& s = cauchy_stress.value();
  // Symmetric 3×3 from SOFA's MatSym3 storage (lower triangle row by row).
  const double m[3][3] = {{s[0], s[1], s[3]}, {s[1], s[2], s[4]}, {s[3], s[4], s[5]}};
  for (const Triangle& t : tris_) {
    const double a[3] = {x[3 * t[1]] - x[3 * t[0]], x[3 * t[1] + 1] - x[3 * t[0] + 1], x[3 * t[1] + 2] - x[3 * t[0] + 2]};
    const double b[3] = {x[3 * t[2]] - x[3 * t[0]], x[3 * t[2] + 1] - x[3 * t[0] + 1], x[3 * t[2] + 2] - x[3 * t[0] + 2]};
    const double av[3] = {(a[1] * b[2] - a[2] * b[1]) / 6.0, (a[2] * b[0] - a[0] * b[2]) / 6.0,
                          (a[0] * b[1] - a[1] * b[0]) / 6.0};
    double fo[3];
    for (int r = 0; r < 3; ++r) fo[r] = m[r][0] * av[0] + m[r][1] * av[1] + m[r][2] * av[2];
    for (unsigned v : t)
      for (int c = 0; c < 3; ++c) f[3 * v + c] += fo[c];
  }
}

void register_triangle_pressure_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TrianglePressureForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "pressure applied on a list of triangles";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TrianglePressureForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
