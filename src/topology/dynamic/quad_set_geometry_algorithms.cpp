#include "topology/dynamic/quad_set_geometry_algorithms.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/quad_set_topology_container.h"

namespace sinew {

void register_quad_set_geometry_algorithms(Registry& r) {
  ComponentInfo info;
  info.name = "QuadSetGeometryAlgorithms";
  info.category = "Topology";
  info.description = "Geometry algorithms dedicated to a quad topology";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.create = creator<QuadSetGeometryAlgorithms>();
  r.add(std::move(info));
}

}  // namespace sinew
