#include "io/mesh_loader.h"

#include <sstream>
#include <type_traits>

#include "core/parse.h"
#include "core/value_text.h"

namespace sinew {

// ------------------------------------------------------------------ text forms of the list fields

namespace io {

namespace {

// Ragged index lists as SOFA writes them: each list is its length followed by
// its entries. One template serves the unsigned lists (polygons, polylines)
// and the signed ones (OBJ face index lists).
template <class T>
std::string ragged_to_text(const std::vector<std::vector<T>>& v) {
  std::string s;
  for (const auto& e : v) {
    if (!s.empty()) s += ' ';
    s += std::to_string(e.size());
    for (T i : e) s += ' ' + std::to_string(i);
  }
  return s;
}

// Reads the form above; false on a bad count or entry. Unsigned lists also
// refuse negative entries, which would wrap around to huge indices.
template <class T>
bool ragged_read_text(std::string_view text, std::vector<std::vector<T>>& v) {
  v.clear();
  const auto toks = parse::tokens(text);
  std::size_t i = 0;
  while (i < toks.size()) {
    long long n = 0;
    if (!parse::read_int(toks[i], n) || n < 0 || i + 1 + static_cast<std::size_t>(n) > toks.size()) return false;
    std::vector<T> e;
    for (long long k = 0; k < n; ++k) {
      long long x = 0;
      if (!parse::read_int(toks[i + 1 + static_cast<std::size_t>(k)], x)) return false;
      if (std::is_unsigned_v<T> && x < 0) return false;
      e.push_back(static_cast<T>(x));
    }
    v.push_back(std::move(e));
    i += 1 + static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::string to_text(const std::vector<std::vector<unsigned>>& v) { return ragged_to_text(v); }
bool read_text(std::string_view text, std::vector<std::vector<unsigned>>& v) { return ragged_read_text(text, v); }
std::string to_text(const std::vector<std::vector<int>>& v) { return ragged_to_text(v); }
bool read_text(std::string_view text, std::vector<std::vector<int>>& v) { return ragged_read_text(text, v); }

std::string to_text(const std::vector<PrimitiveGroup>& v) {
  std::string s;
  for (const auto& g : v) {
    if (!s.empty()) s += ' ';
    s += std::to_string(g.p0) + ' ' + std::to_string(g.nbp) + ' ' + (g.material_name.empty() ? "-" : g.material_name) +
         ' ' + (g.group_name.empty() ? "-" : g.group_name) + ' ' + std::to_string(g.material_id);
  }
  return s;
}

bool read_text(std::string_view text, std::vector<PrimitiveGroup>& v) {
  v.clear();
  const auto toks = parse::tokens(text);
  if (toks.size() % 5 != 0) return false;
  for (std::size_t i = 0; i < toks.size(); i += 5) {
    PrimitiveGroup g;
    long long a = 0, b = 0, c = 0;
    if (!parse::read_int(toks[i], a) || !parse::read_int(toks[i + 1], b) || !parse::read_int(toks[i + 4], c))
      return false;
    g.p0 = static_cast<int>(a);
    g.nbp = static_cast<int>(b);
    g.material_name = toks[i + 2] == "-" ? "" : std::string(toks[i + 2]);
    g.group_name = toks[i + 3] == "-" ? "" : std::string(toks[i + 3]);
    g.material_id = static_cast<int>(c);
    v.push_back(std::move(g));
  }
  return true;
}

}  // namespace io

// ------------------------------------------------------------------ MeshLoader

MeshLoader::MeshLoader() {
  filename.set_file(true);
  tetrahedra.add_alias("tetras");
  hexahedra.add_alias("hexas");
  prisms.add_alias("pentas");
  prisms.add_alias("pentahedra");
  prisms_groups.add_alias("pentahedraGroups");
  for (BaseField* f : std::initializer_list<BaseField*>{&flip_normals, &triangulate, &create_subelements,
                                                        &only_attached_points, &translation, &rotation, &scale3d,
                                                        &transformation})
    f->set_autolink(false);
  for (BaseField* f : std::initializer_list<BaseField*>{&filename, &flip_normals, &triangulate, &create_subelements,
                                                        &only_attached_points, &translation, &rotation, &scale3d,
                                                        &transformation})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{
           &position, &polylines, &edges, &triangles, &quads, &polygons, &high_order_edge_positions,
           &high_order_triangle_positions, &high_order_quad_positions, &tetrahedra, &hexahedra, &prisms,
           &high_order_tetrahedron_positions, &high_order_hexahedron_positions, &pyramids, &normals, &edges_groups,
           &triangles_groups, &quads_groups, &polygons_groups, &tetrahedra_groups, &hexahedra_groups, &prisms_groups,
           &pyramids_groups})
    add_output(f);
}

void MeshLoader::parse(AttributeMap& attrs, Diagnostics& diag) {
  std::string scale_text;
  const bool has_scale = [&] {
    const std::string* s = attrs.take("scale");
    if (s) scale_text = *s;
    return s != nullptr;
  }();
  Engine::parse(attrs, diag);
  if (has_scale) {
    // SOFA reads `scale` as a float (trap: float parsing) and multiplies scale3d.
    double s = 1.0;
    const auto toks = parse::tokens(scale_text);
    if (toks.empty() || !parse::read_double(toks[0], s))
      diag.warning(where, describe() + ": could not read value for attribute 'scale': " + quote_value(scale_text));
    const double sf = static_cast<double>(static_cast<float>(s));
    Vec3 v = scale3d.value();
    scale3d.set(Vec3(v[0] * sf, v[1] * sf, v[2] * sf));
  }
}

io::ReadOptions MeshLoader::read_options() const {
  io::ReadOptions o;
  o.flip_normals = flip_normals.get();
  o.triangulate = triangulate.get();
  return o;
}

void MeshLoader::init() {
  update();  // loads now unless a reader already triggered the load (same inputs: no reload)
}

void MeshLoader::do_update() {
  io::MeshData m;
  std::string error;
  bool ok = true;
  if (needs_file() && filename.get().empty()) {
    msg_error("no file name given (attribute 'filename')");
    ok = false;
  } else if (!read_mesh(m, &error)) {
    msg_error(error.empty() ? "cannot load '" + filename.get() + "'" : error);
    ok = false;
  }
  if (ok && transformation.get().size() != 16) {
    msg_error("transformation must have 16 values (4x4 matrix), got " + std::to_string(transformation.get().size()));
    ok = false;
  }
  if (!ok) {
    set_state(ComponentState::invalid);
    mesh_ = io::MeshData{};
    publish(mesh_);
    return;
  }
  set_state(ComponentState::valid);
  io::FinishOptions fo;
  fo.create_subelements = create_subelements.is_set() ? create_subelements.get() : default_create_subelements();
  fo.only_attached_points = only_attached_points.get();
  fo.triangulate = triangulate.get();
  fo.flip_normals = flip_normals.get();
  fo.translation = translation.get();
  fo.rotation = rotation.get();
  fo.scale = scale3d.get();
  std::copy(transformation.get().begin(), transformation.get().end(), fo.transformation.begin());
  io::finish_mesh(m, fo);
  mesh_ = std::move(m);
  publish(mesh_);
}

void MeshLoader::publish(const io::MeshData& m) {
  position.set(m.positions);
  polylines.set(m.polylines);
  edges.set(m.edges);
  triangles.set(m.triangles);
  quads.set(m.quads);
  polygons.set(m.polygons);
  high_order_edge_positions.set(m.high_order_edge_positions);
  tetrahedra.set(m.tetrahedra);
  hexahedra.set(m.hexahedra);
  prisms.set(m.prisms);
  pyramids.set(m.pyramids);
  normals.set(m.normals);
  edges_groups.set(m.edges_groups);
  triangles_groups.set(m.triangles_groups);
  quads_groups.set(m.quads_groups);
  polygons_groups.set(m.polygons_groups);
  tetrahedra_groups.set(m.tetrahedra_groups);
  hexahedra_groups.set(m.hexahedra_groups);
  prisms_groups.set(m.prisms_groups);
  pyramids_groups.set(m.pyramids_groups);
  publish_extra(m);
}

}  // namespace sinew
