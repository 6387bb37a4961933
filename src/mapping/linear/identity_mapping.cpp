#include "mapping/linear/identity_mapping.h"

#include <algorithm>

#include "core/registry.h"

namespace sinew {

bool IdentityMapping::init_mapping() {
  cwi_ = state_type_info(in_type()).coord_width;
  dwi_ = state_type_info(in_type()).deriv_width;
  cwo_ = state_type_info(out_type()).coord_width;
  dwo_ = state_type_info(out_type()).deriv_width;
  // A default-sized output (one point) is silently resized, as in SOFA; points given explicitly are replaced.
  if (out_size() > 1 && out_size() != in_size())
    msg_warning("the output has " + std::to_string(out_size()) + " points and is resized to the " +
                std::to_string(in_size()) + " points of the input (its given positions are replaced)");
  resize_output(in_size());
  return true;
}

namespace {
// out element i = first min(wi, wo) scalars of in element i (the rest of out is kept).
void copy_elements(const std::vector<double>& in, int wi, std::vector<double>& out, int wo) {
  if (wi == wo) {
    if (out.size() != in.size()) out.resize(in.size());
    std::copy(in.begin(), in.end(), out.begin());
    return;
  }
  const std::size_t n = in.size() / wi;
  if (out.size() != n * wo) out.resize(n * wo, 0.0);
  const int w = std::min(wi, wo);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < w; ++c) out[i * wo + c] = in[i * wi + c];
}
}  // namespace

void IdentityMapping::apply(int x) {
  std::vector<double>* out = out_coord(x);
  if (!out) return;
  copy_elements(in_coord(x), cwi_, *out, cwo_);
}

void IdentityMapping::apply_j(int v, int role) {
  std::vector<double>* out = out_deriv(v, role);
  if (!out) return;
  copy_elements(in_deriv(v, role), dwi_, *out, dwo_);
}

void IdentityMapping::apply_jt(int f, int role) {
  const std::vector<double>* out = out_deriv_read(f, role);
  if (!out) return;
  std::vector<double>& in = in_deriv_write(f, role);
  if (dwi_ == dwo_) {
    const std::size_t n = std::min(in.size(), out->size());
    for (std::size_t i = 0; i < n; ++i) in[i] += (*out)[i];
    return;
  }
  const std::size_t n = std::min(in.size() / dwi_, out->size() / dwo_);
  const int w = std::min(dwi_, dwo_);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < w; ++c) in[i * dwi_ + c] += (*out)[i * dwo_ + c];
}

bool IdentityMapping::jacobian(std::vector<JacobianEntry>& out) {
  const int w = std::min(dwi_, dwo_);
  for (std::size_t i = 0; i < in_size(); ++i)
    for (int c = 0; c < w; ++c)
      out.push_back({0, static_cast<std::uint32_t>(i * dwo_ + c), static_cast<std::uint32_t>(i * dwi_ + c), 1.0});
  return true;
}

void register_identity_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "IdentityMapping";
  info.category = "Mapping/Linear";
  info.description = "output DoFs equal to the input DoFs (same type)";
  info.templates = {"Vec1d,Vec1d", "Vec2d,Vec2d", "Vec3d,Vec3d", "Vec6d,Vec6d",
                    "Rigid2d,Rigid2d", "Rigid3d,Rigid3d", "Rigid3d,Vec3d", "Rigid2d,Vec2d"};
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
