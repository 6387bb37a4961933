#include "forcefield/fem/corotational_fem_force_field.h"

#include "core/registry.h"

namespace sinew {

namespace {
// SOFA's default rotation method per element: the 3-node frame for tetrahedra, the averaged-edge
// frame for hexahedra, the SVD polar decomposition for prisms and pyramids.
const char* default_rotation(FemElementKind kind) {
  switch (kind) {
    case FemElementKind::tetrahedron: return "triangle";
    case FemElementKind::hexahedron: return "hexahedron";
    default: return "stable_polar";
  }
}
// The element-specific method name, if any ("" for prisms and pyramids).
std::string specific_rotation(FemElementKind kind) {
  switch (kind) {
    case FemElementKind::tetrahedron: return "triangle";
    case FemElementKind::hexahedron: return "hexahedron";
    default: return "";
  }
}
std::string rotation_choices(FemElementKind kind) {
  const std::string s = specific_rotation(kind);
  return "stable_polar, polar, identity" + (s.empty() ? std::string() : " or " + s);
}
}  // namespace

CorotationalFEMForceField::CorotationalFEMForceField(FemElementKind kind)
    : ElementFEMForceFieldBase(kind),
      rotation_method_f(this, "rotationMethod", default_rotation(kind),
                        "element rotation extraction: " + rotation_choices(kind) +
                            " (triangle: Gram-Schmidt frame of nodes 0, 1, 2; hexahedron: two averaged edges; "
                            "stable_polar: SVD of the deformation about the centroids; polar: Higham's iteration)",
                        "Material") {}

bool CorotationalFEMForceField::rotation_method(fem::RotationMethod& out) {
  const std::string& m = rotation_method_f.get();
  const std::string specific = specific_rotation(element_kind());
  if (m == "polar") out = fem::RotationMethod::polar;
  else if (m == "stable_polar") out = fem::RotationMethod::stable_polar;
  else if (m == "identity") out = fem::RotationMethod::identity;
  else if (m == specific && m == "triangle") out = fem::RotationMethod::triangle;
  else if (m == specific && m == "hexahedron") out = fem::RotationMethod::hexahedron;
  else {
    msg_error("unknown rotationMethod '" + m + "' (expected " + rotation_choices(element_kind()) + ")");
    return false;
  }
  return true;
}

void register_corotational_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "CorotationalFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "corotational linear elasticity (element-generic FEM on tetrahedra, hexahedra, prisms or pyramids)";
  info.templates = {"Vec3d,Tetrahedron", "Vec3d,Hexahedron", "Vec3d,Prism", "Vec3d,Pyramid"};
  info.default_template = "Vec3d,Tetrahedron";
  info.requirement = Requirement::none;  // the Vec3d state is checked at init
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    return std::make_unique<CorotationalFEMForceField>(fem_element_kind_from_template(tmpl));
  };
  r.add(std::move(info));
}

}  // namespace sinew
