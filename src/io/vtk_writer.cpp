#include "io/vtk_writer.h"

#include <cstdio>
#include <memory>

namespace sinew::io {
namespace {

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

File open_for_writing(const std::string& path, std::string* error) {
  File f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f && error) *error = "cannot open " + path + " for writing";
  return f;
}

bool finish(File& f, const std::string& path, std::string* error) {
  const bool bad = std::ferror(f.get()) != 0;
  FILE* raw = f.release();
  // fclose flushes: a full disk shows up here, not in the writes before.
  if (std::fclose(raw) != 0 || bad) {
    if (error) *error = "write error on " + path;
    return false;
  }
  return true;
}

// Calls f(list, vtk type) for each kind of cell, in the order every writer uses.
template <class F>
void for_each_cell_kind(const VtkMesh& m, F&& f) {
  f(m.edges, 3);        // VTK_LINE
  f(m.triangles, 5);    // VTK_TRIANGLE
  f(m.quads, 9);        // VTK_QUAD
  f(m.tetrahedra, 10);  // VTK_TETRA
  f(m.hexahedra, 12);   // VTK_HEXAHEDRON
}

void write_values(FILE* out, const VtkArray& a, std::size_t rows, const char* indent) {
  const std::size_t c = static_cast<std::size_t>(a.components);
  for (std::size_t i = 0; i < rows; ++i) {
    std::fputs(indent, out);
    for (std::size_t k = 0; k < c; ++k) {
      const std::size_t j = i * c + k;
      const double v = j < a.values.size() ? a.values[j] : 0.0;
      if (a.integer)
        std::fprintf(out, k ? " %lld" : "%lld", static_cast<long long>(v));
      else
        std::fprintf(out, k ? " %.17g" : "%.17g", v);
    }
    std::fputc('\n', out);
  }
}

std::vector<VtkArray> all_point_arrays(const VtkMesh& m) {
  std::vector<VtkArray> arrays;
  for (const auto& [name, vs] : m.point_vectors) {
    VtkArray a{name, 3, {}, false};
    a.values.reserve(vs.size() * 3);
    for (const Vec3& v : vs) a.values.insert(a.values.end(), {v.x(), v.y(), v.z()});
    arrays.push_back(std::move(a));
  }
  arrays.insert(arrays.end(), m.point_data.begin(), m.point_data.end());
  return arrays;
}

// Legacy attribute block: 3 components are VECTORS, anything else SCALARS with that many
// components (VTK accepts 1 to 4), as SOFA's VTKExporter does for its vectors and scalars.
void write_legacy_arrays(FILE* out, const std::vector<VtkArray>& arrays, std::size_t rows) {
  for (const VtkArray& a : arrays) {
    const char* type = a.integer ? "int" : "double";
    if (a.components == 3 && !a.integer) {
      std::fprintf(out, "VECTORS %s %s\n", a.name.c_str(), type);
    } else {
      std::fprintf(out, "SCALARS %s %s %d\nLOOKUP_TABLE default\n", a.name.c_str(), type, a.components);
    }
    write_values(out, a, rows, "");
  }
}

void write_xml_arrays(FILE* out, const std::vector<VtkArray>& arrays, std::size_t rows) {
  for (const VtkArray& a : arrays) {
    std::fprintf(out, "        <DataArray type=\"%s\" Name=\"%s\"", a.integer ? "Int32" : "Float64", a.name.c_str());
    if (a.components > 1) std::fprintf(out, " NumberOfComponents=\"%d\"", a.components);
    std::fprintf(out, " format=\"ascii\">\n");
    write_values(out, a, rows, "          ");
    std::fprintf(out, "        </DataArray>\n");
  }
}

}  // namespace

bool write_vtk(const std::string& path, const VtkMesh& m, const std::string& title, std::string* error) {
  File f = open_for_writing(path, error);
  if (!f) return false;
  FILE* out = f.get();
  std::fprintf(out, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET UNSTRUCTURED_GRID\n", title.c_str());
  std::fprintf(out, "POINTS %zu double\n", m.points.size());
  for (const Vec3& p : m.points) std::fprintf(out, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  const std::size_t n_cells = m.cell_count();
  const std::size_t n_ints = m.edges.size() * 3 + m.triangles.size() * 4 + m.quads.size() * 5 +
                             m.tetrahedra.size() * 5 + m.hexahedra.size() * 9;
  std::fprintf(out, "CELLS %zu %zu\n", n_cells, n_ints);
  for_each_cell_kind(m, [&](const auto& list, int) {
    for (const auto& c : list) {
      std::fprintf(out, "%zu", c.size());
      for (unsigned i : c) std::fprintf(out, " %u", i);
      std::fprintf(out, "\n");
    }
  });
  std::fprintf(out, "CELL_TYPES %zu\n", n_cells);
  for_each_cell_kind(m, [&](const auto& list, int type) {
    for (std::size_t i = 0; i < list.size(); ++i) std::fprintf(out, "%d\n", type);
  });
  const std::vector<VtkArray> point_arrays = all_point_arrays(m);
  if (!point_arrays.empty()) {
    std::fprintf(out, "POINT_DATA %zu\n", m.points.size());
    write_legacy_arrays(out, point_arrays, m.points.size());
  }
  if (!m.cell_data.empty()) {
    std::fprintf(out, "CELL_DATA %zu\n", n_cells);
    write_legacy_arrays(out, m.cell_data, n_cells);
  }
  return finish(f, path, error);
}

bool write_vtu(const std::string& path, const VtkMesh& m, std::string* error) {
  File f = open_for_writing(path, error);
  if (!f) return false;
  FILE* out = f.get();
  const std::size_t n_cells = m.cell_count();
  std::fprintf(out, "<?xml version=\"1.0\"?>\n");
  std::fprintf(out, "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
  std::fprintf(out, "  <UnstructuredGrid>\n");
  std::fprintf(out, "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n", m.points.size(), n_cells);
  const std::vector<VtkArray> point_arrays = all_point_arrays(m);
  if (!point_arrays.empty()) {
    std::fprintf(out, "      <PointData>\n");
    write_xml_arrays(out, point_arrays, m.points.size());
    std::fprintf(out, "      </PointData>\n");
  }
  if (!m.cell_data.empty()) {
    std::fprintf(out, "      <CellData>\n");
    write_xml_arrays(out, m.cell_data, n_cells);
    std::fprintf(out, "      </CellData>\n");
  }
  std::fprintf(out, "      <Points>\n");
  std::fprintf(out, "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const Vec3& p : m.points) std::fprintf(out, "          %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  std::fprintf(out, "        </DataArray>\n");
  std::fprintf(out, "      </Points>\n");
  std::fprintf(out, "      <Cells>\n");
  std::fprintf(out, "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
  for_each_cell_kind(m, [&](const auto& list, int) {
    for (const auto& c : list) {
      std::fputs("          ", out);
      for (std::size_t i = 0; i < c.size(); ++i) std::fprintf(out, i ? " %u" : "%u", c[i]);
      std::fputc('\n', out);
    }
  });
  std::fprintf(out, "        </DataArray>\n");
  // Offsets: the end of each cell in the connectivity list.
  std::fprintf(out, "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n");
  std::size_t end = 0;
  for_each_cell_kind(m, [&](const auto& list, int) {
    for (const auto& c : list) {
      end += c.size();
      std::fprintf(out, "          %zu\n", end);
    }
  });
  std::fprintf(out, "        </DataArray>\n");
  std::fprintf(out, "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for_each_cell_kind(m, [&](const auto& list, int type) {
    for (std::size_t i = 0; i < list.size(); ++i) std::fprintf(out, "          %d\n", type);
  });
  std::fprintf(out, "        </DataArray>\n");
  std::fprintf(out, "      </Cells>\n");
  std::fprintf(out, "    </Piece>\n");
  std::fprintf(out, "  </UnstructuredGrid>\n");
  std::fprintf(out, "</VTKFile>\n");
  return finish(f, path, error);
}

bool write_pvd(const std::string& path, const std::vector<PvdEntry>& entries, std::string* error) {
  File f = open_for_writing(path, error);
  if (!f) return false;
  FILE* out = f.get();
  std::fprintf(out, "<?xml version=\"1.0\"?>\n");
  std::fprintf(out, "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
  std::fprintf(out, "  <Collection>\n");
  for (const PvdEntry& e : entries)
    std::fprintf(out, "    <DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s\"/>\n", e.time, e.file.c_str());
  std::fprintf(out, "  </Collection>\n");
  std::fprintf(out, "</VTKFile>\n");
  return finish(f, path, error);
}

}  // namespace sinew::io
