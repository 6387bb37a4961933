// Mesh2PointTopologicalMapping: creates output points at given barycentric
// positions in each input point, edge, triangle, quad, tetrahedron and
// hexahedron, in that order (spec/mechanics.md §5.7); optionally copies
// edges, triangles and tetrahedra onto the points made from input points.
#pragma once

#include "topology/topological_mapping.h"

namespace sinew {

class Mesh2PointTopologicalMapping final : public TopologicalMapping {
 public:
  Field<std::vector<Vec3>> point_bary_coords{
      this, "pointBaryCoords", {},
      "Coordinates for the points of the output topology created from the points of the input topology", "BaryCoords"};
  Field<std::vector<Vec3>> edge_bary_coords{
      this, "edgeBaryCoords", {},
      "Coordinates for the points of the output topology created from the edges of the input topology", "BaryCoords"};
  Field<std::vector<Vec3>> triangle_bary_coords{
      this, "triangleBaryCoords", {},
      "Coordinates for the points of the output topology created from the triangles of the input topology",
      "BaryCoords"};
  Field<std::vector<Vec3>> quad_bary_coords{
      this, "quadBaryCoords", {},
      "Coordinates for the points of the output topology created from the quads of the input topology", "BaryCoords"};
  Field<std::vector<Vec3>> tetra_bary_coords{
      this, "tetraBaryCoords", {},
      "Coordinates for the points of the output topology created from the tetra of the input topology", "BaryCoords"};
  Field<std::vector<Vec3>> hexa_bary_coords{
      this, "hexaBaryCoords", {},
      "Coordinates for the points of the output topology created from the hexa of the input topology", "BaryCoords"};
  Field<bool> copy_edges{this, "copyEdges", false,
                         "Activate mapping of input edges into the output topology (requires at least one item in "
                         "pointBaryCoords)",
                         "Mapping"};
  Field<bool> copy_triangles{this, "copyTriangles", false,
                             "Activate mapping of input triangles into the output topology (requires at least one "
                             "item in pointBaryCoords)",
                             "Mapping"};
  Field<bool> copy_tetrahedra{this, "copyTetrahedra", false,
                              "Activate mapping of input tetrahedra into the output topology (requires at least one "
                              "item in pointBaryCoords)",
                              "Mapping"};

  void init() override;

  // For each output point: the kind (0 point, 1 edge, 2 triangle, 3 quad, 4 tetra, 5 hexa) and index
  // of the input element it was made from.
  const std::vector<std::pair<int, unsigned>>& point_source() const { return point_source_; }

 private:
  std::vector<std::pair<int, unsigned>> point_source_;
};

}  // namespace sinew
