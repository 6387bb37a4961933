// VisualVectorField (SOFA's Sofa.Component.Visual): draws one vector per
// position (lines, cylinders or arrows) in a viewer. A batch run draws
// nothing; the Data are those of SOFA's component so scenes link and write
// them as in SOFA (vector="@dofs.lambda", Python setting vectorScale).
#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "core/value_text.h"

namespace sinew {

namespace {

class VisualVectorField final : public VisualComponent {
 public:
  Field<bool> enable{this, "enable", true, "draw this model", "Visualization"};
  Field<std::vector<Vec3>> position{this, "position", {}, "starting point of each vector", "Vector", "length"};
  Field<std::vector<Vec3>> vector{this, "vector", {}, "the vectors to draw", "Vector"};
  Field<double> vector_scale{this, "vectorScale", 1.0, "scale applied to the vectors when drawn", "Vector"};
  Field<std::string> draw_mode{this, "drawMode", "Line", "how vectors are drawn: Line, Cylinder or Arrow",
                               "Visualization"};
  Field<std::string> color{this, "color", "1 1 1 1", "colour of the vectors (name, #rrggbb or r g b a)",
                           "Visualization"};

  void init() override {
    const std::string& m = draw_mode.value();
    // SOFA's selectable items keep the default when given an unknown key.
    if (m != "Line" && m != "Cylinder" && m != "Arrow") {
      msg_warning("drawMode " + quote_value(m) + " is not Line, Cylinder or Arrow: Line is used");
      draw_mode.set("Line");
    }
  }
};

}  // namespace

void register_visual_vector_field(Registry& r) {
  ComponentInfo info;
  info.name = "VisualVectorField";
  info.category = "Visual";
  info.description = "draws a vector at each position (viewer only; no effect in batch runs)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<VisualVectorField>();
  r.add(std::move(info));
}

}  // namespace sinew
