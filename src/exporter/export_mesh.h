// What the mesh exporters share: the points to write (the `position` field, else the
// node's mechanical state, else the topology's own points), the cells selected by the
// element flags, and data arrays named by "[Name=][@]object.data" entries
// (VTKExporter's pointsDataFields / cellsDataFields).
#pragma once

#include <string>
#include <vector>

#include "io/vtk_writer.h"

namespace sinew {

class Component;
class MechanicalState;
class MeshTopologyBase;
template <class T>
class Field;
struct FlatVec;

// `position` when it holds points (given or linked), else the state's positions (the first
// three scalars of each DoF: Rigid3d frames give their centres), else the topology's points.
std::vector<Vec3> export_points(const Field<FlatVec>& position, const MechanicalState* state,
                                const MeshTopologyBase* topology);

struct CellFlags {
  bool edges = false, triangles = false, quads = false, tetras = false, hexas = false;
};
// The topology's cells of the selected kinds, into `mesh` (points untouched).
void select_cells(const MeshTopologyBase& topology, const CellFlags& flags, io::VtkMesh& mesh);

// One "[Name=][@]object.data" entry, split as SOFA's VTKExporter does: the name before '=',
// the object path up to the last '.', the data after it. False when there is no '.'.
struct DataFieldEntry {
  std::string name, object, field;
};
bool parse_data_field_entry(const std::string& text, DataFieldEntry& out);

// The entry's values as an array (components per row from the field's element width:
// 3 for Vec3 lists, 1 for scalar lists). False with *why when the object or its data is
// not found or its value holds no numbers.
bool fetch_data_array(Component& owner, const DataFieldEntry& entry, io::VtkArray& out, std::string* why);

}  // namespace sinew
