#include "io/mesh_vtk_loader.h"

#include "core/registry.h"

namespace sinew {

bool MeshVTKLoader::read_mesh(io::MeshData& out, std::string* error) {
  auto m = io::read_vtk(filename.get(), error, read_options());
  if (!m) return false;
  out = std::move(*m);
  return true;
}

void register_mesh_vtk_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshVTKLoader";
  info.category = "Loader";
  info.description = "loads VTK meshes: legacy .vtk (ASCII or binary) and XML .vtu/.vtp";
  info.create = creator<MeshVTKLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
