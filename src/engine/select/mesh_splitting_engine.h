// MeshSplittingEngine: splits a mesh's vertices into nbInputs + 1 parts
// (SOFA's Engine/Select). Part k (1-based fields indicesK, edgeIndicesK, ...,
// hexahedronIndicesK) takes the listed vertices and the vertices of the
// listed elements; the first part listing a vertex wins; part nbInputs + 1
// keeps the rest. Outputs: positionK for each part, and indexPairs (part,
// index in the part) per input vertex, SubsetMultiMapping's format.
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "engine/numbered_fields.h"

namespace sinew {

class MeshSplittingEngine final : public Engine {
 public:
  MeshSplittingEngine();

  Field<std::vector<Vec3>> input_position{this, "position", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Edge>> input_edges{this, "edges", {}, "edges of the mesh", "Inputs"};
  Field<std::vector<Triangle>> input_triangles{this, "triangles", {}, "triangles of the mesh", "Inputs"};
  Field<std::vector<Quad>> input_quads{this, "quads", {}, "quads of the mesh", "Inputs"};
  Field<std::vector<Tetra>> input_tetrahedra{this, "tetrahedra", {}, "tetrahedra of the mesh", "Inputs"};
  Field<std::vector<Hexa>> input_hexahedra{this, "hexahedra", {}, "hexahedra of the mesh", "Inputs"};
  Field<unsigned> nb_inputs{this, "nbInputs", 0, "number of selections (parts: nbInputs + 1)", "Inputs"};
  NumberedFields<std::vector<unsigned>> indices{"indices", "vertices of part "};
  NumberedFields<std::vector<unsigned>> edge_indices{"edgeIndices", "edges of part "};
  NumberedFields<std::vector<unsigned>> triangle_indices{"triangleIndices", "triangles of part "};
  NumberedFields<std::vector<unsigned>> quad_indices{"quadIndices", "quads of part "};
  NumberedFields<std::vector<unsigned>> tetrahedron_indices{"tetrahedronIndices", "tetrahedra of part "};
  NumberedFields<std::vector<unsigned>> hexahedron_indices{"hexahedronIndices", "hexahedra of part "};
  Field<std::vector<unsigned>> index_pairs{this, "indexPairs", {}, "part and index in the part of each vertex",
                                           "Outputs"};
  NumberedFields<std::vector<Vec3>> position{"position", "vertices of part "};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  void grow(unsigned n);
};

}  // namespace sinew
