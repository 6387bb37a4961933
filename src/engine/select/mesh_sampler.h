// MeshSampler: picks `number` well-spread vertices of a mesh (SOFA's
// Engine/Select): farthest point sampling from vertex 0, then Lloyd
// relaxation (each sample moves to the vertex nearest its Voronoi region's
// centroid) for at most maxIter iterations. Distances are geodesic along
// `edges` (Dijkstra) when edges are given, else squared Euclidean distances,
// as SOFA computes them.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class MeshSampler final : public Engine {
 public:
  MeshSampler();

  Field<unsigned> number{this, "number", 1, "number of samples", "Inputs"};
  Field<std::vector<Vec3>> position{this, "position", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "edges for geodesic distances (else Euclidean)", "Inputs"};
  Field<unsigned> max_iter{this, "maxIter", 100, "largest number of Lloyd iterations", "Inputs"};
  Field<std::vector<unsigned>> output_indices{this, "outputIndices", {}, "indices of the samples", "Outputs"};
  Field<std::vector<Vec3>> output_position{this, "outputPosition", {}, "positions of the samples", "Outputs",
                                           "length"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
