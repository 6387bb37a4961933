#include "mapping/nonlinear/distance_multi_mapping.h"

#include "core/node.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "mapping/nonlinear/edge_kernels.h"

namespace sinew {

bool DistanceMultiMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 2);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
              quote_value(geometric_stiffness.get()));
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
      rest.push_back(edge::edge_length(a, b));
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
  for (std::size_t e = 0; e < ends_.size(); ++e) {
    const double* a = &(*in_ptr_[ends_[e][0].input])[ends_[e][0].point * cw_];
    const double* b = &(*in_ptr_[ends_[e][1].input])[ends_[e][1].point * cw_];
    out[e] = edge::unit_direction(a, b, &dir_[e * 3], invlen_[e]) - rest_[e];
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
      double s = 0;
      for (int side = 0; side < 2; ++side)
        if (ends_[e][side].input == k)
          s = edge::add_end_dot(s, side == 0 ? -1.0 : 1.0, &dir_[e * 3], &in[ends_[e][side].point * dw_]);
      out[e] = k == 0 ? s : out[e] + s;
    }
  }
}

void DistanceMultiMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  for (std::size_t k = 0; k < in_.size(); ++k) {
    std::vector<double>& in = in_deriv_write(f, role, k);
    for (std::size_t e = 0; e < ends_.size() && e < out.size(); ++e)
      for (int side = 0; side < 2; ++side)
        if (ends_[e][side].input == k)
          edge::add_end_force(&in[ends_[e][side].point * dw_], side == 0 ? -1.0 : 1.0, &dir_[e * 3], out[e]);
  }
}

void DistanceMultiMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  for (std::size_t i = 0; i < in_.size(); ++i) {
    inw_ptr_[i] = &in_deriv_write(df, kDforce, i);
    in_ptr_[i] = &in_deriv(dx, kDx, i);
  }
  double b[3][3];
  for (std::size_t e = 0; e < ends_.size() && e < child_force.size(); ++e) {
    if (!edge::has_geometric_stiffness(gs_, child_force[e])) continue;
    edge::distance_gs_block(&dir_[e * 3], child_force[e], invlen_[e], k, b);
    const End e0 = ends_[e][0], e1 = ends_[e][1];
    edge::add_block_product(b, &(*in_ptr_[e0.input])[e0.point * dw_], &(*in_ptr_[e1.input])[e1.point * dw_],
                            &(*inw_ptr_[e0.input])[e0.point * dw_], &(*inw_ptr_[e1.input])[e1.point * dw_]);
  }
}

bool DistanceMultiMapping::jacobian(std::vector<JacobianEntry>& out) {
  // Ends may sit on different inputs, so each end's 3 entries go together (unlike
  // edge::append_edge_row, which interleaves them); the pattern is relied upon, keep it.
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
  const std::vector<double>& child_force = out_->read(kForce);
  double b[3][3];
  for (std::size_t e = 0; e < ends_.size() && e < child_force.size(); ++e) {
    if (!edge::has_geometric_stiffness(gs_, child_force[e])) continue;
    // Scale 1: (λ/L)·1 is λ/L exactly, the same bits as scaling by λ/L directly.
    edge::distance_gs_block(&dir_[e * 3], child_force[e], invlen_[e], 1.0, b);
    const End e0 = ends_[e][0], e1 = ends_[e][1];
    edge::add_edge_block(K, in_[e0.input], e0.point * dw_, in_[e1.input], e1.point * dw_, b);
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
