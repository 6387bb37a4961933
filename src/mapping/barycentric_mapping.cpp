#include "mapping/barycentric_mapping.h"

#include "core/node.h"
#include "core/registry.h"
#include "mapping/barycentric_mapping_rigid.h"
#include "topology/grid/regular_grid_topology.h"
#include "topology/grid/sparse_grid_topology.h"

namespace sinew {

namespace {

// "a, b, c" of the first few indices, "... (n in all)" beyond.
std::string index_list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < 8; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  if (v.size() > 8) s += ", ... (" + std::to_string(v.size()) + " in all)";
  return s;
}

bool is_set_container(const MeshTopologyBase& t) {
  const std::string& n = t.class_name();
  const std::string suffix = "SetTopologyContainer";
  return n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

// Messages for what locating the points found; false when a point could not be located.
// `element` names the candidates for degenerate ones (nullptr: grids, where none can be).
bool BarycentricMapping::report(const BaryReport& r, const char* element, std::size_t n_elements) {
  const std::string topo = input_topology->describe();
  if (element && !r.degenerate.empty())
    msg_warning(std::to_string(r.degenerate.size()) + " of " + std::to_string(n_elements) + " " + element +
                "(s) of " + topo + " are degenerate (zero volume or area) and cannot locate points: " +
                index_list(r.degenerate));
  if (r.unlocated != BaryReport::kNone) {
    msg_error("output point " + std::to_string(r.unlocated) + " could not be located in " + topo);
    return false;
  }
  if (!r.outside.empty())
    msg_warning(std::to_string(r.outside.size()) + " output point(s) outside every element of " + topo +
                ", mapped by extrapolation from the nearest element: " + index_list(r.outside));
  return true;
}

bool BarycentricMapping::init_mapping() {
  if (!input_topology) input_topology.set(in_[0]->node() ? in_[0]->node()->find_up<MeshTopologyBase>() : nullptr);
  if (!output_topology) {
    Component* oc = out_ ? static_cast<Component*>(out_) : static_cast<Component*>(vout_);
    if (oc->node()) output_topology.set(oc->node()->find_up<MeshTopologyBase>());
  }
  if (!input_topology) {
    msg_error("no input topology found; set input_topology=\"@...\"");
    return false;
  }
  table_.clear();

  const int x_id = use_rest_position.value() ? kRestPosition : kPosition;
  const std::vector<double>& in = in_coord(x_id);
  std::vector<double> out = *out_coord_read(x_id);  // copy: resizing the output must not invalidate it
  MeshTopologyBase& topo = *input_topology;

  bool ok = false;
  if (dynamic_cast<RegularGridTopology*>(&topo)) {
    ok = init_regular_grid(out);
  } else if (dynamic_cast<SparseGridTopology*>(&topo)) {
    // Also SparseGridRamificationTopology: its cube look-ups are virtual.
    ok = init_sparse_grid(out);
  } else {
    ok = init_mesh(out, in, is_set_container(topo));
  }
  if (!ok) return false;
  resize_output(table_.points());
  return true;
}

bool BarycentricMapping::init_regular_grid(const std::vector<double>& out) {
  auto& grid = static_cast<RegularGridTopology&>(*input_topology);
  grid.nb_points();  // make sure the grid is generated
  const VecNi<3> n = grid.dims();
  if (n[0] < 2 || n[1] < 2 || n[2] < 2) {
    msg_error("input topology " + grid.describe() + " has no volume (n = " + std::to_string(n[0]) + " " +
              std::to_string(n[1]) + " " + std::to_string(n[2]) + "): no barycentric mapper can be created");
    return false;
  }
  mapper_ = "RegularGrid";
  return report(bary_regular_grid(grid, out, table_), nullptr, 0);
}

bool BarycentricMapping::init_sparse_grid(const std::vector<double>& out) {
  auto& grid = static_cast<SparseGridTopology&>(*input_topology);
  if (grid.hexahedra().empty()) {
    msg_error("input topology " + grid.describe() + " has no volume: no barycentric mapper can be created");
    return false;
  }
  mapper_ = "SparseGrid";
  return report(bary_sparse_grid(grid, out, table_), nullptr, 0);
}

// Volume elements, else surface elements, else edges. The set-container mappers use one
// element type only (hexahedra before tetrahedra, quads before triangles); the mesh mapper
// lets both types of a dimension compete.
bool BarycentricMapping::init_mesh(const std::vector<double>& out, const std::vector<double>& in, bool set_container) {
  MeshTopologyBase& topo = *input_topology;
  const std::size_t n_in = in.size() / 3;
  auto check = [&](const auto& list, const char* what) {
    for (std::size_t e = 0; e < list.size(); ++e)
      for (unsigned v : list[e])
        if (v >= n_in) {
          msg_error(std::string(what) + " " + std::to_string(e) + " of " + topo.describe() + " uses point " +
                    std::to_string(v) + " but the input state has " + std::to_string(n_in) + " points");
          return false;
        }
    return true;
  };

  const std::vector<Tetra>& tetras = topo.tetrahedra();
  const std::vector<Hexa>& hexas = topo.hexahedra();
  if (!tetras.empty() || !hexas.empty()) {
    static const std::vector<Tetra> no_tetras;
    static const std::vector<Hexa> no_hexas;
    const std::vector<Tetra>& T = set_container && !hexas.empty() ? no_tetras : tetras;
    const std::vector<Hexa>& H = set_container && hexas.empty() ? no_hexas : hexas;
    if (!check(T, "tetrahedron") || !check(H, "hexahedron")) return false;
    mapper_ = set_container ? (H.empty() ? "TetrahedronSet" : "HexahedronSet") : "Mesh";
    return report(bary_volume(T, H, set_container, in, out, table_), "element", T.size() + H.size());
  }

  const std::vector<Triangle>& tris = topo.triangles();
  const std::vector<Quad>& quads = topo.quads();
  if (!tris.empty() || !quads.empty()) {
    static const std::vector<Triangle> no_tris;
    static const std::vector<Quad> no_quads;
    const std::vector<Triangle>& T = set_container && !quads.empty() ? no_tris : tris;
    const std::vector<Quad>& Q = set_container && quads.empty() ? no_quads : quads;
    if (!check(T, "triangle") || !check(Q, "quad")) return false;
    mapper_ = set_container ? (Q.empty() ? "TriangleSet" : "QuadSet") : "Mesh";
    return report(bary_surface(T, Q, set_container, in, out, table_), "surface element", T.size() + Q.size());
  }

  const std::vector<Edge>& edges = topo.edges();
  if (edges.empty()) {
    msg_error("input topology " + topo.describe() + " has no elements to map onto");
    return false;
  }
  if (!check(edges, "edge")) return false;
  mapper_ = set_container ? "EdgeSet" : "Mesh";
  bary_edges(edges, in, out, table_);
  return true;
}

void BarycentricMapping::apply(int x) {
  if (std::vector<double>* out = out_coord(x)) table_.gather(in_coord(x), *out);
}

void BarycentricMapping::apply_j(int v, int role) {
  if (std::vector<double>* out = out_deriv(v, role)) table_.gather(in_deriv(v, role), *out);
}

void BarycentricMapping::apply_jt(int f, int role) {
  if (const std::vector<double>* out = out_deriv_read(f, role)) table_.scatter_add(*out, in_deriv_write(f, role));
}

// A constraint entry on output point i spreads over its element's vertices with their weights.
void BarycentricMapping::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (out_dof >= table_.points()) return;
  for (std::uint32_t k = table_.begin(out_dof); k < table_.end(out_dof); ++k) {
    const double w = table_.weight(k);
    const double t[3] = {v[0] * w, v[1] * w, v[2] * w};
    sink.add(0, table_.vertex(k), t);
  }
}

bool BarycentricMapping::jacobian(std::vector<JacobianEntry>& out) {
  table_.jacobian(out);
  return true;
}

void register_barycentric_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "BarycentricMapping";
  info.category = "Mapping/Linear";
  info.description = "points embedded in the elements of the input topology (barycentric weights)";
  // Vec3d,Rigid3d embeds frames in tetrahedra: another mapper, another class (barycentric_mapping_rigid.h).
  info.templates = {"Vec3d,Vec3d", "Vec3d,Rigid3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    if (in == StateType::vec3 && out == StateType::rigid3) return std::make_unique<BarycentricMappingRigid>();
    return std::make_unique<BarycentricMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
