#include "projective/fixed_projective_constraint.h"

#include <algorithm>

#include "core/node.h"
#include "core/registry.h"
#include "projective/indices_in_state.h"

namespace sinew {

FixedProjectiveConstraint::FixedProjectiveConstraint() {}

void FixedProjectiveConstraint::init() {
  ProjectiveConstraint::init();
  if (state() != ComponentState::valid) return;
  keep_indices_in_state(*this, indices.get(), mstate->size(), active_);
  follow_.bind(&indices, {&active_});
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
}

void FixedProjectiveConstraint::zero(int id) {
  std::vector<double>& d = mstate->write(id);
  const int w = mstate->info().deriv_width;
  if (fix_all.value()) {
    std::fill(d.begin(), d.end(), 0.0);
    return;
  }
  // Indices may be re-evaluated when linked to an engine whose inputs changed.
  if (indices.parent() || indices.producer()) {
    const auto& idx = indices.get();
    if (idx.size() != active_.size() || !std::equal(idx.begin(), idx.end(), active_.begin())) init();
  }
  for (unsigned i : active_)
    for (int c = 0; c < w; ++c) d[i * w + c] = 0.0;
}

void FixedProjectiveConstraint::project_response(int dx) { zero(dx); }

// SOFA clears the fixed DOFs' columns (every row with fixAll).
void FixedProjectiveConstraint::project_jacobian(ConstraintMatrix& J) {
  if (fix_all.value()) return J.zero_all();
  for (unsigned i : active_) J.zero_dof(static_cast<int>(i), 0, J.width());
}

void FixedProjectiveConstraint::project_velocity(int v, double) {
  if (activate_project_velocity.value()) zero(v);
}

bool FixedProjectiveConstraint::dirichlet_indices(std::vector<std::size_t>& out) {
  const std::size_t w = static_cast<std::size_t>(mstate->info().deriv_width);
  if (fix_all.value()) {
    for (std::size_t i = 0; i < mstate->size() * w; ++i) out.push_back(i);
    return true;
  }
  for (unsigned i : active_)
    for (std::size_t c = 0; c < w; ++c) out.push_back(i * w + c);
  return true;
}

void register_fixed_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "FixedProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "fixes a set of degrees of freedom";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid2d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<FixedProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
