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
// Only the construction at init exists. SOFA also forwards edge and point
// additions, removals and renumberings to the quads; no SOFA example exercises
// that (the one scene that would, through EdgeSetController, is commented out
// in Demos/Coil.scn), so it is not implemented: a change of the input edges
// after init is not reflected in the output.
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

  // Input edge of each output quad (SOFA's Loc2GlobDataVec), filled at init.
  const std::vector<unsigned>& quad_to_edge() const { return quad_to_edge_; }

 private:
  // Rings of every input point written into the output node's Vec3d state, if any; false after an error.
  bool write_ring_positions(std::size_t n_points, unsigned n);
  std::vector<unsigned> quad_to_edge_;
};

}  // namespace sinew
