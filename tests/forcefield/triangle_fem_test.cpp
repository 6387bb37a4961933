// TriangleFEMForceField (SOFA's TriangleFEMForceField, not TriangularFEM):
// a stretched right triangle against a hand computation (plane stress, plane
// strain, thickness, large and small), rigid motions, quads cut in two,
// stored tangent vs assembled matrix, and the SOFA setters' corrections.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "forcefield/fem/triangle_fem_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::dense_stiffness;
using sinew::test::dforce;
using sinew::test::expect_near_rel;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;
using sinew::test::wiggle;

namespace {

std::string right_triangle(const std::string& attrs) {
  return R"(<Node gravity="0 0 0">
    <MeshTopology position="0 0 0  1 0 0  0 1 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <TriangleFEMForceField name="ff" youngModulus="1000" poissonRatio="0.3" )" + attrs + R"(/>
  </Node>)";
}

// B pulled from (1, 0, 0) to (1.1, 0, 0). In the current frame (world axes):
// Δ = (0, 0, −0.1, 0, 0, 0); J from b = 1.1, c = (0, 1): J00 = J12 = −1/1.1,
// J20 = J32 = 1/1.1, J02 = J11 = −1, J22 = J31 = 0, J42 = J51 = 1. Strain
// ε0 = J20·Δ2 = −1/11, ε1 = 0, ε2 = J22·Δ2 = 0. Stress σ = D·ε with D = s·[[a, ν], [ν, a]]:
// σ0 = s·a·ε0, σ1 = s·ν·ε0. Forces F = J·σ: A (−σ0/1.1, −σ1), B (σ0/1.1, 0), C (0, σ1).
void expect_stretch(const std::string& attrs, double s, double a) {
  auto sc = load(right_triangle(attrs));
  auto* ff = get<TriangleFEMForceField>(*sc.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *sc.root->mechanical_state;
  const auto f = force_at(*ff, st, {0, 0, 0, 1.1, 0, 0, 0, 1, 0});
  const double e0 = -1.0 / 11.0, s0 = s * a * e0, s1 = s * 0.3 * e0;
  const std::vector<double> expected{-s0 / 1.1, -s1, 0, s0 / 1.1, 0, 0, 0, s1, 0};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(f[i], expected[i], 1e-12 * std::abs(s)) << attrs << " component " << i;
  EXPECT_LT(f[3], 0);  // B is pulled back
  EXPECT_LT(f[7], 0);  // C is pulled in (Poisson)
}

}  // namespace

TEST(TriangleFEMForceField, StretchedTrianglePlaneStress) {
  // s = E/(1−ν²)·V, V = ½·thickness·|AB × AC| = ½; a = 1.
  const double s = 1000.0 / (1 - 0.09) * 0.5;
  expect_stretch("", s, 1.0);
  expect_stretch("method='large'", s, 1.0);
  expect_stretch("method='small'", s, 1.0);
  expect_stretch("thickness='2.5'", 2.5 * s, 1.0);
}

TEST(TriangleFEMForceField, StretchedTrianglePlaneStrain) {
  // s = E/((1+ν)(1−2ν))·V; a = 1 − ν.
  const double s = 1000.0 / (1.3 * 0.4) * 0.5;
  expect_stretch("planeStrain='true'", s, 0.7);
  expect_stretch("planeStrain='1' method='small'", s, 0.7);
}

TEST(TriangleFEMForceField, LargeIsInvariantUnderRigidMotionSmallIsNot) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 2) / 3.0).toRotationMatrix();
  std::vector<double> x;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) {
    const Vec3 q = R * p + Vec3(0.3, -1.2, 2.0);
    x.insert(x.end(), {q[0], q[1], q[2]});
  }
  auto large = load(right_triangle(""));
  const auto fl = force_at(*get<TriangleFEMForceField>(*large.root, "ff"), *large.root->mechanical_state, x);
  for (double v : fl) EXPECT_NEAR(v, 0.0, 1e-9);
  auto small = load(right_triangle("method='small'"));
  const auto fs = force_at(*get<TriangleFEMForceField>(*small.root, "ff"), *small.root->mechanical_state, x);
  double m = 0;
  for (double v : fs) m = std::max(m, std::abs(v));
  EXPECT_GT(m, 1.0);
}

TEST(TriangleFEMForceField, RestShapeInTheRestFrameAndQuadsCutInTwo) {
  // A tilted triangle: rest B, C in the frame of the rest triangle.
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology position="0 0 0  0 2 0  0 0 1" triangles="0 1 2"/>
    <MechanicalObject/>
    <TriangleFEMForceField name="ff"/>
  </Node>)");
  const auto& e = get<TriangleFEMForceField>(*s.root, "ff")->elements().at(0);
  EXPECT_NEAR(e.rbx, 2, 1e-15);
  EXPECT_NEAR(e.rby, 0, 1e-15);
  EXPECT_NEAR(e.rcx, 0, 1e-15);
  EXPECT_NEAR(std::abs(e.rcy), 1, 1e-15);
  // Default material E = 1000, ν = 0.3, V = ½·2·1 = 1.
  EXPECT_NEAR(e.D[0], 1000 / 0.91, 1e-9);
  EXPECT_NEAR(e.D[8], 1000 / 0.91 * 0.35, 1e-9);
  // No triangles: each quad gives (q0 q1 q2) and (q0 q2 q3).
  auto q = load(R"(<Node gravity="0 0 0">
    <MeshTopology position="0 0 0  1 0 0  1 1 0  0 1 0" quads="0 1 2 3"/>
    <MechanicalObject/>
    <TriangleFEMForceField name="ff"/>
  </Node>)");
  const auto& els = get<TriangleFEMForceField>(*q.root, "ff")->elements();
  ASSERT_EQ(els.size(), 2u);
  EXPECT_EQ((std::array<unsigned, 3>{els[0].a, els[0].b, els[0].c}), (std::array<unsigned, 3>{0, 1, 2}));
  EXPECT_EQ((std::array<unsigned, 3>{els[1].a, els[1].b, els[1].c}), (std::array<unsigned, 3>{0, 2, 3}));
}

TEST(TriangleFEMForceField, AssembledMatrixIsTheStoredTangent) {
  for (const char* m : {"method='large'", "method='small'", "planeStrain='1' thickness='0.1'"}) {
    auto s = load(R"(<Node gravity="0 0 0">
      <MeshTopology position="0 0 0  1 0 0  0 1 0  1.1 0.9 0" triangles="0 1 2  1 3 2"/>
      <MechanicalObject/>
      <TriangleFEMForceField name="ff" youngModulus="60" poissonRatio="0.3" )" + std::string(m) + R"(/>
    </Node>)");
    auto* ff = get<TriangleFEMForceField>(*s.root, "ff");
    MechanicalState& st = *s.root->mechanical_state;
    std::vector<double> x = st.read(kPosition);
    const auto w = wiggle(x.size(), 3);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.05 * w[i];
    force_at(*ff, st, x);
    const auto K = dense_stiffness(*ff, st);
    const std::size_t n = x.size();
    const auto dx = wiggle(n, 7);
    std::vector<double> Kdx(n, 0.0);
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c) Kdx[r] += K[r * n + c] * dx[c];
    expect_near_rel(Kdx, dforce(*ff, st, dx), 1e-12, m);
  }
}

TEST(TriangleFEMForceField, SettersCorrectNegativeValuesAndRefuseInfiniteMaterials) {
  auto bad = sinew::test::build(R"(<Node gravity="0 0 0">
    <MeshTopology position="0 0 0  1 0 0  0 1 0" triangles="0 1 2"/>
    <MechanicalObject/>
    <TriangleFEMForceField name="ff" youngModulus="-5" poissonRatio="-0.1"/>
    <TriangleFEMForceField name="ps" poissonRatio="0.5" planeStrain="true"/>
    <TriangleFEMForceField name="m" method="medium"/>
  </Node>)");
  init_root(*bad.root);
  auto* neg = get<TriangleFEMForceField>(*bad.root, "ff");
  EXPECT_EQ(neg->young_modulus.get(), 1000.0);
  EXPECT_EQ(neg->poisson_ratio.get(), 0.3);
  const auto w2 = sinew::test::messages(bad.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(sinew::test::any_contains(w2, "youngModulus is -5: negative, 1000 is used"));
  EXPECT_TRUE(sinew::test::any_contains(w2, "poissonRatio is -0.1: negative, 0.3 is used"));
  EXPECT_TRUE(sinew::test::any_contains(w2, "method \"medium\" is unknown (large or small): using large"));
  EXPECT_EQ(get<TriangleFEMForceField>(*bad.root, "m")->state(), ComponentState::valid);
  EXPECT_EQ(get<TriangleFEMForceField>(*bad.root, "ps")->state(), ComponentState::invalid);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(bad.root->diagnostics(), Severity::error),
                                        "no finite plane-strain material"));
}
