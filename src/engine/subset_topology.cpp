#include "engine/subset_topology.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/box_roi.h"
#include "engine/empty_coords.h"

namespace sinew {

SubsetTopology::SubsetTopology(StateType type)
    : rest_position(this, "rest_position", empty_coords(type),
                    "rest positions of the points (default: the 'position' of the mechanical state of this "
                    "template, here or above)",
                    "Inputs"),
      points_in_roi(this, "pointsInROI", empty_coords(type), "points in the ROI", "Outputs"),
      points_out_roi(this, "pointsOutROI", empty_coords(type), "points not in the ROI", "Outputs"),
      type_(type) {
  for (BaseField* f : std::initializer_list<BaseField*>{&box, &centers, &radii, &direction, &normal, &edge_angle,
                                                        &tri_angle, &tetrahedra_input, &rest_position, &edges,
                                                        &triangles, &quads, &tetrahedra, &hexahedra, &local_indices})
    add_input(f);
  for (BaseField* f : std::initializer_list<BaseField*>{
           &indices, &edge_indices, &triangle_indices, &quad_indices, &tetrahedron_indices, &hexahedron_indices,
           &points_in_roi, &points_out_roi, &edges_in_roi, &edges_out_roi, &triangles_in_roi, &triangles_out_roi,
           &quads_in_roi, &quads_out_roi, &tetrahedra_in_roi, &tetrahedra_out_roi, &hexahedra_in_roi,
           &hexahedra_out_roi, &nbrborder})
    add_output(f);
}

void SubsetTopology::init() {
  Node& n = *node();
  spheres_ = centers.is_set();
  if (!rest_position.is_set()) {
    // The first mechanical state of this template, in this node or above.
    MechanicalState* ms = nullptr;
    for (const Node* up = &n; up && !ms; up = up->parent())
      for (const auto& o : up->objects())
        if (auto* m = dynamic_cast<MechanicalState*>(o.get()); m && m->state_type() == type_) {
          ms = m;
          break;
        }
    if (ms) {
      if (BaseField* p = ms->find_field("position")) rest_position.set_parent(p);
    } else {
      msg_warning("no 'rest_position' given and no " + std::string(state_type_info(type_).name) +
                  " mechanical state here or above: the subset is empty");
    }
  }
  if (!edges.is_set() || !triangles.is_set() || !tetrahedra.is_set()) {
    if (auto* topo = n.find_up<MeshTopologyBase>()) {
      auto link = [&](BaseField& mine, const char* name) {
        if (!mine.is_set())
          if (BaseField* theirs = topo->find_field(name)) mine.set_parent(theirs);
      };
      link(edges, "edges");
      link(triangles, "triangles");
      link(tetrahedra, "tetrahedra");
    }
  }
  set_state(ComponentState::valid);
  set_dirty();
}

void SubsetTopology::reinit() {
  set_dirty();
  update();
}

bool SubsetTopology::point_in(const double* p, std::size_t roi) const {
  if (spheres_) {
    const Vec3& c = centers.value()[roi];
    const double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
    return !(std::sqrt(dx * dx + dy * dy + dz * dz) > radii.value()[roi]);
  }
  const VecN<6>& b = boxes_[roi];
  return p[0] >= b[0] && p[0] <= b[3] && p[1] >= b[1] && p[1] <= b[4] && p[2] >= b[2] && p[2] <= b[5];
}

bool SubsetTopology::index_in(unsigned i, std::size_t roi) const {
  if (i >= x_->size()) {
    bad_index_ = true;
    return false;
  }
  return point_in(&x_->data[static_cast<std::size_t>(i) * x_->width], roi);
}

template <class Elem>
bool SubsetTopology::elem_in(const Elem& e, std::size_t roi) const {
  for (unsigned v : e)
    if (!index_in(v, roi)) return false;
  return true;
}

template <class Elem>
void SubsetTopology::renumber(Elem& e, const std::vector<unsigned>& map) const {
  for (unsigned& v : e)
    if (v < map.size()) v = map[v];
}

// An element is in when all its vertices are in one same region; the region loop stops at the first.
template <class Elem>
void SubsetTopology::select(const std::vector<Elem>& elems, Field<std::vector<unsigned>>& in_ids,
                            Field<std::vector<Elem>>& in, Field<std::vector<Elem>>& out) {
  auto& ids = in_ids.edit();
  auto& ei = in.edit();
  auto& eo = out.edit();
  const bool local = local_indices.get();
  for (std::size_t i = 0; i < elems.size(); ++i) {
    Elem e = elems[i];
    bool inside = false;
    for (std::size_t r = 0; r < n_roi_ && !inside; ++r) inside = elem_in(e, r);
    if (local) renumber(e, local_);
    if (inside) {
      ids.push_back(static_cast<unsigned>(i));
      ei.push_back(e);
    } else {
      eo.push_back(e);
    }
  }
}

// Border points: the vertices inside the first region of the elements having vertices both in and out of it.
template <class Elem>
void SubsetTopology::mark_border(const std::vector<Elem>& elems) {
  if (n_roi_ == 0) return;
  for (const Elem& e : elems) {
    bool any_in = false, any_out = false;
    for (unsigned v : e) (index_in(v, 0) ? any_in : any_out) = true;
    if (!(any_in && any_out)) continue;
    for (unsigned v : e)
      if (index_in(v, 0)) on_border_[v] = 1;
  }
}

// tetrahedraInput given: the listed tetrahedra are in, the others out; the point lists are rebuilt from the
// tetrahedra's vertices (first appearance order), while `indices` keeps what the region test gave and gets the
// inner tetrahedra's vertices appended (SOFA's behaviour).
void SubsetTopology::select_tetrahedra_by_index() {
  const auto& tets = tetrahedra.get();
  const auto& chosen = tetrahedra_input.get();
  const std::size_t n = x_->size();
  const int w = x_->width;
  const bool local = local_indices.get();
  std::vector<char> keep(tets.size(), 0), seen_in(n, 0), seen_out(n, 0);
  for (unsigned t : chosen)
    if (t < tets.size()) keep[t] = 1;
  std::vector<unsigned> local_out(n, 0);
  auto& idx = indices.edit();
  auto& pin = points_in_roi.edit().data;
  auto& pout = points_out_roi.edit().data;
  pin.clear();
  pout.clear();
  unsigned cin = 0, cout = 0;
  auto& ti = tetrahedron_indices.edit();
  auto& tin = tetrahedra_in_roi.edit();
  auto& tout = tetrahedra_out_roi.edit();
  for (std::size_t i = 0; i < tets.size(); ++i) {
    Tetra t = tets[i];
    const bool in = keep[i];
    for (unsigned& v : t) {
      if (v >= n) {
        bad_index_ = true;
        continue;
      }
      const double* p = &x_->data[static_cast<std::size_t>(v) * w];
      if (in) {
        if (!seen_in[v]) {
          seen_in[v] = 1;
          idx.push_back(v);
          pin.insert(pin.end(), p, p + w);
          if (local) local_[v] = cin++;
        }
        if (local) v = local_[v];
      } else {
        if (!seen_out[v]) {
          seen_out[v] = 1;
          pout.insert(pout.end(), p, p + w);
          if (local) local_out[v] = cout++;
        }
        if (local) v = local_out[v];
      }
    }
    if (in) {
      ti.push_back(static_cast<unsigned>(i));
      tin.push_back(t);
    } else {
      tout.push_back(t);
    }
  }
}

void SubsetTopology::do_update() {
  if (state() == ComponentState::invalid) return;
  boxes_ = box.get();
  if (order_box_corners(boxes_)) box.edit() = boxes_;  // SOFA writes the ordered boxes back
  n_roi_ = boxes_.size();
  if (spheres_) {
    const auto& c = centers.get();
    if (c.empty()) return;
    if (c.size() != radii.get().size()) {
      msg_warning("number of sphere centres (" + std::to_string(c.size()) + ") and radii (" +
                  std::to_string(radii.get().size()) + ") do not match: the outputs are left unchanged");
      return;
    }
    n_roi_ = c.size();
  }

  const FlatVec& x = rest_position.get();
  x_ = &x;
  const std::size_t n = x.size();
  const int w = x.width;
  bad_index_ = false;

  for (auto* f : {&indices, &edge_indices, &triangle_indices, &quad_indices, &tetrahedron_indices,
                  &hexahedron_indices})
    f->edit().clear();
  points_in_roi.edit().data.clear();
  points_out_roi.edit().data.clear();
  edges_in_roi.edit().clear();
  edges_out_roi.edit().clear();
  triangles_in_roi.edit().clear();
  triangles_out_roi.edit().clear();
  quads_in_roi.edit().clear();
  quads_out_roi.edit().clear();
  tetrahedra_in_roi.edit().clear();
  tetrahedra_out_roi.edit().clear();
  hexahedra_in_roi.edit().clear();
  hexahedra_out_roi.edit().clear();

  const bool local = local_indices.get();
  auto& idx = indices.edit();
  auto& pin = points_in_roi.edit().data;
  auto& pout = points_out_roi.edit().data;
  unsigned cin = 0, cout = 0, cborder = 0, nborder = 0;
  if (local) {
    on_border_.assign(n, 0);
    if (tetrahedra.get().empty())
      mark_border(triangles.get());
    else
      mark_border(tetrahedra.get());
    local_.assign(n, 0);
    for (char b : on_border_) nborder += b ? 1u : 0u;
    idx.assign(nborder, 0);
    pin.assign(static_cast<std::size_t>(nborder) * w, 0.0);
    pout.assign(static_cast<std::size_t>(nborder) * w, 0.0);
    cin = cout = nborder;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &x.data[i * w];
    if (local && on_border_[i]) {
      local_[i] = cborder;
      idx[cborder] = static_cast<unsigned>(i);
      std::copy(p, p + w, pin.begin() + static_cast<std::ptrdiff_t>(cborder) * w);
      std::copy(p, p + w, pout.begin() + static_cast<std::ptrdiff_t>(cborder) * w);
      ++cborder;
      continue;
    }
    bool inside = false;
    for (std::size_t r = 0; r < n_roi_ && !inside; ++r) inside = point_in(p, r);
    if (inside) {
      idx.push_back(static_cast<unsigned>(i));
      pin.insert(pin.end(), p, p + w);
      if (local) local_[i] = cin++;
    } else {
      pout.insert(pout.end(), p, p + w);
      if (local) local_[i] = cout++;
    }
  }
  nbrborder.set(nborder);

  select(edges.get(), edge_indices, edges_in_roi, edges_out_roi);
  select(triangles.get(), triangle_indices, triangles_in_roi, triangles_out_roi);
  select(quads.get(), quad_indices, quads_in_roi, quads_out_roi);
  if (tetrahedra_input.is_set())
    select_tetrahedra_by_index();
  else
    select(tetrahedra.get(), tetrahedron_indices, tetrahedra_in_roi, tetrahedra_out_roi);
  select(hexahedra.get(), hexahedron_indices, hexahedra_in_roi, hexahedra_out_roi);

  if (bad_index_)
    msg_warning("some elements use point indices beyond the " + std::to_string(n) +
                " rest positions; they are counted outside the ROI");
}

void register_subset_topology(Registry& r) {
  ComponentInfo info;
  info.name = "SubsetTopology";
  info.category = "Engine/Select";
  info.description = "splits a mesh into the points and elements inside boxes or spheres and the rest";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<SubsetTopology>();
  r.add(std::move(info));
}

}  // namespace sinew
