// Mesh2PointTopologicalMapping: creates output points at given barycentric
// positions in each input point, edge, triangle, quad, tetrahedron and
// hexahedron, in that order (spec/mechanics.md §5.7); optionally copies
// edges, triangles and tetrahedra onto the points made from input points.
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Mesh2PointTopologicalMapping final : public TopologicalMapping {
 public:
  Field<std::vector<Vec3>> point_bary_coords{
      this, "pointBaryCoords", {}, "barycentric offsets of output points created at each input point", "BaryCoords"};
  Field<std::vector<Vec3>> edge_bary_coords{
      this, "edgeBaryCoords", {}, "barycentric coordinates of output points created on each input edge", "BaryCoords"};
  Field<std::vector<Vec3>> triangle_bary_coords{
      this,
      "triangleBaryCoords",
      {},
      "barycentric coordinates of output points created in each input triangle",
      "BaryCoords"};
  Field<std::vector<Vec3>> quad_bary_coords{
      this, "quadBaryCoords", {}, "barycentric coordinates of output points created in each input quad", "BaryCoords"};
  Field<std::vector<Vec3>> tetra_bary_coords{
      this,
      "tetraBaryCoords",
      {},
      "barycentric coordinates of output points created in each input tetrahedron",
      "BaryCoords"};
  Field<std::vector<Vec3>> hexa_bary_coords{this,
                                            "hexaBaryCoords",
                                            {},
                                            "barycentric coordinates of output points created in each input hexahedron",
                                            "BaryCoords"};
  Field<bool> copy_edges{this, "copyEdges", false, "copy the input edges to the output (needs pointBaryCoords)",
                         "Mapping"};
  Field<bool> copy_triangles{this, "copyTriangles", false,
                             "copy the input triangles to the output (needs pointBaryCoords)", "Mapping"};
  Field<bool> copy_tetrahedra{this, "copyTetrahedra", false,
                              "copy the input tetrahedra to the output (needs pointBaryCoords)", "Mapping"};

  void init() override;

  // For each output point: the kind (0 point, 1 edge, 2 triangle, 3 quad, 4 tetra, 5 hexa) and index
  // of the input element it was made from.
  const std::vector<std::pair<int, unsigned>>& point_source() const { return point_source_; }

 private:
  std::vector<std::pair<int, unsigned>> point_source_;
};

}  // namespace sinew
