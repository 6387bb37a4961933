#include "mass/nodal_mass_density.h"

#include "core/registry.h"

namespace sinew {

void register_nodal_mass_density(Registry& r) {
  ComponentInfo info;
  info.name = "NodalMassDensity";
  info.category = "Mass";
  info.description = "Definition of a nodal mass density (one value per dof).";
  info.create = creator<NodalMassDensity>();
  r.add(std::move(info));
}

}  // namespace sinew
