// MeshVTKLoader: VTK legacy (.vtk, ASCII/BINARY) and XML (.vtu/.vtp) meshes
// (spec/mechanics.md §7.4). Point and cell data arrays are kept in mesh().
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshVTKLoader final : public MeshLoader {
 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
};

}  // namespace sinew
