// Colour text as SOFA's RGBAColor reads it: a name (white, red, lime, navy,
// ...), #rgb, #rgba, #rrggbb, #rrggbbaa, or "r g b" / "r g b a" in [0, 1].
#pragma once

#include <array>
#include <optional>
#include <string>

namespace sinew {

using Rgba = std::array<float, 4>;

// nullopt when the text is none of SOFA's colour forms.
std::optional<Rgba> parse_rgba(const std::string& text);

}  // namespace sinew

namespace sinew {

class Component;
class Diagnostics;
template <class T>
class Field;

// Load-time check of a colour field (SOFA's RGBAColor Data): an error naming
// the component and the field when the text is not a colour.
void check_color_field(const Component& c, const Field<std::string>& f, Diagnostics& diag);

}  // namespace sinew
