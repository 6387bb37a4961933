// VisualMesh (SOFA's Sofa.Component.Visual): draws every element of a topology, each shrunk
// towards its centre by `elementSpace`, with SOFA's DrawMesh colours per face (or per-vertex
// values through a colour map). Drawn by src/render (draw_visual_mesh.cpp); batch runs only
// check its inputs.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

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

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
};

}  // namespace sinew
