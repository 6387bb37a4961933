#include "io/grid_mesh_creator.h"

#include <set>

#include "core/alloc_check.h"
#include "core/registry.h"

namespace sinew {

GridMeshCreator::GridMeshCreator() {
  // SOFA's creator loads whatever the filename (the example scenes give "nofile").
  filename.set_file(true, false);
  add_input(&resolution);
  add_input(&triangle_pattern);
}

bool GridMeshCreator::read_mesh(io::MeshData& out, std::string* error) {
  const int rx = resolution.get()[0], ry = resolution.get()[1];
  if (rx < 2 || ry < 2) {
    if (error) *error = "resolution must be at least 2 2 (got " + std::to_string(rx) + " " + std::to_string(ry) + ")";
    return false;
  }
  if (!allocation_fits(static_cast<double>(rx) * ry, 256)) {
    if (error)
      *error = "resolution " + std::to_string(rx) + " " + std::to_string(ry) + " would need " +
               format_bytes(256.0 * rx * ry) + ", more than this machine's " +
               format_bytes(static_cast<double>(physical_memory_bytes())) + " of memory";
    return false;
  }
  const unsigned nx = static_cast<unsigned>(rx), ny = static_cast<unsigned>(ry);
  out = io::MeshData{};
  for (unsigned y = 0; y < ny; ++y)
    for (unsigned x = 0; x < nx; ++x) out.positions.emplace_back(x * 1.0 / (nx - 1), y * 1.0 / (ny - 1), 0.0);
  auto vert = [nx](unsigned x, unsigned y) { return x + y * nx; };
  std::set<Edge> unique;
  auto edge = [&](unsigned a, unsigned b) {
    if (!unique.count(Edge{b, a})) unique.insert(Edge{a, b});
  };
  auto tri = [&](unsigned a, unsigned b, unsigned c) {
    out.triangles.push_back({a, b, c});
    edge(a, b);
    edge(b, c);
    edge(c, a);
  };
  const int pattern = triangle_pattern.get();
  for (unsigned y = 0; y + 1 < ny; ++y)
    for (unsigned x = 0; x + 1 < nx; ++x) {
      const unsigned a = vert(x, y), b = vert(x + 1, y), c = vert(x + 1, y + 1), d = vert(x, y + 1);
      if (pattern == 0) {
        out.quads.push_back({a, b, c, d});
        edge(a, b);
        edge(b, c);
        edge(c, d);
        edge(d, a);
      } else if (pattern == 2 || (pattern == 1 && (x + y) % 2 == 0)) {
        tri(a, b, c);
        tri(a, c, d);
      } else if (pattern == 3 || pattern == 1) {
        tri(a, b, d);
        tri(b, c, d);
      }
    }
  out.edges.assign(unique.begin(), unique.end());
  return true;
}

void register_grid_mesh_creator(Registry& r) {
  ComponentInfo info;
  info.name = "GridMeshCreator";
  info.category = "Loader";
  info.description = "creates a 2-D grid mesh on [0,1]² (quads or triangles)";
  info.create = creator<GridMeshCreator>();
  r.add(std::move(info));
}

}  // namespace sinew
