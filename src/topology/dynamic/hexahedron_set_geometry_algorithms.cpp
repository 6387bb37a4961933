#include "topology/dynamic/hexahedron_set_geometry_algorithms.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/hexahedron_set_topology_container.h"

namespace sinew {

void register_hexahedron_set_geometry_algorithms(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronSetGeometryAlgorithms";
  info.category = "Topology";
  info.description = "Geometry algorithms dedicated to an hexahedral topology";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.create = creator<HexahedronSetGeometryAlgorithms>();
  r.add(std::move(info));
}

}  // namespace sinew
