// What the force fields on the edges of a triangle mesh (TriangularQuadraticSprings,
// TriangularBiquadraticSprings, TriangularTensorMass) check and compute alike at init.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/init_checks.h"
#include "core/roles.h"

namespace sinew {

// SOFA's Lamé pair of these force fields (plane stress): λ = Eν/(1 − ν²), μ = E(1 − ν)/(1 − ν²).
// False, with an error and the component invalid, when ν = ±1 makes them infinite.
inline bool triangle_edge_lame(ForceField& ff, double E, double nu, double& lambda, double& mu) {
  lambda = E * nu / (1 - nu * nu);
  mu = E * (1 - nu) / (1 - nu * nu);
  if (std::isfinite(lambda) && std::isfinite(mu)) return true;
  ff.msg_error("poissonRatio " + std::to_string(nu) + " gives infinite Lamé coefficients (1 − ν² = 0)");
  ff.set_state(ComponentState::invalid);
  return false;
}

// The triangles and edges of `t` index the state and `t` gives the edges of each triangle.
// False, with an error and the component invalid, otherwise.
inline bool triangle_edges_ready(ForceField& ff, const MeshTopologyBase& t) {
  const std::size_t n = ff.mstate->size();
  if (!element_points_in_state(ff, t.triangles(), "triangle", n) || !element_points_in_state(ff, t.edges(), "edge", n)) {
    ff.set_state(ComponentState::invalid);
    return false;
  }
  if (t.edges_in_triangle().size() == t.triangles().size()) return true;
  ff.msg_error("the topology " + t.describe() +
               " gives no edges of its triangles (a triangular set topology or a mesh with triangles is required)");
  ff.set_state(ComponentState::invalid);
  return false;
}

// initialPoints when not given: the state's rest positions.
inline void default_initial_points(const MechanicalState& s, Field<std::vector<Vec3>>& initial_points) {
  if (!initial_points.get().empty()) return;
  const std::vector<double>& r = s.read(kRestPosition);
  std::vector<Vec3> p(r.size() / 3);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vec3(r[3 * i], r[3 * i + 1], r[3 * i + 2]);
  initial_points.set(std::move(p));
}

// Rest area (Heron's formula on the squared edge lengths `rs`, SOFA's arithmetic) and the
// cotangents of the angles (cot[j] at the vertex opposite edge j) of triangle `i`. False, with
// an error naming the triangle, when the area is not positive (a degenerate triangle).
inline bool triangle_rest_cotangents(const ForceField& ff, unsigned i, const Triangle& tri, const double rs[3],
                                     double& area, double cot[3]) {
  area = 0;
  for (int j = 0; j < 3; ++j) area += rs[j] * (rs[(j + 1) % 3] + rs[(j + 2) % 3] - rs[j]);
  area = std::sqrt(area) / 4;
  if (!(area > 0) || !std::isfinite(area)) {
    ff.msg_error("triangle " + std::to_string(i) + " (" + std::to_string(tri[0]) + " " + std::to_string(tri[1]) + " " +
                 std::to_string(tri[2]) + ") is degenerate: its rest area is 0");
    return false;
  }
  for (int j = 0; j < 3; ++j) cot[j] = (rs[(j + 1) % 3] + rs[(j + 2) % 3] - rs[j]) / (4 * area);
  return true;
}

}  // namespace sinew
