// What the force fields on the edges of a triangle mesh (TriangularQuadraticSprings,
// TriangularBiquadraticSprings, TriangularTensorMass) check and compute alike at init.
#pragma once

#include <cmath>
#include <string>

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

}  // namespace sinew
