#include "forcefield/spring/joint_spring_force_field.h"

#include <sstream>

#include "core/node.h"
#include "core/registry.h"
#include "forcefield/spring/spring_force_field.h"

namespace sinew {

JointSpringForceField::JointSpringForceField() {
  infile.set_file(true);
  outfile.set_file(true, /*required=*/false);  // written, so it need not exist
}

std::vector<MechanicalState*> JointSpringForceField::states() const {
  if (s1_ && s1_ == s2_) return {s1_};
  return {s1_, s2_};
}

void JointSpringForceField::init() {
  ready_ = false;
  if (!bind_interaction_states(*this, object1, object2, s1_, s2_)) return;
  if (s1_->state_type() != StateType::rigid3) {
    msg_error(std::string("object1 and object2 must be Rigid3d states (they are ") + s1_->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const std::string err = joints::parse_joint_springs(spring.get(), springs_);
  if (!err.empty()) {
    msg_error("cannot read 'spring': " + err);
    set_state(ComponentState::invalid);
    springs_.clear();
    return;
  }
  work_.assign(springs_.size(), joints::JointWork{});
  in_.reset();
  out_.reset();
  last_time_ = 0;
  if (!outfile.value().empty()) {
    out_ = std::make_unique<std::ofstream>(outfile.value());
    if (!out_->is_open()) {
      msg_error("cannot create the output file " + outfile.value());
      out_.reset();
    }
  }
  if (!infile.value().empty()) {
    in_ = std::make_unique<std::ifstream>(infile.value());
    if (!in_->is_open()) {
      msg_error("cannot open the input file " + infile.value());
      in_.reset();
    }
  }
}

// After every state is initialised (object1/object2 may be in child nodes):
// indices checked, and rest offsets taken from the positions when REST_T was given.
void JointSpringForceField::bwd_init() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  const std::size_t n1 = s1_->size(), n2 = s2_->size();
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const auto& s = springs_[i];
    if (s.m1 >= n1 || s.m2 >= n2) {
      msg_error("spring " + std::to_string(i) + " (" + std::to_string(s.m1) + ", " + std::to_string(s.m2) +
                ") refers to a frame out of range (object1 has " + std::to_string(n1) + " frames, object2 " +
                std::to_string(n2) + ")");
      set_state(ComponentState::invalid);
      springs_.clear();
      work_.clear();
      return;
    }
  }
  const double* x1 = s1_->read(kPosition).data();
  const double* x2 = s2_->read(kPosition).data();
  for (auto& s : springs_) {
    if (!s.init_from_positions) continue;
    const double* a = x1 + 7 * s.m1;
    const double* b = x2 + 7 * s.m2;
    s.init_trans = Vec3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    // q2·q1⁻¹ (SOFA's order; the force uses q1⁻¹·q2·init_rot).
    s.init_rot = quat_mul(Quat::from(b + 3), quat_inverse(Quat::from(a + 3)));
  }
  n1_ = n1;
  n2_ = n2;
  ready_ = true;
}

bool JointSpringForceField::sizes_ok() {
  if (s1_->size() == n1_ && s2_->size() == n2_) return true;
  n1_ = s1_->size();
  n2_ = s2_->size();
  for (std::size_t i = 0; i < springs_.size(); ++i)
    if (springs_[i].m1 >= n1_ || springs_[i].m2 >= n2_) {
      msg_error("spring " + std::to_string(i) + " (" + std::to_string(springs_[i].m1) + ", " +
                std::to_string(springs_[i].m2) + ") refers to a frame removed from its state: the force field stops");
      set_state(ComponentState::invalid);
      springs_.clear();
      work_.clear();
      ready_ = false;
      return false;
    }
  return true;
}

void JointSpringForceField::add_force(const MechParams& p) {
  if (!ready_ || !sizes_ok()) return;
  const auto [x1, v1, f1, x2, v2, f2] = pair_force_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    double constant[6] = {0, 0, 0, 0, 0, 0};
    if (in_) {  // one line per spring and evaluation, from the start again at the end
      if (in_->eof()) {
        in_->clear();
        in_->seekg(0);
      }
      std::string line;
      std::getline(*in_, line);
      std::istringstream ls(line);
      for (double& c : constant) ls >> c;
    }
    joints::add_joint_spring_force(springs_[i], work_[i], x1, v1, f1, x2, v2, f2, constant);
    if (out_) write_output(springs_[i], work_[i], x1, x2, v1, v2, constant);
  }
}

// SOFA's output record (std::ostream's default number format).
void JointSpringForceField::write_output(const joints::JointSpring& s, const joints::JointWork& w, const double*,
                                         const double*, const double* v1, const double* v2,
                                         const double* constant) {
  if (reinit_file.value()) out_->seekp(0, std::ios::beg);
  const double time = node() ? node()->time.value() : 0.0;
  if (!(time >= last_time_ + period.value())) return;
  last_time_ += period.value();
  double dv[6];
  for (int i = 0; i < 6; ++i) dv[i] = v2[6 * s.m2 + i] - v1[6 * s.m1 + i];
  std::ostream& o = *out_;
  o << "T= " << time << "\n";
  o << "  Xrel= " << w.local[0] << " " << w.local[1] << " " << w.local[2] << " " << w.rel.x << " " << w.rel.y << " "
    << w.rel.z << " " << w.rel.w << "\n";
  o << "  Vrel= " << dv[0] << " " << dv[1] << " " << dv[2] << " " << dv[3] << " " << dv[4] << " " << dv[5] << "\n";
  o << "  Frel= " << w.kt[0] * w.local[0] << " " << w.kt[1] * w.local[1] << " " << w.kt[2] * w.local[2] << " "
    << w.fr0[0] << " " << w.fr0[1] << " " << w.fr0[2] << "\n";
  o << "  Fdamp= " << dv[0] * s.kd << " " << dv[1] * s.kd << " " << dv[2] * s.kd << " " << dv[3] * s.kd << " "
    << dv[4] * s.kd << " " << dv[5] * s.kd << "\n";
  if (in_)
    o << "  Fconstant= " << constant[0] << " " << constant[1] << " " << constant[2] << " " << constant[3] << " "
      << constant[4] << " " << constant[5] << "\n";
  o << "  F= " << w.force[0] << " " << w.force[1] << " " << w.force[2] << " " << w.force[3] << " " << w.force[4]
    << " " << w.force[5] << "\n";
  if (reinit_file.value()) o << "\n\n\n\n\n";
  o.flush();
}

void JointSpringForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!ready_ || !sizes_ok()) return;
  const auto [dx1, df1, dx2, df2] = pair_dforce_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < springs_.size(); ++i)
    joints::add_joint_spring_dforce(springs_[i], work_[i], dx1, df1, dx2, df2, kfactor);
}

// ∂f1/∂x1 = ∂f2/∂x2 = −K, ∂f1/∂x2 = ∂f2/∂x1 = K (K of the last add_force).
bool JointSpringForceField::build_stiffness(MatrixSink& K) {
  if (!ready_ || !sizes_ok()) return true;  // no spring in use
  for (std::size_t e = 0; e < springs_.size(); ++e) {
    const auto& s = springs_[e];
    const auto m = joints::joint_stiffness_block(work_[e]);
    const std::size_t p1 = s.m1 * 6, p2 = s.m2 * 6;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        const double k = m[i * 6 + j];  // zeros kept: the pattern stays the same from step to step
        K.add(s1_, p1 + i, s1_, p1 + j, -k);
        K.add(s1_, p1 + i, s2_, p2 + j, k);
        K.add(s2_, p2 + i, s1_, p1 + j, k);
        K.add(s2_, p2 + i, s2_, p2 + j, -k);
      }
  }
  return true;
}

void register_joint_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "JointSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "6-D joint springs (free axes, angular limits) between the frames of two Rigid3d states";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  // object1/object2 may live elsewhere than the node's state: the types are checked at init.
  info.requirement = Requirement::none;
  info.create = creator<JointSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
