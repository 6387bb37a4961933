// VTKExporter (SOFA's Sofa.Component.IO.Mesh; spec/user-interfaces.md §4.2): the node's
// topology and points as VTK unstructured grids for ParaView.
//
// XMLformat (default): `<base><k>.vtu` per export (k = 0, 1, ... ; `<base>` is the filename
// without a trailing ".vtu"), or `<base>.vtu` with `overwrite`, as SOFA names them; Sinew
// also keeps `<base>.pvd`, a collection listing every file written with its simulation
// time, so that ParaView opens the series with real times (SOFA writes no .pvd).
// Legacy format: `<base>_<k>.vtk` (`<base>` without ".vtk"/".vtu"), `<base>.vtk` with overwrite.
// Cells: edges (default on), triangles, quads, tetras, hexas (off) in that order.
// pointsDataFields / cellsDataFields: "[Name=][@]object.data" entries written as arrays.
// Key presses: 'E' writes now (SOFA's 'F', the parallel .pvtu index, is not written).
#pragma once

#include <vector>

#include "core/roles.h"
#include "exporter/export_mesh.h"
#include "exporter/simulation_exporter.h"

namespace sinew {

class VTKExporter final : public SimulationExporter {
 public:
  VTKExporter();

  Field<bool> xml_format{this, "XMLformat", true, "write XML .vtu files (false: legacy .vtk)", "Export"};
  Field<FlatVec> position;
  Field<bool> edges{this, "edges", true, "write the edges", "Export"};
  Field<bool> triangles{this, "triangles", false, "write the triangles", "Export"};
  Field<bool> quads{this, "quads", false, "write the quads", "Export"};
  Field<bool> tetras{this, "tetras", false, "write the tetrahedra", "Export"};
  Field<bool> hexas{this, "hexas", false, "write the hexahedra", "Export"};
  Field<std::vector<std::string>> points_data_fields{
      this, "pointsDataFields", {}, "data written on the points: [Name=][@]object.data ...", "Export"};
  Field<std::vector<std::string>> cells_data_fields{
      this, "cellsDataFields", {}, "data written on the cells: [Name=][@]object.data ...", "Export"};
  Field<bool> overwrite{this, "overwrite", false,
                        "write every export to the same file (false: a numbered file per export)", "Export"};
  Link<MeshTopologyBase> topology{this, "topology", "topology to export (default: the node's)"};
  Link<MechanicalState> mstate{this, "mstate", "mechanical state whose positions are written (default: the node's)"};

  bool write() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }  // key presses (E) too
  // Files written so far (SOFA's nbFiles), and the .pvd collection's path.
  int files_written() const { return files_; }
  const std::string& collection_path() const { return pvd_path_; }

 private:
  void do_init() override;
  bool arrays(const std::vector<DataFieldEntry>& entries, std::size_t rows, const char* where,
              std::vector<io::VtkArray>& out);

  std::vector<DataFieldEntry> point_entries_, cell_entries_;
  int files_ = 0;
  std::vector<io::PvdEntry> series_;
  std::string pvd_path_;
};

}  // namespace sinew
