#include "mapping/nonlinear/distance_mapping.h"

#include <algorithm>

#include "core/node.h"
#include "core/registry.h"
#include "mapping/nonlinear/edge_kernels.h"

namespace sinew {

bool DistanceMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  if (!edge::init_edges(*this, geometric_stiffness.get(), topology, in_size(), gs_, edges_)) return false;
  resize_output(edges_.size());
  dir_.assign(edges_.size() * 3, 0.0);
  invlen_.assign(edges_.size(), 0.0);

  std::vector<double> rest = rest_lengths.get();
  if (rest.size() != edges_.size()) {
    rest.resize(edges_.size(), 0.0);
    if (!compute_distance.value()) {
      const std::vector<double>& x = in_coord(kPosition);
      for (std::size_t e = 0; e < edges_.size(); ++e)
        rest[e] = edge::edge_length(&x[edges_[e][0] * cw_], &x[edges_[e][1] * cw_]);
    }
    rest_lengths.set(rest);
  }
  rest_ = std::move(rest);
  return true;
}

void DistanceMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  out.resize(edges_.size());
  // Every apply (rest positions included, as in SOFA) refreshes the directions J uses.
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* a = &in[edges_[e][0] * cw_];
    const double* b = &in[edges_[e][1] * cw_];
    out[e] = edge::unit_direction(a, b, &dir_[e * 3], invlen_[e]) - rest_[e];
  }
}

void DistanceMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  edge::apply_rows(edges_, dir_, in_deriv(v, role), dw_, *outp);
}

void DistanceMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  edge::apply_rows_transposed(edges_, dir_, *outp, dw_, in_deriv_write(f, role));
}

void DistanceMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  double b[3][3];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    if (!edge::has_geometric_stiffness(gs_, child_force[e])) continue;
    edge::distance_gs_block(&dir_[e * 3], child_force[e], invlen_[e], k, b);
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    edge::add_block_product(b, &d[i0 * dw_], &d[i1 * dw_], &f[i0 * dw_], &f[i1 * dw_]);
  }
}

bool DistanceMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t e = 0; e < edges_.size(); ++e)
    edge::append_edge_row(out, static_cast<std::uint32_t>(e), edges_[e][0] * dw_, edges_[e][1] * dw_, &dir_[e * 3]);
  return true;
}

bool DistanceMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  double b[3][3];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    if (!edge::has_geometric_stiffness(gs_, child_force[e])) continue;
    edge::distance_gs_block(&dir_[e * 3], child_force[e], invlen_[e], 1.0, b);
    edge::add_edge_block(K, s, edges_[e][0] * dw_, s, edges_[e][1] * dw_, b);
  }
  return true;
}

void register_distance_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "DistanceMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps point pairs (topology edges) to their distances";
  info.templates = {"Vec3d,Vec1d", "Rigid3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<DistanceMapping>(in);
  };
  r.add(std::move(info));
}

}  // namespace sinew
