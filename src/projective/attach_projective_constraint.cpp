// Registration of AttachProjectiveConstraint (attach_projective_constraint.h).
#include "projective/attach_projective_constraint.h"

#include "core/registry.h"
#include "core/state_creator.h"

namespace sinew {

void register_attach_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "AttachProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "attaches points of one object to points of another by projection";
  info.templates = {"Vec3d", "Vec2d", "Vec1d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::none;
  info.create = state_creator<AttachProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
