// MeshBoundaryROI: the vertices on the boundary of a triangle/quad mesh
// (SOFA's Engine/Select): the ends of the edges that belong to exactly one
// element, among the elements whose vertices are all in inputROI (all
// elements when it is empty). Output sorted increasingly, each index once.
// Without triangles and quads given, they are taken from the node's
// topology, as SOFA does.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class MeshBoundaryROI final : public Engine {
 public:
  MeshBoundaryROI();

  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the mesh", "Inputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the mesh", "Inputs"};
  Field<std::vector<unsigned>> input_roi{this, "inputROI", {}, "optional subset of the mesh's points", "Inputs"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the boundary points", "Outputs"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
