#include "io/vtk_writer.h"

#include <cstdio>
#include <memory>

namespace sinew::io {

bool write_vtk(const std::string& path, const VtkMesh& m, const std::string& title, std::string* error) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) {
    if (error) *error = "cannot open " + path + " for writing";
    return false;
  }
  FILE* out = f.get();
  std::fprintf(out, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET UNSTRUCTURED_GRID\n", title.c_str());
  std::fprintf(out, "POINTS %zu double\n", m.points.size());
  for (const Vec3& p : m.points) std::fprintf(out, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  // Volumes if any, else surfaces, else edges: one kind of cell keeps the file simple to read.
  const std::size_t n_cells = m.edges.size() + m.triangles.size() + m.quads.size() + m.tetrahedra.size() +
                              m.hexahedra.size();
  const std::size_t n_ints = m.edges.size() * 3 + m.triangles.size() * 4 + m.quads.size() * 5 +
                             m.tetrahedra.size() * 5 + m.hexahedra.size() * 9;
  std::fprintf(out, "CELLS %zu %zu\n", n_cells, n_ints);
  auto cells = [&](const auto& list) {
    for (const auto& c : list) {
      std::fprintf(out, "%zu", c.size());
      for (unsigned i : c) std::fprintf(out, " %u", i);
      std::fprintf(out, "\n");
    }
  };
  cells(m.edges);
  cells(m.triangles);
  cells(m.quads);
  cells(m.tetrahedra);
  cells(m.hexahedra);
  std::fprintf(out, "CELL_TYPES %zu\n", n_cells);
  auto types = [&](std::size_t n, int type) {
    for (std::size_t i = 0; i < n; ++i) std::fprintf(out, "%d\n", type);
  };
  types(m.edges.size(), 3);        // VTK_LINE
  types(m.triangles.size(), 5);    // VTK_TRIANGLE
  types(m.quads.size(), 9);        // VTK_QUAD
  types(m.tetrahedra.size(), 10);  // VTK_TETRA
  types(m.hexahedra.size(), 12);   // VTK_HEXAHEDRON
  if (!m.point_vectors.empty()) {
    std::fprintf(out, "POINT_DATA %zu\n", m.points.size());
    for (const auto& [name, vs] : m.point_vectors) {
      std::fprintf(out, "VECTORS %s double\n", name.c_str());
      for (std::size_t i = 0; i < m.points.size(); ++i) {
        const Vec3 v = i < vs.size() ? vs[i] : Vec3::Zero();
        std::fprintf(out, "%.17g %.17g %.17g\n", v.x(), v.y(), v.z());
      }
    }
  }
  if (std::ferror(out)) {
    if (error) *error = "write error on " + path;
    return false;
  }
  return true;
}

}  // namespace sinew::io
