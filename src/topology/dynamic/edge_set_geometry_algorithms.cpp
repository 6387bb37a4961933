#include "topology/dynamic/edge_set_geometry_algorithms.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_container.h"

namespace sinew {

void register_edge_set_geometry_algorithms(Registry& r) {
  ComponentInfo info;
  info.name = "EdgeSetGeometryAlgorithms";
  info.category = "Topology";
  info.description = "Geometry algorithms dedicated to an edge topology";
  info.templates = {"Vec3d", "Vec2d", "Vec1d", "Rigid3d", "Rigid2d"};
  info.default_template = "Vec3d";
  info.create = creator<EdgeSetGeometryAlgorithms>();
  r.add(std::move(info));
}

}  // namespace sinew
