// Legacy VTK writer (ASCII unstructured grid) for ParaView: points, cells of
// a mesh topology, and optional per-point vectors (e.g. velocities).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew::io {

struct VtkMesh {
  std::vector<Vec3> points;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Quad> quads;
  std::vector<Tetra> tetrahedra;
  std::vector<Hexa> hexahedra;
  std::vector<std::pair<std::string, std::vector<Vec3>>> point_vectors;  // name → one vector per point
};

// Writes `mesh` to `path`; false (with *error) when the file cannot be written.
bool write_vtk(const std::string& path, const VtkMesh& mesh, const std::string& title, std::string* error);

}  // namespace sinew::io
