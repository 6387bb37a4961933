// NodalMassDensity: a mass density per node (kg/m³), read by FEMMass
// (spec/mechanics.md §1.4). Node i uses property[i], else the last value,
// else 1.
#pragma once

#include "core/component.h"

namespace sinew {

class NodalMassDensity final : public Component {
 public:
  Field<std::vector<double>> property{this, "property", {1.0}, "mass density at each node (kg/m³)"};

  double node_property(std::size_t i) const {
    const auto& p = property.get();
    if (i < p.size()) return p[i];
    if (!p.empty()) return p.back();
    return 1.0;
  }
};

}  // namespace sinew
