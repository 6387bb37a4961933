// PolynomialRestShapeSpringsForceField (Vec3d): springs from points of the
// state to their rest positions (or to points of external_rest_shape) whose
// force is a polynomial of the strain (SOFA's component of that name).
//
// Per spring, with d = x[p] − x0[q], s = |d| / L0 (L0: initialLength[i], or
// initialLength[0]; default 1), F = P(s) = Σ_k c_k s^k, and a smoothed length
// D = √(d·d + exp(shift − scale·d·d)) (smoothShift, smoothScale: keeps the
// direction finite at d = 0): f[p] −= F·d/D. SOFA's tangent is diagonal:
// j_c = (P'(s)/L0 − F/D)·(1 − scale·exp(shift − scale·d·d))·(d_c/D)² + F/D,
// df[p]_c −= j_c·dx[p]_c·k, assembled −j_c on the diagonal (it is the exact
// diagonal of ∂f/∂x when the smoothing is negligible; off-diagonal terms are
// left out, as SOFA does). Polynomials, defaults and the "first polynomial
// for all" rule as PolynomialSpringsForceField.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/strain_polynomials.h"

namespace sinew {

class PolynomialRestShapeSpringsForceField : public ForceField {
 public:
  Field<std::vector<unsigned>> points{this, "points", {}, "points held by the springs (empty: all)", "Spring"};
  Field<std::vector<unsigned>> external_points{this, "external_points", {},
                                               "points of external_rest_shape, one per spring (empty: all)", "Spring"};
  Field<std::vector<double>> polynomial_stiffness{
      this, "polynomialStiffness", {}, "coefficients of every spring's polynomial, in order (empty: 100)", "Spring",
      "force"};
  Field<std::vector<unsigned>> polynomial_degree{this, "polynomialDegree", {},
                                                 "degree of each spring's polynomial (empty: 1)", "Spring"};
  Field<bool> recompute_indices{this, "recompute_indices", false, "re-read the point lists at every step", "Spring"};
  Field<bool> draw_spring{this, "drawSpring", false, "draw the springs (viewer)", "Visualization"};
  Field<std::string> spring_color{this, "springColor", "0 1 0 1", "spring colour (viewer)", "Visualization"};
  Field<double> show_indices_scale{this, "showIndicesScale", 1.0, "size of the index labels (viewer)",
                                   "Visualization"};
  Field<std::vector<double>> initial_length{this, "initialLength", {},
                                            "length dividing the distance into a strain (one, or one per spring; "
                                            "empty: 1)", "Spring", "length"};
  Field<double> smooth_shift{this, "smoothShift", 0.0, "shift of the exponential added to d·d in the direction's "
                                                       "length", "Spring"};
  Field<double> smooth_scale{this, "smoothScale", 1.0, "scale of d·d in that exponential", "Spring"};
  Link<MechanicalState> external_rest_shape{this, "external_rest_shape",
                                            "state whose positions are the rest shape (default: own rest positions)"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  // Per spring, after add_force: SOFA's diagonal tangent.
  const std::vector<Vec3>& tangents() const { return jacobian_; }

 private:
  bool read_indices();
  const std::vector<double>* rest_positions() const;

  std::vector<unsigned> index_, ext_index_;
  StrainPolynomials poly_;
  std::vector<Vec3> jacobian_;
};

}  // namespace sinew
