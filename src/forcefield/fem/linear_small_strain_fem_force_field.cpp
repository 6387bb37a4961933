#include "forcefield/fem/linear_small_strain_fem_force_field.h"

#include "core/registry.h"

namespace sinew {

std::optional<double> LinearSmallStrainFEMForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  const std::span<const Vec3> x = as_vec3(mstate->read(kPosition));
  const std::span<const Vec3> x0 = as_vec3(mstate->read(kRestPosition));
  if (x.size() != x0.size()) return std::nullopt;
  // The blocks are those of ∂f/∂x = −K.
  double e = 0;
  auto add = [&](unsigned i, unsigned j, const Mat3& b) { e -= 0.5 * (x[i] - x0[i]).dot(b * (x[j] - x0[j])); };
  visit_kernel([&](const auto& kernel) { kernel.stiffness_blocks(add); });
  return e;
}

void register_linear_small_strain_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "LinearSmallStrainFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "Hooke's law assuming small strain (element-generic FEM on tetrahedra, hexahedra, prisms or pyramids)";
  info.templates = {"Vec3d,Tetrahedron", "Vec3d,Hexahedron", "Vec3d,Prism", "Vec3d,Pyramid"};
  info.default_template = "Vec3d,Tetrahedron";
  info.requirement = Requirement::none;  // the Vec3d state is checked at init
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    return std::make_unique<LinearSmallStrainFEMForceField>(fem_element_kind_from_template(tmpl));
  };
  r.add(std::move(info));
}

}  // namespace sinew
