// The "process" half of element removal in the dynamic containers
// (spec/interaction.md §7.2): arrays and their neighbourhood shells edited in
// place, in SOFA's order, at a cost proportional to the removed elements and
// the shells they touch. Events and propagation are the modifier's job
// (point_set_topology_modifier.h); these functions never notify anyone.
//
// Every removal is "swap with last": for each index (decreasing), the last
// element moves into the slot and the array shrinks; the shells of the moved
// element's vertices/edges/faces are renumbered. Shell order is SOFA's (erase
// keeps the order, renumbering replaces in place), so after removals the
// "around" lists are no longer sorted.
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew::topo {

using IndexList = std::vector<unsigned>;

// The element lists of a dynamic container and the neighbourhood arrays kept
// up to date through removals. Lists of a kind the container does not hold are
// empty (and so are their shells).
struct DynamicMesh {
  std::vector<Edge>* edges = nullptr;
  std::vector<Triangle>* triangles = nullptr;
  std::vector<Tetra>* tetrahedra = nullptr;
  std::vector<Quad>* quads = nullptr;
  std::vector<Hexa>* hexahedra = nullptr;
  unsigned nb_points = 0;
  std::vector<IndexList> edges_around_vertex, triangles_around_vertex, triangles_around_edge;
  std::vector<IndexList> tetrahedra_around_vertex, tetrahedra_around_edge, tetrahedra_around_triangle;
  std::vector<std::array<unsigned, 3>> edges_in_triangle;
  std::vector<std::array<unsigned, 6>> edges_in_tetrahedron;
  std::vector<std::array<unsigned, 4>> triangles_in_tetrahedron;
  // The quad/hexahedron family (SOFA's Edge ⊂ Quad ⊂ Hexahedron containers).
  std::vector<IndexList> quads_around_vertex, quads_around_edge;
  std::vector<IndexList> hexahedra_around_vertex, hexahedra_around_edge, hexahedra_around_quad;
  std::vector<std::array<unsigned, 4>> edges_in_quad;
  std::vector<std::array<unsigned, 12>> edges_in_hexahedron;
  std::vector<std::array<unsigned, 6>> quads_in_hexahedron;
};

// What a removal left without any higher element (in discovery order, unsorted).
struct Isolated {
  std::vector<unsigned> triangles, quads, edges, points;
};

// Tetrahedra `decreasing` (sorted, distinct, in range). Faces and edges left without a tetra are
// reported when `isolated_items`; points left without a tetra when also `isolated_points`.
Isolated remove_tetrahedra_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_items,
                                   bool isolated_points);
// Triangles; edges / points left without a triangle are reported on request.
Isolated remove_triangles_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_edges,
                                  bool isolated_points);
// Hexahedra, as tetrahedra: quads and edges left without a hexahedron are reported when
// `isolated_items`; points left without a hexahedron when also `isolated_points`.
Isolated remove_hexahedra_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_items,
                                  bool isolated_points);
// Quads (hexahedron level renumbered first, as SOFA's HexahedronSetTopologyModifier does); edges /
// points left without a quad are reported on request.
Isolated remove_quads_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_edges,
                              bool isolated_points);
// Edges; points left without an edge are reported on request.
Isolated remove_edges_process(DynamicMesh& m, const std::vector<unsigned>& decreasing, bool isolated_points);
// Points (expected isolated): the last point's index is replaced by the slot's in every element
// and shell, then nb_points shrinks.
void remove_points_process(DynamicMesh& m, const std::vector<unsigned>& decreasing);

// Consistency of a DynamicMesh (tests, validation): every element index < nb_points, every
// element listed exactly in the shells of its vertices/edges/faces and vice versa, the
// element-in-element tables matching the vertices. Returns the first problem, empty if none.
std::string check_dynamic_mesh(const DynamicMesh& m);

}  // namespace sinew::topo
