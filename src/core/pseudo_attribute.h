// Pseudo-attributes: numbers a component parses itself (SOFA's MechanicalObject `dx`,
// `rx`, `scale`, a grid's `xmin`...`zmax`, `nx`), not fields.
#pragma once

#include <string>
#include <string_view>

namespace sinew {

class Component;
class Diagnostics;

// Reads one pseudo-attribute of `c` as a number into `out`. False, with a warning at the
// component's line naming it, when the text is not a number: a link ("@a.b", which only
// fields follow, as in SOFA) or garbage leaves `out` as the number's prefix gives it (0 for
// none, as SOFA's atof), but never silently.
bool read_pseudo_number(const Component& c, Diagnostics& diag, std::string_view key, const std::string& text,
                        double& out);

}  // namespace sinew
