#include "mapping/nonlinear/square_distance_mapping.h"

#include <algorithm>

#include "core/node.h"
#include "core/registry.h"
#include "mapping/nonlinear/edge_kernels.h"

namespace sinew {

bool SquareDistanceMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  if (!edge::init_edges(*this, geometric_stiffness.get(), topology, in_size(), gs_, edges_)) return false;
  resize_output(edges_.size());
  grad_.assign(edges_.size() * 3, 0.0);
  return true;
}

void SquareDistanceMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  out.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    double* g = &grad_[e * 3];
    out[e] = edge::edge_vector(&in[edges_[e][0] * cw_], &in[edges_[e][1] * cw_], g);
    g[0] *= 2;
    g[1] *= 2;
    g[2] *= 2;
  }
}

void SquareDistanceMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  edge::apply_rows(edges_, grad_, in_deriv(v, role), dw_, *outp);
}

void SquareDistanceMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  edge::apply_rows_transposed(edges_, grad_, *outp, dw_, in_deriv_write(f, role));
}

void SquareDistanceMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!edge::has_geometric_stiffness(gs_, lambda)) continue;
    // G = 2λ·[I −I; −I I]: only diagonal entries, so no 3×3 block.
    const double tmp = 2 * lambda * k;
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    for (int c = 0; c < 3; ++c) {
      const double r = tmp * (d[i0 * dw_ + c] - d[i1 * dw_ + c]);
      f[i0 * dw_ + c] = f[i0 * dw_ + c] + r;
      f[i1 * dw_ + c] = f[i1 * dw_ + c] - r;
    }
  }
}

bool SquareDistanceMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t e = 0; e < edges_.size(); ++e)
    edge::append_edge_row(out, static_cast<std::uint32_t>(e), edges_[e][0] * dw_, edges_[e][1] * dw_, &grad_[e * 3]);
  return true;
}

bool SquareDistanceMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!edge::has_geometric_stiffness(gs_, lambda)) continue;
    const double tmp = 2 * lambda;
    const std::size_t i0 = edges_[e][0] * dw_, i1 = edges_[e][1] * dw_;
    for (int c = 0; c < 3; ++c) {
      K.add(s, i0 + c, s, i0 + c, tmp);
      K.add(s, i0 + c, s, i1 + c, -tmp);
      K.add(s, i1 + c, s, i1 + c, tmp);
      K.add(s, i1 + c, s, i0 + c, -tmp);
    }
  }
  return true;
}

void register_square_distance_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SquareDistanceMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps point pairs (topology edges) to their squared distances";
  info.templates = {"Vec3d,Vec1d", "Rigid3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<SquareDistanceMapping>(in);
  };
  r.add(std::move(info));
}

}  // namespace sinew
