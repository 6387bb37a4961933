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
  if (!geometry_state || geometry_state->state_type() != s.state_type())
    return fail("no state compatible with the mass was found for the topology's geometry");
  return true;
}

}  // namespace sinew::meshgeo
