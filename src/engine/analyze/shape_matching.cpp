#include "engine/analyze/shape_matching.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"
#include "math/decompose.h"
#include "math/sofa_vec.h"

namespace sinew {

namespace {

// m += a·bᵀ·w, element by element as SOFA's dyad(a, b)*w.
void add_dyad(Mat3& m, const Vec3& a, const Vec3& b, double w) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) += (a[i] * b[j]) * w;
}

Vec3 at(const std::vector<double>& x, std::size_t i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

}  // namespace

ShapeMatching::ShapeMatching(StateType type)
    : fixed_position0(this, "fixedPosition0", empty_coords(type), "rest positions of non mechanical particles.",
                      "Inputs"),
      fixed_position(this, "fixedPosition", empty_coords(type),
                     "current (fixed) positions of non mechanical particles.", "Inputs"),
      position(this, "position", empty_coords(type), "Input positions.", "Inputs"),
      target_position(this, "targetPosition", empty_coords(type), "Computed target positions.", "Outputs") {
  add_input(&fixed_position0);
  add_input(&fixed_position);
  add_input(&position);
  add_input(&cluster);
  add_output(&target_position);
}

void ShapeMatching::init() {
  if (!mstate) mstate.set(node()->get_mechanical_state());
  if (!mstate) {
    msg_error("no mechanical state: its rest positions define the shapes (set 'mstate' or add a MechanicalObject)");
    set_state(ComponentState::invalid);
    return;
  }
  if (mstate->state_type() != StateType::vec3) {
    msg_error(std::string("needs a Vec3d state (got ") + mstate->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  // Each iteration visits every cluster entry: a count no scene needs would stall the step.
  if (iterations.value() > 100000) {
    msg_error("iterations = " + std::to_string(iterations.value()) + " is more than 100000");
    set_state(ComponentState::invalid);
    return;
  }
  for (const Field<double>* f : {&affine_ratio, &fixed_weight})
    if (!std::isfinite(f->value())) {
      msg_error(f->name() + " must be finite (got " + f->text() + ")");
      set_state(ComponentState::invalid);
      return;
    }
  set_dirty();
  update();
}

void ShapeMatching::do_update() {
  if (!mstate || state() == ComponentState::invalid) return;
  const std::vector<double>& rest = mstate->read(kRestPosition);
  const std::vector<double>& fixed0 = fixed_position0.get().data;
  const std::vector<double>& fixed = fixed_position.get().data;
  const std::vector<double>& current = position.get().data;
  const auto& clusters = cluster.get();
  const std::size_t nbp = rest.size() / 3, nbf = fixed0.size() / 3, nbc = clusters.size();
  if (nbc == 0 || nbp == 0 || current.empty()) return;
  if (current.size() < 3 * nbp) {
    msg_error("position has " + std::to_string(current.size() / 3) + " points, the state " + std::to_string(nbp));
    set_state(ComponentState::invalid);
    return;
  }
  const double wf = fixed_weight.value();
  for (std::size_t i = 0; i < nbc; ++i)
    for (unsigned k : clusters[i])
      if (k >= nbp + nbf || (k >= nbp && k - nbp >= fixed.size() / 3)) {
        msg_error("cluster " + std::to_string(i) + " holds point " + std::to_string(k) + " (there are " +
                  std::to_string(nbp) + " points and " + std::to_string(nbf) + " fixed particles)");
        set_state(ComponentState::invalid);
        return;
      }

  // The rest shapes: centre of mass and (Σ w·x0·x0ᵀ − W·x0cm·x0cmᵀ)⁻¹ per cluster.
  if (old_size_ != nbp + nbf || old_weight_ != wf || cluster_version_ != cluster.version()) {
    xcm0_.assign(nbc, Vec3::Zero());
    xcm_.assign(nbc, Vec3::Zero());
    weight_.assign(nbc, 0.0);
    qx_inv_.assign(nbc, Mat3::Zero());
    t_.assign(nbc, Mat3::Zero());
    clusters_of_.assign(nbp, 0);
    for (std::size_t i = 0; i < nbc; ++i) {
      Mat3 qx = Mat3::Zero();
      for (unsigned k : clusters[i]) {
        const Vec3 p0 = k < nbp ? at(rest, k) : at(fixed0, k - nbp);
        const double w = k < nbp ? 1.0 : wf;
        xcm0_[i] += p0 * w;
        add_dyad(qx, p0, p0, w);
        weight_[i] += w;
        if (k < nbp) ++clusters_of_[k];
      }
      xcm0_[i] /= weight_[i];
      add_dyad(qx, xcm0_[i], xcm0_[i], -weight_[i]);
      const double det = sofa_det(qx);
      if ((!std::isfinite(det) || !sofa_invert(qx, det, qx_inv_[i])) && affine_ratio.value() != 0.0)
        msg_warning("cluster " + std::to_string(i) + " is flat or a single point: its affine fit is undefined");
    }
    old_size_ = nbp + nbf;
    old_weight_ = wf;
    cluster_version_ = cluster.version();
  }

  std::vector<double> target(current.begin(), current.begin() + static_cast<std::ptrdiff_t>(3 * nbp));
  const double ratio = affine_ratio.value();
  for (unsigned iter = 0; iter < iterations.value(); ++iter) {
    for (std::size_t i = 0; i < nbc; ++i) {
      Vec3 xcm = Vec3::Zero();
      Mat3 t = Mat3::Zero();
      for (unsigned k : clusters[i]) {
        const Vec3 p0 = k < nbp ? at(rest, k) : at(fixed0, k - nbp);
        const Vec3 p = k < nbp ? at(target, k) : at(fixed, k - nbp);
        const double w = k < nbp ? 1.0 : wf;
        xcm += p * w;
        add_dyad(t, p, p0, w);
      }
      // Σ w·(x − xcm)(x0 − x0cm)ᵀ = Σ w·x·x0ᵀ − (Σ w·x)·x0cmᵀ
      add_dyad(t, xcm, xcm0_[i], -1.0);
      xcm /= weight_[i];
      Mat3 r = Mat3::Zero();
      if (ratio != 1.0) r = polar_rotation(t);
      if (ratio != 0.0) {
        const Mat3 affine = sofa_mul(t, qx_inv_[i]);
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) t(a, b) = affine(a, b) * ratio + r(a, b) * (1.0 - ratio);
      } else {
        t = r;
      }
      xcm_[i] = xcm;
      t_[i] = t;
    }
    std::fill(target.begin(), target.end(), 0.0);
    for (std::size_t i = 0; i < nbc; ++i)
      for (unsigned k : clusters[i])
        if (k < nbp) {
          const Vec3 d = at(rest, k) - xcm0_[i];
          const Vec3 g = xcm_[i] + sofa_mul(t_[i], d);
          for (int c = 0; c < 3; ++c) target[3 * k + c] += g[c];
        }
    for (std::size_t k = 0; k < nbp; ++k)
      for (int c = 0; c < 3; ++c)
        target[3 * k + c] = clusters_of_[k] ? target[3 * k + c] / static_cast<double>(clusters_of_[k])
                                            : current[3 * k + c];
  }
  FlatVec out;
  out.width = 3;
  out.data = std::move(target);
  target_position.set(std::move(out));
}

void register_shape_matching(Registry& r) {
  ComponentInfo info;
  info.name = "ShapeMatching";
  info.category = "Engine/Analyze";
  info.description = "target positions restoring the rest shape of clusters of points (shape matching)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.create = state_creator<ShapeMatching>();
  r.add(std::move(info));
}

}  // namespace sinew
