#include "forcefield/hyperelastic/standard_tetrahedral_fem_force_field.h"

#include "core/registry.h"

namespace sinew {

void register_standard_tetrahedral_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "StandardTetrahedralFEMForceField";
  info.category = "ForceField/FEM";
  info.description =
      "hyperelastic tetrahedral finite elements through the elasticity tensor (ArrudaBoyce, StVenantKirchhoff, "
      "NeoHookean, MooneyRivlin, VerondaWestman, Costa, Ogden)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<StandardTetrahedralFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
