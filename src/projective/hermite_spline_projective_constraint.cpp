// Registration of HermiteSplineProjectiveConstraint (hermite_spline_projective_constraint.h).
#include "projective/hermite_spline_projective_constraint.h"

#include "core/registry.h"
#include "core/state_creator.h"

namespace sinew {

void register_hermite_spline_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "HermiteSplineProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves points along a cubic Hermite spline between two times";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<HermiteSplineProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
