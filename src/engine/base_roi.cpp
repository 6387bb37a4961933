#include "engine/base_roi.h"

#include "core/node.h"
#include "engine/empty_coords.h"
#include "io/mesh_loader.h"

namespace sinew {

BaseROI::BaseROI(StateType type)
    : position(this, "position", empty_coords(type),
               "rest positions of the points (default: the local MechanicalObject's rest_position, else the local "
               "mesh loader's position, else the first MechanicalObject above)",
               "Inputs"),
      points_in_roi(this, "pointsInROI", empty_coords(type), "points in the ROI", "Outputs"),
      points_out_roi(this, "pointsOutROI", empty_coords(type), "points not in the ROI", "Outputs") {
  dim_ = std::min(3, state_type_info(type).spatial_dim);
  for (BaseField* f : std::initializer_list<BaseField*>{&position, &edges, &triangles, &quads, &tetrahedra, &hexahedra,
                                                        &compute_edges, &compute_triangles, &compute_quads,
                                                        &compute_tetrahedra, &compute_hexahedra, &strict,
                                                        &do_update_field})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{
           &indices, &edge_indices, &triangle_indices, &quad_indices, &tetrahedron_indices, &hexahedron_indices,
           &points_in_roi, &edges_in_roi, &triangles_in_roi, &quads_in_roi, &tetrahedra_in_roi, &hexahedra_in_roi,
           &nb_indices, &points_out_roi, &edges_out_roi, &triangles_out_roi, &quads_out_roi, &tetrahedra_out_roi,
           &hexahedra_out_roi, &indices_out, &edge_out_indices, &triangle_out_indices, &quad_out_indices,
           &tetrahedron_out_indices, &hexahedron_out_indices})
    add_output(f);
}

void BaseROI::init() {
  Node& n = *node();
  if (!position.is_set()) {
    if (auto* mo = n.find_local<MechanicalState>()) {
      BaseField* rp = mo->find_field("rest_position");
      if (!rp) {
        msg_warning("no 'rest_position' in the local mechanical state: the ROI has no input");
        set_state(ComponentState::invalid);
        return;
      }
      position.set_parent(rp);
    } else if (auto* loader = n.find_local<MeshLoader>()) {
      position.set_parent(&loader->position);
    } else if (auto* up = n.find_up<MechanicalState>()) {
      BaseField* rp = up->find_field("rest_position");
      if (!rp) {
        msg_error("no 'rest_position' in mechanical state '" + up->name.value() + "'");
        set_state(ComponentState::invalid);
        return;
      }
      position.set_parent(rp);
    } else {
      msg_error("no positions: set 'position' or put a MechanicalObject or mesh loader before the " + class_name() +
                " in the scene graph");
      set_state(ComponentState::invalid);
      return;
    }
  }
  if (!edges.is_set() || !triangles.is_set() || !quads.is_set() || !tetrahedra.is_set() || !hexahedra.is_set()) {
    if (auto* topo = n.find_local<MeshTopologyBase>()) {
      auto link = [&](Field<bool>& flag, BaseField& mine, const char* name) {
        if (!mine.is_set() && flag.get())
          if (BaseField* theirs = topo->find_field(name)) mine.set_parent(theirs);
      };
      link(compute_edges, edges, "edges");
      link(compute_triangles, triangles, "triangles");
      link(compute_quads, quads, "quads");
      link(compute_tetrahedra, tetrahedra, "tetrahedra");
      link(compute_hexahedra, hexahedra, "hexahedra");
    }
  }
  set_state(ComponentState::valid);
  roi_init();
  force_ = true;  // the initial selection happens even with doUpdate=false
  set_dirty();
  update();
  force_ = false;
  initialized_ = true;
}

void BaseROI::reinit() {
  roi_init();
  set_dirty();
  update();
}

template <class Elem>
bool BaseROI::elem_in(const Elem& e, bool strict_mode) const {
  const std::size_t n = pos_->size();
  for (unsigned v : e)
    if (v >= n) {
      bad_index_ = true;
      return false;
    }
  if (strict_mode) {
    for (unsigned v : e)
      if (!point_in_roi(point(v))) return false;
    return true;
  }
  if (inside_vertices_suffice()) {
    bool all = true;
    for (unsigned v : e) all = all && point_in_roi(point(v));
    if (all) return true;
  }
  double c[3] = {0, 0, 0};
  for (unsigned v : e)
    for (int k = 0; k < dim_; ++k) c[k] += point(v)[k];
  for (int k = 0; k < dim_; ++k) c[k] = c[k] / static_cast<double>(e.size());
  return point_in_roi(c);
}

template <class Elem, class Extra>
void BaseROI::select(const std::vector<Elem>& elems, bool strict_mode, Field<std::vector<unsigned>>& in_ids,
                     Field<std::vector<Elem>>& in_elems, Field<std::vector<unsigned>>& out_ids,
                     Field<std::vector<Elem>>& out_elems, Extra extra) {
  auto& ii = in_ids.edit();
  auto& ie = in_elems.edit();
  auto& oi = out_ids.edit();
  auto& oe = out_elems.edit();
  for (std::size_t e = 0; e < elems.size(); ++e) {
    if (elem_in(elems[e], strict_mode) && extra(elems[e])) {
      ii.push_back(static_cast<unsigned>(e));
      ie.push_back(elems[e]);
    } else {
      oi.push_back(static_cast<unsigned>(e));
      oe.push_back(elems[e]);
    }
  }
}

void BaseROI::do_update() {
  if (state() == ComponentState::invalid) return;
  if (!do_update_field.get() && !force_ && initialized_) return;
  // Clear every output.
  for (auto* f : {&indices, &edge_indices, &triangle_indices, &quad_indices, &tetrahedron_indices, &hexahedron_indices,
                  &indices_out, &edge_out_indices, &triangle_out_indices, &quad_out_indices, &tetrahedron_out_indices,
                  &hexahedron_out_indices})
    f->edit().clear();
  points_in_roi.edit().data.clear();
  points_out_roi.edit().data.clear();
  edges_in_roi.edit().clear();
  triangles_in_roi.edit().clear();
  quads_in_roi.edit().clear();
  tetrahedra_in_roi.edit().clear();
  hexahedra_in_roi.edit().clear();
  edges_out_roi.edit().clear();
  triangles_out_roi.edit().clear();
  quads_out_roi.edit().clear();
  tetrahedra_out_roi.edit().clear();
  hexahedra_out_roi.edit().clear();

  const FlatVec& pos = position.get();
  pos_ = &pos;
  if (pos.size() == 0) {
    msg_warning("no rest positions yet: the ROI selects nothing");
    return;
  }
  if (!roi_do_update()) return;
  bad_index_ = false;
  const int w = pos.width;
  auto& idx = indices.edit();
  auto& out = indices_out.edit();
  auto& pin = points_in_roi.edit().data;
  auto& pout = points_out_roi.edit().data;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const double* p = &pos.data[i * w];
    if (point_in_roi(p)) {
      idx.push_back(static_cast<unsigned>(i));
      pin.insert(pin.end(), p, p + w);
    } else {
      out.push_back(static_cast<unsigned>(i));
      pout.insert(pout.end(), p, p + w);
    }
  }
  const bool s = strict.get();
  auto none = [](const auto&) { return true; };
  if (compute_edges.get())
    select(edges.get(), s, edge_indices, edges_in_roi, edge_out_indices, edges_out_roi,
           [this](const Edge& e) { return edge_extra(e); });
  if (compute_triangles.get())
    select(triangles.get(), s, triangle_indices, triangles_in_roi, triangle_out_indices, triangles_out_roi,
           [this](const Triangle& t) { return triangle_extra(t); });
  if (compute_quads.get()) select(quads.get(), s, quad_indices, quads_in_roi, quad_out_indices, quads_out_roi, none);
  if (compute_tetrahedra.get())
    select(tetrahedra.get(), s, tetrahedron_indices, tetrahedra_in_roi, tetrahedron_out_indices, tetrahedra_out_roi,
           none);
  if (compute_hexahedra.get())
    select(hexahedra.get(), s, hexahedron_indices, hexahedra_in_roi, hexahedron_out_indices, hexahedra_out_roi, none);
  nb_indices.set(static_cast<unsigned>(idx.size()));
  if (bad_index_)
    msg_warning("some elements use point indices beyond the " + std::to_string(pos.size()) +
                " positions; they are counted outside the ROI");
}

}  // namespace sinew
