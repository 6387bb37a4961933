// MeshSTLLoader: STL surfaces, ASCII or binary (auto-detected), duplicate
// vertices merged by exact equality in order of first appearance.
#pragma once

#include "io/mesh_loader.h"

namespace sinew {

class MeshSTLLoader final : public MeshLoader {
 public:
  MeshSTLLoader();
  Field<unsigned> header_size{this, "headerSize", 80u, "size of the binary header (before the facet count)", "Loader"};
  Field<bool> force_binary{this, "forceBinary", false, "read as binary even if the file starts with 'solid'",
                           "Loader"};
  Field<bool> merge_position_using_map{this, "mergePositionUsingMap", true,
                                       "merge duplicated positions with a map (same result either way)", "Loader"};

 protected:
  bool read_mesh(io::MeshData& out, std::string* error) override;
};

}  // namespace sinew
