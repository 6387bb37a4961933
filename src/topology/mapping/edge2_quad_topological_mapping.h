// Edge2QuadTopologicalMapping: the quad skin of a tube around a line of
// Rigid3d frames (SOFA's Edge2QuadTopologicalMapping, Sofa/Component/Topology/
// Mapping). Each input point p gets a ring of N = nbPointsOnEachCircle output
// points, numbered p·N + j; each input edge (p0, p1) gets N quads
// (p0·N+j, p1·N+j, p1·N+j+1, p0·N+j+1), indices taken modulo the ring.
//
// At init the rings are also written into the Vec3d state of the output
// container's node (a MechanicalObject or a visual model), when there is one:
// ring point j of frame (c, R) is
//   c + (R·Y0·cos θj + R·Z0·sin θj)·radius,                θj = 2πj/N,
// with Y0 = y, Z0 = z; for an ellipse (radiusFocal > 0), Z0 = focalAxis
// (normalised), Y0 = Z0 × x and the two terms are scaled by radius and
// radiusFocal. TubularMapping then moves these points with the frames.
//
// flipNormals reverses each quad: (q3, q2, q1, q0) when every edge is mapped,
// (q0, q3, q2, q1) with an edgeList (SOFA builds the two cases differently).
//
// The output follows the input's changes as SOFA's updateTopologicalMappingTopDown:
//   - EDGESADDED: N quads (q0, q1, q2, q3) per new edge, appended in one add_quads (never
//     flipped, as SOFA);
//   - EDGESREMOVED: each removed edge's N quads are removed on their own, with isolated edges
//     and points (removeQuads(..., true, true)), after SOFA's step-by-step bookkeeping of its
//     edge → quads map and quad → edge list (reproduced, so later removals pick the same quads);
//   - POINTSADDED: N output points per new input point, with their DoFs; SOFA builds the
//     ancestor rows of ring j from the input ancestors a as a·N + j accumulated over the rings
//     0..j, and the coefficient rows the same way from the coefficients (c·N + j): reproduced;
//   - the ending event is relayed.
// Point removals are not relayed (SOFA ignores POINTSREMOVED here); SOFA's POINTSRENUMBERING
// has no counterpart in Sinew's events.
#pragma once

#include "topology/dynamic/quad_set_topology_container.h"
#include "topology/dynamic/quad_set_topology_modifier.h"
#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Edge2QuadTopologicalMapping final : public TopologicalMapping {
 public:
  Field<unsigned> nb_points_on_each_circle{this, "nbPointsOnEachCircle", 0u,
                                           "number of points on each ring (discretisation of the circles)", "Mapping"};
  Field<double> radius{this, "radius", 1.0, "radius of the rings, in the plane of the frame's y and z axes", "Mapping",
                       "length"};
  Field<double> radius_focal{this, "radiusFocal", 0.0,
                             "if > 0, the rings are ellipses with this radius along focalAxis", "Mapping", "length"};
  Field<Vec3> focal_axis{this, "focalAxis", Vec3(0, 0, 1), "focal axis of the ellipses, in the frame's axes",
                         "Mapping"};
  Field<std::vector<unsigned>> edge_list{this, "edgeList", {}, "input edges to map (default: all)", "Mapping"};
  Field<bool> flip_normals{this, "flipNormals", false, "reverse the vertex order of the created quads", "Mapping"};
  Link<QuadSetTopologyContainer> to_quad_container{
      this, "toQuadContainer", "output quad container (default: the one found from the output's node)"};
  Link<QuadSetTopologyModifier> to_quad_modifier{
      this, "toQuadModifier", "output quad modifier (default: the one found from the output's node)"};

  void init() override;
  void update_top_down() override;
  bool input_elements(unsigned out, std::vector<unsigned>& in) const override;

  // Input edge of each output quad (SOFA's Loc2GlobDataVec).
  const std::vector<unsigned>& quad_to_edge() const { return quad_to_edge_; }
  // Output quads of an input edge (SOFA's In2OutMap; empty when the edge is not mapped).
  const std::vector<unsigned>& edge_to_quads(unsigned edge) const;

 private:
  // Rings of every input point written into the output node's Vec3d state, if any; false after an error.
  bool write_ring_positions(std::size_t n_points, unsigned n);
  void set_edge_quads(unsigned edge, std::vector<unsigned> quads);
  bool edge_mapped(unsigned edge) const { return edge < edge_to_quads_.size() && !edge_to_quads_[edge].empty(); }
  void on_edges_added(const std::vector<unsigned>& added);
  void on_edges_removed(const std::vector<unsigned>& removed);
  void on_points_added(const TopologyChange& c);

  std::vector<unsigned> quad_to_edge_;
  // SOFA keeps a std::map; a flat array indexed by input edge (empty: absent) is the same relation.
  std::vector<std::vector<unsigned>> edge_to_quads_;
};

}  // namespace sinew
