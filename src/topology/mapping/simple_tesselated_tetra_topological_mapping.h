// SimpleTesselatedTetraTopologicalMapping: a tetrahedral topology refined once
// (SOFA's SimpleTesselatedTetraTopologicalMapping, Sofa/Component/Mapping/Linear).
//
// Output points: the input points (same indices, same positions), then one
// point per input edge, at its midpoint (input edge order). Output tetrahedra:
// eight per input tetrahedron t, in input order, with m_k the midpoint of the
// tetrahedron's local edge k (kEdgesInTetra order (01, 02, 03, 12, 13, 23)):
//   (t0 m0 m1 m2) (t1 m0 m4 m3) (t2 m1 m3 m5) (t3 m2 m5 m4)
//   (m1 m0 m3 m5) (m1 m0 m5 m2) (m4 m0 m5 m3) (m4 m0 m2 m5).
// The output container is cleared, filled (positions included) and initialised.
//
// Outputs, as SOFA's Data: pointMappedFromPoint (output point of each input
// point), pointMappedFromEdge (output point of each input edge), pointSource
// (per output point: p+1 for input point p, −(e+1) for input edge e, 0 for
// none; SOFA stores it in an unsigned vector, so −(e+1) reads 2^32 − (e+1)),
// tetrahedraMappedFromTetra (the eight output tetrahedra of each input one),
// tetraSource (input tetrahedron of each output one).
//
// Topological changes, as SOFA:
//   - from the input (top-down): removed points, edges and tetrahedra update
//     the maps only (swap with the last, the removed one's outputs lose their
//     source); the output topology is not changed. Additions are ignored.
//   - from the output (bottom-up, after the output's subtree was visited):
//     removed output points and tetrahedra update the maps (SOFA's swaps,
//     step by step); an input tetrahedron whose eight children are all gone
//     is removed from the input, through its modifier, at the ending event.
#pragma once

#include <array>
#include <set>
#include <vector>

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class SimpleTesselatedTetraTopologicalMapping final : public TopologicalMapping {
 public:
  static constexpr unsigned kNone = ~0u;  // SOFA's InvalidID

  Field<std::vector<std::array<unsigned, 8>>> tetrahedra_mapped_from_tetra{
      this, "tetrahedraMappedFromTetra", {}, "the eight output tetrahedra of each input tetrahedron", "Outputs"};
  Field<std::vector<unsigned>> tetra_source{this, "tetraSource", {},
                                            "input tetrahedron of each output tetrahedron (InvalidID if none)",
                                            "Outputs"};
  Field<std::vector<unsigned>> point_mapped_from_point{this, "pointMappedFromPoint", {},
                                                       "output point of each input point", "Outputs"};
  Field<std::vector<unsigned>> point_mapped_from_edge{this, "pointMappedFromEdge", {},
                                                      "output point (midpoint) of each input edge", "Outputs"};
  Field<std::vector<unsigned>> point_source{
      this, "pointSource", {},
      "input element of each output point: 0 none, p+1 input point p, -(e+1) input edge e (stored unsigned)",
      "Outputs"};

  void init() override;
  void update_top_down() override;
  void update_bottom_up() override;

  // pointSource entry `i` read as SOFA's int (0, p+1 or −(e+1)).
  int source_of_point(unsigned i) const { return static_cast<int>(point_source.value()[i]); }

 private:
  // Input side (top-down).
  void swap_input(std::vector<unsigned>& from, unsigned a, unsigned b, unsigned (*code)(unsigned));
  void remove_input(std::vector<unsigned>& from, const std::vector<unsigned>& removed, unsigned (*code)(unsigned));
  void remove_input_points(const std::vector<unsigned>& removed);
  void remove_input_edges(const std::vector<unsigned>& removed);
  void swap_input_tetrahedra(unsigned a, unsigned b);
  void remove_input_tetrahedra(const std::vector<unsigned>& removed);
  // Output side (bottom-up).
  void set_point_source(unsigned i, int source);
  void swap_output_points(unsigned a, unsigned b);
  void remove_output_points(const std::vector<unsigned>& removed);
  void swap_output_tetrahedra(unsigned a, unsigned b);
  void remove_output_tetrahedra(const std::vector<unsigned>& removed);

  std::set<unsigned> tetrahedra_to_remove_;  // input tetrahedra left without children
};

}  // namespace sinew
