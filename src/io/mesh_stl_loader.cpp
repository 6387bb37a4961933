#include "io/mesh_stl_loader.h"

#include "core/registry.h"

namespace sinew {

MeshSTLLoader::MeshSTLLoader() {
  add_input(&header_size);
  add_input(&force_binary);
}

bool MeshSTLLoader::read_mesh(io::MeshData& out, std::string* error) {
  io::ReadOptions o = read_options();
  o.force_binary = force_binary.get();
  o.header_size = header_size.get();
  if (o.header_size > 256) {
    if (error) *error = "headerSize " + std::to_string(o.header_size) + " is larger than 256";
    return false;
  }
  auto m = io::read_stl(filename.get(), error, o);
  if (!m) return false;
  out = std::move(*m);
  return true;
}

void register_mesh_stl_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshSTLLoader";
  info.category = "Loader";
  info.description = "loads STL surfaces (ASCII or binary), merging duplicated vertices";
  info.create = creator<MeshSTLLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
