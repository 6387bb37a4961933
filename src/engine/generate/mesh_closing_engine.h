// MeshClosingEngine: closes the holes of a surface mesh (SOFA's
// Engine/Generate). Boundary edges are the oriented edges of triangles and
// quads whose reverse is not used; they are chained into loops (starting at
// the smallest vertex, as SOFA's ordered map); each loop of three or more
// vertices gets a vertex at its centroid and a fan of triangles to it.
// Outputs: the closed mesh (input plus centroids and fans), and the closing
// parts alone (closingPosition, closingTriangles) with, per loop, the input
// indices of its vertices followed by its centroid's index (indices).
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"

namespace sinew {

class MeshClosingEngine final : public Engine {
 public:
  MeshClosingEngine();

  Field<std::vector<Vec3>> input_position{this, "inputPosition", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Triangle>> input_triangles{this, "inputTriangles", {}, "triangles of the mesh", "Inputs"};
  Field<std::vector<Quad>> input_quads{this, "inputQuads", {}, "quads of the mesh", "Inputs"};
  Field<std::vector<Vec3>> position{this, "position", {}, "vertices of the closed mesh", "Outputs", "length"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the closed mesh", "Outputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the closed mesh (the input's)", "Outputs"};
  io::ValueField<std::vector<std::vector<unsigned>>> indices{this, "indices", "vertices of each closing part",
                                                             "Outputs"};
  Field<std::vector<Vec3>> closing_position{this, "closingPosition", {}, "vertices of the closing parts", "Outputs",
                                            "length"};
  Field<std::vector<Triangle>> closing_triangles{this, "closingTriangles", {}, "triangles of the closing parts",
                                                 "Outputs"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
