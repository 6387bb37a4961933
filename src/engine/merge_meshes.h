// MergeMeshes (SOFA's Engine/Generate): appends `nbMeshes` meshes. Points are
// concatenated; each mesh's element indices are shifted by the number of
// points of the meshes before it.
#pragma once

#include "core/engine.h"
#include "core/roles.h"
#include "engine/numbered_fields.h"

namespace sinew {

class MergeMeshes final : public Engine {
 public:
  explicit MergeMeshes(StateType type);

  Field<unsigned> nb_meshes{this, "nbMeshes", 2, "number of meshes to merge", "Inputs"};
  NumberedFields<FlatVec> positions;
  NumberedFields<std::vector<Edge>> edges{"edges", "input edges of mesh "};
  NumberedFields<std::vector<Triangle>> triangles{"triangles", "input triangles of mesh "};
  NumberedFields<std::vector<Quad>> quads{"quads", "input quads of mesh "};
  NumberedFields<std::vector<Tetra>> tetrahedra{"tetrahedra", "input tetrahedra of mesh "};
  NumberedFields<std::vector<Hexa>> hexahedra{"hexahedra", "input hexahedra of mesh "};

  Field<unsigned> npoints{this, "npoints", 0, "number of points of the merged mesh", "Outputs"};
  Field<FlatVec> position;
  Field<std::vector<Edge>> out_edges{this, "edges", {}, "edges of the merged mesh", "Outputs"};
  Field<std::vector<Triangle>> out_triangles{this, "triangles", {}, "triangles of the merged mesh", "Outputs"};
  Field<std::vector<Quad>> out_quads{this, "quads", {}, "quads of the merged mesh", "Outputs"};
  Field<std::vector<Tetra>> out_tetrahedra{this, "tetrahedra", {}, "tetrahedra of the merged mesh", "Outputs"};
  Field<std::vector<Hexa>> out_hexahedra{this, "hexahedra", {}, "hexahedra of the merged mesh", "Outputs"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  void grow(unsigned n);
};

}  // namespace sinew
