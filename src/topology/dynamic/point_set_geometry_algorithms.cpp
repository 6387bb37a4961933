#include "topology/dynamic/point_set_geometry_algorithms.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/point_set_topology_container.h"

namespace sinew {

void PointSetGeometryAlgorithms::init() {
  // Topology: the link, else the node's topology link (last topology of the node, else ancestors').
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  state_ptr_ = node() ? node()->get_mechanical_state() : nullptr;
  if (!topology) {
    msg_error("no topology found in this node or its ancestors");
    set_state(ComponentState::invalid);
    return;
  }
  if (!state_ptr_) msg_error("Unable to get a valid state from the context");
}

void register_point_set_geometry_algorithms(Registry& r) {
  ComponentInfo info;
  info.name = "PointSetGeometryAlgorithms";
  info.category = "Topology";
  info.description = "Geometry algorithms dedicated to a point topology";
  info.templates = {"Vec3d", "Vec2d", "Vec1d"};
  info.default_template = "Vec3d";
  info.create = creator<PointSetGeometryAlgorithms>();
  r.add(std::move(info));
}

}  // namespace sinew
