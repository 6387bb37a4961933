#include "topology/mapping/edge2_quad_topological_mapping.h"

#include <cmath>
#include <limits>

#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

namespace {

// R·v summed column by column, as SOFA's Mat·Vec.
Vec3 mat_vec(const Mat3& R, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = R(i, 0) * v[0] + R(i, 1) * v[1] + R(i, 2) * v[2];
  return r;
}

}  // namespace

void Edge2QuadTopologicalMapping::init() {
  // SOFA's checks, in its order: a radius, a positive one, then the topology types.
  if (!radius.is_set() && !radius_focal.is_set()) {
    msg_error("No radius (neither radius nor radiusFocal) defined");
    set_state(ComponentState::invalid);
    return;
  }
  if (radius.is_set() && !(radius.value() >= std::numeric_limits<double>::min())) {
    msg_error("radius is zero or negative (" + parse::format_double(radius.value()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (radius_focal.is_set() && !(radius_focal.value() >= std::numeric_limits<double>::min()))
    msg_warning("radiusFocal is zero or negative: the rings are circles");
  if (!check_links(true, ElementType::edge, ElementType::quad)) return;

  if (!to_quad_container) to_quad_container.set(find_from_output<QuadSetTopologyContainer>());
  if (!to_quad_container) {
    msg_error("The necessary quad container has not been set (or could not be found).");
    set_state(ComponentState::invalid);
    return;
  }
  if (!to_quad_modifier) to_quad_modifier.set(find_from_output<QuadSetTopologyModifier>());
  if (!to_quad_modifier) {
    msg_error("The necessary quad modifier has not been set (or could not be found) from the output node '" +
              output->node()->name.value() + "'.");
    set_state(ComponentState::invalid);
    return;
  }

  const unsigned n = nb_points_on_each_circle.value();
  if (n == 0) msg_warning("nbPointsOnEachCircle is 0: the tube has no point and no quad");
  const std::vector<Edge>& edges = input->edges();
  const std::size_t np = input->nb_points();
  for (unsigned e : edge_list.get())
    if (e >= edges.size()) {
      msg_error("edgeList names edge " + std::to_string(e) + " but the input topology " + input->describe() +
                " has " + std::to_string(edges.size()) + " edges");
      set_state(ComponentState::invalid);
      return;
    }
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edges[e][0] >= np || edges[e][1] >= np) {
      msg_error("edge " + std::to_string(e) + " of " + input->describe() + " uses a point beyond its " +
                std::to_string(np) + " points");
      set_state(ComponentState::invalid);
      return;
    }
  if (!write_ring_positions(np, n)) return;

  QuadSetTopologyContainer& quads_out = *to_quad_container;
  quads_out.clear_topology();
  quads_out.set_nb_points(np * n);

  const bool flip = flip_normals.value();
  std::vector<Quad> quads;
  quad_to_edge_.clear();
  edge_to_quads_.clear();
  auto add_rings = [&](unsigned e, bool edge_list_order) {
    const unsigned p0 = edges[e][0], p1 = edges[e][1];
    std::vector<unsigned> out;
    for (unsigned j = 0; j < n; ++j) {
      const unsigned q0 = p0 * n + j, q1 = p1 * n + j, q2 = p1 * n + (j + 1) % n, q3 = p0 * n + (j + 1) % n;
      if (!flip) quads.push_back({q0, q1, q2, q3});
      else if (edge_list_order) quads.push_back({q0, q3, q2, q1});
      else quads.push_back({q3, q2, q1, q0});
      quad_to_edge_.push_back(e);
      out.push_back(static_cast<unsigned>(quad_to_edge_.size() - 1));
    }
    set_edge_quads(e, std::move(out));
  };
  if (edge_list.get().empty()) {
    quads.reserve(edges.size() * n);
    for (unsigned e = 0; e < edges.size(); ++e) add_rings(e, false);
  } else {
    for (unsigned e : edge_list.get()) add_rings(e, true);
  }
  quads_out.quads_f.set(std::move(quads));
  quads_out.init();  // the quad container's lower lists (edges), as SOFA's modifier init
}

bool Edge2QuadTopologicalMapping::write_ring_positions(std::size_t n_points, unsigned n) {
  Node* out_node = output->node();
  MechanicalState* ms = out_node->mechanical_state;
  if (ms && ms->state_type() != StateType::vec3) ms = nullptr;  // SOFA writes Vec3d states only
  VisualState* vs = ms ? nullptr : out_node->find_local<VisualState>();
  if (!ms && !vs) return true;  // nothing to place: the mapping below the container will

  MechanicalState* frames = input->node() ? input->node()->mechanical_state : nullptr;
  if (!frames || frames->state_type() != StateType::rigid3) {
    msg_error(std::string("the state of the input topology's node must be Rigid3d (the beam's frames), not ") +
              (frames ? frames->info().name : "missing"));
    set_state(ComponentState::invalid);
    return false;
  }
  if (frames->size() < n_points) {
    msg_error("the input state " + frames->describe() + " has " + std::to_string(frames->size()) +
              " frames but the input topology has " + std::to_string(n_points) + " points");
    set_state(ComponentState::invalid);
    return false;
  }

  const double rho = radius.value();
  const bool ellipse = radius_focal.is_set() && radius_focal.value() >= std::numeric_limits<double>::min();
  const double rho_focal = ellipse ? radius_focal.value() : 0.0;
  const Vec3 x0(1, 0, 0);
  Vec3 y0(0, 1, 0), z0(0, 0, 1);
  if (ellipse) {
    z0 = focal_axis.get();
    const double len = z0.norm();
    if (len > 0) z0 /= len;
    y0 = z0.cross(x0);
  }

  const std::size_t count = n_points * n;
  std::vector<double>* xp = nullptr;
  if (ms) {
    ms->resize(count);
    xp = &ms->write(kPosition);
  } else {
    vs->visual_resize(count);
    xp = vs->visual_vec(kPosition);
  }
  std::vector<double>& x = *xp;
  x.resize(count * 3);
  const std::vector<double>& in = frames->read(kPosition);
  for (std::size_t p = 0; p < n_points; ++p) {
    const double* c = &in[p * 7];
    const Mat3 R = quat_to_matrix(Quat::from(c + 3));
    const Vec3 Y = mat_vec(R, y0), Z = mat_vec(R, z0);
    for (unsigned j = 0; j < n; ++j) {
      const double a = 2.0 * j * M_PI / n;
      const Vec3 r = ellipse ? Vec3(Y * std::cos(a) * rho + Z * std::sin(a) * rho_focal)
                             : Vec3((Y * std::cos(a) + Z * std::sin(a)) * rho);
      for (int k = 0; k < 3; ++k) x[(p * n + j) * 3 + k] = c[k] + r[k];
    }
  }
  return true;
}

const std::vector<unsigned>& Edge2QuadTopologicalMapping::edge_to_quads(unsigned edge) const {
  static const std::vector<unsigned> none;
  return edge < edge_to_quads_.size() ? edge_to_quads_[edge] : none;
}

void Edge2QuadTopologicalMapping::set_edge_quads(unsigned edge, std::vector<unsigned> quads) {
  if (edge >= edge_to_quads_.size()) edge_to_quads_.resize(edge + 1);
  edge_to_quads_[edge] = std::move(quads);
}

bool Edge2QuadTopologicalMapping::input_elements(unsigned out, std::vector<unsigned>& in) const {
  if (out >= quad_to_edge_.size()) return false;
  in.push_back(quad_to_edge_[out]);
  return true;
}

void Edge2QuadTopologicalMapping::update_top_down() {
  if (!input || !output || !to_quad_modifier || state() != ComponentState::valid) return;
  // Handlers below queue events on the output only; the input's list is stable here.
  const std::vector<TopologyChange> changes = input->topology_changes();
  for (const TopologyChange& c : changes) {
    switch (c.type) {
      case TopologyChangeType::ending: to_quad_modifier->notify_ending_event(); break;
      case TopologyChangeType::edges_added: on_edges_added(c.indices); break;
      case TopologyChangeType::edges_removed: on_edges_removed(c.indices); break;
      case TopologyChangeType::points_added: on_points_added(c); break;
      default: break;  // SOFA relays nothing else (point removals included)
    }
  }
}

// Received after the input changed: the new edges can be read. SOFA never flips these quads.
void Edge2QuadTopologicalMapping::on_edges_added(const std::vector<unsigned>& added) {
  const unsigned n = nb_points_on_each_circle.value();
  const std::vector<Edge>& edges = input->edges();
  std::vector<Quad> create;
  for (unsigned k : added) {
    if (k >= edges.size()) continue;
    const unsigned p0 = edges[k][0], p1 = edges[k][1];
    std::vector<unsigned> out;
    for (unsigned j = 0; j < n; ++j) {
      create.push_back({p0 * n + j, p1 * n + j, p1 * n + (j + 1) % n, p0 * n + (j + 1) % n});
      quad_to_edge_.push_back(k);
      out.push_back(static_cast<unsigned>(quad_to_edge_.size() - 1));
    }
    set_edge_quads(k, std::move(out));
  }
  if (!create.empty()) to_quad_modifier->add_quads(create);
}

// Received before the input changes. For each removed edge (decreasing), SOFA first mirrors the
// input's swap-with-last in its edge → quads map, then walks the N last output quads down from
// the end, swapping their entries with the removed quads' ones, and finally removes the removed
// edge's N quads (as they were numbered when the event arrived for that edge) from the output.
void Edge2QuadTopologicalMapping::on_edges_removed(const std::vector<unsigned>& removed) {
  const unsigned n = nb_points_on_each_circle.value();
  if (n == 0 || input->edges().empty()) return;
  unsigned last = static_cast<unsigned>(input->edges().size() - 1);
  unsigned ind_last = static_cast<unsigned>(output->quads().size());
  const std::size_t nq = quad_to_edge_.size();
  auto swap_entries = [&](unsigned a, unsigned b) {
    if (a < nq && b < nq) std::swap(quad_to_edge_[a], quad_to_edge_[b]);
  };
  for (unsigned k : removed) {
    if (!edge_mapped(k) || edge_to_quads_[k].size() != n || ind_last < n || quad_to_edge_.size() < n) {
      msg_info("input edge " + std::to_string(k) + " has no quads of its own in the output; not removed");
      --last;
      continue;
    }
    const std::vector<unsigned> ind_k = edge_to_quads_[k];  // also the quads removed below
    --ind_last;
    if (edge_mapped(last) && k != last) {
      const std::vector<unsigned> ind_real_last = edge_to_quads_[last];
      set_edge_quads(k, ind_real_last);
      set_edge_quads(last, ind_k);
      for (unsigned j = 0; j < n && j < ind_real_last.size(); ++j) swap_entries(ind_real_last[j], ind_k[j]);
    }
    if (ind_k[n - 1] != ind_last && ind_last < nq && ind_k[n - 1] < nq) {
      set_edge_quads(quad_to_edge_[ind_last], ind_k);
      std::vector<unsigned> tail;
      for (unsigned j = 0; j < n; ++j) tail.push_back(ind_last - j);
      set_edge_quads(quad_to_edge_[ind_k[n - 1]], std::move(tail));
      swap_entries(ind_k[n - 1], ind_last);
    }
    for (unsigned j = 1; j < n; ++j) {
      --ind_last;
      if (ind_k[n - 1 - j] != ind_last) swap_entries(ind_k[n - 1 - j], ind_last);
    }
    const unsigned gone = quad_to_edge_.back();
    if (gone < edge_to_quads_.size()) edge_to_quads_[gone].clear();
    quad_to_edge_.resize(quad_to_edge_.size() - n);
    to_quad_modifier->remove_quads(ind_k, true, true);
    --last;
  }
}

// SOFA's relay of added input points: N output points each, with their DoFs. Its ancestor and
// coefficient rows accumulate over the rings (row j holds the entries of rings 0..j) and the
// coefficients go through the same a·N + j transform as the indices; reproduced as is.
void Edge2QuadTopologicalMapping::on_points_added(const TopologyChange& c) {
  const unsigned n = nb_points_on_each_circle.value();
  const unsigned added = static_cast<unsigned>(c.indices.size());
  if (n == 0 || added == 0) return;
  std::vector<std::vector<unsigned>> ancestors;
  std::vector<std::vector<double>> coefficients;
  const bool with_rows = c.ancestors.size() == added && c.coefficients.size() == added;
  if (with_rows) {
    for (unsigned i = 0; i < added; ++i) {
      std::vector<unsigned> row_a;
      std::vector<double> row_c;
      for (unsigned j = 0; j < n; ++j) {
        for (unsigned a : c.ancestors[i]) row_a.push_back(a * n + j);
        for (double w : c.coefficients[i]) row_c.push_back(w * n + j);
        ancestors.push_back(row_a);
        coefficients.push_back(row_c);
      }
    }
  }
  to_quad_modifier->add_points(added * n, std::move(ancestors), std::move(coefficients), true);
}

void register_edge2_quad_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Edge2QuadTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where EdgeSetTopology is converted to QuadSetTopology (a tube around a beam)";
  info.create = creator<Edge2QuadTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
