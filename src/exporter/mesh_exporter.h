// MeshExporter (SOFA's Sofa.Component.IO.Mesh; spec/user-interfaces.md §4.3): the node's
// topology and points in one or all of SOFA's mesh formats.
//
// format: vtkxml (.vtu), vtk (.vtk legacy), netgen (.mesh), tetgen (.node, .ele, .face),
// gmsh (.gmsh, MSH 2.1 text), obj (.obj), or ALL of them. The filename may hold SOFA's
// patterns %n (step counter), %p (points), %E (cells written), %e (elements of the highest
// kind written); with exportEveryNumberOfSteps, the export index is appended on 5 digits.
// Element flags edges/triangles/quads/tetras/hexas are all on by default.
#pragma once

#include "core/roles.h"
#include "exporter/export_mesh.h"
#include "exporter/simulation_exporter.h"

namespace sinew {

class MeshExporter final : public SimulationExporter {
 public:
  MeshExporter();

  Field<std::string> format{this, "format", "ALL", "ALL, vtkxml, vtk, netgen, tetgen, gmsh or obj", "Export"};
  Field<FlatVec> position;
  Field<bool> edges{this, "edges", true, "write the edges", "Export"};
  Field<bool> triangles{this, "triangles", true, "write the triangles", "Export"};
  Field<bool> quads{this, "quads", true, "write the quads", "Export"};
  Field<bool> tetras{this, "tetras", true, "write the tetrahedra", "Export"};
  Field<bool> hexas{this, "hexas", true, "write the hexahedra", "Export"};

  bool write() override;
  // The file name of the next export with extension `ext` (SOFA's getMeshFilename).
  std::string mesh_filename(const io::VtkMesh& mesh, const char* ext);

 private:
  void do_init() override;
  bool write_netgen(const io::VtkMesh& mesh, const std::vector<Triangle>& faces);
  bool write_tetgen(const io::VtkMesh& mesh, const std::vector<Triangle>& faces);
  bool write_gmsh(const io::VtkMesh& mesh);
  bool write_obj(const io::VtkMesh& mesh);

  MeshTopologyBase* topology_ = nullptr;
  MechanicalState* state_ = nullptr;
};

}  // namespace sinew
