#include "mapping/linear/subset_mapping.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
constexpr unsigned kInvalid = 4294967295u;
}

bool SubsetMapping::init_mapping() {
  cw_ = state_type_info(in_type()).coord_width;
  dw_ = state_type_info(in_type()).deriv_width;
  const std::size_t in_n = in_size();
  std::vector<unsigned> ids = indices.get();
  if (ids.empty() && first.value() != kInvalid) {
    unsigned f = first.value(), l = last.value();
    if (f >= in_n) f = 0;
    if (l >= in_n) l = static_cast<unsigned>(in_n) - 1;
    ids.clear();
    for (unsigned i = f; i <= l && l != kInvalid; ++i) ids.push_back(i);
  } else if (ids.empty()) {
    // Nearest input point (first one strictly closer than the shrinking radius).
    const std::vector<double>& in = in_coord(kPosition);
    const std::vector<double>& out = initial_output_positions();
    const int ow = out_ ? out_->info().coord_width : 3;
    const std::size_t n_out = out.size() / ow;
    ids.assign(n_out, kInvalid);
    for (std::size_t i = 0; i < n_out; ++i) {
      double rmax = radius.value();
      bool found = false;
      for (std::size_t j = 0; j < in_n; ++j) {
        double s = 0;
        for (int c = 0; c < cw_ && c < ow; ++c) {
          const double d = out[i * ow + c] - in[j * cw_ + c];
          s += d * d;
        }
        const double r = std::sqrt(s);
        if (r < rmax) {
          ids[i] = static_cast<unsigned>(j);
          found = true;
          rmax = r;
        }
      }
      if (!found && !ignore_not_found.value())
        msg_error("point " + std::to_string(i) + " not found in the input model within a radius of " +
                  std::to_string(rmax));
    }
    indices.set(ids);
  } else if (!ignore_not_found.value()) {
    std::vector<unsigned> kept;
    for (unsigned i : ids) {
      if (i >= in_n) msg_error("incorrect index " + std::to_string(i) + " (input size " + std::to_string(in_n) + ")");
      else kept.push_back(i);
    }
    ids = std::move(kept);
    indices.set(ids);
  }
  if (handle_topology_change.value()) {
    if (!topology && node()) topology.set(node()->get_mesh_topology_link());
    if (!topology) {
      msg_error("no topology component found; set handleTopologyChange to false if no topology is needed");
      return false;
    }
  }
  idx_ = ids;
  resize_output(idx_.size());
  return true;
}

void SubsetMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  if (out_size() < idx_.size() || (resize_to_model.value() && out_size() != idx_.size())) {
    resize_output(idx_.size());
    outp = out_coord(x);
  }
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  const std::size_t n_in = in.size() / cw_;
  out.resize(idx_.size() * cw_);
  const std::vector<double>* rest = nullptr;
  for (std::size_t i = 0; i < idx_.size(); ++i) {
    if (idx_[i] < n_in) {
      for (int c = 0; c < cw_; ++c) out[i * cw_ + c] = in[idx_[i] * cw_ + c];
    } else {
      if (!rest) rest = out_coord_read(kRestPosition);
      if (rest && rest->size() >= (i + 1) * cw_)
        for (int c = 0; c < cw_; ++c) out[i * cw_ + c] = (*rest)[i * cw_ + c];
    }
  }
}

void SubsetMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv_write(v, role);
  const std::size_t n_in = in.size() / dw_;
  out.resize(idx_.size() * dw_);
  for (std::size_t i = 0; i < idx_.size(); ++i)
    if (idx_[i] < n_in)
      for (int c = 0; c < dw_; ++c) out[i * dw_ + c] = in[idx_[i] * dw_ + c];
}

void SubsetMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp || idx_.empty()) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n_in = in.size() / dw_;
  const std::size_t n = std::min(idx_.size(), out.size() / dw_);
  for (std::size_t i = 0; i < n; ++i)
    if (idx_[i] < n_in)
      for (int c = 0; c < dw_; ++c) in[idx_[i] * dw_ + c] += out[i * dw_ + c];
}

bool SubsetMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n_in = in_size();
  for (std::size_t i = 0; i < idx_.size(); ++i)
    if (idx_[i] < n_in)
      for (int c = 0; c < dw_; ++c)
        out.push_back({0, static_cast<std::uint32_t>(i * dw_ + c), static_cast<std::uint32_t>(idx_[i] * dw_ + c), 1.0});
  return true;
}

void register_subset_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SubsetMapping";
  info.category = "Mapping/Linear";
  info.description = "output DoFs are a subset of the input DoFs";
  info.templates = {"Vec1d,Vec1d", "Vec2d,Vec2d", "Vec3d,Vec3d", "Vec6d,Vec6d", "Rigid3d,Rigid3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<SubsetMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
