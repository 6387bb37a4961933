#include "mass/mesh_geometry.h"

#include "core/node.h"

namespace sinew::meshgeo {

namespace {
template <class V>
std::size_t max_of(const V& elems) {
  std::size_t m = 0;
  for (const auto& e : elems)
    for (unsigned i : e) m = std::max<std::size_t>(m, static_cast<std::size_t>(i) + 1);
  return m;
}
}  // namespace

std::size_t max_index_plus_one(const MeshTopologyBase& t, MassElement k) {
  switch (k) {
    case MassElement::edge: return max_of(t.edges());
    case MassElement::triangle: return max_of(t.triangles());
    case MassElement::quad: return max_of(t.quads());
    case MassElement::tetra: return max_of(t.tetrahedra());
    case MassElement::hexa: return max_of(t.hexahedra());
    case MassElement::none: return 0;
  }
  return 0;
}

bool bind_mesh_mass(Mass& mass, Link<MeshTopologyBase>& topology, Link<MechanicalState>& geometry_state) {
  auto fail = [&](const std::string& why) {
    mass.msg_error(why);
    mass.set_state(ComponentState::invalid);
    return false;
  };
  const MechanicalState& s = *mass.mstate;
  if (s.state_type() != StateType::vec1 && s.state_type() != StateType::vec2 && s.state_type() != StateType::vec3)
    return fail(std::string("template ") + s.info().name + " is not supported (Vec1d, Vec2d, Vec3d only)");
  if (!topology) topology.set(mass.node()->get_mesh_topology_link());
  if (!topology) return fail("no topology found");
  if (!geometry_state) {
    Node* tn = topology->node() ? topology->node() : mass.node();
    geometry_state.set(tn->get_mechanical_state());
  }
  // SOFA's Mass<DataTypes, GeometricalTypes>: the template's second type (else the state's)
  // is the geometry's.
  StateType geometry_type = s.state_type();
  const std::string& tmpl = mass.template_name();
  if (const std::size_t comma = tmpl.find(','); comma != std::string::npos) {
    StateType t;
    if (state_type_from_name(tmpl.substr(comma + 1), t)) geometry_type = t;
  }
  if (!geometry_state || geometry_state->state_type() != geometry_type)
    return fail(std::string("no ") + state_type_info(geometry_type).name +
                " state was found for the topology's geometry (geometryState, or the topology's node state)");
  return true;
}

MassElement checked_mass_element(Mass& mass, const MeshTopologyBase& t, const MechanicalState& geometry) {
  const MassElement k = mass_element(t);
  if (k == MassElement::none) {
    mass.msg_error("the topology " + t.describe() + " is empty");
    mass.set_state(ComponentState::invalid);
    return MassElement::none;
  }
  if ((k == MassElement::tetra || k == MassElement::hexa) && geometry.info().spatial_dim < 3) {
    mass.msg_error("volume elements need a 3D geometry state");
    mass.set_state(ComponentState::invalid);
    return MassElement::none;
  }
  return k;
}

bool mass_elements_in_states(Mass& mass, const MeshTopologyBase& t, MassElement k, std::size_t state_size,
                             std::size_t geometry_size) {
  const std::size_t need = max_index_plus_one(t, k);
  if (need <= state_size && need <= geometry_size) return true;
  mass.msg_error("an element of " + t.describe() + " uses point " + std::to_string(need - 1) +
                 " but the state has " + std::to_string(std::min(state_size, geometry_size)) + " points");
  mass.set_state(ComponentState::invalid);
  return false;
}

void reset_negative_total_mass(Mass& mass, Field<double>& total_mass) {
  if (total_mass.value() < 0) {
    mass.msg_warning("totalMass can not be negative: switching back to totalMass = 1");
    total_mass.set(1.0);
  }
}

bool one_nonnegative_mass_per_point(const std::vector<double>& vertex_mass, std::size_t n_points) {
  bool ok = vertex_mass.size() == n_points;
  for (double v : vertex_mass)
    if (v < 0) ok = false;
  return ok;
}

void add_gravity_velocity(MechanicalState& s, int v, const Vec3& g, double dt) {
  std::vector<double>& vv = s.write(v);
  const int w = s.info().deriv_width;
  double hg[3];
  for (int c = 0; c < w; ++c) hg[c] = g[c] * dt;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int c = 0; c < w; ++c) vv[i * w + c] += hg[c];
}

}  // namespace sinew::meshgeo
