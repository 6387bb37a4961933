// Registration of the point, line and plane projective constraints (indexed_projections.h).
#include "core/registry.h"
#include "projective/indexed_projections.h"

namespace sinew {

namespace {

template <class T>
void add_vec3(Registry& r, const char* name, const char* what) {
  ComponentInfo info;
  info.name = name;
  info.category = "Constraint/Projective";
  info.description = what;
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<T>();
  r.add(std::move(info));
}

}  // namespace

void register_affine_projective_constraints(Registry& r) {
  add_vec3<PointProjectiveConstraint>(r, "PointProjectiveConstraint", "keeps DoFs on a point");
  add_vec3<LineProjectiveConstraint>(r, "LineProjectiveConstraint", "keeps DoFs on a line");
  add_vec3<PlaneProjectiveConstraint>(r, "PlaneProjectiveConstraint", "keeps DoFs on a plane");
}

}  // namespace sinew
