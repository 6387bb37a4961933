// Triangle force fields (spec/mechanics.md §2.6, §2.7, §3.5, §3.6):
// rest and rigid-motion invariance, closed-form stresses, forces = −∇energy
// where an energy exists, add_dforce = finite differences of add_force
// (noting where SOFA's corotational tangent deliberately differs) and
// build_stiffness = add_dforce.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "forcefield/spring/fast_triangular_bending_springs.h"
#include "forcefield/spring/triangular_bending_springs.h"
#include "forcefield/fem/triangular_fem_force_field.h"
#include "forcefield/fem/triangular_fem_force_field_optim.h"
#include "spring_helpers.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::dense_stiffness;
using sinew::test::dforce;
using sinew::test::expect_near_rel;
using sinew::test::fd_force;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;
using sinew::test::max_abs;
using sinew::test::wiggle;

namespace {

// Two triangles sharing the edge (1,2), in the z = 0 plane.
std::string square(const std::string& ff) {
  return R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0" triangles="0 1 2  1 3 2"/>
    <MechanicalObject name="dofs"/>
    )" + ff + R"(
  </Node>)";
}

// Rotation of angle a about the unit axis (1,2,2)/3, then a translation.
std::vector<double> rigid_motion(const std::vector<double>& x, double a) {
  const Vec3 axis = Vec3(1, 2, 2) / 3.0;
  const Mat3 R = Eigen::AngleAxisd(a, axis).toRotationMatrix();
  std::vector<double> out(x.size());
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    const Vec3 p = R * Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]) + Vec3(0.3, -1.2, 2.0);
    for (int c = 0; c < 3; ++c) out[3 * i + c] = p[c];
  }
  return out;
}

void expect_matrix_matches_dforce(ForceField& ff, MechanicalState& st, unsigned seed) {
  const auto K = dense_stiffness(ff, st);
  const std::size_t n = st.size() * 3;
  const auto dx = wiggle(n, seed);
  std::vector<double> Kdx(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) Kdx[r] += K[r * n + c] * dx[c];
  expect_near_rel(Kdx, dforce(ff, st, dx), 1e-12, "build_stiffness vs add_dforce");
}

}  // namespace

// ------------------------------------------------------------------ TriangularFEMForceFieldOptim

TEST(TriangularFEMForceFieldOptim, NoForceAtRestNorUnderRigidMotion) {
  auto s = load(square(R"(<TriangularFEMForceFieldOptim name="ff" youngModulus="600" poissonRatio="0.3"/>)"));
  auto* ff = get<TriangularFEMForceFieldOptim>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x0 = st.write(kRestPosition);
  EXPECT_LT(max_abs(force_at(*ff, st, x0)), 1e-12);
  EXPECT_LT(max_abs(force_at(*ff, st, rigid_motion(x0, 0.7))), 1e-11);
}

TEST(TriangularFEMForceFieldOptim, UniaxialStretchGivesThePlaneStressForce) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <TriangularFEMForceFieldOptim name="ff" youngModulus="600" poissonRatio="0.3"/>
  </Node>)");
  auto* ff = get<TriangularFEMForceFieldOptim>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const double e = 1e-3, E = 600, nu = 0.3;
  const auto f = force_at(*ff, st, {0, 0, 0, 1 + e, 0, 0, 0, 1, 0});
  // σ_xx = E/(1−ν²)·ε on an element of area ½: node B receives −σ_xx·½.
  EXPECT_NEAR(f[3], -0.5 * E / (1 - nu * nu) * e, 1e-12);
  EXPECT_NEAR(f[0] + f[3] + f[6], 0.0, 1e-13);
  EXPECT_NEAR(f[1] + f[4] + f[7], 0.0, 1e-13);
}

TEST(TriangularFEMForceFieldOptim, TangentMatchesFiniteDifferencesAtRest) {
  auto s = load(square(R"(<TriangularFEMForceFieldOptim name="ff" youngModulus="600" poissonRatio="0.3"/>)"));
  auto* ff = get<TriangularFEMForceFieldOptim>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x0 = rigid_motion(st.write(kRestPosition), 0.4);
  force_at(*ff, st, x0);
  const auto dx = wiggle(x0.size(), 5);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x0, dx, 1e-6), 1e-6, "Optim tangent at rest");
}

// Away from rest SOFA's tangent omits the derivative of the frame: it is close
// to, but not exactly, the finite difference of add_force.
TEST(TriangularFEMForceFieldOptim, TangentOmitsTheFrameDerivativeWhenStressed) {
  auto s = load(square(R"(<TriangularFEMForceFieldOptim name="ff" youngModulus="600" poissonRatio="0.3"/>)"));
  auto* ff = get<TriangularFEMForceFieldOptim>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kRestPosition);
  const auto w = wiggle(x.size(), 11);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.05 * w[i];
  force_at(*ff, st, x);
  const auto dx = wiggle(x.size(), 12);
  const auto df = dforce(*ff, st, dx), fd = fd_force(*ff, st, x, dx, 1e-6);
  double diff = 0;
  for (std::size_t i = 0; i < df.size(); ++i) diff = std::max(diff, std::fabs(df[i] - fd[i]));
  EXPECT_GT(diff, 1e-6 * max_abs(fd));  // not the exact derivative
  EXPECT_LT(diff, 0.2 * max_abs(fd));   // but a close approximation
  expect_matrix_matches_dforce(*ff, st, 13);
}

// ------------------------------------------------------------------ TriangularFEMForceField

TEST(TriangularFEMForceField, NoForceAtRestNorUnderRigidMotion) {
  auto s = load(square(R"(<TriangularFEMForceField name="ff" youngModulus="60" poissonRatio="0.3" method="large"/>)"));
  auto* ff = get<TriangularFEMForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x0 = st.write(kRestPosition);
  EXPECT_LT(max_abs(force_at(*ff, st, x0)), 1e-12);
  EXPECT_LT(max_abs(force_at(*ff, st, rigid_motion(x0, -1.1))), 1e-11);
}

TEST(TriangularFEMForceField, UniaxialStretchUsesTheCurrentShapeInJ) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <TriangularFEMForceField name="ff" youngModulus="60" poissonRatio="0.3"/>
  </Node>)");
  auto* ff = get<TriangularFEMForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const double e = 1e-2, E = 60, nu = 0.3;
  const auto f = force_at(*ff, st, {0, 0, 0, 1 + e, 0, 0, 0, 1, 0});
  // J rebuilt from the stretched shape (trap 13): F_B = −E/(1−ν²)·½·e/(1+e)².
  EXPECT_NEAR(f[3], -0.5 * E / (1 - nu * nu) * e / ((1 + e) * (1 + e)), 1e-12);
  EXPECT_NEAR(f[0] + f[3] + f[6], 0.0, 1e-13);
}

TEST(TriangularFEMForceField, TangentMatchesFiniteDifferencesAtRestAndTheMatrix) {
  auto s = load(square(R"(<TriangularFEMForceField name="ff" youngModulus="60" poissonRatio="0.3"/>)"));
  auto* ff = get<TriangularFEMForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x0 = rigid_motion(st.write(kRestPosition), 0.3);
  force_at(*ff, st, x0);
  const auto dx = wiggle(x0.size(), 21);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x0, dx, 1e-6), 1e-6, "TriangularFEM tangent at rest");
  std::vector<double> x = x0;
  const auto w = wiggle(x.size(), 22);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.05 * w[i];
  force_at(*ff, st, x);
  expect_matrix_matches_dforce(*ff, st, 23);
}

TEST(TriangularFEMForceField, DegenerateRestTriangleIsRefused) {
  auto s = sinew::test::build(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  2 0 0" triangles="0 1 2"/>
    <MechanicalObject name="dofs"/>
    <TriangularFEMForceField name="ff"/>
  </Node>)");
  init_root(*s.root);
  EXPECT_EQ(get<TriangularFEMForceField>(*s.root, "ff")->state(), ComponentState::invalid);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error), "triangle 0"));
}

TEST(TriangularFEMForceField, SmallMethodUsesWorldAxesAndMatchesFiniteDifferencesAtRest) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0" triangles="0 1 2  1 3 2"/>
    <MechanicalObject name="dofs"/>
    <TriangularFEMForceField name="ff" youngModulus="60" poissonRatio="0.3" method="small"/>
  </Node>)");
  auto* ff = get<TriangularFEMForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x0 = st.write(kRestPosition);
  EXPECT_LT(max_abs(force_at(*ff, st, x0)), 1e-12);
  auto xt = x0;
  for (std::size_t i = 0; i < xt.size(); ++i) xt[i] += (i % 3 == 0 ? 0.7 : -0.2);
  EXPECT_LT(max_abs(force_at(*ff, st, xt)), 1e-12);  // translation
  force_at(*ff, st, x0);
  const auto dx = wiggle(x0.size(), 24);
  auto dxp = dx;
  for (std::size_t i = 2; i < dxp.size(); i += 3) dxp[i] = 0;  // in-plane motion
  expect_near_rel(dforce(*ff, st, dxp), fd_force(*ff, st, x0, dxp, 1e-6), 1e-6, "small tangent at rest");
  // In-plane stretch: forces stay in the xy plane (SOFA writes 0 in z).
  auto xs = x0;
  xs[3] += 1e-2;
  xs[11] += 0.3;  // lifting a vertex out of the plane is ignored by the small method
  const auto f = force_at(*ff, st, xs);
  for (std::size_t i = 2; i < f.size(); i += 3) EXPECT_EQ(f[i], 0.0);
  EXPECT_LT(f[3], 0.0);
}

// ------------------------------------------------------------------ FastTriangularBendingSprings

TEST(FastTriangularBendingSprings, OneSpringPerInnerEdgeWithVolinoWeights) {
  auto s = load(square(R"(<FastTriangularBendingSprings name="ff" bendingStiffness="10"/>)"));
  auto* ff = get<FastTriangularBendingSprings>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  int active = 0;
  for (const auto& es : ff->edge_springs()) {
    if (!es.active) continue;
    ++active;
    // A, B opposite the shared edge (1,2): 0 in the first triangle, 3 in the second.
    EXPECT_EQ(es.vid[0], 0u);
    EXPECT_EQ(es.vid[1], 3u);
    EXPECT_NEAR(es.alpha[0] + es.alpha[1], 1.0, 1e-15);
    EXPECT_NEAR(es.alpha[2] + es.alpha[3], -1.0, 1e-15);
    EXPECT_GT(es.lambda, 0.0);
  }
  EXPECT_EQ(active, 1);
}

TEST(FastTriangularBendingSprings, ForceIsMinusTheGradientAndTheTangentIsExact) {
  auto s = load(square(R"(<FastTriangularBendingSprings name="ff" bendingStiffness="10"/>)"));
  auto* ff = get<FastTriangularBendingSprings>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kRestPosition);
  EXPECT_LT(max_abs(force_at(*ff, st, x)), 1e-12);                    // flat rest shape
  EXPECT_LT(max_abs(force_at(*ff, st, rigid_motion(x, 0.0))), 1e-12);  // translation
  x[11] += 0.2;  // lift vertex 3 out of the plane
  x[2] -= 0.05;
  const auto f = force_at(*ff, st, x);
  EXPECT_GT(max_abs(f), 1e-3);
  auto energy = [&](const std::vector<double>& y) {
    force_at(*ff, st, y);
    return ff->potential_energy().value();
  };
  const double h = 1e-6;
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    EXPECT_NEAR(f[i], -(energy(xp) - energy(xm)) / (2 * h), 1e-7) << "dof " << i;
  }
  force_at(*ff, st, x);
  const auto dx = wiggle(x.size(), 31);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x, dx, 1e-5), 1e-8, "bending tangent");
  expect_matrix_matches_dforce(*ff, st, 32);
}

// ------------------------------------------------------------------ TriangularBendingSprings

TEST(TriangularBendingSprings, SpringBetweenTheOppositeVertices) {
  auto s = load(square(R"(<TriangularBendingSprings name="ff" stiffness="300" damping="0"/>)"));
  auto* ff = get<TriangularBendingSprings>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->spring_list().size(), 1u);
  const auto& sp = ff->spring_list()[0];
  // First triangle holding the edge is triangle 0: m1 in the other (3), m2 in it (0).
  EXPECT_EQ(sp.m1, 3u);
  EXPECT_EQ(sp.m2, 0u);
  EXPECT_NEAR(sp.l0, std::sqrt(1.1 * 1.1 + 0.9 * 0.9), 1e-15);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kRestPosition);
  x[9] += 0.1;
  x[11] += 0.2;
  force_at(*ff, st, x);
  const auto dx = wiggle(x.size(), 41);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x, dx, 1e-6), 1e-6, "bending spring tangent");
  expect_matrix_matches_dforce(*ff, st, 42);
}
