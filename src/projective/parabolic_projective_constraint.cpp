// Registration of ParabolicProjectiveConstraint (parabolic_projective_constraint.h).
#include "projective/parabolic_projective_constraint.h"

#include "core/registry.h"
#include "core/state_creator.h"

namespace sinew {

void register_parabolic_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "ParabolicProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves points along a parabola through three points between two times";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<ParabolicProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
