#include "mapping/nonlinear/square_mapping.h"

#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

bool SquareMapping::init_mapping() {
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 1);
  if (gs_ < 0 || gs_ > 1) {
    msg_error("geometricStiffness must be None or Exact (0 or 1), not " + quote_value(geometric_stiffness.get()));
    return false;
  }
  resize_output(in_size());
  grad_.assign(in_size(), 0.0);
  return true;
}

void SquareMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::size_t n = in.size();
  // SOFA resizes the output to the input at every apply.
  resize_output(n);
  std::vector<double>& out = *out_coord(x);
  out.resize(n);
  grad_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = in[i] * in[i];
    grad_[i] = 2.0 * in[i];
  }
}

void SquareMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv(v, role);
  std::vector<double>& out = *outp;
  const std::size_t n = std::min(grad_.size(), in.size());
  out.resize(grad_.size());
  for (std::size_t i = 0; i < n; ++i) out[i] = grad_[i] * in[i];
}

void SquareMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min({grad_.size(), out.size(), in.size()});
  for (std::size_t i = 0; i < n; ++i) in[i] += grad_[i] * out[i];
}

void SquareMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  const double k2 = k * 2.0;
  const std::size_t n = std::min({d.size(), f.size(), child_force.size()});
  for (std::size_t i = 0; i < n; ++i) f[i] += d[i] * child_force[i] * k2;
}

bool SquareMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t i = 0; i < grad_.size(); ++i)
    out.push_back({0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i), grad_[i]});
  return true;
}

bool SquareMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  const std::size_t n = std::min(in_size(), child_force.size());
  for (std::size_t i = 0; i < n; ++i) K.add(s, i, s, i, 2 * child_force[i]);
  return true;
}

void register_square_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SquareMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps each scalar to its square";
  info.templates = {"Vec1d,Vec1d"};
  info.default_template = "Vec1d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<SquareMapping>(); };
  r.add(std::move(info));
}

}  // namespace sinew
