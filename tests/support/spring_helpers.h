// Helpers shared by the spring_ and tri_ tests: evaluate a force field's
// add_force / add_dforce / build_stiffness at given positions, and compare
// them with finite differences.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "core/matrix_sink.h"
#include "core/roles.h"

namespace sinew::test {

// f(x, v) of `ff` alone on state `s` (other vectors untouched).
inline std::vector<double> force_at(ForceField& ff, MechanicalState& s, const std::vector<double>& x,
                                    const std::vector<double>* v = nullptr) {
  s.write(kPosition) = x;
  if (v) s.write(kVelocity) = *v;
  auto& f = s.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  ff.add_force(MechParams{});
  return f;
}

// kfactor·K·dx via add_dforce (after add_force at the current positions).
inline std::vector<double> dforce(ForceField& ff, MechanicalState& s, const std::vector<double>& dx, double k = 1.0) {
  s.write(kDx) = dx;
  auto& df = s.write(kDforce);
  std::fill(df.begin(), df.end(), 0.0);
  MechParams p;
  p.k = k;
  ff.add_dforce(p, k);
  return df;
}

// Dense K = ∂f/∂x of one state from build_stiffness.
inline std::vector<double> dense_stiffness(ForceField& ff, const MechanicalState& s) {
  MatrixSink sink;
  EXPECT_TRUE(ff.build_stiffness(sink));
  const std::size_t n = s.size() * s.info().deriv_width;
  std::vector<double> K(n * n, 0.0);
  for (const auto& e : sink.entries()) {
    EXPECT_EQ(e.row_state, &s);
    EXPECT_EQ(e.col_state, &s);
    K[e.row * n + e.col] += e.value;
  }
  return K;
}

// Central finite difference of add_force along dx: (f(x+h·dx) − f(x−h·dx)) / 2h.
inline std::vector<double> fd_force(ForceField& ff, MechanicalState& s, const std::vector<double>& x,
                                    const std::vector<double>& dx, double h) {
  std::vector<double> xp = x, xm = x;
  for (std::size_t i = 0; i < x.size(); ++i) {
    xp[i] += h * dx[i];
    xm[i] -= h * dx[i];
  }
  const auto fp = force_at(ff, s, xp), fm = force_at(ff, s, xm);
  std::vector<double> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) out[i] = (fp[i] - fm[i]) / (2 * h);
  force_at(ff, s, x);  // restore the tangent at x
  return out;
}

inline double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

inline void expect_near_rel(const std::vector<double>& a, const std::vector<double>& b, double rel,
                            const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  const double scale = std::max({max_abs(a), max_abs(b), 1e-300});
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], rel * scale) << what << " entry " << i;
}

// Deterministic pseudo-random numbers in [-1, 1].
inline std::vector<double> wiggle(std::size_t n, unsigned seed) {
  std::vector<double> v(n);
  unsigned s = seed * 2654435761u + 12345u;
  for (auto& x : v) {
    s = s * 1664525u + 1013904223u;
    x = (static_cast<double>(s >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
  }
  return v;
}

}  // namespace sinew::test
