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

// At positions x: add_force = −∇E (central differences of potential_energy(), step 1e-6),
// add_dforce = finite differences of add_force along a seeded direction (both to rel), and
// build_stiffness = add_dforce (to 1e-12), symmetric to `symmetry` (absolute).
inline void expect_consistent_energy_and_tangent(ForceField& ff, MechanicalState& s, const std::vector<double>& x,
                                                 unsigned seed, double rel = 1e-7, double symmetry = 1e-9) {
  const auto f = force_at(ff, s, x);
  const double h = 1e-6;
  std::vector<double> g(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    force_at(ff, s, xp);
    const double ep = *ff.potential_energy();
    force_at(ff, s, xm);
    g[i] = -(ep - *ff.potential_energy()) / (2 * h);
  }
  expect_near_rel(f, g, rel, "force vs -dE/dx");
  force_at(ff, s, x);
  const auto dx = wiggle(x.size(), seed);
  const auto k = dforce(ff, s, dx);
  expect_near_rel(k, fd_force(ff, s, x, dx, 1e-6), rel, "add_dforce vs finite differences");
  const auto K = dense_stiffness(ff, s);
  const std::size_t n = x.size();
  std::vector<double> Kdx(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) {
      Kdx[r] += K[r * n + c] * dx[c];
      EXPECT_NEAR(K[r * n + c], K[c * n + r], symmetry) << r << " " << c;
    }
  expect_near_rel(Kdx, k, 1e-12, "build_stiffness vs add_dforce");
}

}  // namespace sinew::test
