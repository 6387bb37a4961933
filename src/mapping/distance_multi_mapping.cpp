#include "mapping/distance_multi_mapping.h"

#include <cmath>
#include <limits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool DistanceMultiMapping::init_mapping() {
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
  const std::vector<Edge>& edges = topology->edges();
  if (edges.empty()) {
    msg_error("the topology " + topology->describe() + " has no edges");
    return false;
  }
  const std::vector<int>& pairs = index_pairs.get();
  const std::size_t n_pairs = pairs.size() / 2;
  ends_.assign(edges.size(), {});
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (int s = 0; s < 2; ++s) {
      const unsigned p = edges[e][s];
      if (p >= n_pairs) {
        msg_error("edge " + std::to_string(e) + " uses index pair " + std::to_string(p) + " but indexPairs has " +
                  std::to_string(n_pairs) + " pairs");
        return false;
      }
      const int input = pairs[2 * p], point = pairs[2 * p + 1];
      if (input < 0 || static_cast<std::size_t>(input) >= in_.size()) {
        msg_error("index pair " + std::to_string(p) + " names input " + std::to_string(input) + " but there are " +
                  std::to_string(in_.size()) + " inputs");
        return false;
      }
      if (point < 0 || static_cast<std::size_t>(point) >= in_[input]->size()) {
        msg_error("index pair " + std::to_string(p) + " names point " + std::to_string(point) + " of input " +
                  std::to_string(input) + " which has " + std::to_string(in_[input]->size()) + " points");
        return false;
      }
      ends_[e][s] = {static_cast<unsigned>(input), static_cast<unsigned>(point)};
    }
  resize_output(edges.size());
  dir_.assign(edges.size() * 3, 0.0);
  invlen_.assign(edges.size(), 0.0);
  in_ptr_.assign(in_.size(), nullptr);
  inw_ptr_.assign(in_.size(), nullptr);

  std::vector<double> rest = rest_lengths.get();
  if (rest.size() != edges.size()) {
    rest.clear();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (compute_distance.value()) {
        rest.push_back(0.0);
        continue;
      }
      const double* a = &in_coord(kPosition, ends_[e][0].input)[ends_[e][0].point * cw_];
      const double* b = &in_coord(kPosition, ends_[e][1].input)[ends_[e][1].point * cw_];
      const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
      rest.push_back(std::sqrt(d0 * d0 + d1 * d1 + d2 * d2));
    }
    rest_lengths.set(rest);
  }
  rest_ = std::move(rest);
  return true;
}

void DistanceMultiMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  for (std::size_t k = 0; k < in_.size(); ++k) in_ptr_[k] = &in_coord(x, k);
  out.resize(ends_.size());
  static const double p = 1.0 / std::sqrt(3.0);
  for (std::size_t e = 0; e < ends_.size(); ++e) {
    const double* a = &(*in_ptr_[ends_[e][0].input])[ends_[e][0].point * cw_];
    const double* b = &(*in_ptr_[ends_[e][1].input])[ends_[e][1].point * cw_];
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

void DistanceMultiMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  for (std::size_t k = 0; k < in_.size(); ++k) in_ptr_[k] = &in_deriv(v, role, k);
  out.resize(ends_.size());
  // SOFA keeps one Jacobian block per input: out = J_0·in_0, then out += J_k·in_k.
  for (std::size_t k = 0; k < in_.size(); ++k) {
    const std::vector<double>& in = *in_ptr_[k];
    for (std::size_t e = 0; e < ends_.size(); ++e) {
      const double* n = &dir_[e * 3];
      double s = 0;
      for (int side = 0; side < 2; ++side) {
        if (ends_[e][side].input != k) continue;
        const double sign = side == 0 ? -1.0 : 1.0;
        const std::size_t base = ends_[e][side].point * dw_;
        for (int c = 0; c < 3; ++c) s += (sign * n[c]) * in[base + c];
      }
      out[e] = k == 0 ? s : out[e] + s;
    }
  }
}

void DistanceMultiMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  for (std::size_t k = 0; k < in_.size(); ++k) {
    std::vector<double>& in = in_deriv(f, role, k);
    for (std::size_t e = 0; e < ends_.size() && e < out.size(); ++e) {
      const double* n = &dir_[e * 3];
      for (int side = 0; side < 2; ++side) {
        if (ends_[e][side].input != k) continue;
        const double sign = side == 0 ? -1.0 : 1.0;
        const std::size_t base = ends_[e][side].point * dw_;
        for (int c = 0; c < 3; ++c) in[base + c] += (sign * n[c]) * out[e];
      }
    }
  }
}

void DistanceMultiMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->vec(kForce);
  for (std::size_t i = 0; i < in_.size(); ++i) {
    inw_ptr_[i] = &in_deriv(df, kDforce, i);
    in_ptr_[i] = &in_deriv(dx, kDx, i);
  }
  for (std::size_t e = 0; e < ends_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!(lambda < 0 || gs_ == 1)) continue;
    const double* d = &dir_[e * 3];
    double b[3][3];
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) b[j][c] = 1.0 * (j == c) - d[j] * d[c];
    const double s = lambda * invlen_[e] * k;
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) b[j][c] *= s;
    const End e0 = ends_[e][0], e1 = ends_[e][1];
    const double* d0 = &(*in_ptr_[e0.input])[e0.point * dw_];
    const double* d1 = &(*in_ptr_[e1.input])[e1.point * dw_];
    double u[3], r[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) u[c] = d1[c] - d0[c];
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) r[j] += b[j][c] * u[c];
    double* f0 = &(*inw_ptr_[e0.input])[e0.point * dw_];
    double* f1 = &(*inw_ptr_[e1.input])[e1.point * dw_];
    for (int j = 0; j < 3; ++j) {
      f0[j] -= r[j];
      f1[j] += r[j];
    }
  }
}

bool DistanceMultiMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t e = 0; e < ends_.size(); ++e) {
    const double* n = &dir_[e * 3];
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? -1.0 : 1.0;
      for (int c = 0; c < 3; ++c)
        out.push_back({ends_[e][side].input, static_cast<std::uint32_t>(e),
                       static_cast<std::uint32_t>(ends_[e][side].point * dw_ + c), sign * n[c]});
    }
  }
  return true;
}

bool DistanceMultiMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->vec(kForce);
  for (std::size_t e = 0; e < ends_.size() && e < child_force.size(); ++e) {
    const double lambda = child_force[e];
    if (!(lambda < 0 || gs_ == 1)) continue;
    const double* d = &dir_[e * 3];
    double b[3][3];
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) b[j][c] = (1.0 * (j == c) - d[j] * d[c]) * (lambda * invlen_[e]);
    const MechanicalState* s0 = in_[ends_[e][0].input];
    const MechanicalState* s1 = in_[ends_[e][1].input];
    const std::size_t i0 = ends_[e][0].point * dw_, i1 = ends_[e][1].point * dw_;
    for (int j = 0; j < 3; ++j)
      for (int c = 0; c < 3; ++c) {
        K.add(s0, i0 + j, s0, i0 + c, b[j][c]);
        K.add(s0, i0 + j, s1, i1 + c, -b[j][c]);
        K.add(s1, i1 + j, s0, i0 + c, -b[j][c]);
        K.add(s1, i1 + j, s1, i1 + c, b[j][c]);
      }
  }
  return true;
}

void register_distance_multi_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "DistanceMultiMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps point pairs taken from several states to their distances";
  info.templates = {"Vec3d,Vec1d", "Rigid3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<DistanceMultiMapping>(in);
  };
  r.add(std::move(info));
}

}  // namespace sinew
