#include "mapping/square_distance_mapping.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool SquareDistanceMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 2);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not \"" + geometric_stiffness.get() +
              "\"");
    return false;
  }
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (set topology=\"@...\" to a container with edges)");
    return false;
  }
  edges_ = topology->edges();
  if (edges_.empty()) {
    msg_error("the topology " + topology->describe() + " has no edges");
    return false;
  }
  const std::size_t n_in = in_size();
  for (std::size_t e = 0; e < edges_.size(); ++e)
    for (unsigned v : edges_[e])
      if (v >= n_in) {
        msg_error("edge " + std::to_string(e) + " uses point " + std::to_string(v) + " but the input has " +
                  std::to_string(n_in) + " points");
        return false;
      }
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
    const double* a = &in[edges_[e][0] * cw_];
    const double* b = &in[edges_[e][1] * cw_];
    double* g = &grad_[e * 3];
    g[0] = b[0] - a[0];
    g[1] = b[1] - a[1];
    g[2] = b[2] - a[2];
    out[e] = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    g[0] *= 2;
    g[1] *= 2;
    g[2] *= 2;
  }
}

void SquareDistanceMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv(v, role);
  out.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* g = &grad_[e * 3];
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    double s = 0;
    if (i1 < i0) {
      for (int k = 0; k < 3; ++k) s += g[k] * in[i1 * dw_ + k];
      for (int k = 0; k < 3; ++k) s += -g[k] * in[i0 * dw_ + k];
    } else {
      for (int k = 0; k < 3; ++k) s += -g[k] * in[i0 * dw_ + k];
      for (int k = 0; k < 3; ++k) s += g[k] * in[i1 * dw_ + k];
    }
    out[e] = s;
  }
}

void SquareDistanceMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv(f, role);
  const std::size_t n = std::min(edges_.size(), out.size());
  for (std::size_t e = 0; e < n; ++e) {
    const double* g = &grad_[e * 3];
    const double fe = out[e];
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    for (int k = 0; k < 3; ++k) in[i0 * dw_ + k] += -g[k] * fe;
    for (int k = 0; k < 3; ++k) in[i1 * dw_ + k] += g[k] * fe;
  }
}

void SquareDistanceMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->vec(kForce);
  std::vector<double>& f = in_deriv(df, kDforce);
  const std::vector<double>& d = in_deriv(dx, kDx);
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!(lambda < 0 || gs_ == 1)) continue;
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
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* g = &grad_[e * 3];
    const auto row = static_cast<std::uint32_t>(e);
    for (int k = 0; k < 3; ++k) {
      out.push_back({0, row, static_cast<std::uint32_t>(edges_[e][0] * dw_ + k), -g[k]});
      out.push_back({0, row, static_cast<std::uint32_t>(edges_[e][1] * dw_ + k), g[k]});
    }
  }
  return true;
}

bool SquareDistanceMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->vec(kForce);
  const MechanicalState* s = in_[0];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!(lambda < 0 || gs_ == 1)) continue;
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
