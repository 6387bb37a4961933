#include "io/mesh_gmsh_loader.h"

#include "core/registry.h"

namespace sinew {

bool MeshGmshLoader::read_mesh(io::MeshData& out, std::string* error) {
  // SOFA copies the reader's lists directly: flipNormals/triangulate do not apply while reading.
  auto m = io::read_gmsh(filename.get(), error);
  if (!m) return false;
  out = std::move(*m);
  return true;
}

void register_mesh_gmsh_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshGmshLoader";
  info.category = "Loader";
  info.description = "loads Gmsh ASCII meshes (v1, v2, v4); creates triangles and edges of volume elements";
  info.create = creator<MeshGmshLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
