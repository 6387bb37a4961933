#include "forcefield/load/quad_pressure_force_field.h"

#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/registry.h"

namespace sinew {

namespace {
double triangle_area(const double* a, const double* b, const double* c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}
}  // namespace

void QuadPressureForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a quad mesh is required")) return;
  const std::vector<Quad>& all = topology->quads();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const std::size_t np = mstate->size();
  list_.clear();
  if (dmin.value() != dmax.value()) {
    const Vec3 n = normal.value();
    const auto in_slab = [&](unsigned v) {
      const double d = x0[3 * v] * n[0] + x0[3 * v + 1] * n[1] + x0[3 * v + 2] * n[2];
      return d > dmin.value() && d < dmax.value();
    };
    for (std::size_t q = 0; q < all.size(); ++q) {
      const Quad& quad = all[q];
      bool inside = true;
      for (unsigned v : quad) inside = inside && v < np && in_slab(v);
      if (inside) list_.push_back(static_cast<unsigned>(q));
    }
  }
  if (!quad_list.value().empty()) list_ = quad_list.value();  // SOFA: the list wins
  quads_.clear();
  area_.clear();
  for (std::size_t i = 0; i < list_.size(); ++i) {
    if (list_[i] >= all.size()) {
      msg_error("quadList entry " + std::to_string(i) + " (" + std::to_string(list_[i]) +
                ") is out of range (the topology has " + std::to_string(all.size()) + " quads)");
      set_state(ComponentState::invalid);
      return;
    }
    const Quad& q = all[list_[i]];
    for (unsigned v : q)
      if (v >= np) {
        msg_error("quad " + std::to_string(list_[i]) + " refers to point " + std::to_string(v) +
                  ", out of the state (" + std::to_string(np) + " points)");
        set_state(ComponentState::invalid);
        return;
      }
    const double* n0 = &x0[3 * q[0]];
    const double* n1 = &x0[3 * q[1]];
    const double* n2 = &x0[3 * q[2]];
    const double* n3 = &x0[3 * q[3]];
    quads_.push_back(q);
    area_.push_back(triangle_area(n0, n1, n2) + triangle_area(n0, n2, n3));
  }
}

void QuadPressureForceField::add_force(const MechParams& p) {
  std::vector<double>& f = mstate->write(p.f);
  const Vec3 P = pressure.value();  // read each step: SOFA updates the force from the current pressure
  for (std::size_t i = 0; i < quads_.size(); ++i) {
    const double fq[3] = {P[0] * area_[i] / 4, P[1] * area_[i] / 4, P[2] * area_[i] / 4};
    for (unsigned v : quads_[i])
      for (int c = 0; c < 3; ++c) f[3 * v + static_cast<unsigned>(c)] += fq[c];
  }
}

void register_quad_pressure_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "QuadPressureForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "pressure on quads, distributed equally to their vertices";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<QuadPressureForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
