// ImprovedJacobiConstraintSolver (SOFA's, after Francu & Moldoveanu, "An
// Improved Jacobi Solver for Particle Simulation", VRPHYS 2014): projected
// Jacobi on the assembled W. Every block is projected from the same violation
// d (updated once per iteration by W·Δf), optionally scaled by a spectral
// factor ρ and extrapolated along the last change of forces (conjugate residue).
#pragma once

#include <vector>

#include "constraint/solver/built_constraint_solver.h"

namespace sinew {

class ImprovedJacobiConstraintSolver : public BuiltConstraintSolver {
 public:
  Field<bool> use_spectral_correction{
      this, "useSpectralCorrection", false,
      "scale each iteration's violation by spectralCorrectionFactor·min(1, 1.8/ρ(W)) (ρ: spectral radius, see the "
      "source for SOFA's definition)",
      "Solver"};
  Field<double> spectral_correction_factor{this, "spectralCorrectionFactor", 1.0,
                                           "factor on the spectral correction", "Solver"};
  Field<bool> use_conjugate_residue{this, "useConjugateResidue", false,
                                    "extrapolate the forces by β·(λ_i − λ_{i−1}), β = min(1, (i/maxIterations)^s)",
                                    "Solver"};
  Field<double> conjugate_residue_speed_factor{this, "conjugateResidueSpeedFactor", 10.0,
                                               "exponent s of β (larger: β reaches 1 later)", "Solver"};

 protected:
  void solve_system() override;
  std::string divergence_hint() const override;

 private:
  std::vector<double> last_f_, delta_f_, corrected_d_;
};

}  // namespace sinew
