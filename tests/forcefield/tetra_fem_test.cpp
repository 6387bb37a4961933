// Kernel of TetrahedronFEMForceField / TetrahedralCorotationalFEMForceField
// (spec/mechanics.md §2.0–§2.2): element stiffness against an independent
// B·D·B construction, derivatives, rigid-motion invariance, plasticity rule,
// hexahedron split.
#include "forcefield/fem/tetra_fem.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "math/decompose.h"

namespace sinew::fem {
namespace {

using Dense = Eigen::MatrixXd;

// A small mesh: two tetrahedra sharing a face, slightly irregular.
struct Mesh {
  std::vector<Vec3> X;
  std::vector<std::array<int, 4>> t;
};

Mesh two_tets() {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1.1, 0.05, 0), Vec3(0.1, 0.9, 0.05), Vec3(0.05, 0.1, 1.2), Vec3(0.9, 0.8, 0.9)};
  m.t = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  return m;
}

TetraFEM make(const Mesh& m, TetraMethod method, double E = 1000, double nu = 0.3) {
  TetraFEM fem;
  std::vector<double> Es(m.t.size(), E), nus(m.t.size(), nu);
  const auto issues = fem.init(m.X, m.t, Es, nus, method);
  EXPECT_TRUE(issues.empty()) << (issues.empty() ? "" : issues[0].message);
  return fem;
}

std::vector<Vec3> forces(TetraFEM& fem, const std::vector<Vec3>& x) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  fem.add_force(x, f);
  return f;
}

// Independent element stiffness V·Bᵀ·D·B from the shape-function gradients
// (inverse of the [1 x y z] matrix), Voigt order xx yy zz xy yz zx.
Dense reference_stiffness(const std::array<Vec3, 4>& p, double E, double nu) {
  Eigen::Matrix4d A;
  for (int k = 0; k < 4; ++k) A.row(k) << 1, p[k][0], p[k][1], p[k][2];
  const Eigen::Matrix4d C = A.inverse();  // column k: coefficients of N_k
  const double V = std::fabs(A.determinant()) / 6.0;
  Dense B = Dense::Zero(6, 12);
  for (int k = 0; k < 4; ++k) {
    const double gx = C(1, k), gy = C(2, k), gz = C(3, k);
    B(0, 3 * k) = gx;
    B(1, 3 * k + 1) = gy;
    B(2, 3 * k + 2) = gz;
    B(3, 3 * k) = gy;
    B(3, 3 * k + 1) = gx;
    B(4, 3 * k + 1) = gz;
    B(4, 3 * k + 2) = gy;
    B(5, 3 * k) = gz;
    B(5, 3 * k + 2) = gx;
  }
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  Dense D = Dense::Zero(6, 6);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) D(i, j) = lambda + (i == j ? 2 * mu : 0);
  D(3, 3) = D(4, 4) = D(5, 5) = mu;
  return V * B.transpose() * D * B;
}

Mat3 rotation(double ax, double ay, double az) {
  return (Eigen::AngleAxisd(az, Vec3::UnitZ()) * Eigen::AngleAxisd(ay, Vec3::UnitY()) *
          Eigen::AngleAxisd(ax, Vec3::UnitX()))
      .toRotationMatrix();
}

TEST(TetraFEMKernel, MaterialEntriesAreLameParametersOver36V) {
  const double E = 1000, nu = 0.4, V = 0.5;
  const TetraMaterial K = tetra_material(E, nu, V);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  EXPECT_NEAR(K.d * 36 * V, lambda + 2 * mu, 1e-9);
  EXPECT_NEAR(K.o * 36 * V, lambda, 1e-9);
  EXPECT_NEAR(K.s * 36 * V, mu, 1e-9);
}

TEST(TetraFEMKernel, ElementStiffnessMatchesBDBConstruction) {
  const Mesh m = two_tets();
  for (int e = 0; e < 2; ++e) {
    std::array<Vec3, 4> p;
    for (int k = 0; k < 4; ++k) p[k] = m.X[m.t[e][k]];
    TetraJ J;
    tetra_strain_displacement(p[0], p[1], p[2], p[3], J);
    const double V = tetra_volume(p[0], p[1], p[2], p[3]);
    Mat12 jkjt;
    tetra_jkjt(J, tetra_material(1000, 0.3, V), jkjt);
    const Dense ref = reference_stiffness(p, 1000, 0.3);
    EXPECT_LT((Dense(jkjt) - ref).cwiseAbs().maxCoeff(), 1e-9 * ref.cwiseAbs().maxCoeff()) << "element " << e;
  }
}

TEST(TetraFEMKernel, SignedVolumeOfUnitTetrahedron) {
  EXPECT_DOUBLE_EQ(tetra_signed_volume(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), 1.0 / 6);
  EXPECT_DOUBLE_EQ(tetra_signed_volume(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)), -1.0 / 6);
}

TEST(TetraFEMKernel, SmallForceIsMinusGradientOfEnergy) {
  const Mesh m = two_tets();
  TetraFEM fem = make(m, TetraMethod::small);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> x = m.X;
  for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng));
  // Energy ½ Σ_e (x−X0)ᵀ K_e (x−X0) with K_e from the independent construction.
  auto energy = [&](const std::vector<Vec3>& y) {
    double E = 0;
    for (int e = 0; e < 2; ++e) {
      std::array<Vec3, 4> p;
      Eigen::Matrix<double, 12, 1> d;
      for (int k = 0; k < 4; ++k) {
        p[k] = m.X[m.t[e][k]];
        d.segment<3>(3 * k) = y[m.t[e][k]] - m.X[m.t[e][k]];
      }
      E += 0.5 * d.dot(reference_stiffness(p, 1000, 0.3) * d);
    }
    return E;
  };
  const auto f = forces(fem, x);
  const double h = 1e-6;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      auto xp = x, xm = x;
      xp[i][c] += h;
      xm[i][c] -= h;
      const double g = (energy(xp) - energy(xm)) / (2 * h);
      EXPECT_NEAR(f[i][c], -g, 1e-6 * (1 + std::fabs(g))) << "node " << i << " comp " << c;
    }
}

TEST(TetraFEMKernel, SmallDForceIsDerivativeOfForce) {
  const Mesh m = two_tets();
  TetraFEM fem = make(m, TetraMethod::small);
  std::vector<Vec3> x = m.X, dx(m.X.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& p : x) p += 0.02 * Vec3(u(rng), u(rng), u(rng));
  for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
  const double h = 1e-6, kf = 0.7;
  auto xp = x;
  for (std::size_t i = 0; i < x.size(); ++i) xp[i] += h * dx[i];
  const auto f0 = forces(fem, x), f1 = forces(fem, xp);
  std::vector<Vec3> df(x.size(), Vec3::Zero());
  fem.add_dforce(dx, df, kf);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double fd = kf * (f1[i][c] - f0[i][c]) / h;
      // df += kf·(∂f/∂x)·dx: exact for the linear method.
      EXPECT_NEAR(df[i][c], fd, 1e-4 * (1 + std::fabs(fd))) << i << "," << c;
    }
}

class TetraFEMCorotational : public ::testing::TestWithParam<TetraMethod> {};

TEST_P(TetraFEMCorotational, RigidMotionGivesNoForce) {
  const Mesh m = two_tets();
  TetraFEM fem = make(m, GetParam());
  const Mat3 R = rotation(0.7, -0.4, 1.9);
  std::vector<Vec3> x;
  for (const auto& p : m.X) x.push_back(R * p + Vec3(3, -2, 5));
  const auto f = forces(fem, x);
  for (const auto& v : f) EXPECT_LT(v.norm(), 1e-9);
}

TEST_P(TetraFEMCorotational, RotatedDeformationGivesRotatedForces) {
  const Mesh m = two_tets();
  TetraFEM a = make(m, GetParam()), b = make(m, GetParam());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  std::vector<Vec3> x = m.X;
  for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng));
  const Mat3 R = rotation(0.3, 1.1, -0.6);
  std::vector<Vec3> xr;
  for (const auto& p : x) xr.push_back(R * p);
  const auto f = forces(a, x), fr = forces(b, xr);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_LT((R * f[i] - fr[i]).norm(), 1e-9 * (1 + f[i].norm()));
}

TEST_P(TetraFEMCorotational, DForceNearRestMatchesFiniteDifferences) {
  // At rest the force vanishes, so the ignored ∂R/∂x term does not contribute:
  // SOFA's tangent equals the true derivative there.
  const Mesh m = two_tets();
  TetraFEM fem = make(m, GetParam());
  const Mat3 R = rotation(0.2, 0.5, -0.3);
  std::vector<Vec3> x;
  for (const auto& p : m.X) x.push_back(R * p);
  forces(fem, x);  // sets the rotations
  std::vector<Vec3> dx(x.size());
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
  std::vector<Vec3> df(x.size(), Vec3::Zero());
  fem.add_dforce(dx, df, 1.0);
  const double h = 1e-6;
  auto xp = x, xm = x;
  for (std::size_t i = 0; i < x.size(); ++i) {
    xp[i] += h * dx[i];
    xm[i] -= h * dx[i];
  }
  TetraFEM f2 = make(m, GetParam()), f3 = make(m, GetParam());
  const auto fp = forces(f2, xp), fm = forces(f3, xm);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double fd = (fp[i][c] - fm[i][c]) / (2 * h);
      EXPECT_NEAR(df[i][c], fd, 1e-5 * (1 + std::fabs(fd))) << i << "," << c;
    }
}

TEST_P(TetraFEMCorotational, StiffnessBlocksReproduceDForce) {
  const Mesh m = two_tets();
  TetraFEM fem = make(m, GetParam());
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> x = m.X;
  for (auto& p : x) p += 0.1 * Vec3(u(rng), u(rng), u(rng));
  forces(fem, x);
  const std::size_t n = x.size();
  Dense K = Dense::Zero(3 * n, 3 * n);
  fem.add_stiffness_blocks([&](int i, int j, const Mat3& b) { K.block<3, 3>(3 * i, 3 * j) += b; });
  Eigen::VectorXd dx(3 * n);
  for (int i = 0; i < dx.size(); ++i) dx[i] = u(rng);
  std::vector<Vec3> dxv(n), df(n, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) dxv[i] = dx.segment<3>(3 * i);
  const double kf = 1.3;
  fem.add_dforce(dxv, df, kf);
  const Eigen::VectorXd ref = kf * K * dx;
  for (std::size_t i = 0; i < n; ++i) EXPECT_LT((df[i] - ref.segment<3>(3 * i)).norm(), 1e-9 * (1 + ref.norm()));
  // symmetric
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(Methods, TetraFEMCorotational,
                         ::testing::Values(TetraMethod::large, TetraMethod::polar, TetraMethod::svd));

TEST(TetraFEMKernel, SvdEqualsPolarForWellShapedElements) {
  const Mesh m = two_tets();
  TetraFEM p = make(m, TetraMethod::polar), s = make(m, TetraMethod::svd);
  std::vector<Vec3> x = m.X;
  x[4] += Vec3(0.05, -0.02, 0.03);
  const auto fp = forces(p, x), fs = forces(s, x);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(fp[i], fs[i]);
}

TEST(TetraFEMKernel, SvdHandlesAnInvertedElement) {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.t = {{0, 1, 2, 3}};
  TetraFEM fem = make(m, TetraMethod::svd);
  std::vector<Vec3> x = m.X;
  x[3] = Vec3(0.1, 0.1, -0.5);  // through the opposite face
  const auto f = forces(fem, x);
  Vec3 sum = Vec3::Zero();
  for (const auto& v : f) {
    EXPECT_TRUE(v.allFinite());
    sum += v;
  }
  EXPECT_LT(sum.norm(), 1e-9 * (1 + f[3].norm()));
  EXPECT_GT(f[3].norm(), 1.0);  // a real (not garbage-free zero) response
  // SOFA's stable polar factor of an inverted F keeps U = F·V·S⁻¹ (det < 0):
  // the rotation used is then a reflection and the element relaxes towards
  // the mirrored rest shape. Check that the rotation is orthogonal.
  const Mat3& r = fem.rot[0];
  EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-9);
}

TEST(TetraFEMKernel, PlasticityFollowsSofaCreepRule) {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.t = {{0, 1, 2, 3}};
  TetraFEM elastic = make(m, TetraMethod::small), plastic = make(m, TetraMethod::small);
  plastic.plasticity = {0.5, 0.001, 0.25};  // max, yield, creep
  std::vector<Vec3> x = m.X;
  x[1][0] += 0.01;  // stretch
  const auto fe = forces(elastic, x);
  const auto fp = forces(plastic, x);
  // First call: the whole strain exceeds the yield, εp = creep·ε, stress from (1−creep)·ε.
  for (int i = 0; i < 4; ++i) EXPECT_LT((fp[i] - 0.75 * fe[i]).norm(), 1e-12 * (1 + fe[i].norm()));
  // Second call: elastic strain is 0.75·ε, εp = 0.25ε + 0.25·0.75ε.
  const auto fp2 = forces(plastic, x);
  const double remaining = 1 - (0.25 + 0.25 * 0.75);
  for (int i = 0; i < 4; ++i) EXPECT_LT((fp2[i] - remaining * fe[i]).norm(), 1e-12 * (1 + fe[i].norm()));
  // Reset clears the plastic strain.
  plastic.reset_plasticity();
  const auto fp3 = forces(plastic, x);
  for (int i = 0; i < 4; ++i) EXPECT_LT((fp3[i] - 0.75 * fe[i]).norm(), 1e-12 * (1 + fe[i].norm()));
}

TEST(TetraFEMKernel, PlasticStrainIsCappedAtMax) {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.t = {{0, 1, 2, 3}};
  TetraFEM fem = make(m, TetraMethod::small);
  fem.plasticity = {1e-3, 1e-6, 1.0};
  std::vector<Vec3> x = m.X;
  x[1][0] += 0.1;
  forces(fem, x);
  const auto& p = fem.plastic[0];
  double n2 = 0;
  for (double v : p) n2 += v * v;
  EXPECT_NEAR(std::sqrt(n2), 1e-3, 1e-12);
}

TEST(TetraFEMKernel, DegenerateElementIsReportedWithItsIndex) {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 1)};
  m.t = {{0, 1, 2, 4}, {0, 1, 2, 3}, {0, 1, 2, 9}};
  TetraFEM fem;
  std::vector<double> E(3, 1000), nu(3, 0.3);
  const auto issues = fem.init(m.X, m.t, E, nu, TetraMethod::large);
  ASSERT_EQ(issues.size(), 2u);
  EXPECT_EQ(issues[0].element, 1);
  EXPECT_NE(issues[0].message.find("degenerate"), std::string::npos);
  EXPECT_EQ(issues[1].element, 2);
  EXPECT_NE(issues[1].message.find("out of range"), std::string::npos);
}

TEST(TetraFEMKernel, HexahedronSplitCoversTheCubeWithSixTetrahedra) {
  // One unit cube (grid node order) in a 2×2×2 cell grid, cell index i = 3 (odd x, odd y).
  std::vector<Vec3> X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                         Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  for (std::size_t cell = 0; cell < 8; ++cell) {
    std::vector<std::array<unsigned, 8>> hexa(cell + 1, {0, 1, 2, 3, 4, 5, 6, 7});
    const auto tets = split_hexahedra(hexa, 2, 2);
    ASSERT_EQ(tets.size(), 6 * (cell + 1));
    double v = 0;
    for (std::size_t k = 6 * cell; k < tets.size(); ++k)
      v += tetra_volume(X[tets[k][0]], X[tets[k][1]], X[tets[k][2]], X[tets[k][3]]);
    EXPECT_NEAR(v, 1.0, 1e-12) << "cell " << cell;
  }
}

TEST(TetraFEMKernel, AssembledLargeForceEqualsMatrixFreeForce) {
  const Mesh m = two_tets();
  TetraFEM a = make(m, TetraMethod::large), b = make(m, TetraMethod::large);
  b.assembling = true;
  std::vector<Vec3> x = m.X;
  x[4] += Vec3(0.05, -0.02, 0.03);
  x[0] += Vec3(-0.01, 0.02, 0.0);
  const auto fa = forces(a, x), fb = forces(b, x);
  // Same up to the three tiny J entries zeroed by computeGlobalMatrix.
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_LT((fa[i] - fb[i]).norm(), 1e-9 * (1 + fa[i].norm()));
}

}  // namespace
}  // namespace sinew::fem

namespace sinew::fem {
namespace {

TEST(TetraFEMKernel, NodeRotationsFollowARigidRotation) {
  const Mesh m = two_tets();
  TetraFEM fem = make(m, TetraMethod::large);
  const Mat3 R = rotation(0.4, -0.2, 0.9);
  std::vector<Vec3> x;
  for (const auto& p : m.X) x.push_back(R * p);
  forces(fem, x);
  std::vector<Mat3> r(m.X.size() + 1);
  fem.node_rotations(r);
  for (std::size_t i = 0; i < m.X.size(); ++i) EXPECT_LT((r[i] - R).norm(), 1e-9) << i;
  EXPECT_LT((r.back() - R).norm(), 1e-9);  // a point without element: element 0's rotation (SOFA)
  fem.node_rotations(r, false);          // last-element rule (hexahedra split internally)
  for (std::size_t i = 0; i < m.X.size(); ++i) EXPECT_LT((r[i] - R).norm(), 1e-9) << i;
  TetraFEM small = make(m, TetraMethod::small);
  small.node_rotations(r);
  EXPECT_EQ(r[0], Mat3::Identity());
}

}  // namespace
}  // namespace sinew::fem

namespace sinew::fem {
namespace {

// Uniaxial stretch ε along x: σ = (λ+2μ)ε, λε, λε → von Mises = 2μ|ε|.
TEST(TetraFEMKernel, VonMisesOfAUniformStretch) {
  Mesh m;
  m.X = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.t = {{0, 1, 2, 3}};
  const double E = 1000, nu = 0.3, eps = 1e-3;
  for (TetraMethod method : {TetraMethod::small, TetraMethod::large, TetraMethod::polar}) {
    TetraFEM fem = make(m, method, E, nu);
    std::vector<double> Es{E}, nus{nu};
    fem.prepare_von_mises(Es, nus);
    std::vector<Vec3> x = m.X;
    for (auto& p : x) p[0] *= 1 + eps;
    std::vector<double> vme, vmn;
    const double mu = E / (2 * (1 + nu));
    fem.von_mises(x, 2, vme, vmn);
    ASSERT_EQ(vme.size(), 1u);
    const double green = eps + 0.5 * eps * eps;
    EXPECT_NEAR(vme[0], 2 * mu * green, 1e-9);
    EXPECT_NEAR(vmn[2], vme[0], 1e-15);
    if (method != TetraMethod::small) {
      fem.von_mises(x, 1, vme, vmn);
      EXPECT_NEAR(vme[0], 2 * mu * eps, 1e-6 * 2 * mu * eps);
      // TetrahedralCorotational's variant: material entries already divided by 36·V0; zero unless large.
      fem.von_mises(x, 3, vme, vmn);
      const double expect = method == TetraMethod::large ? 2 * mu * eps / (36.0 / 6.0) : 0.0;
      EXPECT_NEAR(vme[0], expect, 1e-6 * 2 * mu * eps);
    }
  }
}

}  // namespace
}  // namespace sinew::fem
