// MeshOffLoader: Object File Format meshes (.off): triangles and quads.
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshOffLoader final : public MeshLoader {
 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
};

}  // namespace sinew
