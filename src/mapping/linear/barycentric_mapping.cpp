#include "mapping/linear/barycentric_mapping.h"

#include "core/node.h"
#include "core/registry.h"
#include "mapping/linear/barycentric_mapping_rigid.h"
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
  frozen_ = false;
  snapshot_.clear();

  const int x_id = use_rest_position.value() ? kRestPosition : kPosition;
  const std::vector<double>& in = in_coord(x_id);
  std::vector<double> out = *out_coord_read(x_id);  // copy: resizing the output must not invalidate it

  if (!choose_mapper()) return false;
  std::string bad;
  const Located r = locate(in, out, bad);
  if (!bad.empty()) {
    msg_error(bad);
    return false;
  }
  if (!report(r.report, r.element, r.n_elements)) return false;
  // The version is taken now; lists still being filled by later inits (a topological mapping
  // writing the input) relocate once, as a propagation would.
  version_ = input_version();
  needed_ = table_.vertices_needed();
  resize_output(table_.points());
  return true;
}

// SOFA's createMapperFromTopology: grids by type, set containers by their highest kind, any
// other mesh the MeshMapper. The choice is kept for the mapping's life (relocations included).
bool BarycentricMapping::choose_mapper() {
  MeshTopologyBase& topo = *input_topology;
  if (auto* grid = dynamic_cast<RegularGridTopology*>(&topo)) {
    grid->nb_points();  // make sure the grid is generated
    const VecNi<3> n = grid->dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) {
      msg_error("input topology " + grid->describe() + " has no volume (n = " + std::to_string(n[0]) + " " +
                std::to_string(n[1]) + " " + std::to_string(n[2]) + "): no barycentric mapper can be created");
      return false;
    }
    mapper_ = "RegularGrid";
  } else if (dynamic_cast<SparseGridTopology*>(&topo)) {
    // Also SparseGridRamificationTopology: its cube look-ups are virtual.
    if (topo.hexahedra().empty()) {
      msg_error("input topology " + topo.describe() + " has no volume: no barycentric mapper can be created");
      return false;
    }
    mapper_ = "SparseGrid";
  } else if (!is_set_container(topo)) {
    mapper_ = "Mesh";
  } else if (!topo.hexahedra().empty()) {
    mapper_ = "HexahedronSet";
  } else if (!topo.tetrahedra().empty()) {
    mapper_ = "TetrahedronSet";
  } else if (!topo.quads().empty()) {
    mapper_ = "QuadSet";
  } else if (!topo.triangles().empty()) {
    mapper_ = "TriangleSet";
  } else {
    mapper_ = "EdgeSet";
  }
  using K = MeshTopologyBase::Elements;
  searched_.reset();
  if (mapper_ == "TetrahedronSet") searched_ = K::tetrahedra;
  if (mapper_ == "HexahedronSet") searched_ = K::hexahedra;
  if (mapper_ == "QuadSet") searched_ = K::quads;
  if (mapper_ == "TriangleSet") searched_ = K::triangles;
  if (mapper_ == "EdgeSet") searched_ = K::edges;
  return true;
}

// The chosen mapper's init on the current lists: the table for points `out`, element vertices
// read from `in`. Volume elements, else surface elements, else edges; the set-container mappers
// use their one element type (hexahedra before tetrahedra, quads before triangles), the mesh
// mapper lets both types of a dimension compete. `bad` names what made it impossible (an
// element using a point the input does not have, no element at all).
BarycentricMapping::Located BarycentricMapping::locate(const std::vector<double>& in, const std::vector<double>& out,
                                                       std::string& bad) {
  Located r;
  table_.clear();
  MeshTopologyBase& topo = *input_topology;
  if (mapper_ == "RegularGrid") {
    r.report = bary_regular_grid(static_cast<RegularGridTopology&>(topo), out, table_);
    return r;
  }
  if (mapper_ == "SparseGrid") {
    r.report = bary_sparse_grid(static_cast<SparseGridTopology&>(topo), out, table_);
    return r;
  }
  const std::size_t n_in = in.size() / 3;
  auto check = [&](const auto& list, const char* what) {
    for (std::size_t e = 0; e < list.size(); ++e)
      for (unsigned v : list[e])
        if (v >= n_in) {
          bad = std::string(what) + " " + std::to_string(e) + " of " + topo.describe() + " uses point " +
                std::to_string(v) + " but the input state has " + std::to_string(n_in) + " points";
          return false;
        }
    return true;
  };
  static const std::vector<Tetra> no_tetras;
  static const std::vector<Hexa> no_hexas;
  static const std::vector<Triangle> no_tris;
  static const std::vector<Quad> no_quads;
  const bool mesh = mapper_ == "Mesh", set = !mesh;
  // The elements of one dimension (both kinds compete; a set-container mapper leaves one empty).
  // False when there are none.
  auto dimension = [&](const auto& A, const char* a, const auto& B, const char* b, auto bary, const char* word) {
    if (A.empty() && B.empty()) return false;
    if (check(A, a) && check(B, b)) {
      r.report = bary(A, B, set, in, out, table_);
      r.element = word;
      r.n_elements = A.size() + B.size();
    }
    return true;
  };
  if (dimension(mesh || mapper_ == "TetrahedronSet" ? topo.tetrahedra() : no_tetras, "tetrahedron",
                mesh || mapper_ == "HexahedronSet" ? topo.hexahedra() : no_hexas, "hexahedron", bary_volume,
                "element"))
    return r;
  if (mapper_ == "TetrahedronSet" || mapper_ == "HexahedronSet") {
    bad = std::string("no ") + (mapper_ == "TetrahedronSet" ? "tetrahedron" : "hexahedron") + " left in " +
          topo.describe();
    return r;
  }
  if (dimension(mesh || mapper_ == "TriangleSet" ? topo.triangles() : no_tris, "triangle",
                mesh || mapper_ == "QuadSet" ? topo.quads() : no_quads, "quad", bary_surface, "surface element"))
    return r;
  const std::vector<Edge>& edges = topo.edges();
  if ((mapper_ != "Mesh" && mapper_ != "EdgeSet") || edges.empty()) {
    bad = mapper_ == "Mesh" || mapper_ == "EdgeSet"
              ? "input topology " + topo.describe() + " has no elements to map onto"
              : "no " + std::string(mapper_ == "QuadSet" ? "quad" : "triangle") + " left in " + topo.describe();
    return r;
  }
  if (!check(edges, "edge")) return r;
  bary_edges(edges, in, out, table_);
  return r;
}

// Called during a propagation, before the container changes (core/topology_change.h). SOFA
// relocates here; the lists are not final yet (removed elements still listed, points not
// renumbered), so the positions are kept (relocation_snapshot.h) and the relocation waits for
// the next use of the map.
void BarycentricMapping::handle_topology_change(MeshTopologyBase& source) {
  if (state() != ComponentState::valid || !input_topology) return;
  snapshot_.take(source, in_[0], in_coord(kPosition), out_, *out_coord_read(kPosition), 3);
}

// SOFA's processTopologicalChanges (clear, then the mapper's init from positions), on the final
// lists. Without a propagation (lists changed by a modifier whose visit does not reach the
// mapping) SOFA keeps its stale map; Sinew relocates from the current positions, with a warning.
void BarycentricMapping::relocate() {
  if (!input_topology) return;
  std::vector<double> in, out;  // copies: resize_output may reallocate the output
  const std::string unannounced = snapshot_.select(in_coord(kPosition), *out_coord_read(kPosition), in, out,
                                                   input_topology->describe(), "relocating the output points from their current positions");
  if (!unannounced.empty()) msg_warning(unannounced);
  version_ = input_version();
  std::string bad;
  const Located r = locate(in, out, bad);
  frozen_ = !bad.empty() || r.report.unlocated != BaryReport::kNone;
  if (frozen_) {
    table_.clear();
    for (std::size_t i = 0; i < out.size() / 3; ++i) table_.end_point();
    if (!warned_frozen_) {
      warned_frozen_ = true;
      msg_warning((bad.empty() ? "an output point could not be located in " + input_topology->describe() : bad) +
                  " after a topological change: the output points keep their positions (SOFA's map would "
                  "name elements that no longer exist)");
    }
  }
  needed_ = table_.vertices_needed();
  snapshot_.clear();
  resize_output(table_.points());
}

void BarycentricMapping::apply(int x) {
  follow_topology();
  std::vector<double>* out = out_coord(x);
  if (!out) return;
  if (frozen_) return hold_output(x, *out, *out_coord_read(kPosition));
  table_.gather(in_coord(x), *out);
}

void BarycentricMapping::apply_j(int v, int role) {
  follow_topology();
  if (std::vector<double>* out = out_deriv(v, role)) table_.gather(in_deriv(v, role), *out);
}

void BarycentricMapping::apply_jt(int f, int role) {
  follow_topology();
  if (const std::vector<double>* out = out_deriv_read(f, role)) table_.scatter_add(*out, in_deriv_write(f, role));
}

// A constraint entry on output point i spreads over its element's vertices with their weights.
// (Rows are built after the positions were mapped, so no relocation is pending here; if one
// were, the table could name points the input lost: nothing is added.)
void BarycentricMapping::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (out_dof >= table_.points() || snapshot_.pending) return;
  for (std::uint32_t k = table_.begin(out_dof); k < table_.end(out_dof); ++k) {
    const double w = table_.weight(k);
    const double t[3] = {v[0] * w, v[1] * w, v[2] * w};
    sink.add(0, table_.vertex(k), t);
  }
}

bool BarycentricMapping::jacobian(std::vector<JacobianEntry>& out) {
  follow_topology();
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
