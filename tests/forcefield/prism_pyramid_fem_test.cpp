// Prism and pyramid elements of the element-generic FEM (CorotationalFEMForceField,
// LinearSmallStrainFEMForceField, FEMMass with templates "Vec3d,Prism" and
// "Vec3d,Pyramid"): the reference elements (partition of unity, gradients
// against finite differences, the quadrature's volume), the patch test (a
// linear displacement stores exactly V·½ε:C:ε), the mass (ρ·V), the SVD
// rotation, and SOFA's two example scenes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "badinput_helpers.h"
#include "core/node.h"
#include "forcefield/fem/element_fem.h"
#include "mass/fem_mass.h"
#include "math/decompose.h"
#include "math/finite_element.h"
#include "test_scene.h"
#include "topology/mesh_topology.h"
#include "test_paths.h"

namespace sinew {
namespace {

// Reference nodes (SOFA's referenceElementNodes).
const Vec3 kPrismRef[6] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
const Vec3 kPyramidRef[5] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {0, 0, 1}};

template <class E>
void check_reference_element(const Vec3 (&ref)[E::kNodes], double expected_volume) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.05, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    const fe::Vec3d q = {u(rng), u(rng), u(rng)};
    double N[E::kNodes], g[E::kNodes][3];
    E::shape(q, N);
    E::gradient(q, g);
    double sum = 0;
    for (double n : N) sum += n;
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int c = 0; c < 3; ++c) {
      const double h = 1e-6;
      fe::Vec3d qp = q, qm = q;
      qp[c] += h;
      qm[c] -= h;
      double Np[E::kNodes], Nm[E::kNodes];
      E::shape(qp, Np);
      E::shape(qm, Nm);
      for (int i = 0; i < E::kNodes; ++i) EXPECT_NEAR(g[i][c], (Np[i] - Nm[i]) / (2 * h), 1e-8) << i << "," << c;
    }
  }
  // Each shape function is 1 at its node and 0 at the others.
  for (int i = 0; i < E::kNodes; ++i) {
    double N[E::kNodes];
    E::shape({ref[i][0], ref[i][1], ref[i][2]}, N);
    for (int j = 0; j < E::kNodes; ++j) EXPECT_NEAR(N[j], i == j ? 1.0 : 0.0, 1e-15) << i << "," << j;
  }
  // The quadrature integrates the reference element's own volume.
  const auto pts = E::points();
  const auto w = E::weights();
  double volume = 0;
  for (int q = 0; q < E::kPoints; ++q) {
    double g[E::kNodes][3];
    E::gradient(pts[q], g);
    volume += w[q] * std::abs(fe::determinant(fe::jacobian<E::kNodes>(ref, g)));
  }
  EXPECT_NEAR(volume, expected_volume, 1e-9);
}

TEST(PrismPyramidElements, ReferenceElements) {
  check_reference_element<fe::Prism6>(kPrismRef, 0.5);
  check_reference_element<fe::Pyramid5>(kPyramidRef, 8.0 / 3.0);
}

// Energy ½uᵀKu of the linear displacement u = A·X against V·½ε:C:ε (isotropic C).
template <class E>
void patch_test(const std::array<Vec3, E::kNodes>& X, double volume) {
  const double young = 1000, nu = 0.3;
  double lambda, mu;
  fem::lame_parameters(young, nu, lambda, mu);
  constexpr int D = 3 * E::kNodes;
  std::vector<double> K(D * D);
  ASSERT_TRUE(fem::element_stiffness<E>(X, lambda, mu, K.data()));
  Mat3 A;
  A << 0.01, 0.002, -0.003, 0.004, -0.02, 0.001, 0.0, 0.005, 0.015;
  std::vector<double> u(D);
  for (int n = 0; n < E::kNodes; ++n) {
    const Vec3 d = A * X[n];
    for (int c = 0; c < 3; ++c) u[3 * n + c] = d[c];
  }
  double energy = 0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) energy += 0.5 * u[i] * K[i * D + j] * u[j];
  const Mat3 eps = 0.5 * (A + A.transpose());
  const double expected = volume * (mu * (eps.array() * eps.array()).sum() + 0.5 * lambda * eps.trace() * eps.trace());
  EXPECT_NEAR(energy, expected, 1e-12 * expected);
  // Rigid translations are free of force: K·1 = 0 per direction.
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < D; ++i) {
      double s = 0;
      for (int n = 0; n < E::kNodes; ++n) s += K[i * D + 3 * n + c];
      EXPECT_NEAR(s, 0.0, 1e-9 * young);
    }
}

TEST(PrismPyramidElements, PatchTestStoresTheExactStrainEnergy) {
  // A sheared prism (triangle area ½, height 2: V = 1) and a pyramid (base 2×2, height 3: V = 4).
  patch_test<fe::Prism6>({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.2, 2), Vec3(1.3, 0.2, 2),
                          Vec3(0.3, 1.2, 2)},
                         1.0);
  patch_test<fe::Pyramid5>({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0), Vec3(0.5, 1.4, 3)}, 4.0);
}

TEST(PrismPyramidElements, FemMassIsDensityTimesVolume) {
  // ρ = 3 on the prism and pyramid of the patch test.
  std::array<double, 6> rho6;
  rho6.fill(3.0);
  double M6[36];
  ASSERT_TRUE(FEMMass::prism_mass({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.2, 2), Vec3(1.3, 0.2, 2),
                                   Vec3(0.3, 1.2, 2)},
                                  rho6, M6));
  double total = 0;
  for (double m : M6) total += m;
  EXPECT_NEAR(total, 3.0, 1e-12);
  std::array<double, 5> rho5;
  rho5.fill(3.0);
  double M5[25];
  ASSERT_TRUE(
      FEMMass::pyramid_mass({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0), Vec3(0.5, 1.4, 3)}, rho5, M5));
  total = 0;
  for (double m : M5) total += m;
  // SOFA's Gauss points use the truncated 1/1.73205080757: the rule is exact to ~1e-12 only.
  EXPECT_NEAR(total, 12.0, 1e-10);
}

TEST(PrismPyramidElements, StablePolarRotationIsAlwaysARotation) {
  const Mat3 R = Eigen::AngleAxisd(0.8, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  Mat3 S;
  S << 1.2, 0.1, 0.0, 0.1, 0.9, 0.05, 0.0, 0.05, 1.1;
  EXPECT_TRUE((stable_polar_rotation(R * S) - R).norm() < 1e-12);
  // A reflecting M (an inverted element) still gives a proper rotation, unlike Higham's polar factor.
  Mat3 F = R * S;
  F.col(2) = -F.col(2);
  const Mat3 Q = stable_polar_rotation(F);
  EXPECT_NEAR(Q.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((Q * Q.transpose() - Mat3::Identity()).norm() < 1e-12);
}

TEST(PrismPyramidElements, HexahedraSplitIntoTwoPrismsEach) {
  auto s = test::load(R"(<Node>
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="state"/>
    <Node name="prisms"><MeshTopology name="out"/><Hexa2PrismTopologicalMapping input="@../grid" output="@out"/></Node>
  </Node>)");
  ASSERT_FALSE(s.root->children().empty());
  auto* out = test::get<MeshTopology>(*s.root->children().front(), "out");
  ASSERT_NE(out, nullptr);
  const auto& p = out->prisms.get();
  ASSERT_EQ(p.size(), 4u);
  // First cell (0 1 4 3 6 7 10 9 in SOFA's numbering): (0, 5, 1 | 3, 6, 2) → (0, 7, 1 | 3, 10, 4).
  EXPECT_EQ(p[0], (Prism{0, 7, 1, 3, 10, 4}));
  EXPECT_EQ(p[1], (Prism{0, 6, 7, 3, 9, 10}));
}

class PrismPyramidExample : public ::testing::TestWithParam<const char*> {};

TEST_P(PrismPyramidExample, Runs100Steps) {
  const test::Outcome o = test::run_sofa_example(GetParam(), 100);
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100) << o.all();
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
}

INSTANTIATE_TEST_SUITE_P(Sofa, PrismPyramidExample,
                         ::testing::Values("Component/SolidMechanics/FEM/PyramidCorotationalFEMForceField.scn",
                                           "Component/Topology/Mapping/Hexa2PrismTopologicalMapping.scn"),
                         [](const auto& info) {
                           return std::string(info.param).find("Pyramid") != std::string::npos ? "Pyramid" : "Prism";
                         });

}  // namespace
}  // namespace sinew
