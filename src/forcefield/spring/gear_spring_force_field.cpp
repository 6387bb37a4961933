#include "forcefield/spring/gear_spring_force_field.h"

#include "core/node.h"
#include "core/registry.h"
#include "forcefield/spring/spring_force_field.h"

namespace sinew {

GearSpringForceField::GearSpringForceField() {
  filename.set_file(true, /*required=*/false);  // written, so it need not exist
}

std::vector<MechanicalState*> GearSpringForceField::states() const {
  if (s1_ && s1_ == s2_) return {s1_};
  return {s1_, s2_};
}

void GearSpringForceField::init() {
  ready_ = false;
  if (!bind_interaction_states(*this, object1, object2, s1_, s2_)) return;
  if (s1_->state_type() != StateType::rigid3) {
    msg_error(std::string("object1 and object2 must be Rigid3d states (they are ") + s1_->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const std::string err = gears::parse_gear_springs(spring.get(), springs_);
  if (!err.empty()) {
    msg_error("cannot read 'spring': " + err);
    set_state(ComponentState::invalid);
    springs_.clear();
    return;
  }
  work_.assign(springs_.size(), gears::GearWork{});
  out_.reset();
  last_time_ = 0;
  if (!filename.value().empty()) {
    out_ = std::make_unique<std::ofstream>(filename.value());
    if (!out_->is_open()) {
      msg_error("cannot create the output file " + filename.value());
      out_.reset();
    }
  }
}

// Every index within its state (the states may change size: checked at each use).
bool GearSpringForceField::indices_ok() {
  const std::size_t n1 = s1_->size(), n2 = s2_->size();
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const auto& s = springs_[i];
    if (s.p1 < n1 && s.m1 < n1 && s.p2 < n2 && s.m2 < n2) continue;
    msg_error("spring " + std::to_string(i) + " (pivot " + std::to_string(s.p1) + ", gear " + std::to_string(s.m1) +
              "; pivot " + std::to_string(s.p2) + ", gear " + std::to_string(s.m2) +
              ") refers to a frame out of range (object1 has " + std::to_string(n1) + " frames, object2 " +
              std::to_string(n2) + "): the force field stops");
    set_state(ComponentState::invalid);
    springs_.clear();
    work_.clear();
    ready_ = false;
    return false;
  }
  return true;
}

// After every state is initialised (object1/object2 may be in child nodes):
// the angles from the positions (SOFA's bwdInit → reinit).
void GearSpringForceField::bwd_init() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  if (!indices_ok()) return;
  ready_ = true;
  reinit();
}

void GearSpringForceField::reinit() {
  if (!ready_ || !indices_ok()) return;
  const double* x1 = s1_->read(kPosition).data();
  const double* x2 = s2_->read(kPosition).data();
  for (std::size_t i = 0; i < springs_.size(); ++i) gears::init_gear_work(springs_[i], x1, x2, work_[i]);
}

void GearSpringForceField::add_force(const MechParams& p) {
  if (!ready_ || !indices_ok()) return;
  const auto [x1, v1, f1, x2, v2, f2] = pair_force_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    gears::add_gear_spring_force(springs_[i], work_[i], x1, v1, f1, x2, v2, f2);
    if (out_) write_output(work_[i]);
  }
}

// SOFA's output record (std::ostream's default number format).
void GearSpringForceField::write_output(const gears::GearWork& w) {
  if (reinit_file.value()) out_->seekp(0, std::ios::beg);
  const double time = node() ? node()->time.value() : 0.0;
  if (!(time >= last_time_ + period.value())) return;
  last_time_ += period.value();
  std::ostream& o = *out_;
  o << "T= " << time << "\n";
  o << "  Angles= " << w.angle1 << " , " << w.angle2 << "\n";
  o << "  F= " << w.torque << "\n";
  if (reinit_file.value()) o << "\n\n\n\n\n";
  o.flush();
}

void GearSpringForceField::add_dforce(const MechParams& p, double kfactor) {
  if (!ready_ || !indices_ok()) return;
  const auto [dx1, df1, dx2, df2] = pair_dforce_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < springs_.size(); ++i)
    gears::add_gear_spring_dforce(springs_[i], work_[i], dx1, df1, dx2, df2, kfactor);
}

// The matrix of add_dforce, block by block (k = 1).
bool GearSpringForceField::build_stiffness(MatrixSink& K) {
  if (!ready_ || !indices_ok()) return true;  // no spring in use
  for (std::size_t e = 0; e < springs_.size(); ++e) {
    const auto& s = springs_[e];
    const auto& w = work_[e];
    // Holding each gear on its pivot: A = diag(kt I, R diag(kr) Rᵀ) on (pivot − gear).
    auto hold = [&](MechanicalState* st, const double* pivot_frame, unsigned gear, unsigned pivot, unsigned axis) {
      const Mat3 R = quat_to_matrix(Quat::from(pivot_frame + 3));
      Vec3 kr(s.hard_rot, s.hard_rot, s.hard_rot);
      kr[axis] = 0;
      const Mat3 A = R * kr.asDiagonal() * R.transpose();
      auto add = [&](unsigned a, unsigned b, double sign) {
        for (int i = 0; i < 3; ++i) {
          K.add(st, 6 * a + i, st, 6 * b + i, sign * s.hard_trans);
          for (int j = 0; j < 3; ++j) K.add(st, 6 * a + 3 + i, st, 6 * b + 3 + j, sign * A(i, j));
        }
      };
      add(gear, gear, -1);
      if (gear != pivot) {
        add(gear, pivot, 1);
        add(pivot, gear, 1);
        add(pivot, pivot, -1);
      }
    };
    hold(s1_, w.x1, s.m1, s.p1, s.axis[0]);
    hold(s2_, w.x2, s.m2, s.p2, s.axis[1]);
    // The coupling: torques about a1 = R1 e_axis1 and a2 = R2 e_axis2.
    const Vec3 a1 = quat_to_matrix(Quat::from(w.x1 + 3)).col(s.axis[0]);
    const Vec3 a2 = quat_to_matrix(Quat::from(w.x2 + 3)).col(s.axis[1]);
    auto couple = [&](MechanicalState* sa, unsigned ga, const Vec3& u, MechanicalState* sb, unsigned gb, const Vec3& v,
                      double c) {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) K.add(sa, 6 * ga + 3 + i, sb, 6 * gb + 3 + j, c * u[i] * v[j]);
    };
    couple(s1_, s.m1, a1, s1_, s.m1, a1, -s.soft_rot * s.ratio);
    couple(s1_, s.m1, a1, s2_, s.m2, a2, -s.soft_rot);
    couple(s2_, s.m2, a2, s1_, s.m1, a1, -s.soft_rot);
    couple(s2_, s.m2, a2, s2_, s.m2, a2, -s.soft_rot / s.ratio);
  }
  return true;
}

void register_gear_spring_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "GearSpringForceField";
  info.category = "ForceField/Spring";
  info.description = "gear couplings (gear ratio, gears held on pivots) between the frames of two Rigid3d states";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  // object1/object2 may live elsewhere than the node's state: the types are checked at init.
  info.requirement = Requirement::none;
  info.create = creator<GearSpringForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
