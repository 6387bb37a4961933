// MeshBarycentricMapperEngine: the element of a mesh holding each mapped point
// and the point's barycentric coordinates in it (SOFA's Engine/Generate).
// Volumes (tetrahedra, then hexahedra) win over surfaces (triangles, then
// quads); edges are the last resort. Each element's local frame is its edge
// vectors from vertex 0 (for surfaces the third axis is their cross product);
// a point inside an element (all coordinates within bounds, surfaces with a
// 0.01 tolerance off-plane) has distance ≤ 0, otherwise the squared distance
// to the element's centre; the element of smallest distance wins (the first
// on ties). As in SOFA, points falling in hexahedra, quads or edges are
// reported as not implemented, and the linear interpolation's first weight is
// 1 − (b0 − b1 − b2) (SOFA's formula). linearInterpolationValues is
// flattened (3 or 4 weights per point, in the order of the indices).
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"

namespace sinew {

class MeshBarycentricMapperEngine final : public Engine {
 public:
  MeshBarycentricMapperEngine();

  Field<std::vector<Vec3>> input_positions{this, "inputPositions", {}, "points of the mesh (master)", "Inputs",
                                           "length"};
  Field<std::vector<Vec3>> mapped_positions{this, "mappedPointPositions", {}, "points to map", "Inputs", "length"};
  Field<std::vector<Vec3>> barycentric_positions{this, "barycentricPositions", {},
                                                 "barycentric coordinates of each mapped point", "Outputs"};
  Field<std::vector<unsigned>> table_elements{this, "tableElements", {}, "element holding each mapped point",
                                              "Outputs"};
  Field<bool> compute_linear_interpolation{this, "computeLinearInterpolation", false,
                                           "also output interpolation indices and weights (debug)", "Inputs"};
  io::ValueField<std::vector<std::vector<unsigned>>> interpolation_indices{
      this, "linearInterpolationIndices", "vertices interpolating each mapped point", "Outputs"};
  Field<std::vector<double>> interpolation_values{this, "linearInterpolationValues", {},
                                                  "their weights, point after point", "Outputs"};
  Link<MeshTopologyBase> topology{this, "topology", "mesh the points are mapped into (default: the node's)"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
