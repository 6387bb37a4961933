#include "haptics/lcp_force_feedback.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "constraint/solver/lcp_constraint_solver.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew::haptics {

LCPForceFeedback::LCPForceFeedback(bool rigid) : rigid_(rigid) {
  listening.set(true);  // SOFA sets f_listening in the constructor
}

LCPForceFeedback::~LCPForceFeedback() {
  // Detach from the drivers before the buffers go: the servo thread may be in a call.
  detach_slots();
}

void LCPForceFeedback::init() {
  Node* n = node();
  if (!n) return;
  tool_ = n->get_mechanical_state();
  if (!tool_) {
    msg_error("no mechanical state in the node (the tool's DoFs): no force is computed");
    set_state(ComponentState::invalid);
    return;
  }
  const StateType want = rigid_ ? StateType::rigid3 : StateType::vec1;
  if (tool_->state_type() != want) {
    msg_error(std::string("the node's state is ") + tool_->info().name + " but the template is " +
              (rigid_ ? "Rigid3d" : "Vec1d"));
    set_state(ComponentState::invalid);
    return;
  }
  // SOFA: the constraint solver found from the node upwards.
  ConstraintSolver* any = n->find_up<ConstraintSolver>();
  solver_ = dynamic_cast<LCPConstraintSolver*>(any);
  if (!solver_) {
    msg_error(any ? "the constraint solver found (" + any->class_name() +
                        ") is not an LCPConstraintSolver: only its problems are re-solved at the device rate"
                  : std::string("no constraint solver found from the node upwards: no force is computed"));
    set_state(ComponentState::invalid);
    return;
  }
  if (solver_timeout.value() < 0 || !std::isfinite(solver_timeout.value())) {
    msg_error("solverTimeout must be >= 0 (seconds)");
    set_state(ComponentState::invalid);
    return;
  }
  if (solver_max_it.value() < 0) {
    msg_error("solverMaxIt must be >= 0");
    set_state(ComponentState::invalid);
    return;
  }
}

void LCPForceFeedback::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_end || state() != ComponentState::valid || !solver_ || !tool_) return;
  take_snapshot();
}

// Simulation thread: fills the back buffer and publishes it.
void LCPForceFeedback::take_snapshot() {
  const ConstraintProblem& cp = solver_->problem();
  if (!tool_->has_vec(kFreePosition)) return;  // no free motion: no problem to re-solve
  HapticProblem& b = buffers_[back_];
  b.n = cp.n;
  b.mu = solver_->mu.value();
  b.tolerance = solver_->tolerance.value();
  b.W.assign(cp.W.begin(), cp.W.begin() + static_cast<std::ptrdiff_t>(cp.n) * cp.n);
  b.dfree.assign(cp.dfree.begin(), cp.dfree.begin() + cp.n);
  b.f.assign(cp.f.begin(), cp.f.begin() + cp.n);
  const std::vector<double>& xf = tool_->read(kFreePosition);
  b.free_position.assign(xf.begin(), xf.end());
  b.dofs = tool_->size();
  const ConstraintMatrix& J = tool_->constraint_jacobian();
  b.width = tool_->info().deriv_width;
  b.row_id.clear();
  b.row_begin.clear();
  b.entry_dof.clear();
  b.entry_value.clear();
  const auto entries = J.entries();
  for (const ConstraintMatrix::Row& r : J.rows()) {
    if (r.id < 0 || r.id >= cp.n) continue;  // rows of another solve (cannot happen after a solve)
    b.row_id.push_back(r.id);
    b.row_begin.push_back(static_cast<int>(b.entry_dof.size()));
    for (int k = r.begin; k < r.end; ++k) {
      b.entry_dof.push_back(entries[static_cast<std::size_t>(k)].dof);
      const double* v = J.value(k);
      b.entry_value.insert(b.entry_value.end(), v, v + b.width);
    }
  }
  b.row_begin.push_back(static_cast<int>(b.entry_dof.size()));
  b.dx.assign(b.dofs * static_cast<std::size_t>(b.width), 0.0);
  b.force.assign(b.dofs * static_cast<std::size_t>(b.width), 0.0);
  b.valid = true;
  // Publish: the back buffer becomes the shared one; the old shared one (not
  // the reader's) is the next back buffer.
  back_ = shared_.exchange(back_ | kFresh, std::memory_order_acq_rel) & 3u;
  snapshots_.fetch_add(1, std::memory_order_relaxed);
}

void LCPForceFeedback::compute_state_force(std::span<const double> pose, std::span<double> forces) {
  std::fill(forces.begin(), forces.end(), 0.0);
  if (!activate.value() || state() != ComponentState::valid) return;
  std::lock_guard<std::mutex> lock(servo_mutex_);
  // Take the newest snapshot when one was published since the last take.
  if (shared_.load(std::memory_order_acquire) & kFresh)
    front_ = shared_.exchange(front_, std::memory_order_acq_rel) & 3u;
  HapticProblem& p = buffers_[front_];
  if (!p.valid) return;
  solve(p, pose, forces);
}

// Servo thread: steps 2–5 of the header on the reader's buffer.
void LCPForceFeedback::solve(HapticProblem& p, std::span<const double> pose, std::span<double> forces) {
  if (p.row_id.empty()) return;
  const int cw = rigid_ ? 7 : 1;
  const int w = p.width;
  const std::size_t given = pose.size() / static_cast<std::size_t>(cw);
  const std::size_t common = std::min(given, p.dofs);
  const bool rot = deriv_rotations.value();
  // dx = pose − stored free position (SOFA's derivVectors); DoFs the caller
  // did not give are taken at the origin (−x0), as SOFA does.
  for (std::size_t i = 0; i < p.dofs; ++i) {
    const double* x0 = &p.free_position[i * static_cast<std::size_t>(cw)];
    double* d = &p.dx[i * static_cast<std::size_t>(w)];
    if (!rigid_) {
      d[0] = i < common ? pose[i] - x0[0] : -x0[0];
      continue;
    }
    const Quat q0 = Quat::from(x0 + 3);
    if (i < common) {
      const double* x1 = &pose[i * 7];
      for (int k = 0; k < 3; ++k) d[k] = x1[k] - x0[k];
      Vec3 a = Vec3::Zero();
      if (rot) a = quat_rotate(q0, quat_angular_displacement(Quat::from(x1 + 3), q0));
      for (int k = 0; k < 3; ++k) d[3 + k] = a[k];
    } else {
      for (int k = 0; k < 3; ++k) d[k] = -x0[k];
      Vec3 a = Vec3::Zero();
      if (rot) a = -quat_rotate(q0, quat_to_rotation_vector(q0));
      for (int k = 0; k < 3; ++k) d[3 + k] = a[k];
    }
  }
  const bool all_frames = local_haptic_constraint_all_frames.value();
  const std::size_t rows = p.row_id.size();
  // dfree_i ±= J_i·dx, one entry at a time as SOFA adds them.
  auto add_j_dx = [&](double sign) {
    for (std::size_t r = 0; r < rows; ++r) {
      double& dfree = p.dfree[static_cast<std::size_t>(p.row_id[r])];
      for (int e = p.row_begin[r]; e < p.row_begin[r + 1]; ++e) {
        const double* v = &p.entry_value[static_cast<std::size_t>(e) * w];
        const std::size_t dof = all_frames ? 0 : static_cast<std::size_t>(p.entry_dof[static_cast<std::size_t>(e)]);
        const double* d = &p.dx[dof * static_cast<std::size_t>(w)];
        double s = 0;
        for (int k = 0; k < w; ++k) s += v[k] * d[k];
        dfree += sign * s;
      }
    }
  };
  add_j_dx(1.0);
  const auto t0 = std::chrono::steady_clock::now();
  const auto deadline =
      t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(
               solver_timeout.value()));
  const LcpResult res = nlcp_gauss_seidel_timed(p.n, p.dfree.data(), p.W.data(), p.f.data(), p.mu,
                                                p.tolerance * 0.001, solver_max_it.value(), deadline);
  add_j_dx(-1.0);  // restore dfree
  solves_.fetch_add(1, std::memory_order_relaxed);
  if (res.timed_out) timeouts_.fetch_add(1, std::memory_order_relaxed);
  last_rows_.store(p.n, std::memory_order_relaxed);
  // force = forceCoef · Σ Jᵢᵀ λᵢ (rows with λᵢ ≠ 0).
  std::fill(p.force.begin(), p.force.end(), 0.0);
  for (std::size_t r = 0; r < rows; ++r) {
    const double lambda = p.f[static_cast<std::size_t>(p.row_id[r])];
    if (lambda == 0.0) continue;
    for (int e = p.row_begin[r]; e < p.row_begin[r + 1]; ++e) {
      const double* v = &p.entry_value[static_cast<std::size_t>(e) * w];
      const std::size_t dof = all_frames ? 0 : static_cast<std::size_t>(p.entry_dof[static_cast<std::size_t>(e)]);
      double* out = &p.force[dof * static_cast<std::size_t>(w)];
      for (int k = 0; k < w; ++k) out[k] += v[k] * lambda;
    }
  }
  const std::size_t n_out = std::min(forces.size(), p.force.size());
  const double coef = force_coef.value();
  for (std::size_t i = 0; i < n_out; ++i) forces[i] = p.force[i] * coef;
}

Vec3 LCPForceFeedback::compute_force(const Vec3& p, const Quat& q) {
  (void)q;  // SOFA builds the tool at (x, y, z) with the identity orientation
  if (!rigid_) return Vec3::Zero();
  Vec3 f = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  compute_wrench(p, Quat{}, Vec3::Zero(), Vec3::Zero(), f, torque);
  return f;
}

void LCPForceFeedback::compute_wrench(const Vec3& p, const Quat& q, const Vec3& v, const Vec3& w, Vec3& force,
                                      Vec3& torque) {
  (void)v, (void)w;  // SOFA ignores the tool's velocity
  force = Vec3::Zero();
  torque = Vec3::Zero();
  if (!rigid_) return;
  const double pose[7] = {p[0], p[1], p[2], q.x, q.y, q.z, q.w};
  double out[6] = {0, 0, 0, 0, 0, 0};
  compute_state_force(std::span<const double>(pose, 7), std::span<double>(out, 6));
  force = Vec3(out[0], out[1], out[2]);
  torque = Vec3(out[3], out[4], out[5]);
}

}  // namespace sinew::haptics

namespace sinew {
void register_lcp_force_feedback(Registry& r) {
  ComponentInfo info;
  info.name = "LCPForceFeedback";
  info.category = "Haptics";
  info.description = "haptic force from the last constraint problem re-solved at the device's pose (1 kHz)";
  info.templates = {"Vec1d", "Rigid3d"};
  info.default_template = "Rigid3d";
  info.requirement = Requirement::state;
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    return std::make_unique<haptics::LCPForceFeedback>(tmpl != "Vec1d");
  };
  r.add(std::move(info));
}
}  // namespace sinew
