// VisualBoundingBox: the box is its `bbox` (min x y z, max x y z), drawn as
// lines of colour `color`.
#pragma once

#include <optional>
#include <utility>

#include "core/roles.h"

namespace sinew {

class VisualBoundingBox final : public VisualComponent {
 public:
  Field<std::vector<double>> bbox{this, "bbox", {}, "box drawn: min x y z, max x y z", "Visualization"};
  Field<std::string> color{this, "color", "yellow", "colour of the lines", "Visualization"};
  Field<double> thickness{this, "thickness", 1.0, "line width in pixels", "Visualization"};
  Field<bool> enable{this, "enable", true, "draw the box", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  // The corners (min, max); nullopt for an empty or inverted box.
  std::optional<std::pair<Vec3, Vec3>> box() const;
};

}  // namespace sinew
