#include "mapping/distance_mapping.h"

#include <cmath>
#include <limits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool DistanceMapping::init_mapping() {
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
  dir_.assign(edges_.size() * 3, 0.0);
  invlen_.assign(edges_.size(), 0.0);

  std::vector<double> rest = rest_lengths.get();
  if (rest.size() != edges_.size()) {
    rest.resize(edges_.size(), 0.0);
    if (!compute_distance.value()) {
      const std::vector<double>& x = in_coord(kPosition);
      for (std::size_t e = 0; e < edges_.size(); ++e) {
        const double* a = &x[edges_[e][0] * cw_];
        const double* b = &x[edges_[e][1] * cw_];
        const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
        rest[e] = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
      }
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
  static const double p = 1.0 / std::sqrt(3.0);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* a = &in[edges_[e][0] * cw_];
    const double* b = &in[edges_[e][1] * cw_];
    double* d = &dir_[e * 3];
    d[0] = b[0] - a[0];
    d[1] = b[1] - a[1];
    d[2] = b[2] - a[2];
    const double dist = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    out[e] = dist - rest_[e];
    if (dist > std::numeric_limits<double>::epsilon()) {
      invlen_[e] = 1 / dist;
      d[0] *= invlen_[e];
      d[1] *= invlen_[e];
      d[2] *= invlen_[e];
    } else {
      invlen_[e] = 0;
      d[0] = d[1] = d[2] = p;
    }
  }
}

void DistanceMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv(v, role);
  out.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* n = &dir_[e * 3];
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    // Sparse row in increasing column order: the lower point index first.
    double s = 0;
    if (i1 < i0) {
      for (int k = 0; k < 3; ++k) s += n[k] * in[i1 * dw_ + k];
      for (int k = 0; k < 3; ++k) s += -n[k] * in[i0 * dw_ + k];
    } else {
      for (int k = 0; k < 3; ++k) s += -n[k] * in[i0 * dw_ + k];
      for (int k = 0; k < 3; ++k) s += n[k] * in[i1 * dw_ + k];
    }
    out[e] = s;
  }
}

void DistanceMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv(f, role);
  const std::size_t n = std::min(edges_.size(), out.size());
  for (std::size_t e = 0; e < n; ++e) {
    const double* d = &dir_[e * 3];
    const double fe = out[e];
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    for (int k = 0; k < 3; ++k) in[i0 * dw_ + k] += -d[k] * fe;
    for (int k = 0; k < 3; ++k) in[i1 * dw_ + k] += d[k] * fe;
  }
}

bool DistanceMapping::gs_block(std::size_t e, const std::vector<double>& child_force, double scale,
                               double b[3][3]) const {
  const double lambda = child_force[e];
  if (!(lambda < 0 || gs_ == 1)) return false;
  const double* d = &dir_[e * 3];
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) b[j][k] = 1.0 * (j == k) - d[j] * d[k];
  const double s = lambda * invlen_[e] * scale;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) b[j][k] *= s;
  return true;
}

void DistanceMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->vec(kForce);
  std::vector<double>& f = in_deriv(df, kDforce);
  const std::vector<double>& d = in_deriv(dx, kDx);
  double b[3][3];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    if (!gs_block(e, child_force, k, b)) continue;
    const unsigned i0 = edges_[e][0], i1 = edges_[e][1];
    double u[3];
    for (int c = 0; c < 3; ++c) u[c] = d[i1 * dw_ + c] - d[i0 * dw_ + c];
    double r[3] = {0, 0, 0};
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) r[j] += b[j][c] * u[c];
    for (int j = 0; j < 3; ++j) {
      f[i0 * dw_ + j] -= r[j];
      f[i1 * dw_ + j] += r[j];
    }
  }
}

bool DistanceMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const double* d = &dir_[e * 3];
    const auto row = static_cast<std::uint32_t>(e);
    for (int k = 0; k < 3; ++k) {
      out.push_back({0, row, static_cast<std::uint32_t>(edges_[e][0] * dw_ + k), -d[k]});
      out.push_back({0, row, static_cast<std::uint32_t>(edges_[e][1] * dw_ + k), d[k]});
    }
  }
  return true;
}

bool DistanceMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->vec(kForce);
  const MechanicalState* s = in_[0];
  double b[3][3];
  for (std::size_t e = 0; e < edges_.size() && e < child_force.size(); ++e) {
    if (!gs_block(e, child_force, 1.0, b)) continue;
    const std::size_t i0 = edges_[e][0] * dw_, i1 = edges_[e][1] * dw_;
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) {
        K.add(s, i0 + j, s, i0 + c, b[j][c]);
        K.add(s, i0 + j, s, i1 + c, -b[j][c]);
        K.add(s, i1 + j, s, i0 + c, -b[j][c]);
        K.add(s, i1 + j, s, i1 + c, b[j][c]);
      }
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
