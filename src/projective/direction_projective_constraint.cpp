#include "projective/direction_projective_constraint.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "projective/indices_in_state.h"

namespace sinew {

void DirectionProjectiveConstraint::init() {
  if (!init_state_of_type(*this, type_)) return;
  d_ = mstate->info().spatial_dim;
  follow_.bind(&indices);
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
  drop_indices_beyond_state(*this, indices, mstate->size());
  reinit();
}

void DirectionProjectiveConstraint::reinit() {
  if (state() != ComponentState::valid) return;
  const std::vector<double>& given = direction.get();
  if (given.size() > static_cast<std::size_t>(d_))
    msg_warning("direction has " + std::to_string(given.size()) + " values, a point of this state has " +
                std::to_string(d_) + "; the extra values are ignored");
  n_.assign(static_cast<std::size_t>(d_), 0.0);
  for (int c = 0; c < d_ && c < static_cast<int>(given.size()); ++c) n_[c] = given[c];
  double n2 = n_[0] * n_[0];
  for (int c = 1; c < d_; ++c) n2 += n_[c] * n_[c];
  const double norm = std::sqrt(n2);
  if (norm == 0) {
    msg_warning("direction is zero: the listed DoFs cannot move at all");
  } else {
    const double inv = 1 / norm;
    for (double& c : n_) c *= inv;
  }
  direction.set(n_);
  P_.assign(static_cast<std::size_t>(d_ * d_), 0.0);
  for (int i = 0; i < d_; ++i)
    for (int j = 0; j < d_; ++j) P_[i * d_ + j] = n_[i] * n_[j];

  // SOFA's fill: DoFs in order, the cursor in the sorted indices advancing on each match.
  std::vector<unsigned> sorted = indices.get();
  std::sort(sorted.begin(), sorted.end());
  const std::size_t nb = mstate->size();
  projected_.assign(nb, 0);
  auto it = sorted.begin();
  for (std::size_t i = 0; i < nb; ++i)
    if (it != sorted.end() && i == *it) {
      projected_[i] = 1;
      ++it;
    }

  const std::vector<double>& x = mstate->read(kPosition);
  const int cw = mstate->info().coord_width;
  for (unsigned id : indices.get())
    for (int c = 0; c < d_; ++c) origin_.push_back(x[id * cw + c]);
}

void DirectionProjectiveConstraint::project_response(int dx) {
  if (state() != ComponentState::valid) return;
  std::vector<double>& v = mstate->write(dx);
  const std::size_t n = std::min(mstate->size(), projected_.size());
  double in[3];
  for (std::size_t i = 0; i < n; ++i) {
    if (!projected_[i]) continue;
    double* p = &v[i * d_];
    for (int c = 0; c < d_; ++c) in[c] = p[c];
    for (int r = 0; r < d_; ++r) {
      double s = P_[r * d_] * in[0];
      for (int c = 1; c < d_; ++c) s += P_[r * d_ + c] * in[c];
      p[r] = s;
    }
  }
}

void DirectionProjectiveConstraint::project_jacobian(ConstraintMatrix& J) {
  if (J.empty() || warned_rows_) return;
  warned_rows_ = true;
  msg_error("cannot project Lagrangian constraint rows (SOFA does not either); the rows on its DoFs are kept");
}

void DirectionProjectiveConstraint::project_position(int xid, double) {
  if (state() != ComponentState::valid) return;
  std::vector<double>& x = mstate->write(xid);
  const int cw = mstate->info().coord_width;
  const std::size_t n = mstate->size(), n_origins = origin_.size() / d_;
  const std::vector<unsigned>& idx = indices.get();
  for (std::size_t k = 0; k < idx.size() && k < n_origins; ++k) {
    if (idx[k] >= n) continue;
    double* p = &x[idx[k] * cw];
    const double* o = &origin_[k * d_];
    double s = (p[0] - o[0]) * n_[0];
    for (int c = 1; c < d_; ++c) s += (p[c] - o[c]) * n_[c];
    for (int c = 0; c < d_; ++c) p[c] = o[c] + n_[c] * s;
  }
}

void register_direction_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "DirectionProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "keeps points on the line through their initial position along a direction";
  info.templates = {"Vec3d", "Vec2d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<DirectionProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
