#include "core/init_checks.h"

#include "core/node.h"

namespace sinew {

bool require_vec3_state(ForceField& c) {
  if (c.mstate->state_type() == StateType::vec3) return true;
  c.msg_error("only Vec3d states are supported");
  c.set_state(ComponentState::invalid);
  return false;
}

bool bind_node_topology(ForceField& c, Link<MeshTopologyBase>& topology, std::string_view requirement) {
  if (!topology) topology.set(c.node()->get_mesh_topology_link());
  if (topology) return true;
  c.msg_error("no topology found (" + std::string(requirement) + ")");
  c.set_state(ComponentState::invalid);
  return false;
}

bool triangle_in_state(const ForceField& c, std::size_t i, const Triangle& t, std::size_t n_points) {
  if (t[0] < n_points && t[1] < n_points && t[2] < n_points) return true;
  c.msg_error("triangle " + std::to_string(i) + " refers to a point >= " + std::to_string(n_points) +
              " (the number of points of the state)");
  return false;
}

}  // namespace sinew
