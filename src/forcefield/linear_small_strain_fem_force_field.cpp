#include "forcefield/linear_small_strain_fem_force_field.h"

#include "core/registry.h"

namespace sinew {

void register_linear_small_strain_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "LinearSmallStrainFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "Hooke's law assuming small strain (element-generic FEM on tetrahedra or hexahedra)";
  info.templates = {"Vec3d,Tetrahedron", "Vec3d,Hexahedron"};
  info.default_template = "Vec3d,Tetrahedron";
  info.requirement = Requirement::none;  // the Vec3d state is checked at init
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    return std::make_unique<LinearSmallStrainFEMForceField>(fem_element_kind_from_template(tmpl));
  };
  r.add(std::move(info));
}

}  // namespace sinew
