// VisualGrid (SOFA's Sofa.Component.Visual): a square grid of lines through the origin in the
// plane normal to x, y or z, drawn unlit by src/render.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class VisualGrid final : public VisualComponent {
 public:
  Field<std::string> plane{this, "plane", "z", "plane of the grid: normal to x, y or z", "Visualization"};
  Field<double> size{this, "size", 10.0, "side of the square grid", "Visualization", "length"};
  Field<int> nb_subdiv{this, "nbSubdiv", 16, "number of subdivisions", "Visualization"};
  Field<std::string> color{this, "color", "0.34117647058 0.34117647058 0.34117647058 1", "colour of the lines",
                           "Visualization"};
  Field<double> thickness{this, "thickness", 1.0, "thickness of the lines (pixels)", "Visualization"};
  Field<int> nb_line_segments{this, "nbLineSegments", 1, "segments per grid line", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  // SOFA's VisualGrid::buildGrid: the lines' end points, two per segment, in its order.
  void lines(std::vector<Vec3>& out) const;
};

}  // namespace sinew
