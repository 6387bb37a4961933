#include "visual/rendering2d/ogl_color_map.h"

#include <algorithm>

#include "core/diagnostics.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "visual/color_map.h"

namespace sinew {

void OglColorMap::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  const auto& schemes = color_map_schemes();
  if (std::find(schemes.begin(), schemes.end(), color_scheme.value()) == schemes.end())
    diag.error(where, describe() + ": colorScheme " + quote_value(color_scheme.value()) +
                          " is not one of OglColorMap's schemes (see `sinew components OglColorMap`)");
}

void OglColorMap::init() {
  if (palette_size.get() < 2)
    msg_warning("paletteSize " + std::to_string(palette_size.get()) + " is below 2: 256 colours are used");
}

const std::vector<Rgba>& OglColorMap::palette() const {
  if (scheme_version_ != color_scheme.version() || size_version_ != palette_size.version() || palette_.empty()) {
    palette_ = build_palette(palette_size.get(), color_scheme.get());
    scheme_version_ = color_scheme.version();
    size_version_ = palette_size.version();
  }
  return palette_;
}

void register_ogl_color_map(Registry& r) {
  ComponentInfo info;
  info.name = "OglColorMap";
  info.category = "Visual";
  info.description = "colour palette turning values into colours, with an on-screen legend (viewer only)";
  info.create = creator<OglColorMap>();
  r.add(std::move(info));
}

}  // namespace sinew
