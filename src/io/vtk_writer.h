// VTK writers for ParaView: legacy ASCII `.vtk` and XML `.vtu` unstructured grids (points,
// cells of a mesh topology, point and cell data arrays), and the `.pvd` collection that
// makes a numbered series of `.vtu` files one time series. Used by `sinew run --vtk` and
// by the exporters (VTKExporter, MeshExporter; docs/exporters.md).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew::io {

// One data array: `components` scalars per point (or cell), flat.
struct VtkArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
  bool integer = false;  // written as Int32 (XML) / int (legacy), e.g. index lists
};

struct VtkMesh {
  std::vector<Vec3> points;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Quad> quads;
  std::vector<Tetra> tetrahedra;
  std::vector<Hexa> hexahedra;
  std::vector<std::pair<std::string, std::vector<Vec3>>> point_vectors;  // name → one vector per point
  std::vector<VtkArray> point_data;  // further per-point arrays (after point_vectors)
  std::vector<VtkArray> cell_data;   // per-cell arrays, cells in the order written below

  std::size_t cell_count() const {
    return edges.size() + triangles.size() + quads.size() + tetrahedra.size() + hexahedra.size();
  }
};

// Cells are written edges, triangles, quads, tetrahedra then hexahedra (VTK types 3, 5, 9,
// 10, 12), as SOFA's exporters order them. Numbers are written with 17 significant digits
// so that a file read back gives the same doubles.

// Legacy ASCII `.vtk` (DATASET UNSTRUCTURED_GRID). `title` is the second line.
// False (with *error) when the file cannot be written.
bool write_vtk(const std::string& path, const VtkMesh& mesh, const std::string& title, std::string* error);

// XML `.vtu` (VTKFile type UnstructuredGrid, ascii arrays, Float64 points, Int32 cells).
bool write_vtu(const std::string& path, const VtkMesh& mesh, std::string* error);

// A `.pvd` collection: one DataSet per (time, file) entry; files are written as given
// (relative to the .pvd's folder for ParaView).
struct PvdEntry {
  double time = 0;
  std::string file;
};
bool write_pvd(const std::string& path, const std::vector<PvdEntry>& entries, std::string* error);

}  // namespace sinew::io
