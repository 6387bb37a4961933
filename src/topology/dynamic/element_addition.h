// The "process" half of element addition in the dynamic containers
// (spec/interaction.md §7.2 "Triangle addition"): the new element is appended
// and the neighbourhood arrays of a live DynamicMesh (element_removal.h) grow
// with it, in SOFA's order: the new index is pushed at the end of each shell,
// and a missing edge of a new triangle is created with the triangle's vertex
// order at that corner. Events are the modifier's job.
#pragma once

#include <vector>

#include "topology/dynamic/element_removal.h"

namespace sinew::topo {

inline constexpr unsigned kNoIndex = ~0u;

// The index of the edge joining a and b (either orientation), first found in a's edge shell;
// kNoIndex when there is none.
unsigned find_edge(const DynamicMesh& m, unsigned a, unsigned b);

// Appends edge e (growing the point count when it names a point beyond it).
void add_edge_process(DynamicMesh& m, const Edge& e);

// Appends triangle t: its index joins the shells of its vertices; for each corner j the edge
// (t[j+1], t[j+2]) is looked up and created when absent. Returns the indices of the edges it
// created, in creation order.
std::vector<unsigned> add_triangle_process(DynamicMesh& m, const Triangle& t);

}  // namespace sinew::topo
