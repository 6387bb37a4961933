// The penalty of one point against an axis-aligned ellipsoid, in the
// ellipsoid's frame: SOFA's formula shared by EllipsoidForceField and
// InteractionEllipsoidForceField (spec/mechanics.md §3.12).
//
// With q = Σ dp_j²/r_j² (the normalised squared distance), v = √q − 1 and
// g = dp_j/r_j² (the gradient direction of q/2), a point is in contact when
// (q − 1)·k < 0 (inside for k > 0, outside for k < 0), and
//     f = −|k|·v·g/|g| − c_d·|v|·vel.
// The tangent m is SOFA's: exact but for the derivative of 1/|g|, where SOFA
// has −|k|·v/|g|² (not +|k|·v/|g|³) times g_i·g_j/r_j² — kept, since it is what
// SOFA's implicit solves use (the error is proportional to the penetration).
#pragma once

#include <cmath>

namespace sinew {

struct EllipsoidPenalty {
  double force[3] = {0, 0, 0};
  double m[3][3] = {};  // ∂f/∂x as SOFA computes it
};

// dp: point − centre; inv_r2: 1/r_j²; dim: 1 to 3 components used; vel: the
// point's velocity. False (out untouched) when the point is not in contact.
inline bool ellipsoid_penalty(const double* dp, const double* inv_r2, unsigned dim, double k, double kd,
                              const double* vel, EllipsoidPenalty& out) {
  double q = 0;
  for (unsigned j = 0; j < dim; ++j) q += (dp[j] * dp[j]) * inv_r2[j];
  if (!((q - 1) * k < 0)) return false;
  const double kabs = std::fabs(k);
  const double norm = std::sqrt(q);
  const double v = norm - 1;
  double g[3] = {0, 0, 0};
  for (unsigned j = 0; j < dim; ++j) g[j] = dp[j] * inv_r2[j];
  const double gn2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  const double gn = std::sqrt(gn2);
  const double fi = -kabs * v / gn;
  const double di = kd * std::fabs(v);
  for (unsigned j = 0; j < dim; ++j) out.force[j] = g[j] * fi - vel[j] * di;
  const double fact1 = -kabs / (norm * gn);
  const double fact2 = -kabs * v / gn;
  const double fact3 = -kabs * v / gn2;
  for (unsigned ci = 0; ci < dim; ++ci) {
    for (unsigned cj = 0; cj < dim; ++cj) out.m[ci][cj] = g[ci] * g[cj] * (fact1 + fact3 * inv_r2[cj]);
    out.m[ci][ci] += fact2 * inv_r2[ci];
  }
  return true;
}

}  // namespace sinew
