#include "exporter/export_mesh.h"

#include <charconv>

#include "core/node.h"
#include "core/path.h"
#include "core/roles.h"

namespace sinew {

std::vector<Vec3> export_points(const Field<FlatVec>& position, const MechanicalState* state,
                                const MeshTopologyBase* topology) {
  std::vector<Vec3> points;
  auto from_flat = [&](const std::vector<double>& data, int width) {
    if (width < 1) return;
    const std::size_t w = static_cast<std::size_t>(width), n = data.size() / w;
    points.resize(n, Vec3::Zero());
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < 3 && k < w; ++k) points[i][static_cast<int>(k)] = data[i * w + k];
  };
  const FlatVec& given = position.get();
  if (!given.data.empty()) {
    from_flat(given.data, given.width);
  } else if (state) {
    from_flat(state->read(kPosition), state->info().coord_width);
  } else if (topology && topology->has_positions()) {
    points.resize(topology->nb_points());
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = topology->point(i);
  }
  return points;
}

void select_cells(const MeshTopologyBase& t, const CellFlags& f, io::VtkMesh& mesh) {
  mesh.edges = f.edges ? t.edges() : std::vector<Edge>{};
  mesh.triangles = f.triangles ? t.triangles() : std::vector<Triangle>{};
  mesh.quads = f.quads ? t.quads() : std::vector<Quad>{};
  mesh.tetrahedra = f.tetras ? t.tetrahedra() : std::vector<Tetra>{};
  mesh.hexahedra = f.hexas ? t.hexahedra() : std::vector<Hexa>{};
}

bool parse_data_field_entry(const std::string& text, DataFieldEntry& out) {
  std::string rest = text;
  out = {};
  if (const auto eq = rest.find('='); eq != std::string::npos) {
    out.name = rest.substr(0, eq);
    rest = rest.substr(eq + 1);
  }
  if (!rest.empty() && rest[0] == '@') rest.erase(0, 1);
  const auto dot = rest.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == rest.size()) return false;
  out.object = rest.substr(0, dot);
  out.field = rest.substr(dot + 1);
  if (out.name.empty()) out.name = out.field;
  return true;
}

bool fetch_data_array(Component& owner, const DataFieldEntry& e, io::VtkArray& out, std::string* why) {
  Node* node = owner.node();
  if (!node) return false;
  std::string reason;
  Base* b = resolve_object_path(*node, &owner, e.object, [](Base* c) { return dynamic_cast<Component*>(c) != nullptr; },
                                &reason);
  if (!b) {
    if (why) *why = "no object '" + e.object + "'" + (reason.empty() ? "" : " (" + reason + ")");
    return false;
  }
  BaseField* f = b->find_field(e.field);
  if (!f) {
    if (why) *why = "object '" + e.object + "' has no data '" + e.field + "'";
    return false;
  }
  out = {};
  out.name = e.name;
  f->update();
  if (const int w = f->row_width(); w > 0) {
    out.components = w;
    f->get_rows(out.values);
  } else if (const FieldLayout l = f->layout(); l.scalar != FieldLayout::Scalar::none && l.data) {
    out.components = l.dims == 2 ? l.cols : 1;
    const std::size_t n = l.rows * static_cast<std::size_t>(l.cols);
    out.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      switch (l.scalar) {
        case FieldLayout::Scalar::f64: out.values[i] = static_cast<const double*>(l.data)[i]; break;
        case FieldLayout::Scalar::f32: out.values[i] = static_cast<const float*>(l.data)[i]; break;
        case FieldLayout::Scalar::i32: out.values[i] = static_cast<const int*>(l.data)[i]; break;
        case FieldLayout::Scalar::u32: out.values[i] = static_cast<const unsigned*>(l.data)[i]; break;
        case FieldLayout::Scalar::boolean: out.values[i] = static_cast<const bool*>(l.data)[i] ? 1 : 0; break;
        default: break;
      }
    }
    out.integer = l.scalar == FieldLayout::Scalar::i32 || l.scalar == FieldLayout::Scalar::u32 ||
                  l.scalar == FieldLayout::Scalar::boolean;
  } else {
    // No memory layout: the value's text, one number per row.
    const std::string text = f->text();
    const char* p = text.data();
    const char* end = p + text.size();
    while (p < end) {
      while (p < end && (*p == ' ' || *p == '\n' || *p == '\t')) ++p;
      double v = 0;
      auto r = std::from_chars(p, end, v);
      if (r.ec != std::errc()) break;
      out.values.push_back(v);
      p = r.ptr;
    }
  }
  if (out.values.empty()) {
    if (why) *why = "data '" + e.object + "." + e.field + "' holds no numbers";
    return false;
  }
  return true;
}

}  // namespace sinew
