#include "visual/drawing/line_axis.h"

#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

void LineAxis::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  // SOFA looks for the letters and ignores anything else: a warning, not an error.
  if (axis.value().find_first_not_of("xyzXYZ") != std::string::npos)
    diag.warning(where, describe() + ": axis " + quote_value(axis.value()) +
                            " holds characters other than x, y, z; they are ignored");
  if (nb_line_segments.value() < 1) diag.error(where, describe() + ": nbLineSegments must be at least 1");
  if (!(size.value() >= 0)) diag.error(where, describe() + ": size must not be negative");
}

bool LineAxis::draws(int k) const {
  static const char* const letters[3] = {"xX", "yY", "zZ"};
  return axis.get().find_first_of(letters[k]) != std::string::npos;
}

void register_line_axis(Registry& r) {
  ComponentInfo info;
  info.name = "LineAxis";
  info.category = "Visual";
  info.description = "the coordinate axes through the origin (viewer only)";
  info.create = creator<LineAxis>();
  r.add(std::move(info));
}

}  // namespace sinew
