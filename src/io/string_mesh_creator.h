// StringMeshCreator: a 1-D mesh of `resolution` points on [0,1] along x,
// joined by edges (spec/mechanics.md §7.6). MeshLoader transforms apply.
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class StringMeshCreator final : public MeshLoader {
 public:
  StringMeshCreator();
  Field<unsigned> resolution{this, "resolution", 2u, "number of vertices", "Loader"};

 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
  bool needs_file() const override { return false; }
};

}  // namespace sinew
