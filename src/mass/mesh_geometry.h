// Element measures used by the mesh-based masses (DiagonalMass,
// MeshMatrixMass), with SOFA's expressions (sofa::geometry::Edge/Triangle/
// Quad/Tetrahedron/Hexahedron) on flat coordinate arrays of width `w`
// (1, 2 or 3 spatial components per point), and the init steps both masses
// share (binding, checks, SOFA's fallbacks for bad mass input).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/roles.h"

namespace sinew::meshgeo {

// Point i of a flat array of width w, padded with zeros to 3 components.
inline std::array<double, 3> pt(const std::vector<double>& x, int w, std::size_t i) {
  std::array<double, 3> p{0, 0, 0};
  for (int c = 0; c < w && c < 3; ++c) p[c] = x[i * w + c];
  return p;
}

inline double edge_length(const std::vector<double>& x, int w, unsigned a, unsigned b) {
  double s = 0;
  for (int c = 0; c < w; ++c) {
    const double d = x[b * w + c] - x[a * w + c];
    s = c == 0 ? d * d : s + d * d;
  }
  return std::sqrt(s);
}

inline double triangle_area(const std::vector<double>& x, int w, unsigned i0, unsigned i1, unsigned i2) {
  const auto n0 = pt(x, w, i0), n1 = pt(x, w, i1), n2 = pt(x, w, i2);
  if (w == 3) {
    const double a0 = n1[0] - n0[0], a1 = n1[1] - n0[1], a2 = n1[2] - n0[2];
    const double b0 = n2[0] - n0[0], b1 = n2[1] - n0[1], b2 = n2[2] - n0[2];
    const double c0 = a1 * b2 - a2 * b1, c1 = a2 * b0 - a0 * b2, c2 = a0 * b1 - a1 * b0;
    return 0.5 * std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
  }
  if (w == 2)
    return 0.5 * (n0[0] * n1[1] + n1[0] * n2[1] + n2[0] * n0[1] - n1[0] * n0[1] - n2[0] * n1[1] - n0[0] * n2[1]);
  const double a = edge_length(x, w, i0, i1), b = edge_length(x, w, i0, i2), c = edge_length(x, w, i1, i2);
  return 0.25 * std::sqrt((a + b + c) * (-a + b + c) * (a - b + c) * (a + b - c));
}

inline double quad_area(const std::vector<double>& x, int w, const Quad& q) {
  return triangle_area(x, w, q[0], q[1], q[2]) + triangle_area(x, w, q[0], q[2], q[3]);
}

// |dot(cross(n1−n0, n2−n0), n3−n0)| / 6 (3D only).
inline double tetra_volume(const std::vector<double>& x, unsigned i0, unsigned i1, unsigned i2, unsigned i3) {
  const double* n0 = &x[i0 * 3];
  const double* n1 = &x[i1 * 3];
  const double* n2 = &x[i2 * 3];
  const double* n3 = &x[i3 * 3];
  const double a0 = n1[0] - n0[0], a1 = n1[1] - n0[1], a2 = n1[2] - n0[2];
  const double b0 = n2[0] - n0[0], b1 = n2[1] - n0[1], b2 = n2[2] - n0[2];
  const double c0 = n3[0] - n0[0], c1 = n3[1] - n0[1], c2 = n3[2] - n0[2];
  const double x0 = a1 * b2 - a2 * b1, x1 = a2 * b0 - a0 * b2, x2 = a0 * b1 - a1 * b0;
  const double v = (x0 * c0 + x1 * c1 + x2 * c2) / 6.0;
  return std::fabs(v);
}

// Sum of the absolute volumes of SOFA's 6-tetrahedron split.
inline double hexa_volume(const std::vector<double>& x, const Hexa& h) {
  return tetra_volume(x, h[0], h[5], h[1], h[6]) + tetra_volume(x, h[0], h[1], h[3], h[6]) +
         tetra_volume(x, h[1], h[3], h[6], h[2]) + tetra_volume(x, h[6], h[3], h[0], h[7]) +
         tetra_volume(x, h[6], h[7], h[0], h[5]) + tetra_volume(x, h[7], h[5], h[4], h[0]);
}

// Which element kind a mass uses: the highest present (hexa > tetra > quad > triangle > edge).
enum class MassElement { none, edge, triangle, quad, tetra, hexa };
inline MassElement mass_element(const MeshTopologyBase& t) {
  if (!t.hexahedra().empty()) return MassElement::hexa;
  if (!t.tetrahedra().empty()) return MassElement::tetra;
  if (!t.quads().empty()) return MassElement::quad;
  if (!t.triangles().empty()) return MassElement::triangle;
  if (!t.edges().empty()) return MassElement::edge;
  return MassElement::none;
}

// Largest point index used by the elements of kind k (+1), to check them against a state size.
std::size_t max_index_plus_one(const MeshTopologyBase& t, MassElement k);

// Shared init of the mesh-based masses: Vec1d/2d/3d state, topology (link,
// else the node's last one) and the state holding the topology's geometry
// (link, else the state of the topology's node). Reports and returns false
// (component invalid) when one is missing.
bool bind_mesh_mass(Mass& mass, Link<MeshTopologyBase>& topology, Link<MechanicalState>& geometry_state);

// The element kind the mass will use, checked against the state: an empty
// topology, or volume elements on a 1D/2D state, are reported and mark the
// mass invalid (the result is then MassElement::none).
MassElement checked_mass_element(Mass& mass, const MeshTopologyBase& t, const MechanicalState& geometry);

// The elements of kind k must only use points present in both the mass's state
// and the geometry state; otherwise reports the largest index and marks the
// mass invalid.
bool mass_elements_in_states(Mass& mass, const MeshTopologyBase& t, MassElement k, std::size_t state_size,
                             std::size_t geometry_size);

// SOFA resets a negative totalMass to 1 (with a warning) before deriving the
// density from it.
void reset_negative_total_mass(Mass& mass, Field<double>& total_mass);

// A vertexMass list is usable when it has one non-negative value per point.
bool one_nonnegative_mass_per_point(const std::vector<double>& vertex_mass, std::size_t n_points);

// v += dt·g on every point (add_gravity_to_v of the diagonal masses: gravity
// does not depend on the mass there).
void add_gravity_velocity(MechanicalState& s, int v, const Vec3& g, double dt);

}  // namespace sinew::meshgeo
