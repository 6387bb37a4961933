// SubsetTopologicalMapping: the output topology is a part of the input one
// (its points, or the same points, and some of its elements), both set up by
// the scene (spec/mechanics.md §5.7). At init the mapping pairs each output
// element with the input element of the same vertices (vertex order ignored;
// points by equal position unless `samePoints`), in the maps below. Unlike
// the other topological mappings it leaves the output's lists as they are.
//
// The output then follows the input's changes (SOFA's
// updateTopologicalMappingTopDown): points added and removed (all of them
// with `samePoints`, else those of the subset), and with `handleEdges` /
// `handleTriangles` the edges and triangles of the subset: removed ones leave
// the output, added ones join it when all their vertices and ancestors are in
// it. Quads, tetrahedra and hexahedra are paired at init only; their events
// are reported as unsupported, as SOFA does.
#pragma once

#include <vector>

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class SubsetTopologicalMapping final : public TopologicalMapping {
 public:
  static constexpr unsigned kNone = ~0u;  // SOFA's InvalidID: no partner

  Field<bool> same_points{this, "samePoints", false, "True if the same set of points is used in both topologies",
                          "Mapping"};
  Field<bool> handle_edges{this, "handleEdges", false, "True if edges events and mapping should be handled",
                           "Mapping"};
  Field<bool> handle_triangles{this, "handleTriangles", false,
                               "True if triangles events and mapping should be handled", "Mapping"};
  Field<bool> handle_quads{this, "handleQuads", false, "True if quads events and mapping should be handled",
                           "Mapping"};
  Field<bool> handle_tetrahedra{this, "handleTetrahedra", false,
                                "True if tetrahedra events and mapping should be handled", "Mapping"};
  Field<bool> handle_hexahedra{this, "handleHexahedra", false,
                               "True if hexahedra events and mapping should be handled", "Mapping"};
  // Input (source) → output (destination) and back, per element kind; kNone where unpaired.
  Field<std::vector<unsigned>> point_s2d{this, "pointS2D", {}, "source -> destination points", "Outputs"};
  Field<std::vector<unsigned>> point_d2s{this, "pointD2S", {}, "destination -> source points", "Outputs"};
  Field<std::vector<unsigned>> edge_s2d{this, "edgeS2D", {}, "source -> destination edges", "Outputs"};
  Field<std::vector<unsigned>> edge_d2s{this, "edgeD2S", {}, "destination -> source edges", "Outputs"};
  Field<std::vector<unsigned>> triangle_s2d{this, "triangleS2D", {}, "source -> destination triangles", "Outputs"};
  Field<std::vector<unsigned>> triangle_d2s{this, "triangleD2S", {}, "destination -> source triangles", "Outputs"};
  Field<std::vector<unsigned>> quad_s2d{this, "quadS2D", {}, "source -> destination quads", "Outputs"};
  Field<std::vector<unsigned>> quad_d2s{this, "quadD2S", {}, "destination -> source quads", "Outputs"};
  Field<std::vector<unsigned>> tetrahedron_s2d{this, "tetrahedronS2D", {}, "source -> destination tetrahedra",
                                               "Outputs"};
  Field<std::vector<unsigned>> tetrahedron_d2s{this, "tetrahedronD2S", {}, "destination -> source tetrahedra",
                                               "Outputs"};
  Field<std::vector<unsigned>> hexahedron_s2d{this, "hexahedronS2D", {}, "source -> destination hexahedra",
                                              "Outputs"};
  Field<std::vector<unsigned>> hexahedron_d2s{this, "hexahedronD2S", {}, "destination -> source hexahedra",
                                              "Outputs"};

  void init() override;
  void update_top_down() override;
  // SOFA's getGlobIndex: the input element of output element `out`, through the map of the
  // highest handled kind (hexahedra first); `out` itself when no such map exists.
  bool input_elements(unsigned out, std::vector<unsigned>& in) const override;

 private:
  void on_points_added(const TopologyChange& c);
  void on_points_removed(const TopologyChange& c);
  void on_edges_added(const TopologyChange& c);
  void on_edges_removed(const TopologyChange& c);
  void on_triangles_added(const TopologyChange& c);
  void on_triangles_removed(const TopologyChange& c);
};

}  // namespace sinew
