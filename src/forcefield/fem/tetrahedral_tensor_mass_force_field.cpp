#include "forcefield/fem/tetrahedral_tensor_mass_force_field.h"

#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/registry.h"
#include "forcefield/fem/sofa_mat3.h"
#include "topology/mesh_topology.h"

namespace sinew {


bool TetrahedralTensorMassForceField::elements_ready(const MeshTopologyBase& t) {
  const std::size_t n = mstate->size();
  if (!element_points_in_state(*this, t.tetrahedra(), "tetrahedron", n) ||
      !element_points_in_state(*this, t.edges(), "edge", n))
    return false;
  if (t.edges_in_tetrahedron().size() == t.tetrahedra().size()) return true;
  msg_error("the topology " + t.describe() +
            " gives no edges of its tetrahedra (a tetrahedral set topology or a mesh with tetrahedra is required)");
  return false;
}

bool TetrahedralTensorMassForceField::lame(double E, double nu, double& lambda, double& mu) {
  lambda = E * nu / ((1 - 2 * nu) * (1 + nu));
  mu = E / (2 * (1 + nu));
  if (std::isfinite(lambda) && std::isfinite(mu)) return true;
  msg_error("poissonRatio " + std::to_string(nu) + " gives infinite Lamé coefficients (ν = 0.5 or ν = −1)");
  return false;
}

bool TetrahedralTensorMassForceField::element_terms(unsigned i, const MeshTopologyBase& t, double sign) {
  if (i >= t.edges_in_tetrahedron().size()) return true;
  const double* x0 = mstate->read(kRestPosition).data();
  const auto& te = t.edges_in_tetrahedron()[i];
  const Tetra& tet = t.tetrahedra()[i];
  Vec3 p[4], shape[4];
  for (int j = 0; j < 4; ++j) p[j] = fem::at3(x0, tet[j]);
  const double volume = fem::dot3(fem::cross3(p[1] - p[0], p[2] - p[0]), p[0] - p[3]);  // six times the signed volume
  if (!(volume != 0) || !std::isfinite(volume)) {
    msg_error("tetrahedron " + std::to_string(i) + " (" + std::to_string(tet[0]) + " " + std::to_string(tet[1]) + " " +
              std::to_string(tet[2]) + " " + std::to_string(tet[3]) + ") is degenerate: its rest volume is 0");
    return false;
  }
  for (int j = 0; j < 4; ++j) {
    const Vec3 c = fem::cross3(p[(j + 2) % 4] - p[(j + 1) % 4], p[(j + 3) % 4] - p[(j + 1) % 4]);
    const Vec3 s = j % 2 == 0 ? c : Vec3(-c);
    shape[j] = Vec3(s[0] / volume, s[1] / volume, s[2] / volume);
  }
  const double lambdastar = lambda_ * std::fabs(volume) / 6, mustar = mu_ * std::fabs(volume) / 6;
  for (int j = 0; j < 6; ++j) {
    const unsigned k = topo::kEdgesInTetra[j][0], l = topo::kEdgesInTetra[j][1];
    if (te[j] >= edge_tensor_.size()) continue;
    Mat3& m = edge_tensor_[te[j]];
    const double val1 = fem::dot3(shape[k], shape[l]) * mustar;
    // Added or subtracted in place: the same roundings on removal as on creation.
    const bool direct = t.edges()[te[j]][0] != tet[l];
    for (int u = 0; u < 3; ++u) {
      for (int v = 0; v < 3; ++v) {
        const double term = lambdastar * shape[l][u] * shape[k][v] + mustar * shape[k][u] * shape[l][v];
        double& e = direct ? m(u, v) : m(v, u);
        if (sign > 0) e += term; else e -= term;
      }
      if (sign > 0) m(u, u) += val1; else m(u, u) -= val1;
    }
  }
  return true;
}

void register_tetrahedral_tensor_mass_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedralTensorMassForceField";
  info.category = "ForceField/FEM";
  info.description = "linear elasticity on a tetrahedral mesh, as one tensor per edge";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TetrahedralTensorMassForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
