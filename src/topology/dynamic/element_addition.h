// The "process" half of element addition in the dynamic containers
// (spec/interaction.md §7.2 "Triangle addition"): the new element is appended
// and the neighbourhood arrays of a live DynamicMesh (element_removal.h) grow
// with it, in SOFA's order: the new index is pushed at the end of each shell,
// a missing edge of a new triangle is created with the triangle's vertex order
// at that corner, and a missing face of a new tetrahedron with the vertex order
// of its local face. Events are the modifier's job (the processes return what
// they created, in order).
#pragma once

#include <vector>

#include "topology/dynamic/element_removal.h"
#include "topology/mesh_topology.h"

namespace sinew::topo {

inline constexpr unsigned kNoIndex = ~0u;

// The index of the edge joining a and b (either orientation), first found in a's edge shell;
// kNoIndex when there is none.
unsigned find_edge(const DynamicMesh& m, unsigned a, unsigned b);

// Appends n isolated points: the vertex shells of the kinds the mesh holds grow with empty
// lists (SOFA's addPointsProcess chain).
void add_points_process(DynamicMesh& m, unsigned n);

// Appends edge e (growing the point count when it names a point beyond it).
void add_edge_process(DynamicMesh& m, const Edge& e);

// The index of the triangle with vertices a, b, c (any order), when exactly one exists; kNoIndex
// otherwise (SOFA intersects the three vertex shells and refuses ambiguity).
unsigned find_triangle(const DynamicMesh& m, unsigned a, unsigned b, unsigned c);

// Appends triangle t: its index joins the shells of its vertices; for each corner j the edge
// (t[j+1], t[j+2]) is looked up and created when absent. Returns the indices of the edges it
// created, in creation order.
std::vector<unsigned> add_triangle_process(DynamicMesh& m, const Triangle& t);

// An element a tetrahedron addition created on its way, in creation order.
struct Created {
  enum class Kind { edge, triangle, quad } kind;
  unsigned index;
};

// Appends tetrahedron t: its index joins the shells of its vertices; for each face j (vertices
// kTrianglesInTetra[j] of t, in that order) the triangle is looked up and created when absent
// (with add_triangle_process, so its missing edges come first); then for each local edge j
// (kEdgesInTetra[j]) the edge is looked up and created as (t[a], t[b]) when absent. The new
// index joins the face and edge shells. Returns what it created, in order.
std::vector<Created> add_tetrahedron_process(DynamicMesh& m, const Tetra& t);

// The index of the quad with vertices a, b, c, d (any order), when exactly one exists; kNoIndex
// otherwise (SOFA's getQuadIndex intersects the four vertex shells).
unsigned find_quad(const DynamicMesh& m, unsigned a, unsigned b, unsigned c, unsigned d);

// Appends quad q (SOFA's addQuadProcess): its index joins the shells of its vertices; for each
// corner j the edge (q[j+1], q[j+2]) is looked up and created, in that vertex order, when absent.
// Returns the indices of the edges it created, in creation order.
std::vector<unsigned> add_quad_process(DynamicMesh& m, const Quad& q);

// Appends hexahedron h (SOFA's addHexahedronProcess): its index joins the shells of its
// vertices; for each face j (vertices kQuadsInHexa[j] of h, in that order) the quad is looked up
// and created when absent (with add_quad_process, so its missing edges come first); then for each
// local edge j (kEdgesInHexa[j]) the edge is looked up and created as (h[a], h[b]) when absent.
// Returns what it created, in order.
std::vector<Created> add_hexahedron_process(DynamicMesh& m, const Hexa& h);

}  // namespace sinew::topo
