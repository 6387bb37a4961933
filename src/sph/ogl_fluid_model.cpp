// OglFluidModel (SofaSphFluid): screen-space fluid rendering of a point set
// (sprites splatted to depth and thickness buffers, blurred, shaded). A
// viewer-side component: batch runs check its inputs; the renderer does not
// draw it yet.
#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

namespace {

class OglFluidModel final : public VisualComponent {
 public:
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

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    check_color_field(*this, sprite_diffuse_color, diag);
    if (!(sprite_radius.value() > 0)) diag.error(where, describe() + ": spriteRadius must be positive");
    if (sprite_thickness.value() < 0) diag.error(where, describe() + ": spriteThickness must not be negative");
    if (sprite_blur_radius.value() < 0) diag.error(where, describe() + ": spriteBlurRadius must not be negative");
  }
};

}  // namespace

void register_ogl_fluid_model(Registry& r) {
  ComponentInfo info;
  info.name = "OglFluidModel";
  info.category = "Visual";
  info.description = "screen-space fluid rendering of particles (SofaSphFluid; viewer only)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = creator<OglFluidModel>();
  r.add(std::move(info));
}

}  // namespace sinew
