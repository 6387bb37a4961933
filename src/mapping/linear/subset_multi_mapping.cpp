#include "mapping/linear/subset_multi_mapping.h"

#include <algorithm>

#include "core/registry.h"

namespace sinew {

bool GatherMultiMapping::init_mapping() {
  cwi_ = state_type_info(in_type()).coord_width;
  dwi_ = state_type_info(in_type()).deriv_width;
  cwo_ = state_type_info(out_type()).coord_width;
  dwo_ = state_type_info(out_type()).deriv_width;
  src_.clear();
  if (!sources(src_)) return false;
  resize_output(src_.size());
  in_ptr_.assign(in_.size(), nullptr);
  return true;
}

bool SubsetMultiMapping::sources(std::vector<Source>& src) {
  const std::vector<int>& pairs = index_pairs.get();
  if (pairs.size() % 2 != 0) {
    msg_error("indexPairs has " + std::to_string(pairs.size()) +
              " values: it must hold (input index, point index) couples");
    return false;
  }
  const std::size_t n = pairs.size() / 2;
  src.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    const int input = pairs[2 * i], point = pairs[2 * i + 1];
    if (input < 0 || static_cast<std::size_t>(input) >= in_.size()) {
      msg_error("indexPairs couple " + std::to_string(i) + " names input " + std::to_string(input) +
                " but there are " + std::to_string(in_.size()) + " inputs");
      return false;
    }
    if (point < 0 || static_cast<std::size_t>(point) >= in_[input]->size()) {
      msg_error("indexPairs couple " + std::to_string(i) + " names point " + std::to_string(point) + " of input " +
                std::to_string(input) + " (" + in_[input]->describe() + ") which has " +
                std::to_string(in_[input]->size()) + " points");
      return false;
    }
    src[i] = {static_cast<unsigned>(input), static_cast<unsigned>(point)};
  }
  return true;
}

namespace {
// out[i] = first min(wi, wo) scalars of input src[i].input's element src[i].point.
template <class Src>
void gather(const std::vector<Src>& src, const std::vector<const std::vector<double>*>& in, int wi,
            std::vector<double>& out, int wo) {
  if (out.size() != src.size() * wo) out.resize(src.size() * wo, 0.0);
  const int w = std::min(wi, wo);
  for (std::size_t i = 0; i < src.size(); ++i) {
    const std::vector<double>& v = *in[src[i].input];
    const std::size_t at = static_cast<std::size_t>(src[i].point) * wi;
    if (at + w > v.size()) continue;  // the input shrank since init
    for (int c = 0; c < w; ++c) out[i * wo + c] = v[at + c];
  }
}
}  // namespace

void GatherMultiMapping::apply(int x) {
  std::vector<double>* out = out_coord(x);
  if (!out) return;
  for (std::size_t k = 0; k < in_.size(); ++k) in_ptr_[k] = &in_coord(x, k);
  gather(src_, in_ptr_, cwi_, *out, cwo_);
}

void GatherMultiMapping::apply_j(int v, int role) {
  std::vector<double>* out = out_deriv(v, role);
  if (!out) return;
  for (std::size_t k = 0; k < in_.size(); ++k) in_ptr_[k] = &in_deriv(v, role, k);
  gather(src_, in_ptr_, dwi_, *out, dwo_);
}

void GatherMultiMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  const int w = std::min(dwi_, dwo_);
  const std::size_t n = std::min(src_.size(), out.size() / dwo_);
  // Output points in order, each into its input (SOFA's loop).
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double>& in = in_deriv_write(f, role, src_[i].input);
    const std::size_t at = static_cast<std::size_t>(src_[i].point) * dwi_;
    if (at + w > in.size()) continue;
    for (int c = 0; c < w; ++c) in[at + c] += out[i * dwo_ + c];
  }
}

bool GatherMultiMapping::jacobian(std::vector<JacobianEntry>& out) {
  const int w = std::min(dwi_, dwo_);
  for (std::size_t i = 0; i < src_.size(); ++i)
    for (int c = 0; c < w; ++c)
      out.push_back({src_[i].input, static_cast<std::uint32_t>(i * dwo_ + c),
                     static_cast<std::uint32_t>(src_[i].point * dwi_ + c), 1.0});
  return true;
}

void register_subset_multi_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SubsetMultiMapping";
  info.category = "Mapping/Linear";
  info.description = "gathers points of several input states into one output state";
  info.templates = {"Vec3d,Vec3d", "Vec2d,Vec2d", "Vec1d,Vec1d", "Rigid3d,Rigid3d", "Rigid3d,Vec3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<SubsetMultiMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
