#include "projective/fixed_plane_projective_constraint.h"

#include <algorithm>
#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "projective/indices_in_state.h"

namespace sinew {

void FixedPlaneProjectiveConstraint::init() {
  ProjectiveConstraint::init();
  if (state() != ComponentState::valid) return;
  const StateTypeInfo& ti = mstate->info();
  const bool rigid = ti.coord_width != ti.deriv_width;
  projected_ = rigid ? ti.spatial_dim : ti.deriv_width;

  // The direction is a coordinate of the state: missing entries are zero (a
  // rigid's orientation is the identity), extra entries are dropped.
  const std::vector<double>& d = direction.get();
  dir_.assign(static_cast<std::size_t>(ti.coord_width), 0.0);
  if (rigid) dir_.back() = 1.0;
  if (d.size() > dir_.size())
    msg_warning("direction has " + std::to_string(d.size()) + " values, a " + ti.name + " coordinate has " +
                std::to_string(ti.coord_width) + "; the extra values are ignored");
  for (std::size_t c = 0; c < d.size() && c < dir_.size(); ++c) dir_[c] = d[c];
  bool zero = true;
  for (int c = 0; c < projected_; ++c) zero = zero && dir_[c] == 0.0;
  if (zero) msg_warning("direction is zero: the constraint has no effect");

  std::vector<unsigned> all = indices.get();
  // As SOFA: the points are selected only when the two planes differ.
  const double lo = dmin.get(), hi = dmax.get();
  if (lo > hi)
    msg_warning("dmin (" + std::to_string(lo) + ") is greater than dmax (" + std::to_string(hi) +
                "): no point lies between the planes");
  if (lo != hi) {
    const std::vector<double>& x = mstate->read(kPosition);
    const std::size_t cw = static_cast<std::size_t>(ti.coord_width);
    std::size_t added = 0;
    for (std::size_t i = 0; i < mstate->size(); ++i) {
      double s = 0.0;
      for (int c = 0; c < projected_; ++c) s += x[i * cw + c] * dir_[c];
      if (s > lo && s < hi) {
        all.push_back(static_cast<unsigned>(i));
        ++added;
      }
    }
    // SOFA appends the selected points to its `indices` Data; do the same when
    // the field is ours to write (not fed by a link or an engine).
    if (added > 0 && !indices.parent() && !indices.producer()) indices.set(all);
  }
  keep_indices_in_state(*this, all, mstate->size(), active_);
  follow_.bind(&indices, {&active_});
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
}

void FixedPlaneProjectiveConstraint::project_response(int dx) {
  std::vector<double>& v = mstate->write(dx);
  const std::size_t w = static_cast<std::size_t>(mstate->info().deriv_width);
  for (unsigned i : active_) {
    double* p = v.data() + i * w;
    double s = 0.0;
    for (int c = 0; c < projected_; ++c) s += p[c] * dir_[c];
    for (int c = 0; c < projected_; ++c) p[c] -= dir_[c] * s;
  }
}

// Entries on constrained DOFs lose their component along the direction (SOFA adds −dir·(val·dir)).
void FixedPlaneProjectiveConstraint::project_jacobian(ConstraintMatrix& J) {
  J.compress();
  for (std::size_t e = 0; e < J.entries().size(); ++e) {
    const int dof = J.entries()[e].dof;
    if (std::find(active_.begin(), active_.end(), static_cast<unsigned>(dof)) == active_.end()) continue;
    double* p = J.value(static_cast<int>(e));
    double s = 0.0;
    for (int c = 0; c < projected_; ++c) s += p[c] * dir_[c];
    for (int c = 0; c < projected_; ++c) p[c] -= dir_[c] * s;
  }
}

bool FixedPlaneProjectiveConstraint::dirichlet_indices(std::vector<std::size_t>& out) {
  // Every derivative component whose coordinate entry of the direction is non-zero.
  const std::size_t w = static_cast<std::size_t>(mstate->info().deriv_width);
  for (unsigned i : active_)
    for (std::size_t c = 0; c < w; ++c)
      if (dir_[c] != 0.0) out.push_back(i * w + c);
  return true;
}

void register_fixed_plane_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "FixedPlaneProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "keeps the points between two parallel planes from moving along the planes' normal";
  info.templates = {"Vec3d", "Vec6d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<FixedPlaneProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
