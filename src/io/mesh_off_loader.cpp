#include "io/mesh_off_loader.h"

#include "core/registry.h"

namespace sinew {

bool MeshOffLoader::read_mesh(io::MeshData& out, std::string* error) {
  auto m = io::read_off(filename.get(), error, read_options());
  if (!m) return false;
  out = std::move(*m);
  return true;
}

void register_mesh_off_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshOffLoader";
  info.category = "Loader";
  info.description = "loads OFF meshes (triangles and quads)";
  info.create = creator<MeshOffLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
