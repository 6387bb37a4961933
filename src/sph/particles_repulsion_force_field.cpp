#include "sph/particles_repulsion_force_field.h"

#include <cmath>
#include <string>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "sph/spatial_grid_container.h"

namespace sinew {

void ParticlesRepulsionForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (!(distance.value() > 0))
    diag.error(where, describe() + ": distance must be positive (got " + parse::format_double(distance.value()) + ")");
}

void ParticlesRepulsionForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d state (got " + std::string(mstate->info().name) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (!node()->find_up<SpatialGridContainer>())
    msg_error("no SpatialGridContainer in this node or above: the slow O(n²) neighbour search is used");
}

void ParticlesRepulsionForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  const double h = distance.value();
  const double h2 = h * h;
  const double ks = stiffness.value();
  const double kd = damping.value();
  const std::size_t n = x.size() / 3;
  pair_i_.clear();
  pair_j_.clear();
  SpatialGridContainer* grid = node()->find_up<SpatialGridContainer>();
  if (grid && grid->state() == ComponentState::valid) {
    grid->update(x);
    grid->grid().for_each_pair(h, [&](std::uint32_t a, std::uint32_t b, double) {
      pair_i_.push_back(a < b ? a : b);
      pair_j_.push_back(a < b ? b : a);
    });
  } else {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const double dx = x[3 * j] - x[3 * i], dy = x[3 * j + 1] - x[3 * i + 1], dz = x[3 * j + 2] - x[3 * i + 2];
        if (dx * dx + dy * dy + dz * dz < h2) {
          pair_i_.push_back(static_cast<std::uint32_t>(i));
          pair_j_.push_back(static_cast<std::uint32_t>(j));
        }
      }
  }
  // Rows by lower index, pairs of a row in the order found.
  row_start_.assign(n + 1, 0);
  for (std::uint32_t i : pair_i_) ++row_start_[i + 1];
  for (std::size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
  nb_j_.resize(pair_i_.size());
  for (std::size_t k = 0; k < pair_i_.size(); ++k) nb_j_[row_start_[pair_i_[k]]++] = pair_j_[k];
  for (std::size_t i = n; i > 0; --i) row_start_[i] = row_start_[i - 1];
  row_start_[0] = 0;

  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = row_start_[i]; e < row_start_[i + 1]; ++e) {
      const std::uint32_t j = nb_j_[e];
      double nv[3] = {x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1], x[3 * j + 2] - x[3 * i + 2]};
      const double d2 = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
      if (d2 == 0.0 || !(d2 < h2)) continue;
      double d = std::sqrt(d2);
      for (double& c : nv) c /= d;
      d -= h;
      const double fi = ks * d, di = kd * d;
      for (int c = 0; c < 3; ++c) {
        const double force = nv[c] * fi - (v[3 * j + c] - v[3 * i + c]) * di;
        f[3 * i + c] += force;
        f[3 * j + c] -= force;
      }
    }
}

void ParticlesRepulsionForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(kPosition);
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  const double h = distance.value();
  const double h2 = h * h;
  const double ks = stiffness.value() * kfactor;
  const std::size_t n = row_start_.empty() ? 0 : row_start_.size() - 1;
  if (x.size() / 3 < n) return;  // the pairs are stale (particles removed since add_force)
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t e = row_start_[i]; e < row_start_[i + 1]; ++e) {
      const std::uint32_t j = nb_j_[e];
      const double nv[3] = {x[3 * j] - x[3 * i], x[3 * j + 1] - x[3 * i + 1], x[3 * j + 2] - x[3 * i + 2]};
      const double d2 = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
      if (d2 == 0.0 || !(d2 < h2)) continue;
      double dot = (dx[3 * j] - dx[3 * i]) * nv[0];
      dot += (dx[3 * j + 1] - dx[3 * i + 1]) * nv[1];
      dot += (dx[3 * j + 2] - dx[3 * i + 2]) * nv[2];
      const double s = (ks * dot) / d2;
      for (int c = 0; c < 3; ++c) {
        const double dfc = nv[c] * s;
        df[3 * i + c] += dfc;
        df[3 * j + c] -= dfc;
      }
    }
}

void register_particles_repulsion_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "ParticlesRepulsionForceField";
  info.category = "SPH";
  info.description = "short-range repulsion between close particles (SofaSphFluid)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<ParticlesRepulsionForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
