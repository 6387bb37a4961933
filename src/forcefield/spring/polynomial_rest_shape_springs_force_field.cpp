#include "forcefield/spring/polynomial_rest_shape_springs_force_field.h"

#include <cmath>
#include <string>

#include "core/registry.h"

namespace sinew {

void PolynomialRestShapeSpringsForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error(std::string("needs a Vec3d state (got ") + mstate->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (external_rest_shape && external_rest_shape->state_type() != StateType::vec3) {
    msg_error("external_rest_shape " + external_rest_shape->describe() + " is not a Vec3d state");
    set_state(ComponentState::invalid);
  }
}

const std::vector<double>* PolynomialRestShapeSpringsForceField::rest_positions() const {
  if (external_rest_shape) return &external_rest_shape->read(kPosition);
  return &mstate->read(kRestPosition);
}

// SOFA's recomputeIndices. The external index is used only with external_rest_shape
// (otherwise a spring holds its point to that point's own rest position).
bool PolynomialRestShapeSpringsForceField::read_indices() {
  index_ = points.value();
  ext_index_ = external_points.value();
  const std::size_t n = mstate->size();
  const std::size_t n_ext = rest_positions()->size() / 3;
  if (index_.empty())
    for (unsigned i = 0; i < n; ++i) index_.push_back(i);
  if (ext_index_.empty())
    for (unsigned i = 0; i < n_ext; ++i) ext_index_.push_back(i);
  if (index_.size() > ext_index_.size()) {
    msg_error("points has " + std::to_string(index_.size()) + " entries but the rest shape only " +
              std::to_string(ext_index_.size()) + " (external_points or the external state's points)");
    return false;
  }
  for (unsigned i : index_)
    if (i >= n) {
      msg_error("points: point " + std::to_string(i) + " is beyond the state's " + std::to_string(n) + " points");
      return false;
    }
  for (std::size_t k = 0; k < index_.size(); ++k) {
    const unsigned q = external_rest_shape ? ext_index_[k] : index_[k];
    if (q >= n_ext) {
      msg_error("the rest shape has no point " + std::to_string(q) + " (it has " + std::to_string(n_ext) + ")");
      return false;
    }
  }
  return true;
}

void PolynomialRestShapeSpringsForceField::bwd_init() {
  if (state() != ComponentState::valid) return;
  if (polynomial_stiffness.value().empty()) polynomial_stiffness.set({100.0});
  if (initial_length.value().empty()) initial_length.set({1.0});
  if (polynomial_degree.value().empty()) polynomial_degree.set({1u});
  for (double l : initial_length.value())
    if (!(l > 0) || !std::isfinite(l)) {
      msg_error("initialLength " + std::to_string(l) + ": lengths must be positive (the strain divides by them)");
      set_state(ComponentState::invalid);
      return;
    }
  if (!read_indices()) {
    set_state(ComponentState::invalid);
    return;
  }
  const std::string bad = poly_.build(polynomial_degree.value(), polynomial_stiffness.value());
  if (!bad.empty()) {
    msg_error(bad);
    set_state(ComponentState::invalid);
    return;
  }
  jacobian_.assign(index_.size(), Vec3::Zero());
}

void PolynomialRestShapeSpringsForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  if (recompute_indices.value() && (!read_indices() || index_.size() != jacobian_.size())) {
    if (index_.size() != jacobian_.size())
      msg_error("recompute_indices: the number of springs changed (" + std::to_string(jacobian_.size()) + " → " +
                std::to_string(index_.size()) + "), which SOFA does not follow either");
    set_state(ComponentState::invalid);
    return;
  }
  if (const std::string w = poly_.first_for_all_warning(index_.size()); !w.empty()) msg_warning(w);
  const double* x = mstate->read(p.x).data();
  const double* x0 = rest_positions()->data();
  double* f = mstate->write(p.f).data();
  const auto& l0 = initial_length.value();
  const double shift = smooth_shift.value(), scale = smooth_scale.value();
  for (std::size_t i = 0; i < index_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(index_[i]);
    const std::size_t b = 3 * std::size_t(external_rest_shape ? ext_index_[i] : index_[i]);
    const double d[3] = {x[a] - x0[b], x[a + 1] - x0[b + 1], x[a + 2] - x0[b + 2]};
    double sq = d[0] * d[0];
    sq += d[1] * d[1];
    sq += d[2] * d[2];
    const double rest = i < l0.size() ? l0[i] : l0[0];
    const double strain = std::sqrt(sq) / rest;
    const unsigned poly = poly_.polynomial_of(i, index_.size());
    const double force = poly_.value(poly, strain);
    const double smooth = std::exp(shift - scale * sq);
    const double len = std::sqrt(sq + smooth);
    const double u[3] = {d[0] / len, d[1] / len, d[2] / len};
    for (int c = 0; c < 3; ++c) f[a + c] -= force * u[c];
    // SOFA's ComputeJacobian (diagonal).
    const double pf = force / len;
    const double pd = poly_.derivative(poly, strain) / rest;
    const double ed = 1.0 - scale * smooth;
    for (int c = 0; c < 3; ++c) jacobian_[i][c] = (pd - pf) * ed * u[c] * u[c] + pf;
  }
}

void PolynomialRestShapeSpringsForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  const double* dx = mstate->read(p.dx).data();
  double* df = mstate->write(p.df).data();
  for (std::size_t i = 0; i < index_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(index_[i]);
    for (int c = 0; c < 3; ++c) df[a + c] -= jacobian_[i][c] * dx[a + c] * kfactor;
  }
}

bool PolynomialRestShapeSpringsForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  for (std::size_t i = 0; i < index_.size(); ++i) {
    const std::size_t a = 3 * std::size_t(index_[i]);
    for (int c = 0; c < 3; ++c) K.add(s, a + c, s, a + c, -jacobian_[i][c]);
  }
  return true;
}

void register_polynomial_rest_shape_springs_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "PolynomialRestShapeSpringsForceField";
  info.category = "ForceField/Spring";
  info.description = "springs to the rest shape whose force is a polynomial of the strain";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<PolynomialRestShapeSpringsForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
