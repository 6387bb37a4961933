// Visual3DText (SOFA's Sofa.Component.Visual): a text facing the camera, its top-left corner at
// a 3D position, drawn by src/render with SOFA's ASCII font texture (render/draw_text.h).
#pragma once

#include <string>

#include "core/roles.h"

namespace sinew {

class Visual3DText final : public VisualComponent {
 public:
  Field<std::string> text{this, "text", "", "the text", "Visualization"};
  Field<Vec3> position{this, "position", Vec3::Zero(), "top-left corner of the text", "Visualization", "length"};
  // float in SOFA: the glyphs' height in world units (each glyph half as wide).
  Field<double> scale{this, "scale", 1.0, "height of the glyphs (world units)", "Visualization", "length"};
  Field<std::string> color{this, "color", "1 1 1 1", "colour of the text", "Visualization"};
  // SOFA disables the depth test whatever this says (Visual3DText::doDrawVisual); kept as SOFA.
  Field<bool> depth_test{this, "depthTest", true, "perform the depth test (not used by SOFA's drawing)",
                         "Visualization"};

  Field<bool> enable{this, "enable", true, "draw the text", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
};

}  // namespace sinew
