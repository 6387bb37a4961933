// Colour palettes as SOFA's helper::ColorMap builds them (the colour schemes of
// OglColorMap), and its evaluator: a value in [vmin, vmax] picks a colour by
// linear interpolation between the two nearest palette entries.
#pragma once

#include <string>
#include <vector>

#include "visual/color.h"

namespace sinew {

// The schemes OglColorMap offers (its `colorScheme` options, in SOFA's order).
const std::vector<std::string>& color_map_schemes();

// The palette of `scheme` with `size` colours (SOFA's ColorMap(paletteSize, name)): a size
// below 2 becomes 256; a name SOFA's ColorMap does not know gives the HSV palette. Two of
// OglColorMap's options are such names: "Custom" and "Red to Yellow" (SOFA's ColorMap spells
// that preset "Red to Yello"), so both give HSV, as in SOFA.
std::vector<Rgba> build_palette(unsigned size, const std::string& scheme);

// SOFA's ColorMap::evaluator: below vmin the first colour, from the last interval on the last
// one, else c_i + (c_{i+1} − c_i)·(e − i) with e = (v − vmin)·(n − 1)/(vmax − vmin)
// (vmax == vmin: e = 0, the first colour). `palette` must not be empty.
Rgba evaluate_palette(const std::vector<Rgba>& palette, double vmin, double vmax, double v);

// SOFA's ColorMap text (its operator>>): empty → nothing (the caller keeps its default); the
// name of one of ColorMap's schemes (HSV, "Red to Blue", ..., SOFA's spelling "Red to Yello")
// → that palette of 256 colours; else a list of colours, each a name, #hex or up to four
// numbers. Empty result for an empty or unreadable text.
std::vector<Rgba> parse_color_map(const std::string& text);

}  // namespace sinew
