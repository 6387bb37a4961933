#include "forcefield/fem/corotational_fem_force_field.h"

#include "core/registry.h"

namespace sinew {

CorotationalFEMForceField::CorotationalFEMForceField(FemElementKind kind)
    : ElementFEMForceFieldBase(kind),
      rotation_method_f(
          this, "rotationMethod", kind == FemElementKind::hexahedron ? "hexahedron" : "triangle",
          kind == FemElementKind::hexahedron
              ? "element rotation extraction: stable_polar, polar, identity or hexahedron (two averaged edges)"
              : "element rotation extraction: stable_polar, polar, identity or triangle (Gram-Schmidt frame of nodes "
                "0, 1, 2)",
          "Material") {}

bool CorotationalFEMForceField::rotation_method(fem::RotationMethod& out) {
  const std::string& m = rotation_method_f.get();
  const bool hexa = element_kind() == FemElementKind::hexahedron;
  if (m == "polar") out = fem::RotationMethod::polar;
  else if (m == "identity") out = fem::RotationMethod::identity;
  else if (m == "triangle" && !hexa) out = fem::RotationMethod::triangle;
  else if (m == "hexahedron" && hexa) out = fem::RotationMethod::hexahedron;
  else if (m == "stable_polar") {
    msg_error("rotationMethod 'stable_polar' is not supported yet (use polar, identity or " +
              std::string(hexa ? "hexahedron" : "triangle") + ")");
    return false;
  } else {
    msg_error("unknown rotationMethod '" + m + "' (expected stable_polar, polar, identity or " +
              std::string(hexa ? "hexahedron" : "triangle") + ")");
    return false;
  }
  return true;
}

void register_corotational_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "CorotationalFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "corotational linear elasticity (element-generic FEM on tetrahedra or hexahedra)";
  info.templates = {"Vec3d,Tetrahedron", "Vec3d,Hexahedron"};
  info.default_template = "Vec3d,Tetrahedron";
  info.requirement = Requirement::none;  // the Vec3d state is checked at init
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    return std::make_unique<CorotationalFEMForceField>(fem_element_kind_from_template(tmpl));
  };
  r.add(std::move(info));
}

}  // namespace sinew
