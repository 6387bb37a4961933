#include "mapping/linear/center_of_mass_mapping.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool CenterOfMassMapping::read_masses() {
  Node* n = in_[0]->node();
  Mass* mass = n ? n->mass : nullptr;
  if (!mass) {
    msg_error("no mass in the input's " + (n ? n->describe() : std::string("node")) +
              " (the centre of mass needs the element masses)");
    return false;
  }
  MatrixSink& sink = mass_sink_;  // kept: no allocation once warm
  sink.clear();
  if (!mass->build_mass(sink)) {
    msg_error("the mass " + mass->describe() + " cannot give its element masses");
    return false;
  }
  const std::size_t count = in_size();
  m_.assign(count, 0.0);
  for (const MatrixSink::Entry& e : sink.entries()) {
    if (e.row_state != in_[0] || e.col_state != in_[0] || e.row != e.col) continue;
    const std::size_t dof = e.row / dw_;
    if (e.row % dw_ == 0 && dof < count) m_[dof] += e.value;
  }
  return true;
}

bool CenterOfMassMapping::init_mapping() {
  const StateTypeInfo& ti = state_type_info(in_type());
  cw_ = ti.coord_width;
  dw_ = ti.deriv_width;
  dim_ = ti.spatial_dim;
  if (!read_masses()) return false;
  total_ = 0.0;
  for (double m : m_) total_ += m;
  if (total_ == 0.0) {
    msg_error("the total mass of the input is 0");
    return false;
  }
  if (out_size() == 0) resize_output(1);
  else if (out_size() > 1)
    msg_warning("the output has " + std::to_string(out_size()) + " points; only the first is the centre of mass");
  return true;
}

void CenterOfMassMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp || outp->size() < static_cast<std::size_t>(dim_)) return;
  if (x == kPosition) read_masses();
  const std::vector<double>& in = in_coord(x);
  const std::size_t n = std::min(in.size() / cw_, m_.size());
  double s[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < dim_; ++c) s[c] += in[i * cw_ + c] * m_[i];
  for (int c = 0; c < dim_; ++c) (*outp)[c] = s[c] / total_;
}

void CenterOfMassMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp || outp->size() < static_cast<std::size_t>(dim_)) return;
  const std::vector<double>& in = in_deriv(v, role);
  const std::size_t n = std::min(in.size() / dw_, m_.size());
  double s[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < dim_; ++c) s[c] += in[i * dw_ + c] * m_[i];
  for (int c = 0; c < dim_; ++c) (*outp)[c] = s[c] / total_;
}

void CenterOfMassMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp || outp->size() < static_cast<std::size_t>(dim_)) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(in.size() / dw_, m_.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double w = m_[i] / total_;
    for (int c = 0; c < dim_; ++c) in[i * dw_ + c] += out[c] * w;
  }
}

bool CenterOfMassMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (int c = 0; c < dim_; ++c)
    for (std::size_t i = 0; i < m_.size(); ++i)
      out.push_back({0, static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(i * dw_ + c), m_[i] / total_});
  return true;
}

bool CenterOfMassMapping::apply_jt_constraints() {
  // SOFA's applyJT for constraints only warns: rows on the centre of mass reach no frame.
  if (!warned_constraints_) {
    warned_constraints_ = true;
    msg_warning("constraints on the centre of mass are not carried to the input frames (as in SOFA)");
  }
  return true;
}

void register_center_of_mass_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "CenterOfMassMapping";
  info.category = "Mapping/Linear";
  info.description = "sets one point at the centre of mass of the input frames";
  info.templates = {"Rigid3d,Vec3d", "Rigid2d,Vec2d"};
  info.default_template = "Rigid3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<CenterOfMassMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
