// VisualMesh (SOFA's Sofa.Component.Visual): draws every element of a
// topology (tetrahedra, hexahedra, prisms, pyramids, triangles, quads),
// each shrunk towards its centre by `elementSpace`, optionally coloured by
// per-vertex values through a colour map. A viewer-side component: batch
// runs only check its inputs.
#include <sstream>
#include <string>
#include <vector>

#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"
#include "core/value_text.h"
#include "visual/color.h"

namespace sinew {

namespace {

// SOFA's ColorMap text: a preset name or a list of colours.
bool is_color_map_text(const std::string& text) {
  static const char* const presets[] = {"Red to Blue",   "Blue to Red",    "Yellow to Cyan", "Cyan to Yellow",
                                        "Red to Yello",  "Yellow to Red",  "Yellow to Green", "Green to Yellow",
                                        "Green to Cyan", "Cyan to Green",  "Cyan to Blue",   "Blue to Cyan",
                                        "Red",           "RedInv",         "Green",          "GreenInv",
                                        "Blue",          "BlueInv",        "HSV"};
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) return true;
  for (const char* p : presets)
    if (text == p) return true;
  std::istringstream in(text);
  std::string word;
  while (in >> word)
    if (!parse_rgba(word)) return false;
  return true;
}

class VisualMesh final : public VisualComponent {
 public:
  Field<std::vector<Vec3>> position{this, "position", {}, "positions of the mesh vertices", "Vector", "length"};
  Field<double> element_space{this, "elementSpace", 0.15, "gap between elements, as a fraction of their size (0 to 1)",
                              "Visualization"};
  Field<bool> lighting{this, "lighting", true, "shade the mesh with the lights", "Visualization"};
  Field<std::vector<double>> vertex_values{this, "vertexValues", {}, "one value per vertex, drawn through colorMap",
                                           "Visualization"};
  Field<std::string> color_map{this, "colorMap", "", "colour map of vertexValues: a preset (HSV, Blue to Red, ...) "
                               "or a list of colours (empty: SOFA's default)", "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the mesh", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology whose elements are drawn (default: the node's)"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    const double s = element_space.value();
    if (!(s >= 0.0 && s <= 1.0))
      diag.error(where, describe() + ": elementSpace " + std::to_string(s) + " is not in [0, 1]");
    if (color_map.link_path().empty() && !is_color_map_text(color_map.value()))
      diag.error(where, describe() + ": colorMap " + quote_value(color_map.value()) +
                            " is neither a preset name nor a list of colours");
  }

  void init() override {
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
};

}  // namespace

void register_visual_mesh(Registry& r) {
  ComponentInfo info;
  info.name = "VisualMesh";
  info.category = "Visual";
  info.description = "draws the elements of a volumetric or surface topology (viewer only)";
  info.create = creator<VisualMesh>();
  r.add(std::move(info));
}

}  // namespace sinew
