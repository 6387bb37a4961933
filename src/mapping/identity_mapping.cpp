#include "mapping/identity_mapping.h"

#include <algorithm>

#include "core/registry.h"

namespace sinew {

bool IdentityMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  resize_output(in_size());
  return true;
}

void IdentityMapping::apply(int x) {
  std::vector<double>* out = out_coord(x);
  if (!out) return;
  const std::vector<double>& in = in_coord(x);
  if (out->size() != in.size()) out->resize(in.size());
  std::copy(in.begin(), in.end(), out->begin());
}

void IdentityMapping::apply_j(int v, int role) {
  std::vector<double>* out = out_deriv(v, role);
  if (!out) return;
  const std::vector<double>& in = in_deriv(v, role);
  if (out->size() != in.size()) out->resize(in.size());
  std::copy(in.begin(), in.end(), out->begin());
}

void IdentityMapping::apply_jt(int f, int role) {
  const std::vector<double>* out = out_deriv(f, role);
  if (!out) return;
  std::vector<double>& in = in_deriv(f, role);
  const std::size_t n = std::min(in.size(), out->size());
  for (std::size_t i = 0; i < n; ++i) in[i] += (*out)[i];
}

bool IdentityMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n = in_size() * static_cast<std::size_t>(dw_);
  for (std::size_t i = 0; i < n; ++i)
    out.push_back({0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i), 1.0});
  return true;
}

void register_identity_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "IdentityMapping";
  info.category = "Mapping/Linear";
  info.description = "output DoFs equal to the input DoFs (same type)";
  info.templates = {"Vec1d,Vec1d", "Vec2d,Vec2d", "Vec3d,Vec3d", "Vec6d,Vec6d", "Rigid2d,Rigid2d", "Rigid3d,Rigid3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<IdentityMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
