#include "topology/dynamic/triangle_set_geometry_algorithms.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/triangle_set_topology_container.h"

namespace sinew {

void TriangleSetGeometryAlgorithms::init() {
  EdgeSetGeometryAlgorithms::init();
  if (recompute_triangles_orientation.value()) {
    // Reorienting triangles is a topology change; not available yet.
    msg_error("recomputeTrianglesOrientation is not supported yet");
    set_state(ComponentState::invalid);
  }
}

void register_triangle_set_geometry_algorithms(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleSetGeometryAlgorithms";
  info.category = "Topology";
  info.description = "Geometry algorithms dedicated to a triangular topology";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.create = creator<TriangleSetGeometryAlgorithms>();
  r.add(std::move(info));
}

}  // namespace sinew
