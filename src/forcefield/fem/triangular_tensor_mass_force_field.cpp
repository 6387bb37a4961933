#include "forcefield/fem/triangular_tensor_mass_force_field.h"

#include "core/registry.h"
#include "forcefield/fem/sofa_mat3.h"
#include "forcefield/triangle_edge_setup.h"

namespace sinew {


bool TriangularTensorMassForceField::elements_ready(const MeshTopologyBase& t) { return triangle_edges_ready(*this, t); }

bool TriangularTensorMassForceField::lame(double E, double nu, double& lambda, double& mu) {
  return triangle_edge_lame(*this, E, nu, lambda, mu);
}

bool TriangularTensorMassForceField::element_terms(unsigned i, const MeshTopologyBase& t, double sign) {
  if (i >= t.edges_in_triangle().size()) return true;
  const double* x0 = mstate->read(kRestPosition).data();
  const auto& te = t.edges_in_triangle()[i];
  const Triangle& tri = t.triangles()[i];
  Vec3 p[3];
  double rs[3], cot[3];
  for (int j = 0; j < 3; ++j) p[j] = fem::at3(x0, tri[j]);
  for (int j = 0; j < 3; ++j) {
    const Vec3 d = p[(j + 1) % 3] - p[(j + 2) % 3];
    rs[j] = fem::dot3(d, d);
  }
  double area = 0;
  if (!triangle_rest_cotangents(*this, i, tri, rs, area, cot)) return false;
  const double lambdastar = lambda_ / (4 * area), mustar = mu_ / (8 * area);
  for (int j = 0; j < 3; ++j) {
    const int k = (j + 1) % 3, l = (j + 2) % 3;
    if (te[j] >= edge_tensor_.size()) continue;
    Mat3& m = edge_tensor_[te[j]];
    const Vec3 dpl = p[j] - p[k], dpk = p[j] - p[l];
    const double val1 = -cot[j] * (lambda_ + mu_) / 2;
    // SOFA adds (or subtracts) the term in place: the same roundings on removal as on creation.
    const bool direct = t.edges()[te[j]][0] == tri[l];
    for (int u = 0; u < 3; ++u) {
      for (int v = 0; v < 3; ++v) {
        const double term = lambdastar * dpl[u] * dpk[v] + mustar * dpk[u] * dpl[v];
        double& e = direct ? m(u, v) : m(v, u);
        if (sign > 0) e += term; else e -= term;
      }
      if (sign > 0) m(u, u) += val1; else m(u, u) -= val1;
    }
  }
  return true;
}

void register_triangular_tensor_mass_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularTensorMassForceField";
  info.category = "ForceField/FEM";
  info.description = "linear elastic membrane on a triangular mesh, as one tensor per edge";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularTensorMassForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
