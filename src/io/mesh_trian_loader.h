// MeshTrianLoader: .trian triangulations (SOFA's IO/Mesh). Format: the number
// of vertices, their x y z, the number of triangles, then per triangle its
// three vertices and the three neighbouring triangles (−1 on the border;
// neighbour j lies across the edge opposite vertex j). With trian2, the
// "trian2" layout: 13 header lines, then "<tag> n" blocks of vertices,
// normals and triangles (no neighbours).
// Extra outputs: neighborTable (3 per triangle), edgesOnBorder (in file
// order, each triangle's border edges for j = 0, 1, 2 as SOFA lists them),
// trianglesOnBorderList.
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshTrianLoader final : public MeshLoader {
 public:
  Field<bool> trian2{this, "trian2", false, "the file is in the trian2 layout", "Loader"};
  Field<std::vector<int>> neighbor_table{this, "neighborTable", {}, "the 3 neighbouring triangles of each triangle",
                                         "Vectors"};
  Field<std::vector<Edge>> edges_on_border{this, "edgesOnBorder", {}, "edges on the border of the mesh", "Vectors"};
  Field<std::vector<unsigned>> triangles_on_border{this, "trianglesOnBorderList", {},
                                                   "triangles with an edge on the border", "Vectors"};

  MeshTrianLoader();

 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
  void publish_extra(const io::MeshData&) override;

 private:
  std::vector<int> neighbors_;
  std::vector<Edge> border_edges_;
  std::vector<unsigned> border_triangles_;
};

}  // namespace sinew
