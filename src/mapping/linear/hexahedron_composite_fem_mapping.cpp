#include "mapping/linear/hexahedron_composite_fem_mapping.h"

#include "core/node.h"
#include "core/registry.h"
#include "math/sofa_vec.h"
#include "topology/grid/sparse_grid_ramification_topology.h"

namespace sinew {

namespace {

// Rᵀ·v summed as SOFA's Mat::multTranspose.
Vec3 mult_transpose(const Mat3& R, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = R(0, i) * v[0] + R(1, i) * v[1] + R(2, i) * v[2];
  return r;
}

// W·u (3 × 24 by 24), each row summed in column order.
Vec3 weight_times(const Eigen::Matrix<double, 3, 24>& W, const Eigen::Matrix<double, 24, 1>& u) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    double s = W(i, 0) * u[0];
    for (int j = 1; j < 24; ++j) s += W(i, j) * u[j];
    r[i] = s;
  }
  return r;
}

}  // namespace

bool HexahedronCompositeFEMMapping::init_mapping() {
  Node* in_node = in_[0]->node();
  const auto* grid = dynamic_cast<const SparseGridRamificationTopology*>(in_node->get_mesh_topology_link());
  if (!grid) {
    msg_error("the input " + in_[0]->describe() +
              " must lie on a SparseGridRamificationTopology or SparseGridMultipleTopology");
    return false;
  }
  ff_ = in_node->find_up<HexahedronCompositeFEMForceFieldAndMass>();
  if (!ff_ || ff_->state() != ComponentState::valid) {
    msg_error(std::string("needs a valid HexahedronCompositeFEMForceFieldAndMass beside its input ") +
              in_[0]->describe());
    return false;
  }
  const int levels = ff_->nb_virtual_finer_levels.value();
  if (levels <= 0 || ff_->final_weights().empty() || grid->ramified_levels() < levels) {
    msg_error("the force field " + ff_->describe() +
              " has no homogenized weights (nbVirtualFinerLevels must be > 0, within the grid's virtual levels)");
    return false;
  }
  const auto coarse = grid->ramified_level(0), finest = grid->ramified_level(levels);
  coarse_hexas_.assign(coarse.hexas.begin(), coarse.hexas.end());
  fine_hexas_.assign(finest.hexas.begin(), finest.hexas.end());
  const auto x_in = as_vec3(in_coord(kPosition));
  if (x_in.empty() || coarse.points.empty() || ff_->kernel().size() != coarse_hexas_.size()) {
    msg_error("the input " + in_[0]->describe() + " does not match the grid " + grid->describe());
    return false;
  }
  for (const Hexa& h : coarse_hexas_)
    for (unsigned v : h)
      if (v >= x_in.size()) {
        msg_error("the grid " + grid->describe() + " has more points than the input " + in_[0]->describe());
        return false;
      }
  q_coarse0_.assign(x_in.begin(), x_in.end());
  // The grid is built without rotation: the fine points follow the input's translation only.
  const Vec3 translation0 = x_in[0] - coarse.points[0];
  q_fine0_.clear();
  for (const Vec3& p : finest.points) q_fine0_.push_back(p + translation0);
  q_fine_ = q_fine0_;

  const std::vector<double>& p0 = initial_output_positions();
  const std::size_t n = p0.size() / 3;
  cube_.assign(n, 0);
  bary_.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p(p0[3 * i], p0[3 * i + 1], p0[3 * i + 2]);
    double fx = 0, fy = 0, fz = 0;
    unsigned c = grid->find_cube_on_level(levels, p, fx, fy, fz);
    if (c == MeshTopologyBase::kInvalidIndex) c = grid->find_nearest_cube_on_level(levels, p, fx, fy, fz);
    if (c == MeshTopologyBase::kInvalidIndex || c >= fine_hexas_.size()) {
      msg_error("point " + std::to_string(i) + " of the output is in no cell of the grid's virtual level " +
                std::to_string(levels));
      return false;
    }
    cube_[i] = c;
    bary_[i] = {(1 - fx) * (1 - fy) * (1 - fz), fx * (1 - fy) * (1 - fz), fx * fy * (1 - fz),
                (1 - fx) * fy * (1 - fz),       (1 - fx) * (1 - fy) * fz, fx * (1 - fy) * fz,
                fx * fy * fz,                   (1 - fx) * fy * fz};
  }
  // Each fine point: the rows of its corner in the final weights of every fine hexahedron
  // around it, by coarse hexahedron (a later hexahedron of the same coarse one replaces).
  fine_weights_.assign(q_fine0_.size(), {});
  const auto& finals = ff_->final_weights();
  for (std::size_t h = 0; h < finals.size() && h < fine_hexas_.size(); ++h)
    for (int w = 0; w < 8; ++w)
      fine_weights_[fine_hexas_[h][w]][finals[h].coarse] = finals[h].W.block<3, 24>(3 * w, 0);
  u_.assign(coarse_hexas_.size(), Eigen::Matrix<double, 24, 1>::Zero());
  R_.assign(coarse_hexas_.size(), Mat3::Identity());
  resize_output(n);
  return true;
}

void HexahedronCompositeFEMMapping::coarse_displacements(std::span<const Vec3> in, bool positions) {
  const auto& R = ff_->kernel().R;
  if (positions)
    for (std::size_t i = 0; i < coarse_hexas_.size() && i < R.size(); ++i) R_[i] = R[i];
  for (std::size_t i = 0; i < coarse_hexas_.size(); ++i)
    for (int w = 0; w < 8; ++w) {
      const unsigned v = coarse_hexas_[i][w];
      Vec3 u = sofa_mul(R_[i], in[v]);
      if (positions) u -= q_coarse0_[v];
      for (int c = 0; c < 3; ++c) u_[i][3 * w + c] = static_cast<double>(static_cast<float>(u[c]));
    }
}

void HexahedronCompositeFEMMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const auto in = as_vec3(in_coord(x));
  coarse_displacements(in, true);
  for (std::size_t i = 0; i < q_fine_.size(); ++i) {
    if (fine_weights_[i].empty()) {
      q_fine_[i] = q_fine0_[i];
      continue;
    }
    Vec3 q = Vec3::Zero();
    for (const auto& [coarse, W] : fine_weights_[i])
      q += mult_transpose(R_[coarse], q_fine0_[i] + weight_times(W, u_[coarse]));
    q /= static_cast<double>(fine_weights_[i].size());
    q_fine_[i] = q;
  }
  auto out = as_vec3(*outp);
  for (std::size_t i = 0; i < cube_.size() && i < out.size(); ++i) {
    Vec3 p = Vec3::Zero();
    for (int w = 0; w < 8; ++w) p += q_fine_[fine_hexas_[cube_[i]][w]] * bary_[i][w];
    out[i] = p;
  }
}

void HexahedronCompositeFEMMapping::apply_j(int v, int role) {
  std::vector<double>* outv = out_deriv(v, role);
  if (!outv) return;
  coarse_displacements(as_vec3(in_deriv(v, role)), false);
  fine_d_.assign(q_fine_.size(), Vec3::Zero());
  for (std::size_t i = 0; i < fine_d_.size(); ++i) {
    if (fine_weights_[i].empty()) continue;
    for (const auto& [coarse, W] : fine_weights_[i]) fine_d_[i] += mult_transpose(R_[coarse], weight_times(W, u_[coarse]));
    fine_d_[i] /= static_cast<double>(fine_weights_[i].size());
  }
  auto out = as_vec3(*outv);
  for (std::size_t i = 0; i < cube_.size() && i < out.size(); ++i) {
    Vec3 d = Vec3::Zero();
    for (int w = 0; w < 8; ++w) d += fine_d_[fine_hexas_[cube_[i]][w]] * bary_[i][w];
    out[i] = d;
  }
}

void HexahedronCompositeFEMMapping::apply_jt(int f, int role) {
  const std::vector<double>* outf = out_deriv_read(f, role);
  if (!outf) return;
  const auto fo = as_vec3(*outf);
  fine_d_.assign(q_fine_.size(), Vec3::Zero());
  for (std::size_t i = 0; i < cube_.size() && i < fo.size(); ++i)
    for (int w = 0; w < 8; ++w) fine_d_[fine_hexas_[cube_[i]][w]] += fo[i] * bary_[i][w];
  auto fin = as_vec3(in_deriv_write(f, role));
  for (std::size_t i = 0; i < fine_d_.size(); ++i) {
    const double count = static_cast<double>(fine_weights_[i].size());
    for (const auto& [coarse, W] : fine_weights_[i]) {
      const Vec3 rf = sofa_mul(R_[coarse], fine_d_[i]);
      const Hexa& h = coarse_hexas_[coarse];
      for (int w = 0; w < 8; ++w) {
        Vec3 d;
        for (int c = 0; c < 3; ++c) {
          const int j = 3 * w + c;
          d[c] = (W(0, j) * rf[0] + W(1, j) * rf[1] + W(2, j) * rf[2]) / count;
        }
        fin[h[w]] += mult_transpose(R_[coarse], d);
      }
    }
  }
}

void register_hexahedron_composite_fem_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronCompositeFEMMapping";
  info.category = "Mapping/Linear";
  info.description =
      "points moved with the fine displacements of a HexahedronCompositeFEMForceFieldAndMass's homogenization";
  info.templates = {"Vec3d,Vec3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> {
    return std::make_unique<HexahedronCompositeFEMMapping>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
