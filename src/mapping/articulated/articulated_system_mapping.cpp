#include "mapping/articulated/articulated_system_mapping.h"

#include <algorithm>
#include <string>

#include "core/constraint_matrix.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"
#include "math/sofa_vec.h"

namespace sinew {

namespace {

Vec3 vec_at(const double* p) { return Vec3(p[0], p[1], p[2]); }
Vec3 vec_at(const std::vector<double>& v, std::size_t i) { return vec_at(&v[3 * i]); }
void put_vec(double* p, const Vec3& a) { p[0] = a[0], p[1] = a[1], p[2] = a[2]; }

}  // namespace

ArticulatedSystemMapping::ArticulatedSystemMapping()
    : input1(this, "input1", "the joint coordinates (Vec1d)", /*multi=*/true, false),
      input2(this, "input2", "the frame the system hangs from (Rigid3d, optional)", /*multi=*/true, false),
      output_link(this, "output", "the frames of the system (Rigid3d)", /*multi=*/true, false) {}

std::vector<MechanicalState*> ArticulatedSystemMapping::inputs() const {
  std::vector<MechanicalState*> v;
  if (in_) v.push_back(in_);
  if (root_) v.push_back(root_);
  return v;
}

bool ArticulatedSystemMapping::resolve_links() {
  in_ = first_link_state(*this, input1, StateType::vec1, "input1 (the joint coordinates)");
  out_ = in_ ? first_link_state(*this, output_link, StateType::rigid3, "output (the frames)") : nullptr;
  if (!in_ || !out_) return false;
  root_ = nullptr;
  if (!input2.targets().empty()) {
    root_ = first_link_state(*this, input2, StateType::rigid3, "input2 (the base frame)");
    if (!root_) return false;
  }
  if (in_ == out_ || root_ == out_) {
    msg_error("an input is also the output");
    return false;
  }
  return true;
}

void ArticulatedSystemMapping::init() {
  have_centers_ = false;
  if (!resolve_links()) {
    set_state(ComponentState::invalid);
    return;
  }
  if (root_) {
    const std::size_t frames = root_->size();
    if (frames == 0) {
      msg_error("input2 (the base frame) has no frame");
      set_state(ComponentState::invalid);
      return;
    }
    // Default: the last frame of input2 (SOFA's indexInput2).
    root_index_ = frames - 1;
    if (index_input2.is_set()) {
      if (index_input2.value() < frames)
        root_index_ = index_input2.value();
      else
        msg_warning("indexInput2 is " + std::to_string(index_input2.value()) + " but input2 has " +
                    std::to_string(frames) + " frames: frame " + std::to_string(root_index_) + " is used");
    }
  }
  const std::size_t n = in_->size();
  axis_.assign(3 * n, 0.0);
  pos_.assign(3 * n, 0.0);
  previous_.assign(n, 0.0);
  // SOFA maps here, before bwd_init has found the centres: only frame 0 follows input2.
  apply(kPosition);
  apply_j(kVelocity, kVelocity);
  if (apply_rest_position.value()) apply(kRestPosition);
}

void ArticulatedSystemMapping::bwd_init() {
  if (state() == ComponentState::invalid) return;
  if (!container) {
    // SOFA searches from input1's node downwards.
    if (Node* n = in_->node()) container.set(n->find_down<ArticulatedHierarchyContainer>());
  }
  if (!container) {
    msg_error("no ArticulatedHierarchyContainer: set `container` or put one at or below input1's node");
    set_state(ComponentState::invalid);
    return;
  }
  if (container->state() == ComponentState::invalid) {
    msg_error("its ArticulatedHierarchyContainer is invalid");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<ArticulationCenter*>& centers = container->centers();
  if (centers.size() > in_->size()) {
    msg_error("the container has " + std::to_string(centers.size()) + " articulation centres, more than the " +
              std::to_string(in_->size()) + " coordinates of input1");
    set_state(ComponentState::invalid);
    return;
  }
  for (ArticulationCenter* ac : centers) {
    ac->orientation = Quat{};
    ac->displacement = Vec3::Zero();
  }
  have_centers_ = true;
  if (!checked_centers(in_->size(), out_->size())) set_state(ComponentState::invalid);
}

void ArticulatedSystemMapping::reset() {
  if (state() == ComponentState::invalid) return;
  // SOFA's reset is its init: increments counted from zero again, centres kept.
  std::fill(previous_.begin(), previous_.end(), 0.0);
  apply(kPosition);
  apply_j(kVelocity, kVelocity);
}

const std::vector<ArticulationCenter*>* ArticulatedSystemMapping::checked_centers(std::size_t coords,
                                                                                  std::size_t frames) {
  if (!have_centers_ || !container) return nullptr;
  const std::vector<ArticulationCenter*>& centers = container->centers();
  std::string problem;
  for (const ArticulationCenter* ac : centers) {
    const int p = ac->parent_index.value(), c = ac->child_index.value();
    if (p < 0 || c < 0 || static_cast<std::size_t>(p) >= frames || static_cast<std::size_t>(c) >= frames)
      problem = ac->describe() + " joins frames " + std::to_string(p) + " and " + std::to_string(c) +
                " but the output has " + std::to_string(frames);
    else if (p == c)
      problem = ac->describe() + " joins frame " + std::to_string(p) + " to itself";
    else if (ac->articulation_process.value() < 0 || ac->articulation_process.value() > 2)
      problem = ac->describe() + " has articulationProcess " + std::to_string(ac->articulation_process.value()) +
                " (0, 1 or 2)";
    for (const Articulation* a : ac->articulations) {
      const int i = a->articulation_index.value();
      if (i < 0 || static_cast<std::size_t>(i) >= coords)
        problem = a->describe() + " has articulationIndex " + std::to_string(i) + " but input1 has " +
                  std::to_string(coords) + " coordinates";
    }
    if (!problem.empty()) break;
  }
  if (problem.empty()) return &centers;
  if (!warned_fit_) {
    warned_fit_ = true;
    msg_error(problem + ": the articulated system is not mapped");
  }
  return nullptr;
}

void ArticulatedSystemMapping::apply(int x) {
  const std::vector<double>& in = in_->read(vec_for(*in_, x, kPosition));
  std::vector<double>& out = out_->write(vec_for(*out_, x, kPosition));
  const std::size_t n = in.size(), frames = out.size() / 7;
  if (root_ && frames > 0) {
    const std::vector<double>& base = root_->read(vec_for(*root_, x, kPosition));
    if (base.size() >= 7 * (root_index_ + 1))
      for (int k = 0; k < 7; ++k) out[k] = base[7 * root_index_ + k];
  }
  if (axis_.size() != 3 * n) {  // input1 resized since init
    axis_.resize(3 * n, 0.0);
    pos_.resize(3 * n, 0.0);
    previous_.resize(n, 0.0);
  }
  if (const std::vector<ArticulationCenter*>* centers = checked_centers(n, frames)) {
    for (ArticulationCenter* ac : *centers) {
      double* pf = &out[7 * ac->parent_index.value()];
      double* cf = &out[7 * ac->child_index.value()];
      const Vec3 parent_c = vec_at(pf);
      const Quat parent_q = Quat::from(pf + 3);
      const Quat child_q_before = Quat::from(cf + 3);
      const Vec3& on_parent = ac->pos_on_parent.value();
      const Vec3& on_child = ac->pos_on_child.value();
      Vec3 global = parent_c + quat_rotate(parent_q, on_parent);
      ac->global_position.set(global);
      Vec3 child_c = Vec3::Zero();
      Quat child_q;
      switch (ac->articulation_process.value()) {
        case 0: {
          // The child turned as its parent and put in place at the joint, then each
          // articulation in turn, about or along its axis carried by the child.
          child_q = parent_q;
          child_c = parent_c + quat_rotate(parent_q, on_parent - on_child);
          Vec3 joint = global;
          for (Articulation* a : ac->articulations) {
            Vec3 local = a->axis.value();
            sofa_normalize(local);
            if (local != a->axis.value()) a->axis.set(local);  // SOFA normalises the Data
            const int ind = a->articulation_index.value();
            const double value = in[ind];
            const Vec3 axis = quat_rotate(child_q, local);
            put_vec(&axis_[3 * ind], axis);
            if (a->rotation.value()) {
              const Quat dq = quat_from_axis_angle(axis, value);
              // The child's centre turns about the joint.
              const Vec3 to_center = quat_rotate(child_q, Vec3::Zero() - on_child);
              child_c += quat_rotate(dq, to_center) - to_center;
              child_q = quat_then(child_q, dq);
            }
            if (a->translation.value()) {
              child_c += axis * value;
              joint += axis * value;
            }
            put_vec(&pos_[3 * ind], joint);
          }
          break;
        }
        case 1:
        case 2: {
          // Increments since the last apply, about axes carried by the parent (1) or by
          // the child's previous orientation (2).
          const bool on_parent_axes = ac->articulation_process.value() == 1;
          Vec3 displacement = Vec3::Zero();
          for (Articulation* a : ac->articulations) {
            const int ind = a->articulation_index.value();
            const double value = in[ind], step = value - previous_[ind];
            const Vec3 axis = quat_rotate(on_parent_axes ? parent_q : child_q_before, a->axis.value());
            put_vec(&axis_[3 * ind], axis);
            if (a->rotation.value()) ac->orientation = quat_then(ac->orientation, quat_from_axis_angle(axis, step));
            if (a->translation.value()) {
              if (on_parent_axes)
                ac->displacement += axis * step;
              else
                displacement += axis * value;
            }
            if (!on_parent_axes) put_vec(&pos_[3 * ind], global);
          }
          if (on_parent_axes) {
            // The joint follows the translations; every articulation sits at it.
            global = parent_c + quat_rotate(parent_q, on_parent) + ac->displacement;
            ac->global_position.set(global);
            for (Articulation* a : ac->articulations) put_vec(&pos_[3 * a->articulation_index.value()], global);
          } else {
            ac->displacement = displacement;
          }
          child_q = quat_then(parent_q, ac->orientation);
          child_c = global - quat_rotate(child_q, on_child);
          if (!on_parent_axes) child_c += ac->displacement;
          break;
        }
      }
      put_vec(cf, child_c);
      child_q.store(cf + 3);
    }
  }
  for (std::size_t i = 0; i < n; ++i) previous_[i] = in[i];
}

void ArticulatedSystemMapping::apply_j(int v, int role) {
  const std::vector<double>& in = in_->read(vec_for(*in_, v, role));
  std::vector<double>& out = out_->write(vec_for(*out_, v, role));
  const std::vector<double>& xto = out_->read(kPosition);
  const std::size_t frames = xto.size() / 7;
  out.assign(6 * frames, 0.0);
  if (frames == 0) return;
  if (root_) {
    const std::vector<double>& base = root_->read(vec_for(*root_, v, role));
    if (base.size() >= 6 * (root_index_ + 1))
      for (int k = 0; k < 6; ++k) out[k] = base[6 * root_index_ + k];
  }
  const std::vector<ArticulationCenter*>* centers = checked_centers(in.size(), frames);
  if (!centers || axis_.size() != 3 * in.size()) return;
  for (const ArticulationCenter* ac : *centers) {
    const int parent = ac->parent_index.value(), child = ac->child_index.value();
    double* vp = &out[6 * parent];
    double* vc = &out[6 * child];
    Vec3 w = vec_at(vc + 3) + vec_at(vp + 3);
    const Vec3 P = vec_at(&xto[7 * parent]), C = vec_at(&xto[7 * child]);
    Vec3 lin = vec_at(vp) + sofa_cross(P - C, vec_at(vp + 3));
    for (const Articulation* a : ac->articulations) {
      const int ind = a->articulation_index.value();
      const Vec3 axis = vec_at(axis_, ind), A = vec_at(pos_, ind);
      if (a->rotation.value()) {
        lin += sofa_cross(A - C, axis * in[ind]);
        w += axis * in[ind];
      }
      if (a->translation.value()) lin += axis * in[ind];
    }
    put_vec(vc, lin);
    put_vec(vc + 3, w);
  }
}

void ArticulatedSystemMapping::apply_jt(int f, int role) {
  const std::vector<double>& fo = out_->read(vec_for(*out_, f, role));
  std::vector<double>& fi = in_->write(vec_for(*in_, f, role));
  const std::vector<double>& xto = out_->read(kPosition);
  const std::size_t frames = std::min(xto.size() / 7, fo.size() / 6);
  if (frames == 0) return;
  frame_force_.assign(fo.begin(), fo.begin() + 6 * frames);
  const std::vector<ArticulationCenter*>* centers = checked_centers(fi.size(), frames);
  if (centers && axis_.size() == 3 * fi.size()) {
    // Leaves first: each child's force and torque pass to its parent, and to its joint coordinates.
    for (auto it = centers->rbegin(); it != centers->rend(); ++it) {
      const ArticulationCenter* ac = *it;
      const int parent = ac->parent_index.value(), child = ac->child_index.value();
      double* fp = &frame_force_[6 * parent];
      const double* fc = &frame_force_[6 * child];
      const Vec3 fc_lin = vec_at(fc), fc_rot = vec_at(fc + 3);
      const Vec3 P = vec_at(&xto[7 * parent]), C = vec_at(&xto[7 * child]);
      put_vec(fp, vec_at(fp) + fc_lin);
      put_vec(fp + 3, vec_at(fp + 3) + (fc_rot + sofa_cross(C - P, fc_lin)));
      for (auto a = ac->articulations.rbegin(); a != ac->articulations.rend(); ++a) {
        const int ind = (*a)->articulation_index.value();
        const Vec3 axis = vec_at(axis_, ind), A = vec_at(pos_, ind);
        const Vec3 torque = fc_rot + sofa_cross(C - A, fc_lin);
        if ((*a)->rotation.value()) fi[ind] += sofa_dot(axis, torque);
        if ((*a)->translation.value()) fi[ind] += sofa_dot(axis, fc_lin);
      }
    }
  }
  if (root_) {
    std::vector<double>& fr = root_->write(vec_for(*root_, f, role));
    if (fr.size() >= 6 * (root_index_ + 1))
      for (int k = 0; k < 6; ++k) fr[6 * root_index_ + k] += frame_force_[k];
  }
}

// J as apply_j computes it, column by column: the input columns are the joint
// coordinates (input 0) then the base frame's six (input 1). Each frame's rows get the
// columns of its chain (its ancestors' articulations and the base), all six rows of each,
// zeros included, so that the pattern depends on the hierarchy only.
bool ArticulatedSystemMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::vector<double>& xto = out_->read(kPosition);
  const std::size_t frames = xto.size() / 7, n = in_->size();
  const std::size_t cols = n + (root_ ? 6 : 0);
  const std::vector<ArticulationCenter*>* centers = checked_centers(n, frames);
  if (frames == 0) return true;
  if (!centers && have_centers_) return false;
  // Row r of frame f, column c: jac_[(6 f + r)·cols + c]; used_[f·cols + c]: structurally there.
  jac_.assign(6 * frames * cols, 0.0);
  used_.assign(frames * cols, 0);
  auto at = [&](std::size_t f, int r, std::size_t c) -> double& { return jac_[(6 * f + r) * cols + c]; };
  if (root_)
    for (int k = 0; k < 6; ++k) {
      at(0, k, n + k) = 1.0;
      used_[n + k] = 1;
    }
  if (centers && axis_.size() == 3 * n) {
    for (const ArticulationCenter* ac : *centers) {
      const std::size_t parent = ac->parent_index.value(), child = ac->child_index.value();
      const Vec3 P = vec_at(&xto[7 * parent]), C = vec_at(&xto[7 * child]);
      for (std::size_t c = 0; c < cols; ++c) {
        if (!used_[parent * cols + c] && !used_[child * cols + c]) continue;
        used_[child * cols + c] |= used_[parent * cols + c];
        const Vec3 wp(at(parent, 3, c), at(parent, 4, c), at(parent, 5, c));
        const Vec3 lin = Vec3(at(parent, 0, c), at(parent, 1, c), at(parent, 2, c)) + sofa_cross(P - C, wp);
        for (int k = 0; k < 3; ++k) {
          at(child, 3 + k, c) += wp[k];
          at(child, k, c) = lin[k];
        }
      }
      for (const Articulation* a : ac->articulations) {
        const std::size_t ind = a->articulation_index.value();
        const Vec3 axis = vec_at(axis_, ind), A = vec_at(pos_, ind);
        used_[child * cols + ind] = 1;
        if (a->rotation.value()) {
          const Vec3 lin = sofa_cross(A - C, axis);
          for (int k = 0; k < 3; ++k) {
            at(child, k, ind) += lin[k];
            at(child, 3 + k, ind) += axis[k];
          }
        }
        if (a->translation.value())
          for (int k = 0; k < 3; ++k) at(child, k, ind) += axis[k];
      }
    }
  }
  for (std::size_t f = 0; f < frames; ++f)
    for (int r = 0; r < 6; ++r)
      for (std::size_t c = 0; c < cols; ++c)
        if (used_[f * cols + c]) {
          const bool base = c >= n;
          out.push_back({base ? 1u : 0u, static_cast<std::uint32_t>(6 * f + r),
                         static_cast<std::uint32_t>(base ? c - n : c), at(f, r, c)});
        }
  return true;
}

bool ArticulatedSystemMapping::apply_jt_constraints() {
  ConstraintMatrix& c = out_->constraint_jacobian();
  if (c.empty()) return true;
  c.compress();
  const std::vector<double>& xto = out_->read(kPosition);
  const std::size_t frames = xto.size() / 7;
  ConstraintMatrix& j1 = in_->constraint_jacobian();
  const std::vector<ArticulationCenter*>* centers = checked_centers(in_->size(), frames);
  const bool ok = centers && axis_.size() == 3 * in_->size();
  const std::vector<double>* base = root_ ? &root_->read(kPosition) : nullptr;
  const auto entries = c.entries();
  for (const ConstraintMatrix::Row& row : c.rows()) {
    for (int e = row.begin; e < row.end; ++e) {
      const int frame = entries[e].dof;
      if (frame < 0 || static_cast<std::size_t>(frame) >= frames) continue;
      const double* v = c.value(e);
      const Vec3 lin = vec_at(v), rot = vec_at(v + 3);
      const Vec3 C = vec_at(&xto[7 * frame]);
      if (ok) {
        // Every joint coordinate between this frame and frame 0.
        container->ancestors(frame, chain_);
        for (const ArticulationCenter* ac : chain_)
          for (const Articulation* a : ac->articulations) {
            const int ind = a->articulation_index.value();
            const Vec3 axis = vec_at(axis_, ind), A = vec_at(pos_, ind);
            double value = 0.0;
            if (a->rotation.value()) value = sofa_dot(axis, rot + sofa_cross(C - A, lin));
            if (a->translation.value()) value = sofa_dot(axis, lin);  // SOFA: the translation wins
            j1.add(row.id, ind, &value);
          }
      }
      if (base && base->size() >= 7 * (root_index_ + 1)) {
        const Vec3 origin = vec_at(&(*base)[7 * root_index_]);
        const Vec3 torque = rot + sofa_cross(C - origin, lin);
        const double t[6] = {lin[0], lin[1], lin[2], torque[0], torque[1], torque[2]};
        root_->constraint_jacobian().add(row.id, static_cast<int>(root_index_), t);
      }
    }
  }
  return true;
}

void register_articulated_system_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "ArticulatedSystemMapping";
  info.category = "Mapping/Articulated";
  info.description = "frames of an articulated rigid system from its joint coordinates (inputs Vec1d and Rigid3d)";
  info.templates = {"Vec1d,Rigid3d,Rigid3d"};
  info.default_template = "Vec1d,Rigid3d,Rigid3d";
  info.create = creator<ArticulatedSystemMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
