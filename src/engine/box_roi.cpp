#include "engine/box_roi.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
FlatVec empty_flat(StateType t) {
  FlatVec v;
  v.width = state_type_info(t).coord_width;
  return v;
}
}  // namespace

BoxROI::BoxROI(StateType type)
    : position(this, "position", empty_flat(type), "points to select from (default: the state's rest_position)",
               "Inputs"),
      points_in_roi(this, "pointsInROI", empty_flat(type), "points in the ROI", "Outputs") {
  for (BaseField* f : std::initializer_list<BaseField*>{&box, &oriented_box, &position, &edges, &triangles, &quads,
                                                        &tetrahedra, &hexahedra, &strict})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{
           &indices, &edge_indices, &triangle_indices, &quad_indices, &tetrahedron_indices, &hexahedron_indices,
           &points_in_roi, &edges_in_roi, &triangles_in_roi, &quads_in_roi, &tetrahedra_in_roi, &hexahedra_in_roi,
           &nb_indices, &indices_out})
    add_output(f);
}

void BoxROI::init() {
  if (!oriented_box.get().empty()) {
    msg_error("orientedBox is not supported yet; use box");
    state_ = ComponentState::invalid;
    return;
  }
  if (!box.is_set()) box.set({(VecN<6>() << 0, 0, 0, 1, 1, 1).finished()});
  Node& n = *node();
  if (!position.is_set()) {
    if (auto* mo = n.find_local<MechanicalState>()) {
      if (BaseField* rp = mo->find_field("rest_position")) position.set_parent(rp);
    } else if (auto* up = n.find_up<MechanicalState>()) {
      if (BaseField* rp = up->find_field("rest_position")) position.set_parent(rp);
    } else {
      msg_error("no positions: set 'position' or put the BoxROI next to a MechanicalObject");
      state_ = ComponentState::invalid;
      return;
    }
  }
  if (auto* topo = n.find_local<MeshTopologyBase>()) {
    auto link = [&](Field<bool>& flag, BaseField& mine, const char* name) {
      if (flag.value() && !mine.is_set())
        if (BaseField* theirs = topo->find_field(name)) mine.set_parent(theirs);
    };
    link(compute_edges, edges, "edges");
    link(compute_triangles, triangles, "triangles");
    link(compute_quads, quads, "quads");
    link(compute_tetrahedra, tetrahedra, "tetrahedra");
    link(compute_hexahedra, hexahedra, "hexahedra");
  }
  set_dirty();
  update();
}

bool BoxROI::inside(const double* p) const {
  for (const VecN<6>& b : boxes_)
    if (b[0] <= p[0] && p[0] <= b[3] && b[1] <= p[1] && p[1] <= b[4] && b[2] <= p[2] && p[2] <= b[5]) return true;
  return false;
}

template <class Elem>
void BoxROI::select(const std::vector<Elem>& elems, const std::vector<double>& x, int w,
                    Field<std::vector<unsigned>>& ids, Field<std::vector<Elem>>& out) {
  auto& id_list = ids.edit();
  auto& elem_list = out.edit();
  id_list.clear();
  elem_list.clear();
  const std::size_t n = x.size() / w;
  for (std::size_t e = 0; e < elems.size(); ++e) {
    const Elem& el = elems[e];
    bool in = true;
    if (strict.value()) {
      for (unsigned v : el)
        if (v >= n || !inside(&x[v * w])) {
          in = false;
          break;
        }
    } else {
      double c[3] = {0, 0, 0};
      for (unsigned v : el)
        for (int k = 0; k < 3; ++k) c[k] += v < n ? x[v * w + k] : 0.0;
      for (double& k : c) k /= static_cast<double>(el.size());
      in = inside(c);
    }
    if (in) {
      id_list.push_back(static_cast<unsigned>(e));
      elem_list.push_back(el);
    }
  }
}

void BoxROI::do_update() {
  boxes_ = box.get();
  for (VecN<6>& b : boxes_)
    for (int a = 0; a < 3; ++a)
      if (b[a] > b[a + 3]) std::swap(b[a], b[a + 3]);
  const FlatVec& pos = position.get();
  const int w = pos.width;
  const std::size_t n = pos.size();
  auto& idx = indices.edit();
  auto& out = indices_out.edit();
  auto& pts = points_in_roi.edit();
  idx.clear();
  out.clear();
  pts.data.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &pos.data[i * w];
    if (w >= 3 && inside(p)) {
      idx.push_back(static_cast<unsigned>(i));
      pts.data.insert(pts.data.end(), p, p + w);
    } else {
      out.push_back(static_cast<unsigned>(i));
    }
  }
  nb_indices.set(static_cast<unsigned>(idx.size()));
  if (compute_edges.value()) select(edges.get(), pos.data, w, edge_indices, edges_in_roi);
  if (compute_triangles.value()) select(triangles.get(), pos.data, w, triangle_indices, triangles_in_roi);
  if (compute_quads.value()) select(quads.get(), pos.data, w, quad_indices, quads_in_roi);
  if (compute_tetrahedra.value()) select(tetrahedra.get(), pos.data, w, tetrahedron_indices, tetrahedra_in_roi);
  if (compute_hexahedra.value()) select(hexahedra.get(), pos.data, w, hexahedron_indices, hexahedra_in_roi);
}

void register_box_roi(Registry& r) {
  ComponentInfo info;
  info.name = "BoxROI";
  info.category = "Engine/Select";
  info.description = "selects the points and elements inside axis-aligned boxes";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType st;
    if (!state_type_from_name(t, st)) return nullptr;
    return std::make_unique<BoxROI>(st);
  };
  r.add(std::move(info));
}

}  // namespace sinew
