// Registration of LinearVelocityProjectiveConstraint (linear_velocity_projective_constraint.h).
#include "projective/linear_velocity_projective_constraint.h"

#include "core/registry.h"
#include "core/state_creator.h"

namespace sinew {

void register_linear_velocity_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "LinearVelocityProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "imposes a velocity interpolated between key times";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<LinearVelocityProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
