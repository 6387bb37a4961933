#include "forcefield/spring/polynomial_springs_force_field.h"

#include <cmath>
#include <string>

#include "core/registry.h"
#include "forcefield/spring/spring_force_field.h"

namespace sinew {

std::vector<MechanicalState*> PolynomialSpringsForceField::states() const {
  if (s1_ && s1_ == s2_) return {s1_};
  return {s1_, s2_};
}

void PolynomialSpringsForceField::init() {
  if (!bind_interaction_states(*this, object1, object2, s1_, s2_)) return;
  if (s1_->state_type() != StateType::vec3) {
    msg_error(std::string("object1/object2 are ") + s1_->info().name + " states; only Vec3d is supported");
    set_state(ComponentState::invalid);
  }
}

bool PolynomialSpringsForceField::read_indices() {
  first_ = first_points.value();
  second_ = second_points.value();
  if (first_.empty())
    for (unsigned i = 0; i < s1_->size(); ++i) first_.push_back(i);
  if (second_.empty())
    for (unsigned i = 0; i < s2_->size(); ++i) second_.push_back(i);
  if (first_.size() > second_.size()) {
    msg_error("firstObjectPoints has " + std::to_string(first_.size()) + " points but secondObjectPoints only " +
              std::to_string(second_.size()) + ": springs pair them one to one");
    return false;
  }
  for (unsigned i : first_)
    if (i >= s1_->size()) {
      msg_error("firstObjectPoints: point " + std::to_string(i) + " is beyond object1's " +
                std::to_string(s1_->size()) + " points");
      return false;
    }
  for (std::size_t k = 0; k < first_.size(); ++k)
    if (second_[k] >= s2_->size()) {
      msg_error("secondObjectPoints: point " + std::to_string(second_[k]) + " is beyond object2's " +
                std::to_string(s2_->size()) + " points");
      return false;
    }
  return true;
}

// SOFA's bwdInit: defaults, indices, rest lengths, the polynomial table.
void PolynomialSpringsForceField::bwd_init() {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  if (polynomial_stiffness.value().empty()) polynomial_stiffness.set({100.0});
  if (polynomial_degree.value().empty()) polynomial_degree.set({1u});
  if (!read_indices()) {
    set_state(ComponentState::invalid);
    return;
  }
  const std::size_t n = first_.size();
  rest_.assign(n, 0.0);
  rest_pending_.assign(n, compute_zero_length.value() == 1 ? 1 : 0);
  jacobian_.assign(n, Mat3::Zero());
  if (compute_zero_length.value() != 1) {
    const auto& z = zero_length.value();
    if (z.empty() || (z.size() > 1 && z.size() < n)) {
      msg_error("computeZeroLength is " + std::to_string(compute_zero_length.value()) + " but zeroLength has " +
                std::to_string(z.size()) + " values for " + std::to_string(n) + " springs (one, or one per spring)");
      set_state(ComponentState::invalid);
      return;
    }
    for (std::size_t i = 0; i < n; ++i) rest_[i] = z.size() > 1 ? z[i] : z[0];
    for (std::size_t i = 0; i < n; ++i)
      if (!(rest_[i] > 0)) {
        msg_error("zeroLength of spring " + std::to_string(i) + " is " + std::to_string(rest_[i]) +
                  ": rest lengths must be positive (the strain divides by them)");
        set_state(ComponentState::invalid);
        return;
      }
  }
  // Polynomial p uses the next degree[p] coefficients.
  const std::string bad = poly_.build(polynomial_degree.value(), polynomial_stiffness.value());
  if (!bad.empty()) {
    msg_error(bad);
    set_state(ComponentState::invalid);
    return;
  }
}

void PolynomialSpringsForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  if (recompute_indices.value()) {
    if (!read_indices() || first_.size() != rest_.size()) {
      if (first_.size() != rest_.size())
        msg_error("recompute_indices: the number of springs changed (" + std::to_string(rest_.size()) + " → " +
                  std::to_string(first_.size()) + "), which SOFA does not follow either");
      set_state(ComponentState::invalid);
      return;
    }
  }
  if (const std::string w = poly_.first_for_all_warning(first_.size()); !w.empty()) msg_warning(w);
  const double compression = compressible.value() ? -1.0 : 0.0;
  const auto [x1, v1, f1, x2, v2, f2] = pair_force_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < first_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(first_[i]), b = 3 * std::size_t(second_[i]);
    const Vec3 d(x2[b] - x1[a], x2[b + 1] - x1[a + 1], x2[b + 2] - x1[a + 2]);
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (rest_pending_[i]) {
      rest_[i] = length;
      rest_pending_[i] = 0;
    }
    if (!(length > 0) || !(rest_[i] > 0) || !std::isfinite(length)) {
      // SOFA divides by both: a NaN force. The spring is left out while it lasts.
      jacobian_[i].setZero();
      if (!warned_degenerate_) {
        msg_warning("spring " + std::to_string(i) + " (points " + std::to_string(first_[i]) + " and " +
                    std::to_string(second_[i]) + ") has a zero or non-finite length or rest length: it gives no "
                    "force while so (SOFA's would be NaN)");
        warned_degenerate_ = true;
      }
      continue;
    }
    const Vec3 u(d[0] / length, d[1] / length, d[2] / length);
    const double strain = std::fabs(length - rest_[i]) / rest_[i];
    const unsigned poly = poly_.polynomial_of(i, first_.size());
    const double force = poly_.value(poly, strain);
    const double sign = length - rest_[i] >= 0 ? 1.0 : compression;
    for (int c = 0; c < 3; ++c) {
      const double fc = force * sign * u[c];
      f1[a + c] += fc;
      f2[b + c] -= fc;
    }
    // SOFA's ComputeJacobian.
    const double pf = force / length;
    const double pd = poly_.derivative(poly, strain) / rest_[i];
    Mat3& J = jacobian_[i];
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) J(r, c) = (pd - pf) * u[r] * u[c];
      J(r, r) += pf;
    }
  }
}

void PolynomialSpringsForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid || !s1_ || !s2_) return;
  const auto [dx1, df1, dx2, df2] = pair_dforce_vectors(*s1_, *s2_, p);
  for (std::size_t i = 0; i < first_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(first_[i]), b = 3 * std::size_t(second_[i]);
    const double e0 = dx2[b] - dx1[a], e1 = dx2[b + 1] - dx1[a + 1], e2 = dx2[b + 2] - dx1[a + 2];
    const Mat3& J = jacobian_[i];
    for (int r = 0; r < 3; ++r) {
      const double delta = J(r, 0) * e0 + J(r, 1) * e1 + J(r, 2) * e2;
      df1[a + r] += delta * kfactor;
      df2[b + r] -= delta * kfactor;
    }
  }
}

// SOFA's buildStiffnessMatrix: −J on (1,1) and (2,2), +J on (1,2) and (2,1).
bool PolynomialSpringsForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid || !s1_ || !s2_) return true;
  for (std::size_t i = 0; i < first_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(first_[i]), b = 3 * std::size_t(second_[i]);
    const Mat3& J = jacobian_[i];
    K.add_block(s1_, a, s1_, a, -J);
    K.add_block(s1_, a, s2_, b, J);
    K.add_block(s2_, b, s1_, a, J);
    K.add_block(s2_, b, s2_, b, -J);
  }
  return true;
}

void register_polynomial_springs_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "PolynomialSpringsForceField";
  info.category = "ForceField/Spring";
  info.description = "springs between two sets of points whose force is a polynomial of the strain";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::none;
  info.create = creator<PolynomialSpringsForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
