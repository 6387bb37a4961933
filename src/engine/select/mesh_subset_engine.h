// MeshSubsetEngine: the sub-mesh spanned by a list of vertices (SOFA's
// Engine/Select). Output vertex i is input vertex indices[i]; an element is
// kept (renumbered) when all its vertices are in the list. A vertex listed
// twice maps to its last position in the list, as SOFA's map does.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class MeshSubsetEngine final : public Engine {
 public:
  MeshSubsetEngine();

  Field<std::vector<Vec3>> input_position{this, "inputPosition", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Edge>> input_edges{this, "inputEdges", {}, "edges of the mesh", "Inputs"};
  Field<std::vector<Triangle>> input_triangles{this, "inputTriangles", {}, "triangles of the mesh", "Inputs"};
  Field<std::vector<Quad>> input_quads{this, "inputQuads", {}, "quads of the mesh", "Inputs"};
  Field<std::vector<Tetra>> input_tetrahedra{this, "inputTetrahedra", {}, "tetrahedra of the mesh", "Inputs"};
  Field<std::vector<Hexa>> input_hexahedra{this, "inputHexahedra", {}, "hexahedra of the mesh", "Inputs"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "vertices kept", "Inputs"};
  Field<std::vector<Vec3>> position{this, "position", {}, "vertices of the subset", "Outputs", "length"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "edges of the subset", "Outputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the subset", "Outputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the subset", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedra of the subset", "Outputs"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedra of the subset", "Outputs"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
