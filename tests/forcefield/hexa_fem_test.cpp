#include "forcefield/fem/hexa_fem.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "math/decompose.h"

namespace sinew::fem {
namespace {

using Dense = Eigen::MatrixXd;

// Unit-cell corners in the hexahedron node order, scaled by (a, b, c).
std::array<Vec3, 8> box_nodes(double a = 1, double b = 1, double c = 1) {
  return {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a, b, 0), Vec3(0, b, 0),
          Vec3(0, 0, c), Vec3(a, 0, c), Vec3(a, b, c), Vec3(0, b, c)};
}

Dense as_dense(const Mat24& K) { return Dense(K); }

// Regular grid of nx×ny×nz points (RegularGridTopology numbering).
struct Grid {
  std::vector<Vec3> X;
  std::vector<std::array<int, 8>> hexa;
};

Grid make_grid(int nx, int ny, int nz, double h = 1.0) {
  Grid g;
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) g.X.emplace_back(i * h, j * h, k * h);
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        g.hexa.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                          id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return g;
}

void perturb(std::vector<Vec3>& X, double amplitude, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (auto& p : X) p += Vec3(u(rng), u(rng), u(rng));
}

HexaFEM make_fem(const Grid& g, HexaMethod m, double E = 4000, double nu = 0.45) {
  HexaFEM fem;
  std::vector<double> Es(g.hexa.size(), E), nus(g.hexa.size(), nu);
  const auto issues = fem.init(g.X, g.hexa, Es, nus, m);
  EXPECT_TRUE(issues.empty()) << (issues.empty() ? "" : issues[0].message);
  return fem;
}

std::vector<Vec3> forces(HexaFEM& fem, const std::vector<Vec3>& x) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  fem.add_force(x, f);
  return f;
}

Eigen::VectorXd flat(const std::vector<Vec3>& v) {
  Eigen::VectorXd r(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) r.segment<3>(3 * i) = v[i];
  return r;
}

// Dense −kfactor·Σ_e Tᵀ K_e T with T = blockdiag(R_e), computed with plain Eigen.
Dense reference_tangent(const HexaFEM& fem, std::size_t n, double kfactor) {
  Dense A = Dense::Zero(3 * n, 3 * n);
  for (std::size_t e = 0; e < fem.size(); ++e) {
    Dense T = Dense::Zero(24, 24);
    for (int k = 0; k < 8; ++k) T.block<3, 3>(3 * k, 3 * k) = fem.R[e];
    const Dense Kw = T.transpose() * as_dense(fem.K[e]) * T;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        A.block<3, 3>(3 * fem.hexa[e][i], 3 * fem.hexa[e][j]) -= kfactor * Kw.block<3, 3>(3 * i, 3 * j);
  }
  return A;
}

// ---------------------------------------------------------------- stiffness

TEST(HexaStiffness, UnitCubeSymmetricWithSixRigidModes) {
  const double E = 1000, nu = 0.3;
  Mat24 K;
  const auto info = hexa_element_stiffness(box_nodes(), E, nu, K);
  EXPECT_TRUE(info.parallelepiped);
  EXPECT_FALSE(info.singular);
  EXPECT_DOUBLE_EQ(info.min_det, 0.125);  // (1/2)³
  EXPECT_EQ(K, K.transpose());            // mirrored, hence exactly symmetric

  Eigen::SelfAdjointEigenSolver<Dense> eig(as_dense(K));
  const auto& ev = eig.eigenvalues();  // ascending
  const double top = ev.maxCoeff();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev[i]), 1e-10 * top) << i;
  for (int i = 6; i < 24; ++i) EXPECT_GT(ev[i], 1e-3 * top) << i;

  // Closed form (2×2×2 Gauss is exact on a cube): K00 = ∫ U qx² + W qy² + W qz² = (U + 2W)/9.
  const HexaMaterial m = hexa_material(E, nu);
  EXPECT_NEAR(K(0, 0), (m.u + 2 * m.w) / 9, 1e-12 * m.u);
  // And the material itself: λ + 2μ, λ, μ.
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  EXPECT_NEAR(m.u, lambda + 2 * mu, 1e-12 * m.u);
  EXPECT_NEAR(m.v, lambda, 1e-12 * m.u);
  EXPECT_NEAR(m.w, mu, 1e-12 * m.u);
}

TEST(HexaStiffness, DistortedElementAnnihilatesRigidMotions) {
  std::array<Vec3, 8> n = box_nodes(2.0, 1.0, 1.5);
  n[6] += Vec3(0.3, -0.2, 0.25);
  n[5] += Vec3(-0.1, 0.1, 0.05);
  Mat24 K;
  const auto info = hexa_element_stiffness(n, 5000, 0.45, K);
  EXPECT_FALSE(info.parallelepiped);  // general Jacobian at every Gauss point
  EXPECT_GT(info.min_det, 0);
  EXPECT_EQ(K, K.transpose());

  // Translations and infinitesimal rotations u = w × X produce no force.
  const Vec3 axes[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  const double scale = as_dense(K).norm();
  for (const Vec3& a : axes) {
    Eigen::Matrix<double, 24, 1> t, r;
    for (int k = 0; k < 8; ++k) {
      t.segment<3>(3 * k) = a;
      r.segment<3>(3 * k) = a.cross(n[k]);
    }
    EXPECT_LT((K * t).norm(), 1e-12 * scale * t.norm());
    EXPECT_LT((K * r).norm(), 1e-12 * scale * r.norm());
  }
  Eigen::SelfAdjointEigenSolver<Dense> eig(as_dense(K));
  EXPECT_GT(eig.eigenvalues()[6], 1e-3 * eig.eigenvalues().maxCoeff());
}

TEST(HexaStiffness, ConstantStrainEnergyOnFrustum) {
  // Square frustum: base [0,1]², top [0.25,0.75]² at height 1. The trilinear
  // map is exactly this solid; V = (1 + 1/4 + 1/2)/3.
  std::array<Vec3, 8> n = {Vec3(0, 0, 0),       Vec3(1, 0, 0),       Vec3(1, 1, 0),       Vec3(0, 1, 0),
                           Vec3(0.25, 0.25, 1), Vec3(0.75, 0.25, 1), Vec3(0.75, 0.75, 1), Vec3(0.25, 0.75, 1)};
  const double V = (1.0 + 0.25 + 0.5) / 3.0;
  const double E = 3000, nu = 0.3;
  Mat24 K;
  const auto info = hexa_element_stiffness(n, E, nu, K);
  EXPECT_FALSE(info.parallelepiped);

  // Linear field u = G·X with symmetric strain ε = sym(G).
  Mat3 G;
  G << 0.01, 0.02, -0.005, 0.0, -0.03, 0.01, 0.015, 0.0, 0.02;
  Eigen::Matrix<double, 24, 1> u;
  for (int k = 0; k < 8; ++k) u.segment<3>(3 * k) = G * n[k];
  const Mat3 eps = 0.5 * (G + G.transpose());
  Eigen::Matrix<double, 6, 1> ev;  // Voigt xx yy zz xy yz zx, engineering shear
  ev << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(0, 1), 2 * eps(1, 2), 2 * eps(2, 0);
  const HexaMaterial m = hexa_material(E, nu);
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(m.v);
  D.diagonal() << m.u, m.u, m.u, m.w, m.w, m.w;
  const double expected = ev.dot(D * ev) * V;
  EXPECT_NEAR(u.dot(K * u), expected, 1e-12 * expected);
}

TEST(HexaStiffness, ParallelepipedShortcutMatchesGeneralPath) {
  // A sheared parallelepiped takes the shortcut; moving node 6 just past the
  // 0.1% tolerance switches to the general path, which must agree closely.
  std::array<Vec3, 8> n;
  const Vec3 a(1.0, 0.1, 0.0), b(0.2, 0.9, 0.1), c(0.1, -0.2, 1.3), o(5, -3, 2);
  for (int k = 0; k < 8; ++k) n[k] = o + (k == 1 || k == 2 || k == 5 || k == 6 ? a : Vec3::Zero()) +
                                     (k == 2 || k == 3 || k == 6 || k == 7 ? b : Vec3::Zero()) + (k >= 4 ? c : Vec3::Zero());
  Mat24 K1, K2;
  EXPECT_TRUE(hexa_element_stiffness(n, 1000, 0.3, K1).parallelepiped);
  std::array<Vec3, 8> m = n;
  m[6] += Vec3(0, 0, 0.0011 * c.norm());
  EXPECT_FALSE(hexa_element_stiffness(m, 1000, 0.3, K2).parallelepiped);
  EXPECT_LT((as_dense(K1) - as_dense(K2)).norm(), 2e-3 * as_dense(K1).norm());
  EXPECT_GT((as_dense(K1) - as_dense(K2)).norm(), 0.0);
}

TEST(HexaStiffness, CoefficientScalesEveryEntry) {
  Mat24 K1, K2;
  hexa_element_stiffness(box_nodes(), hexa_material(1000, 0.3), 1.0, K1);
  hexa_element_stiffness(box_nodes(), hexa_material(1000, 0.3), 0.5, K2);
  EXPECT_EQ(K2, K1 * 0.5);
}

// ------------------------------------------------------------------- frames

TEST(HexaFrames, RotatedBoxGivesTransposedRotation) {
  const Mat3 Q = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 0.5).normalized()).toRotationMatrix();
  std::array<Vec3, 8> n = box_nodes(2, 1, 3);
  for (auto& p : n) p = Q * p + Vec3(1, 2, 3);
  EXPECT_LT((hexa_frame_large(n) - Q.transpose()).norm(), 1e-14);
  EXPECT_LT((hexa_frame_polar(n) - Q.transpose()).norm(), 1e-14);
}

TEST(HexaFrames, LargeFrameFollowsEdgeX) {
  // Sheared box: x axis stays along the averaged x edges, polar does not.
  std::array<Vec3, 8> n = box_nodes();
  for (int k : {3, 2, 7, 6}) n[k][0] += 0.5;  // y edges lean towards +x
  const Mat3 L = hexa_frame_large(n);
  EXPECT_LT((L - Mat3::Identity()).norm(), 1e-15);
  const Mat3 P = hexa_frame_polar(n);
  EXPECT_GT((P - Mat3::Identity()).norm(), 1e-2);
  EXPECT_NEAR(P.determinant(), 1.0, 1e-14);
}

// ------------------------------------------------------------------- forces

TEST(HexaForce, SmallForcesAreMinusEnergyGradient) {
  std::mt19937 rng(7);
  Grid g = make_grid(3, 3, 2);
  perturb(g.X, 0.15, rng);
  HexaFEM fem = make_fem(g, HexaMethod::small);
  std::vector<Vec3> x = g.X;
  perturb(x, 0.1, rng);

  // Energy ½ Σ ΔᵀKΔ with Δ = X0 − x per element, computed independently.
  auto energy = [&](const std::vector<Vec3>& y) {
    double en = 0;
    for (std::size_t e = 0; e < fem.size(); ++e) {
      Eigen::Matrix<double, 24, 1> d;
      for (int k = 0; k < 8; ++k) d.segment<3>(3 * k) = g.X[g.hexa[e][k]] - y[g.hexa[e][k]];
      en += 0.5 * d.dot(fem.K[e] * d);
    }
    return en;
  };
  const auto f = forces(fem, x);
  EXPECT_NEAR(fem.potential_energy, energy(x), 1e-12 * energy(x));
  EXPECT_GT(energy(x), 0);

  const double h = 1e-6;
  double max_err = 0, max_f = 0;
  for (std::size_t p = 0; p < x.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      std::vector<Vec3> xp = x, xm = x;
      xp[p][c] += h;
      xm[p][c] -= h;
      const double fd = -(energy(xp) - energy(xm)) / (2 * h);
      max_err = std::max(max_err, std::abs(fd - f[p][c]));
      max_f = std::max(max_f, std::abs(f[p][c]));
    }
  EXPECT_GT(max_f, 1.0);
  EXPECT_LT(max_err, 1e-6 * max_f);
}

TEST(HexaForce, RigidMotionGivesZeroForceForLargeAndPolar) {
  std::mt19937 rng(3);
  Grid g = make_grid(3, 2, 4, 0.5);
  perturb(g.X, 0.08, rng);
  const Mat3 Q = Eigen::AngleAxisd(0.9, Vec3(1, 1, -0.4).normalized()).toRotationMatrix();
  std::vector<Vec3> x;
  for (const auto& p : g.X) x.push_back(Q * p + Vec3(-3, 10, 0.5));

  for (HexaMethod m : {HexaMethod::large, HexaMethod::polar}) {
    HexaFEM fem = make_fem(g, m, 4000, 0.45);
    const auto f = forces(fem, x);
    double max_f = 0;
    for (const auto& v : f) max_f = std::max(max_f, v.norm());
    // Scale: a unit displacement of one node would give forces ~ E·h = 2000.
    EXPECT_LT(max_f, 1e-9) << static_cast<int>(m);
    // Δ is a uniform translation in the element frame (|Δ| ~ 10): round-off only.
    EXPECT_LT(std::abs(fem.potential_energy), 1e-8);
    for (std::size_t e = 0; e < fem.size(); ++e) EXPECT_LT((fem.R[e] - fem.R0[e] * Q.transpose()).norm(), 1e-13);
  }
  // The small method is not rotation invariant: the same motion loads it.
  HexaFEM small = make_fem(g, HexaMethod::small);
  const auto fs = forces(small, x);
  double max_small = 0;
  for (const auto& v : fs) max_small = std::max(max_small, v.norm());
  EXPECT_GT(max_small, 1.0);
}

TEST(HexaForce, StiffnessKeptOrUpdated) {
  std::mt19937 rng(11);
  Grid g = make_grid(2, 2, 3);
  HexaFEM fem = make_fem(g, HexaMethod::large);
  std::vector<Vec3> x = g.X;
  perturb(x, 0.2, rng);
  const std::vector<Mat24> K_init = fem.K;
  forces(fem, x);
  for (std::size_t e = 0; e < fem.size(); ++e) EXPECT_EQ(fem.K[e], K_init[e]);

  fem.update_stiffness = true;
  forces(fem, x);
  for (std::size_t e = 0; e < fem.size(); ++e) {
    std::array<Vec3, 8> deformed;
    for (int k = 0; k < 8; ++k) {
      const Vec3& p = x[g.hexa[e][k]];
      const Mat3& R = fem.R[e];
      for (int c = 0; c < 3; ++c) deformed[k][c] = R(c, 0) * p[0] + R(c, 1) * p[1] + R(c, 2) * p[2];
    }
    Mat24 Kd;
    hexa_element_stiffness(deformed, 4000, 0.45, Kd);
    EXPECT_EQ(fem.K[e], Kd);
    EXPECT_NE(fem.K[e], K_init[e]);
  }
}

// ------------------------------------------------------------------ tangent

TEST(HexaDForce, EqualsRotatedStiffnessProductForLargeAndPolar) {
  for (HexaMethod m : {HexaMethod::large, HexaMethod::polar, HexaMethod::small}) {
    std::mt19937 rng(21);
    Grid g = make_grid(3, 2, 3);
    perturb(g.X, 0.15, rng);
    HexaFEM fem = make_fem(g, m);
    std::vector<Vec3> x = g.X, dx(g.X.size());
    for (auto& p : x) p = Eigen::AngleAxisd(0.4, Vec3::UnitY()) * p;
    perturb(x, 0.2, rng);
    for (auto& v : dx) v = Vec3::Random();
    forces(fem, x);  // sets R

    const double kf = 0.37;
    std::vector<Vec3> df(x.size(), Vec3::Ones());  // accumulates into existing values
    fem.add_dforce(dx, df, kf);
    const Dense A = reference_tangent(fem, x.size(), kf);
    const Eigen::VectorXd expected = flat(std::vector<Vec3>(x.size(), Vec3::Ones())) + A * flat(dx);
    EXPECT_LT((flat(df) - expected).norm(), 1e-12 * expected.norm()) << static_cast<int>(m);

    // The block sink assembles the same matrix.
    Dense B = Dense::Zero(3 * x.size(), 3 * x.size());
    fem.add_stiffness_blocks(kf, [&](int r, int c, const Mat3& blk) { B.block<3, 3>(3 * r, 3 * c) += blk; });
    EXPECT_LT((B - A).norm(), 1e-12 * A.norm());
    if (m != HexaMethod::small) {
      // R really enters: with R = I the product differs.
      HexaFEM unrotated = fem;
      for (auto& R : unrotated.R) R.setIdentity();
      EXPECT_GT((reference_tangent(unrotated, x.size(), kf) - A).norm(), 1e-3 * A.norm());
    }
  }
}

TEST(HexaDForce, SmallMatchesFiniteDifferencesOfForce) {
  std::mt19937 rng(5);
  Grid g = make_grid(3, 3, 3);
  perturb(g.X, 0.2, rng);
  HexaFEM fem = make_fem(g, HexaMethod::small);
  std::vector<Vec3> x = g.X, dx(g.X.size());
  perturb(x, 0.1, rng);
  for (auto& v : dx) v = Vec3::Random();

  const double h = 1e-4;
  std::vector<Vec3> xp = x, xm = x;
  for (std::size_t i = 0; i < x.size(); ++i) {
    xp[i] += h * dx[i];
    xm[i] -= h * dx[i];
  }
  const Eigen::VectorXd fd = (flat(forces(fem, xp)) - flat(forces(fem, xm))) / (2 * h);
  std::vector<Vec3> df(x.size(), Vec3::Zero());
  forces(fem, x);
  fem.add_dforce(dx, df, 1.0);  // df = −K dx = ∂f/∂x·dx
  EXPECT_LT((flat(df) - fd).norm(), 1e-5 * fd.norm());
  EXPECT_GT(fd.norm(), 1.0);
}

TEST(HexaDForce, LargeAndPolarMatchFiniteDifferencesAtRigidConfiguration) {
  // Away from rest SOFA's tangent drops dR/dx, but at a rigidly moved
  // configuration that term vanishes, so finite differences must agree.
  std::mt19937 rng(9);
  Grid g = make_grid(3, 2, 3);
  perturb(g.X, 0.1, rng);
  const Mat3 Q = Eigen::AngleAxisd(-0.6, Vec3(0.2, 1, 0.3).normalized()).toRotationMatrix();
  std::vector<Vec3> x, dx(g.X.size());
  for (const auto& p : g.X) x.push_back(Q * p + Vec3(0.3, 0, -1));
  for (auto& v : dx) v = Vec3::Random();
  for (HexaMethod m : {HexaMethod::large, HexaMethod::polar}) {
    HexaFEM fem = make_fem(g, m);
    const double h = 1e-6;
    std::vector<Vec3> xp = x, xm = x;
    for (std::size_t i = 0; i < x.size(); ++i) {
      xp[i] += h * dx[i];
      xm[i] -= h * dx[i];
    }
    const Eigen::VectorXd fd = (flat(forces(fem, xp)) - flat(forces(fem, xm))) / (2 * h);
    std::vector<Vec3> df(x.size(), Vec3::Zero());
    forces(fem, x);
    fem.add_dforce(dx, df, 1.0);
    EXPECT_LT((flat(df) - fd).norm(), 1e-5 * fd.norm()) << static_cast<int>(m);
  }
}

// ------------------------------------------------------- warp node rotations

TEST(HexaNodeRotations, IdentitySeededAverage) {
  Grid g = make_grid(3, 2, 2);
  HexaFEM fem = make_fem(g, HexaMethod::large);
  const Mat3 Q = Eigen::AngleAxisd(0.8, Vec3::UnitZ()).toRotationMatrix();
  std::vector<Vec3> x;
  for (const auto& p : g.X) x.push_back(Q * p);
  forces(fem, x);
  std::vector<Mat3> rot(x.size());
  fem.node_rotations(rot);
  // Grid frames R0 = I, so every element contributes Qᵀ. Corner point 0 has
  // one element: polar(I + Qᵀ) is the half rotation.
  EXPECT_LT((rot[0] - Eigen::AngleAxisd(-0.4, Vec3::UnitZ()).toRotationMatrix()).norm(), 1e-12);
  // Point 1 (middle of an x edge) has two elements: polar((I + 2Qᵀ)/2).
  EXPECT_EQ(fem.node_hexa_count[1], 2);
  const Mat3 expect1 = polar_rotation((Mat3::Identity() + 2 * Q.transpose()) / 2);
  EXPECT_LT((rot[1] - expect1).norm(), 1e-14);
}

// ------------------------------------------------------------------ problems

TEST(HexaInit, FlatHexahedronIsReportedWithItsIndex) {
  Grid g = make_grid(3, 2, 2);  // two elements
  // Flatten element 1 completely: its top face onto its bottom face.
  for (int k = 4; k < 8; ++k) g.X[g.hexa[1][k]] = g.X[g.hexa[1][k - 4]];
  g.hexa[1] = {g.hexa[1][0], g.hexa[1][1], g.hexa[1][2], g.hexa[1][3],
               g.hexa[1][0], g.hexa[1][1], g.hexa[1][2], g.hexa[1][3]};
  for (HexaMethod m : {HexaMethod::small, HexaMethod::large, HexaMethod::polar}) {
    HexaFEM fem;
    std::vector<double> E(2, 1000), nu(2, 0.3);
    const auto issues = fem.init(g.X, g.hexa, E, nu, m);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].element, 1);
    EXPECT_TRUE(issues[0].fatal);
    EXPECT_NE(issues[0].message.find("degenerate"), std::string::npos);
    // Still usable without crashing, and the good element still works.
    std::vector<Vec3> x = g.X;
    x[g.hexa[0][6]] += Vec3(0.1, 0, 0);
    const auto f = forces(fem, x);
    for (const auto& v : f) EXPECT_TRUE(v.allFinite());
    EXPECT_GT(f[g.hexa[0][6]].norm(), 1.0);
  }
}

TEST(HexaInit, OutOfRangeAndSizeProblems) {
  Grid g = make_grid(2, 2, 3);  // two elements, 12 points
  g.hexa[0][5] = 99;
  HexaFEM fem;
  std::vector<double> E(2, 1000), nu(2, 0.3);
  auto issues = fem.init(g.X, g.hexa, E, nu, HexaMethod::large);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].element, 0);
  EXPECT_TRUE(issues[0].fatal);
  EXPECT_NE(issues[0].message.find("99"), std::string::npos);
  EXPECT_EQ(fem.active[0], 0);
  std::vector<Vec3> x = g.X, dx(x.size(), Vec3::Ones());
  x[0] += Vec3(0.1, 0, 0);
  std::vector<Vec3> f(x.size(), Vec3::Zero()), df(x.size(), Vec3::Zero());
  fem.add_force(x, f);  // skips element 0, no out-of-bounds access
  fem.add_dforce(dx, df, 1.0);
  int blocks = 0;
  fem.add_stiffness_blocks(1.0, [&](int, int, const Mat3&) { ++blocks; });
  EXPECT_EQ(blocks, 64);

  std::vector<double> E1(1, 1000);
  issues = fem.init(g.X, g.hexa, E1, nu, HexaMethod::large);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].element, -1);
}

TEST(HexaInit, InvertedHexahedronIsAWarningAndKeepsSignedDet) {
  std::array<Vec3, 8> n = box_nodes();
  std::swap(n[1], n[3]);  // mirror numbering: negative Jacobian
  std::swap(n[5], n[7]);
  Mat24 K;
  const auto info = hexa_element_stiffness(n, 1000, 0.3, K);
  EXPECT_DOUBLE_EQ(info.min_det, -0.125);
  EXPECT_LT(K(0, 0), 0.0);  // signed detJ: the element is "anti-stiff", as in SOFA

  HexaFEM fem;
  std::vector<Vec3> X(n.begin(), n.end());
  std::vector<std::array<int, 8>> hexa = {{0, 1, 2, 3, 4, 5, 6, 7}};
  std::vector<double> E(1, 1000), nu(1, 0.3);
  const auto issues = fem.init(X, hexa, E, nu, HexaMethod::small);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_FALSE(issues[0].fatal);
  EXPECT_EQ(issues[0].element, 0);
}

}  // namespace
}  // namespace sinew::fem
