#include "mapping/linear/distance_to_plane_mapping.h"

#include <cmath>
#include <limits>

#include "core/registry.h"

namespace sinew {

bool DistanceToPlaneMapping::init_mapping() {
  const StateTypeInfo& ti = state_type_info(in_type());
  cw_ = ti.coord_width;
  dw_ = ti.deriv_width;
  dim_ = ti.spatial_dim;
  auto check = [&](const Field<std::vector<double>>& f) {
    // SOFA's Data is a fixed-size vector: fewer values leave zeros behind, more are ignored.
    if (f.get().size() == static_cast<std::size_t>(dim_)) return true;
    msg_error(f.name() + " has " + std::to_string(f.get().size()) + " values; a " + ti.name + " input needs " +
              std::to_string(dim_));
    return false;
  };
  if (!check(plane_normal)) return false;
  std::vector<double> point = plane_point.get();
  if (point.empty()) point.assign(dim_, 0.0);  // unset: the origin
  else if (!check(plane_point)) return false;
  std::vector<double> n = plane_normal.get();
  double n2 = 0;
  for (double c : n) n2 += c * c;
  const double norm = std::sqrt(n2);
  if (!(norm >= std::numeric_limits<double>::epsilon())) {
    msg_error("planeNormal has a null norm");
    return false;
  }
  for (double& c : n) c /= norm;
  plane_normal.set(n);  // SOFA stores the normalised normal back
  n_ = n;
  offset_ = 0;
  for (int k = 0; k < dim_; ++k) offset_ += point[k] * n_[k];
  resize_output(in_size());
  return true;
}

void DistanceToPlaneMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::size_t n = in.size() / cw_;
  // SOFA re-inits when a topology change left the sizes apart.
  if (out_size() != n) {
    resize_output(n);
    outp = out_coord(x);
  }
  std::vector<double>& out = *outp;
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < dim_; ++k) s += in[i * cw_ + k] * n_[k];
    out[i] = s - offset_;
  }
}

void DistanceToPlaneMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv(v, role);
  std::vector<double>& out = *outp;
  const std::size_t n = std::min(in.size() / dw_, out.size());
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0;
    for (int k = 0; k < dim_; ++k) s += in[i * dw_ + k] * n_[k];
    out[i] = s;
  }
}

void DistanceToPlaneMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(in.size() / dw_, out.size());
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim_; ++k) in[i * dw_ + k] = in[i * dw_ + k] + n_[k] * out[i];
}

bool DistanceToPlaneMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n = out_size();
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < dim_; ++k)
      out.push_back({0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i * dw_ + k), n_[k]});
  return true;
}

void register_distance_to_plane_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "DistanceToPlaneMapping";
  info.category = "Mapping/Linear";
  info.description = "maps points to their signed distances to a plane";
  // SOFA's class has one template parameter, the input; the output is always Vec1d.
  info.templates = {"Vec3d", "Vec2d", "Vec6d", "Rigid3d", "Rigid2d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in;
    if (!state_type_from_name(t, in)) return nullptr;
    return std::make_unique<DistanceToPlaneMapping>(in);
  };
  r.add(std::move(info));
}

}  // namespace sinew
