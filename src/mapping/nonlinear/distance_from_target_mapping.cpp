#include "mapping/nonlinear/distance_from_target_mapping.h"

#include <cmath>

#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

namespace {
FlatVec empty_coords(StateType t) {
  FlatVec v;
  v.width = state_type_info(t).coord_width;
  return v;
}
}  // namespace

DistanceFromTargetMapping::DistanceFromTargetMapping(StateType in)
    : MappingBase(in, StateType::vec1),
      target_positions(this, "targetPositions", empty_coords(in), "positions the distances are measured from",
                       "Mapping", "length") {}

bool DistanceFromTargetMapping::init_mapping() {
  const StateTypeInfo& ti = state_type_info(in_type());
  cw_ = ti.coord_width;
  dw_ = ti.deriv_width;
  dim_ = std::min(3, ti.spatial_dim);
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 2);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
              quote_value(geometric_stiffness.get()));
    return false;
  }
  const FlatVec& targets = target_positions.get();
  std::vector<unsigned> idx = indices.get();
  // SOFA's init: missing indices are the targets' own numbers.
  if (idx.size() < targets.size()) {
    for (std::size_t i = idx.size(); i < targets.size(); ++i) idx.push_back(static_cast<unsigned>(i));
    indices.set(idx);
  }
  if (idx.size() != targets.size()) {
    msg_error("indices has " + std::to_string(idx.size()) + " entries but targetPositions has " +
              std::to_string(targets.size()) + " positions (one target per index)");
    return false;
  }
  const std::size_t n_in = in_size();
  for (std::size_t i = 0; i < idx.size(); ++i)
    if (idx[i] >= n_in) {
      msg_error("indices[" + std::to_string(i) + "] = " + std::to_string(idx[i]) + " but the input has " +
                std::to_string(n_in) + " points");
      return false;
    }
  std::vector<double> rest = rest_lengths.get();
  if (rest.size() != idx.size()) {  // unset (or partly set) rest lengths are 0
    rest.resize(idx.size(), 0.0);
    rest_lengths.set(rest);
  }
  idx_ = std::move(idx);
  rest_ = std::move(rest);
  dir_.assign(idx_.size() * dw_, 0.0);
  invlen_.assign(idx_.size(), 0.0);
  resize_output(idx_.size());
  return true;
}

void DistanceFromTargetMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  const FlatVec& targets = target_positions.get();
  if (targets.size() != idx_.size()) {
    msg_error("targetPositions changed to " + std::to_string(targets.size()) + " positions for " +
              std::to_string(idx_.size()) + " indices; the mapping stops");
    set_state(ComponentState::invalid);
    return;
  }
  out.resize(idx_.size());
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    double* u = &dir_[i * dw_];
    const double* p = &in[idx_[i] * cw_];
    const double* t = &targets.data[i * cw_];
    // The gap covers the point's position only (the rotation entries stay 0).
    for (int k = 0; k < dw_; ++k) u[k] = k < dim_ ? p[k] - t[k] : 0.0;
    double n2 = 0;
    for (int k = 0; k < dw_; ++k) n2 += u[k] * u[k];
    const double norm = std::sqrt(n2);
    out[i] = norm - rest_[i];
    if (norm > 1e-10) {
      invlen_[i] = 1 / norm;
      for (int k = 0; k < dw_; ++k) u[k] *= invlen_[i];
    } else {  // an arbitrary unit vector, and no geometric stiffness
      invlen_[i] = 0;
      for (int k = 0; k < dw_; ++k) u[k] = 0.0;
      u[0] = 1.0;
    }
  }
}

void DistanceFromTargetMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv(v, role);
  out.resize(idx_.size());
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    const double* u = &dir_[i * dw_];
    const double* d = &in[idx_[i] * dw_];
    double s = 0;
    for (int k = 0; k < dw_; ++k) s += u[k] * d[k];
    out[i] = s;
  }
}

void DistanceFromTargetMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(idx_.size(), out.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double* u = &dir_[i * dw_];
    double* g = &in[idx_[i] * dw_];
    for (int k = 0; k < dw_; ++k) g[k] += u[k] * out[i];
  }
}

void DistanceFromTargetMapping::gs_block(std::size_t i, double lambda, double scale, double* b) const {
  const double* u = &dir_[i * dw_];
  for (int j = 0; j < dw_; ++j)
    for (int k = 0; k < dw_; ++k) b[j * dw_ + k] = 1.0 * (j == k) - u[j] * u[k];
  const double s = lambda * invlen_[i] * scale;
  for (int j = 0; j < dw_ * dw_; ++j) b[j] *= s;
}

void DistanceFromTargetMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  double b[36];
  const std::size_t n = std::min(idx_.size(), child_force.size());
  for (std::size_t i = 0; i < n; ++i) {
    // Compression (λ > 0) would make the block indefinite: Stabilized keeps extension only.
    if (!(child_force[i] < 0 || gs_ == 1)) continue;
    gs_block(i, child_force[i], k, b);
    const double* dxi = &d[idx_[i] * dw_];
    double* fi = &f[idx_[i] * dw_];
    for (int j = 0; j < dw_; ++j) {
      double s = 0;
      for (int c = 0; c < dw_; ++c) s += b[j * dw_ + c] * dxi[c];
      fi[j] += s;
    }
  }
}

bool DistanceFromTargetMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t i = 0; i < idx_.size(); ++i)
    for (int k = 0; k < dw_; ++k)
      out.push_back({0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(idx_[i] * dw_ + k),
                     dir_[i * dw_ + k]});
  return true;
}

bool DistanceFromTargetMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  double b[36];
  const std::size_t n = std::min(idx_.size(), child_force.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!(child_force[i] < 0 || gs_ == 1)) continue;
    gs_block(i, child_force[i], 1.0, b);
    const std::size_t o = idx_[i] * dw_;
    for (int j = 0; j < dw_; ++j)
      for (int c = 0; c < dw_; ++c) K.add(s, o + j, s, o + c, b[j * dw_ + c]);
  }
  return true;
}

void register_distance_from_target_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "DistanceFromTargetMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps point positions to their distances from target points";
  info.templates = {"Vec3d,Vec1d", "Vec1d,Vec1d", "Rigid3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out) || out != StateType::vec1) return nullptr;
    return std::make_unique<DistanceFromTargetMapping>(in);
  };
  r.add(std::move(info));
}

}  // namespace sinew
