#include "io/string_mesh_creator.h"

#include "core/registry.h"

namespace sinew {

StringMeshCreator::StringMeshCreator() { add_input(&resolution); }

bool StringMeshCreator::read_mesh(io::MeshData& out, std::string* error) {
  const unsigned n = resolution.get();
  if (n < 2) {
    if (error) *error = "resolution must be at least 2 (got " + std::to_string(n) + ")";
    return false;
  }
  out = io::MeshData{};
  // SOFA evaluates x * 1. / (n-1) left to right: a division, not a product with the reciprocal.
  for (unsigned x = 0; x < n; ++x) out.positions.emplace_back(x * 1. / (n - 1), 0, 0);
  for (unsigned e = 1; e < n; ++e) out.edges.push_back({e - 1, e});
  return true;
}

void register_string_mesh_creator(Registry& r) {
  ComponentInfo info;
  info.name = "StringMeshCreator";
  info.category = "Loader";
  info.description = "creates a 1-D mesh (points on [0,1] along x joined by edges)";
  info.create = creator<StringMeshCreator>();
  r.add(std::move(info));
}

}  // namespace sinew
