// Numerical kernel of SOFA's linear springs (SpringForceField and the
// force fields built on it, TriangularBendingSprings), for points of
// dimension N = 1, 2 or 3 stored flat. Coordinates have stride CS and
// derivatives stride DS (both N for Vec states; Rigid3d: 7 and 6, the spring
// then acts on the frames' centres and translations only, as SOFA's
// getCPos/getDPos do).
//
// Every operation follows SOFA's order so that results match to round-off:
// u = x2_b − x1_a, d = |u| (sum of squares in index order), û = u·(1/d),
// F = ks·(d − L0) + kd·(û·(v2_b − v1_a)), f1_a += F·û, f2_b −= F·û, and the
// stored tangent K = (ks − F/d)·ûûᵀ + (F/d)·I (the damping force enters the
// geometric term; there is no damping matrix). Spec: mechanics.md §3.1, §3.5.
#pragma once

#include <array>
#include <cmath>

namespace sinew::springs {

struct LinearSpring {
  unsigned m1 = 0, m2 = 0;  // index in state 1, index in state 2
  double ks = 0, kd = 0, l0 = 0;
  bool elongation_only = false;
  bool enabled = true;
};

// Row-major N×N tangent block (only the first N·N entries are used).
using Block = std::array<double, 9>;

// Adds the force of `s`; returns false (K = 0) when the spring is inactive:
// disabled, shorter than `min_length`, or compressed with elongation_only.
// energy += ½·ks·(d − L0)² when active.
template <int N, int CS = N, int DS = N>
inline bool add_spring_force(const LinearSpring& s, const double* x1, const double* v1, double* f1,
                             const double* x2, const double* v2, double* f2, Block& K, double& energy,
                             double min_length = 1.0e-9) {
  const unsigned a = s.m1, b = s.m2;
  double u[N];
  for (int c = 0; c < N; ++c) u[c] = x2[b * CS + c] - x1[a * CS + c];
  double n2 = u[0] * u[0];
  for (int c = 1; c < N; ++c) n2 += u[c] * u[c];
  const double d = std::sqrt(n2);
  if (!(s.enabled && d > min_length && (!s.elongation_only || d > s.l0))) {
    K.fill(0.0);
    return false;
  }
  const double inv = 1.0 / d;
  for (int c = 0; c < N; ++c) u[c] *= inv;
  const double elongation = d - s.l0;
  energy += elongation * elongation * s.ks / 2;
  double ev = u[0] * (v2[b * DS] - v1[a * DS]);
  for (int c = 1; c < N; ++c) ev += u[c] * (v2[b * DS + c] - v1[a * DS + c]);
  const double F = s.ks * elongation + s.kd * ev;
  for (int c = 0; c < N; ++c) {
    const double fc = u[c] * F;
    f1[a * DS + c] += fc;
    f2[b * DS + c] -= fc;
  }
  const double tgt = F * inv;
  for (int j = 0; j < N; ++j) {
    for (int k = 0; k < N; ++k) K[j * N + k] = (s.ks - tgt) * u[j] * u[k];
    K[j * N + j] += tgt;
  }
  return true;
}

// df1_a += kfactor·K·(dx2_b − dx1_a), df2_b −= the same (SOFA: (K·δ)·kFactor).
template <int N, int DS = N>
inline void add_spring_dforce(const LinearSpring& s, const Block& K, const double* dx1, double* df1,
                              const double* dx2, double* df2, double kfactor) {
  const unsigned a = s.m1, b = s.m2;
  double d[N];
  for (int c = 0; c < N; ++c) d[c] = dx2[b * DS + c] - dx1[a * DS + c];
  for (int j = 0; j < N; ++j) {
    double r = K[j * N] * d[0];
    for (int k = 1; k < N; ++k) r += K[j * N + k] * d[k];
    const double v = r * kfactor;
    df1[a * DS + j] += v;
    df2[b * DS + j] -= v;
  }
}

}  // namespace sinew::springs
