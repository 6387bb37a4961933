// PolynomialSpringsForceField (Vec3d): springs between point i of
// firstObjectPoints (object1) and point i of secondObjectPoints (object2)
// whose force is a polynomial of the strain (SOFA's component of that name).
//
// Per spring, with d = x2 − x1, L = |d|, u = d/L and rest length L0 (the
// first length seen when computeZeroLength = 1, else zeroLength[i] or
// zeroLength[0]): strain s = |L − L0|/L0, F = P(s) = Σ_k c_k s^k (k = 1..deg,
// the coefficients of spring i taken in order from polynomialStiffness),
// f1 += F·σ·u, f2 −= F·σ·u, σ = 1 when stretched, else −1 with
// compressible = 1 and 0 otherwise (SOFA's flag works this way round).
// Tangent (SOFA's, whatever σ): J = (P'(s)/L0 − P(s)/L)·u uᵀ + P(s)/L·I,
// df1 += J·(dx2 − dx1)·k, df2 −= the same; the assembled blocks are −J, +J.
// When polynomialDegree has not one entry per spring, every spring uses the
// first polynomial (SOFA warns at every step; Sinew once). Empty point lists
// mean every point of the object; more first points than second ones is an
// error (SOFA then keeps no spring). recompute_indices re-reads the lists at
// every step, as SOFA. A spring of zero length or rest length gives no force
// while so (SOFA's would be NaN), with a warning.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"
#include "forcefield/spring/strain_polynomials.h"

namespace sinew {

class PolynomialSpringsForceField : public ForceField {
 public:
  Link<MechanicalState> object1{this, "object1", "first state (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "second state (default: the node's)"};
  Field<std::vector<unsigned>> first_points{this, "firstObjectPoints", {}, "points of object1 (empty: all)", "Spring"};
  Field<std::vector<unsigned>> second_points{this, "secondObjectPoints", {}, "points of object2 (empty: all)", "Spring"};
  Field<std::vector<double>> polynomial_stiffness{
      this, "polynomialStiffness", {}, "coefficients of every spring's polynomial, in order (empty: 100)", "Spring",
      "force"};
  Field<std::vector<unsigned>> polynomial_degree{this, "polynomialDegree", {},
                                                 "degree of each spring's polynomial (empty: 1)", "Spring"};
  Field<int> compute_zero_length{this, "computeZeroLength", 1,
                                 "1: rest lengths are the first lengths seen; else zeroLength", "Spring"};
  Field<std::vector<double>> zero_length{this, "zeroLength", {}, "rest lengths (one, or one per spring)", "Spring",
                                         "length"};
  Field<bool> recompute_indices{this, "recompute_indices", false, "re-read the point lists at every step", "Spring"};
  Field<bool> compressible{this, "compressible", false,
                           "compressed springs push back (SOFA's flag: without it they give no force)", "Spring"};
  Field<int> draw_mode{this, "drawMode", 0, "0: lines, 1: cylinders, 2: arrows (viewer)", "Visualization"};
  Field<double> show_arrow_size{this, "showArrowSize", static_cast<double>(0.01f), "arrow or cylinder size (viewer)",
                                "Visualization"};
  Field<std::string> spring_color{this, "springColor", "0 1 0 1", "spring colour (viewer)", "Visualization"};
  Field<double> show_indices_scale{this, "showIndicesScale", static_cast<double>(0.02f),
                                   "scale of the point markers (viewer)", "Visualization"};

  void init() override;
  void bwd_init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;
  bool is_interaction() const override { return true; }
  std::vector<MechanicalState*> states() const override;
  MechanicalState* single_state() const override { return s1_ && s1_ == s2_ ? s1_ : nullptr; }

  // Per spring, after add_force: rest length, current length, tangent J.
  const std::vector<double>& rest_lengths() const { return rest_; }
  const std::vector<Mat3>& tangents() const { return jacobian_; }

 private:
  bool read_indices();                     // SOFA's recomputeIndices; false when the lists are unusable

  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  std::vector<unsigned> first_, second_;
  StrainPolynomials poly_;
  std::vector<double> rest_;
  std::vector<char> rest_pending_;           // rest length still to take from the first length seen
  std::vector<Mat3> jacobian_;
  bool warned_degenerate_ = false;
};

}  // namespace sinew
