// The LCP solver's kernels on hand-solved problems: frictionless LCPs of 1
// and 3 rows, one Coulomb contact sticking and sliding, the two 3×3 contact
// updates agreeing, and non-convergence reported with its error.
#include <gtest/gtest.h>

#include <vector>

#include "constraint/solver/lcp_gauss_seidel.h"

namespace sinew {
namespace {

// W f + q ≥ 0, f ≥ 0, complementary: W = [2], q = −1 → f = 1/2; q = +1 → f = 0.
TEST(LcpGaussSeidel, OneRowFrictionless) {
  std::vector<double> work;
  const double W[1] = {2.0};
  double f[1] = {7.0};  // ignored: gaussSeidelLCP1 starts from zero
  const double q[1] = {-1.0};
  LcpResult r = gauss_seidel_lcp1(1, q, W, f, 1e-12, 100, 0, 0, work);
  EXPECT_TRUE(r.converged);
  EXPECT_DOUBLE_EQ(f[0], 0.5);
  const double q2[1] = {1.0};
  r = gauss_seidel_lcp1(1, q2, W, f, 1e-12, 100, 0, 0, work);
  EXPECT_TRUE(r.converged);
  EXPECT_DOUBLE_EQ(f[0], 0.0);
}

// W = [[2,1,0],[1,2,1],[0,1,2]], q = (−1, 1, −1): active set {0, 2} gives
// f = (1/2, 0, 1/2) and w₁ = 1 + 1/2 + 1/2 = 2 ≥ 0.
TEST(LcpGaussSeidel, ThreeRowsFrictionless) {
  std::vector<double> work;
  const double W[9] = {2, 1, 0, 1, 2, 1, 0, 1, 2};
  const double q[3] = {-1, 1, -1};
  double f[3] = {};
  const LcpResult r = gauss_seidel_lcp1(3, q, W, f, 1e-12, 100, 0, 0, work);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(f[0], 0.5, 1e-12);
  EXPECT_NEAR(f[1], 0.0, 1e-12);
  EXPECT_NEAR(f[2], 0.5, 1e-12);
  // max_f releases a constraint whose force reaches it.
  gauss_seidel_lcp1(3, q, W, f, 1e-12, 100, 0, /*max_f=*/0.4, work);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[2], 0.0);
}

// One contact, W = 2·I, dfree = (−1, 0.3, 0.4): fn = 1/2; the tangential
// update gives (ft, fs) = −2·(0.3, 0.4)/(2+2) = (−0.15, −0.2), inside the cone
// for mu = 1 (|.| = 0.25 ≤ 0.5), scaled to mu·fn = 0.1 for mu = 0.2.
TEST(LcpGaussSeidel, OneFrictionContactSticksOrSlides) {
  const double W[9] = {2, 0, 0, 0, 2, 0, 0, 0, 2};
  const double dfree[3] = {-1, 0.3, 0.4};
  double f[3] = {};
  LcpResult r = nlcp_gauss_seidel(3, dfree, W, f, 1.0, 1e-12, 100, false, 0, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(f[0], 0.5, 1e-14);
  EXPECT_NEAR(f[1], -0.15, 1e-14);
  EXPECT_NEAR(f[2], -0.2, 1e-14);
  r = nlcp_gauss_seidel(3, dfree, W, f, 0.2, 1e-12, 100, false, 0, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(f[0], 0.5, 1e-14);
  EXPECT_NEAR(f[1], -0.06, 1e-14);
  EXPECT_NEAR(f[2], -0.08, 1e-14);
  // Separating: no force.
  const double away[3] = {1, 0.3, 0.4};
  nlcp_gauss_seidel(3, away, W, f, 0.2, 1e-12, 100, false, 0, 0);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_EQ(f[1], 0.0);
  // min_w: a contact with a smaller self-compliance gets no force.
  nlcp_gauss_seidel(3, dfree, W, f, 0.2, 1e-12, 100, false, /*min_w=*/3.0, 0);
  EXPECT_EQ(f[0], 0.0);
}

// Two coupled frictionless contacts (3 rows each, mu tiny): the NLCP gives
// the LCP solution of the normal rows, W_nn = [[2,1],[1,2]], q = (−1, −1) →
// fn = (1/3, 1/3). One iteration is not enough: reported, with its error.
TEST(LcpGaussSeidel, CoupledContactsAndNonConvergence) {
  std::vector<double> W(36, 0.0);
  auto w = [&](int i, int j) -> double& { return W[i * 6 + j]; };
  for (int i = 0; i < 6; ++i) w(i, i) = 2;
  w(0, 3) = w(3, 0) = 1;
  const double dfree[6] = {-1, 0, 0, -1, 0, 0};
  double f[6] = {};
  LcpResult r = nlcp_gauss_seidel(6, dfree, W.data(), f, 1e-18, 1e-12, 1000, false, 0, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(f[0], 1.0 / 3, 1e-10);
  EXPECT_NEAR(f[3], 1.0 / 3, 1e-10);
  double g[6] = {};
  r = nlcp_gauss_seidel(6, dfree, W.data(), g, 1e-18, 1e-12, 1, false, 0, 0);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_GT(r.error, 1e-12 * 3);
  // A warm start at the solution converges in one sweep.
  double h[6] = {1.0 / 3, 0, 0, 1.0 / 3, 0, 0};
  r = nlcp_gauss_seidel(6, dfree, W.data(), h, 1e-18, 1e-9, 1000, true, 0, 0);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
}

// The unbuilt update (d includes the old forces) gives the built update's
// forces, and its d includes the change of force.
TEST(LcpGaussSeidel, UnbuiltContactUpdateMatchesBuilt) {
  ContactBlock33 b;
  const double w[6] = {3, 0.5, -0.2, 2, 0.1, 1.5};
  for (int i = 0; i < 6; ++i) b.w[i] = w[i];
  const double f0[3] = {0.4, 0.1, -0.05};
  const double dfree[3] = {-0.7, 0.2, 0.3};  // violation without this contact's force
  for (double mu : {0.05, 0.8}) {
    double dn = dfree[0], dt = dfree[1], ds = dfree[2];
    double fn = f0[0], ft = f0[1], fs = f0[2];
    contact_gs_state(b, mu, dn, dt, ds, fn, ft, fs);
    // d with the old forces included
    double un = dfree[0] + w[0] * f0[0] + w[1] * f0[1] + w[2] * f0[2];
    double ut = dfree[1] + w[1] * f0[0] + w[3] * f0[1] + w[4] * f0[2];
    double us = dfree[2] + w[2] * f0[0] + w[4] * f0[1] + w[5] * f0[2];
    double gn = f0[0], gt = f0[1], gs = f0[2];
    contact_new_gs_state(b, mu, un, ut, us, gn, gt, gs);
    EXPECT_NEAR(gn, fn, 1e-14) << mu;
    EXPECT_NEAR(gt, ft, 1e-14) << mu;
    EXPECT_NEAR(gs, fs, 1e-14) << mu;
    EXPECT_NEAR(un, dn, 1e-14) << mu;
    EXPECT_NEAR(ut, dt, 1e-14) << mu;
    EXPECT_NEAR(us, ds, 1e-14) << mu;
  }
}

}  // namespace
}  // namespace sinew
