#include "exporter/vtk_exporter.h"

#include <filesystem>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {
namespace {

bool ends_with(const std::string& s, const char* tail) {
  const std::string t(tail);
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

std::vector<DataFieldEntry> parse_entries(Component& c, const std::vector<std::string>& list, const char* field) {
  std::vector<DataFieldEntry> out;
  for (const std::string& text : list) {
    DataFieldEntry e;
    if (!parse_data_field_entry(text, e)) {
      c.msg_error(std::string(field) + ": '" + text + "' is not [Name=][@]object.data; it is not written");
      continue;
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace

VTKExporter::VTKExporter()
    : position(this, "position", FlatVec{3, {}},
               "points written (default: the mechanical state's positions, else the topology's points)", "Export",
               "length") {}

void VTKExporter::do_init() {
  if (!mstate && node()) mstate.set(node()->get_mechanical_state());
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology: put one in this node or above, or set the topology link");
    set_state(ComponentState::invalid);
    return;
  }
  point_entries_ = parse_entries(*this, points_data_fields.get(), "pointsDataFields");
  cell_entries_ = parse_entries(*this, cells_data_fields.get(), "cellsDataFields");
  // Names that cannot be found are reported once here; later writes skip them quietly.
  for (const auto* list : {&point_entries_, &cell_entries_}) {
    for (const DataFieldEntry& e : *list) {
      io::VtkArray a;
      std::string why;
      if (!fetch_data_array(*this, e, a, &why))
        msg_error(std::string(list == &point_entries_ ? "pointsDataFields" : "cellsDataFields") + ": " + why +
                  "; it is not written");
    }
  }
  files_ = 0;
  series_.clear();
  set_state(ComponentState::valid);
}

bool VTKExporter::arrays(const std::vector<DataFieldEntry>& entries, std::size_t rows, const char* where,
                         std::vector<io::VtkArray>& out) {
  for (const DataFieldEntry& e : entries) {
    io::VtkArray a;
    if (!fetch_data_array(*this, e, a, nullptr)) continue;
    const std::size_t have = a.values.size() / static_cast<std::size_t>(std::max(a.components, 1));
    if (have != rows) {
      // VTK readers refuse an array of the wrong length: it is left out, with a reason.
      msg_warning(std::string(where) + ": " + e.object + "." + e.field + " has " + std::to_string(have) +
                  " values where " + std::to_string(rows) + " are written; left out of this export");
      continue;
    }
    out.push_back(std::move(a));
  }
  return true;
}

bool VTKExporter::write() {
  if (state() != ComponentState::valid || !topology) return false;
  io::VtkMesh mesh;
  mesh.points = export_points(position, mstate.get(), topology.get());
  select_cells(*topology, {edges.get(), triangles.get(), quads.get(), tetras.get(), hexas.get()}, mesh);
  arrays(point_entries_, mesh.points.size(), "pointsDataFields", mesh.point_data);
  arrays(cell_entries_, mesh.cell_count(), "cellsDataFields", mesh.cell_data);

  const std::string given = target_path(base_name(), false);
  if (given.empty()) return false;
  const std::string k = std::to_string(files_);
  std::string path, error;
  bool ok = false;
  if (xml_format.get()) {
    const std::string base = ends_with(given, ".vtu") ? given.substr(0, given.size() - 4) : given;
    path = overwrite.get() ? base + ".vtu" : base + k + ".vtu";
    ok = io::write_vtu(path, mesh, &error);
    if (ok) {
      // The collection names its files relative to its own folder, as ParaView expects.
      const double t = node() ? node()->time.get() : 0.0;
      const std::string file = std::filesystem::path(path).filename().string();
      if (overwrite.get()) series_.clear();
      series_.push_back({t, file});
      pvd_path_ = base + ".pvd";
      ok = io::write_pvd(pvd_path_, series_, &error);
    }
  } else {
    std::string base = given;
    if (ends_with(base, ".vtk") || ends_with(base, ".vtu")) base.resize(base.size() - 4);
    path = overwrite.get() ? base + ".vtk" : base + "_" + k + ".vtk";
    ok = io::write_vtk(path, mesh, "Exported VTK file", &error);
  }
  if (!ok) {
    msg_error("filename: " + error);
    return false;
  }
  ++files_;
  if (print_log.get()) msg_info("exported " + path);
  return true;
}

void VTKExporter::handle_event(Event& e) {
  if (e.kind == Event::Kind::key_pressed) {
    if (e.key == 'E' || e.key == 'e') write();
    return;
  }
  SimulationExporter::handle_event(e);
}

void register_vtk_exporter(Registry& r) {
  ComponentInfo info;
  info.name = "VTKExporter";
  info.category = "Exporter";
  info.description = "writes the node's topology and points to VTK files (.vtu series with a .pvd, or legacy .vtk)";
  info.create = creator<VTKExporter>();
  r.add(std::move(info));
}

}  // namespace sinew
