#include "visual/drawing/visual_mesh.h"

#include <sstream>
#include <string>
#include <vector>

#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"
#include "core/value_text.h"
#include "visual/color.h"
#include "visual/color_map.h"

namespace sinew {

void VisualMesh::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  const double s = element_space.value();
  if (!(s >= 0.0 && s <= 1.0))
    diag.error(where, describe() + ": elementSpace " + std::to_string(s) + " is not in [0, 1]");
  const std::string& cm = color_map.value();
  if (color_map.link_path().empty() && cm.find_first_not_of(" \t\r\n") != std::string::npos &&
      parse_color_map(cm).empty())
    diag.error(where, describe() + ": colorMap " + quote_value(color_map.value()) +
                          " is neither a preset name nor a list of colours");
}

void VisualMesh::init() {
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology.get()) {
    msg_error("no topology found (topology link empty and none in the node): nothing to draw");
    set_state(ComponentState::invalid);
    return;
  }
  const std::size_t n = position.get().size(), v = vertex_values.get().size();
  if (v != 0 && v != n)
    msg_warning("vertexValues has " + std::to_string(v) + " values for " + std::to_string(n) +
                " vertices: the mesh is drawn without them");
}

void register_visual_mesh(Registry& r) {
  ComponentInfo info;
  info.name = "VisualMesh";
  info.category = "Visual";
  info.description = "draws the elements of a volumetric or surface topology (viewer only)";
  info.create = creator<VisualMesh>();
  r.add(std::move(info));
}

}  // namespace sinew
