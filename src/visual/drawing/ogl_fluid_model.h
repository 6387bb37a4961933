// OglFluidModel (SofaSphFluid's screen-space fluid rendering): SOFA splats each particle as a
// sphere sprite to depth and thickness buffers, blurs them and shades the result as a surface;
// src/render/fluid_surface.h draws it so. A visual component, so it lives in src/visual although
// it comes with the SPH plugin.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class OglFluidModel final : public VisualComponent {
 public:
  Field<bool> enable{this, "enable", true, "display the object or not", "Visualization"};
  Field<std::vector<Vec3>> position{this, "position", {}, "particle positions (usually linked to a state)",
                                    "Vector", "length"};
  Field<unsigned> debug_fbo{this, "debugFBO", 9u, "render pass shown for debugging (9: final picture)",
                            "Visualization"};
  Field<double> sprite_radius{this, "spriteRadius", 1.0, "radius of the sprites", "Visualization", "length"};
  Field<double> sprite_thickness{this, "spriteThickness", static_cast<double>(0.01f), "thickness of a sprite",
                                 "Visualization"};
  Field<double> sprite_blur_radius{this, "spriteBlurRadius", 10.0, "blur radius (pixels)", "Visualization"};
  Field<double> sprite_blur_scale{this, "spriteBlurScale", static_cast<double>(0.1f), "blur scale",
                                  "Visualization"};
  Field<double> sprite_blur_depth_falloff{this, "spriteBlurDepthFalloff", 1.0, "blur depth falloff",
                                          "Visualization"};
  Field<std::string> sprite_diffuse_color{this, "spriteDiffuseColor", "0 0 1 1", "diffuse colour of the fluid",
                                          "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;

};

}  // namespace sinew
