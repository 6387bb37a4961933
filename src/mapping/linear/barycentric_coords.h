// Barycentric coordinates for BarycentricMapping, computed once at init: for
// each output point, the element of the input topology that holds it (else the
// nearest one, extrapolating) and the weights of that element's vertices,
// appended to a BaryTable. One function per kind of input topology; they follow
// SOFA's mappers operation by operation, including the order in which an
// element's vertices are summed, because the regression scenes compare with SOFA.
//
// Points are read from `out` and element vertices from `in` (x y z per point).
// Messages are left to the mapping: the functions only report what they found.
#pragma once

#include <limits>
#include <vector>

#include "core/roles.h"
#include "mapping/linear/barycentric_table.h"

namespace sinew {

class RegularGridTopology;
class SparseGridTopology;

struct BaryReport {
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> degenerate;  // elements without a local frame (zero volume or area): they take no point
  std::vector<std::size_t> outside;     // points extrapolated well outside their element
  std::size_t unlocated = kNone;        // first point no element could take (the table then stops before it)
};

// SOFA's 3×3 inverse (Mat::invert: cofactors over the determinant, same operation
// order); false, `d` untouched, when |det| < machine epsilon.
bool bary_invert3(const double f[3][3], double d[3][3]);

// Trilinear weights in the grid's cell (needs at least 2 points along each axis).
BaryReport bary_regular_grid(const RegularGridTopology& grid, const std::vector<double>& out, BaryTable& table);
// Trilinear weights in the sparse grid's cell, else in its nearest boundary cell.
BaryReport bary_sparse_grid(const SparseGridTopology& grid, const std::vector<double>& out, BaryTable& table);

// Nearest element by SOFA's distance criterion, tetrahedra before hexahedra (or
// triangles before quads). `set_container`: the *SetTopologyContainer mappers'
// variant (no distance cut-off, weights summed in element-vertex order rather
// than in lattice order). Elements must use valid vertex indices of `in`.
BaryReport bary_volume(const std::vector<Tetra>& tetras, const std::vector<Hexa>& hexas, bool set_container,
                       const std::vector<double>& in, const std::vector<double>& out, BaryTable& table);
BaryReport bary_surface(const std::vector<Triangle>& triangles, const std::vector<Quad>& quads, bool set_container,
                        const std::vector<double>& in, const std::vector<double>& out, BaryTable& table);
// First edge whose segment the point projects onto, else the last edge (extrapolated). Needs one edge.
void bary_edges(const std::vector<Edge>& edges, const std::vector<double>& in, const std::vector<double>& out,
                BaryTable& table);

}  // namespace sinew
