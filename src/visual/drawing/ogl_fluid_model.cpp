#include "visual/drawing/ogl_fluid_model.h"

#include <string>
#include <vector>

#include "core/registry.h"
#include "core/roles.h"
#include "visual/color.h"

namespace sinew {

void OglFluidModel::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, sprite_diffuse_color, diag);
  if (!(sprite_radius.value() > 0)) diag.error(where, describe() + ": spriteRadius must be positive");
  if (sprite_thickness.value() < 0) diag.error(where, describe() + ": spriteThickness must not be negative");
  if (sprite_blur_radius.value() < 0) diag.error(where, describe() + ": spriteBlurRadius must not be negative");
}

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
