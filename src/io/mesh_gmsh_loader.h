// MeshGmshLoader: Gmsh ASCII meshes v1, v2 and v4 (spec/mechanics.md §7.3).
// createSubelements is on unless the attribute is given (trap 2).
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshGmshLoader final : public MeshLoader {
 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
  bool default_create_subelements() const override { return true; }
};

}  // namespace sinew
