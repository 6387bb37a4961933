#include "engine/generate/generate_rigid_mass.h"

#include "core/registry.h"
#include <Eigen/Geometry>

namespace sinew {

GenerateRigidMass::GenerateRigidMass() {
  add_input(&density);
  add_input(&position);
  add_input(&triangles);
  add_input(&quads);
  add_input(&polygons);
  add_output(&rigid_mass);
  add_output(&mass);
  add_output(&volume);
  add_output(&inertia_matrix);
  add_output(&mass_center);
  add_output(&center_to_origin);
}

void GenerateRigidMass::init() {
  set_dirty();
  update();
}

void accumulate_volume_integrals(const Vec3& v0, const Vec3& v1, const Vec3& v2, std::array<double, 10>& a) {
  const Vec3 n = (v1 - v0).cross(v2 - v0);
  // Per axis: f1 = Σv, f2 = Σ_{i≤j} vi vj, f3 = Σ_{i≤j≤k} vi vj vk, gi = f2 + vi (f1 + vi).
  double f1[3], f2[3], f3[3], g0[3], g1[3], g2[3];
  for (int c = 0; c < 3; ++c) {
    const double t0 = v0[c] + v1[c];
    f1[c] = t0 + v2[c];
    const double t1 = v0[c] * v0[c];
    const double t2 = t1 + v1[c] * t0;
    f2[c] = t2 + v2[c] * f1[c];
    f3[c] = v0[c] * t1 + v1[c] * t2 + v2[c] * f2[c];
    g0[c] = f2[c] + v0[c] * (f1[c] + v0[c]);
    g1[c] = f2[c] + v1[c] * (f1[c] + v1[c]);
    g2[c] = f2[c] + v2[c] * (f1[c] + v2[c]);
  }
  a[0] += n[0] * f1[0];
  a[1] += n[0] * f2[0];
  a[2] += n[1] * f2[1];
  a[3] += n[2] * f2[2];
  a[4] += n[0] * f3[0];
  a[5] += n[1] * f3[1];
  a[6] += n[2] * f3[2];
  a[7] += n[0] * (v0[1] * g0[0] + v1[1] * g1[0] + v2[1] * g2[0]);
  a[8] += n[1] * (v0[2] * g0[1] + v1[2] * g1[1] + v2[2] * g2[1]);
  a[9] += n[2] * (v0[0] * g0[2] + v1[0] * g1[2] + v2[0] * g2[2]);
}

void GenerateRigidMass::do_update() {
  const std::vector<Vec3>& x = position.get();
  std::array<double, 10> a{};
  bool bad = false;
  auto tri = [&](unsigned i, unsigned j, unsigned k) {
    if (i >= x.size() || j >= x.size() || k >= x.size()) {
      bad = true;
      return;
    }
    accumulate_volume_integrals(x[i], x[j], x[k], a);
  };
  for (const Triangle& t : triangles.get()) tri(t[0], t[1], t[2]);
  for (const Quad& q : quads.get()) {
    tri(q[0], q[1], q[2]);
    tri(q[0], q[2], q[3]);
  }
  for (const std::vector<unsigned>& p : polygons.get())
    for (std::size_t j = 2; j < p.size(); ++j) tri(p[0], p[j - 1], p[j]);
  if (bad) msg_error("an element refers to a point beyond the " + std::to_string(x.size()) +
                     " positions: it is left out of the integrals");
  a[0] /= 6.0;
  for (int i = 1; i <= 3; ++i) a[i] /= 24.0;
  for (int i = 4; i <= 6; ++i) a[i] /= 60.0;
  for (int i = 7; i <= 9; ++i) a[i] /= 120.0;

  const double v = a[0];
  if (v == 0.0) {
    msg_warning("the mesh's volume is zero: outputs not updated");
    return;
  }
  if (v < 0.0) msg_warning("the mesh's volume is negative (inward-facing triangles?)");
  const Vec3 c(a[1] / v, a[2] / v, a[3] / v);
  // Inertia about the origin, then about the centre of mass, per unit volume.
  Mat3 I;
  I(0, 0) = a[5] + a[6] - v * (c[1] * c[1] + c[2] * c[2]);
  I(1, 1) = a[4] + a[6] - v * (c[2] * c[2] + c[0] * c[0]);
  I(2, 2) = a[4] + a[5] - v * (c[0] * c[0] + c[1] * c[1]);
  I(0, 1) = I(1, 0) = -a[7] + v * c[0] * c[1];
  I(0, 2) = I(2, 0) = -a[9] + v * c[2] * c[0];
  I(1, 2) = I(2, 1) = -a[8] + v * c[1] * c[2];
  I /= v;
  const double m = v * density.get();

  std::vector<double>& rm = rigid_mass.edit();
  rm.assign({m, v});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rm.push_back(I(i, j));
  mass.set(m);
  volume.set(v);
  inertia_matrix.set(I);
  mass_center.set(c);
  center_to_origin.set(-c);
}

void register_generate_rigid_mass(Registry& r) {
  ComponentInfo info;
  info.name = "GenerateRigidMass";
  info.category = "Engine/Generate";
  info.description = "rigid mass (mass, volume, inertia, centre) of a closed surface mesh of uniform density";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<GenerateRigidMass>(); };
  r.add(std::move(info));
}

}  // namespace sinew
