// LineAxis (SOFA's Sofa.Component.Visual): the coordinate axes through the origin, x red,
// y green, z blue, drawn unlit by src/render: segments of `size` centred on the origin, or, with
// `infinite`, lines across the scene's bounding box.
#pragma once

#include <string>

#include "core/roles.h"

namespace sinew {

class LineAxis final : public VisualComponent {
 public:
  Field<std::string> axis{this, "axis", "xyz", "axes to draw (letters x, y, z, either case)", "Visualization"};
  Field<double> size{this, "size", 10.0, "length of the lines", "Visualization", "length"};
  Field<bool> infinite{this, "infinite", false, "draw lines across the scene instead of `size`", "Visualization"};
  Field<double> thickness{this, "thickness", 1.0, "thickness of the lines (pixels)", "Visualization"};
  Field<bool> vanishing{this, "vanishing", false, "infinite lines fade away (not drawn: they end at the scene)",
                        "Visualization"};
  Field<int> nb_line_segments{this, "nbLineSegments", 1, "segments per axis line", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  // Whether axis k (0 x, 1 y, 2 z) is drawn (SOFA's updateLine: its letter in `axis`).
  bool draws(int k) const;
};

}  // namespace sinew
