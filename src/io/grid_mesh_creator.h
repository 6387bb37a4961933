// GridMeshCreator: a 2-D grid of resolution[0]×resolution[1] points on
// [0,1]² (z = 0) with quads or one of three triangle patterns; edges are the
// unique element sides in sorted order (SOFA's GridMeshCreator).
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class GridMeshCreator final : public MeshLoader {
 public:
  GridMeshCreator();
  Field<VecNi<2>> resolution{this, "resolution", VecNi<2>(2, 2), "number of vertices in each direction", "Loader"};
  Field<int> triangle_pattern{this, "trianglePattern", 2,
                              "0: quads, 1: alternate triangles, 2: upward triangles, 3: downward triangles",
                              "Loader"};

 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
  bool needs_file() const override { return false; }
};

}  // namespace sinew
