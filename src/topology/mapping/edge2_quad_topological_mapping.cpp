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
  auto add_rings = [&](unsigned e, bool edge_list_order) {
    const unsigned p0 = edges[e][0], p1 = edges[e][1];
    for (unsigned j = 0; j < n; ++j) {
      const unsigned q0 = p0 * n + j, q1 = p1 * n + j, q2 = p1 * n + (j + 1) % n, q3 = p0 * n + (j + 1) % n;
      if (!flip) quads.push_back({q0, q1, q2, q3});
      else if (edge_list_order) quads.push_back({q0, q3, q2, q1});
      else quads.push_back({q3, q2, q1, q0});
      quad_to_edge_.push_back(e);
    }
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

void register_edge2_quad_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Edge2QuadTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where EdgeSetTopology is converted to QuadSetTopology (a tube around a beam)";
  info.create = creator<Edge2QuadTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
