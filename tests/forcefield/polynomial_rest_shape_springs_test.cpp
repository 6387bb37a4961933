// PolynomialRestShapeSpringsForceField: the force by hand (polynomial of the
// strain, direction through the smoothed length), SOFA's diagonal tangent
// (equal to the finite-difference diagonal when the smoothing is negligible,
// its formula otherwise), springs to an external state, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "badinput_helpers.h"
#include "core/simulation.h"
#include "forcefield/spring/polynomial_rest_shape_springs_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

namespace sinew::polynomial_rest_shape_springs_test {

using test::dforce;
using test::force_at;
using test::get;
using test::load;

namespace {
std::string rest_scene(const std::string& attrs) {
  return R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="dofs" rest_position="0 0 0  1 1 1" position="0 0 0  1 1 1"/>
    <PolynomialRestShapeSpringsForceField name="ff" )" +
         attrs + "/></Node>";
}
}  // namespace

TEST(PolynomialRestShapeSprings, ForceByHand) {
  // Negligible smoothing (scale 1e7, as SOFA's example): D = |d|.
  auto s = load(rest_scene(R"(points="1" polynomialStiffness="10 4" polynomialDegree="2" initialLength="2"
                          smoothShift="0.0001" smoothScale="1e7")"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialRestShapeSpringsForceField>(*s.root, "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kPosition);
  x[3] = 4;  // point 1 moved by d = (3, 0, 0): s = 1.5, P = 10·1.5 + 4·2.25 = 24
  const auto f = force_at(ff, st, x);
  EXPECT_NEAR(f[3], -24.0, 1e-12);
  EXPECT_NEAR(f[4], 0.0, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(f[i], 0.0);  // point 0 has no spring
  // Smoothed (default shift 0, scale 1): D = √(9 + e^−9).
  auto s2 = load(rest_scene(R"(points="1" polynomialStiffness="10 4" polynomialDegree="2" initialLength="2")"));
  auto& ff2 = *get<PolynomialRestShapeSpringsForceField>(*s2.root, "ff");
  MechanicalState& st2 = *s2.root->mechanical_state;
  const auto f2 = force_at(ff2, st2, x);
  EXPECT_NEAR(f2[3], -24.0 * 3 / std::sqrt(9 + std::exp(-9.0)), 1e-12);
}

TEST(PolynomialRestShapeSprings, DiagonalTangent) {
  auto s = load(rest_scene(R"(polynomialStiffness="10 4  3" polynomialDegree="2 1" smoothShift="0.0001"
                          smoothScale="1e7")"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialRestShapeSpringsForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kPosition);
  const double moved[6] = {0.3, -0.2, 0.5, 1.7, 0.6, 1.4};
  for (int i = 0; i < 6; ++i) x[i] = moved[i];
  force_at(ff, st, x);
  // Diagonal of ∂f/∂x by central differences against −j.
  const double h = 1e-6;
  for (int i = 0; i < 6; ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const double fp = force_at(ff, st, xp)[i], fm = force_at(ff, st, xm)[i];
    force_at(ff, st, x);
    EXPECT_NEAR((fp - fm) / (2 * h), -ff.tangents()[i / 3][i % 3], 1e-6) << "dof " << i;
  }
  // add_dforce and the assembled diagonal apply the same j.
  std::vector<double> dx(6);
  for (int i = 0; i < 6; ++i) dx[i] = 0.1 * (i + 1);
  const auto df = dforce(ff, st, dx, 2.0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(df[i], -ff.tangents()[i / 3][i % 3] * dx[i] * 2.0, 1e-14);
  const auto K = sinew::test::dense_stiffness(ff, st);
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(K[r * 6 + c], r == c ? -ff.tangents()[r / 3][r % 3] : 0.0, 1e-14);
}

TEST(PolynomialRestShapeSprings, SpringsToAnExternalState) {
  auto s = load(R"(<Node name="root" gravity="0 0 0">
    <Node name="anchor"><MechanicalObject name="target" position="5 0 0  0 0 7"/></Node>
    <Node name="body"><MechanicalObject name="dofs" position="0 0 0"/>
      <PolynomialRestShapeSpringsForceField name="ff" points="0" external_points="1" external_rest_shape="@../anchor/target"
        polynomialStiffness="2" smoothScale="1e7" smoothShift="0"/></Node></Node>)");
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialRestShapeSpringsForceField>(*s.root->find_child_named("body"), "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  MechanicalState& st = *s.root->find_child_named("body")->mechanical_state;
  // d = x − (0, 0, 7): s = 7, P = 14, pulled towards the target.
  const auto f = force_at(ff, st, st.read(kPosition));
  EXPECT_NEAR(f[2], 14.0, 1e-12);
}

TEST(PolynomialRestShapeSprings, BadInputIsAnError) {
  using namespace sinew::test;
  TempDir dir;
  auto run = [&](const std::string& attrs) {
    return run_xml(dir, R"(<Node name="root" gravity="0 0 0" dt="0.01"><DefaultAnimationLoop/>
      <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0"/><UniformMass totalMass="1"/>
      <PolynomialRestShapeSpringsForceField name="ps" )" + attrs + "/></Node>");
  };
  Outcome o = run(R"(points="5")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "points", "5"})) << o.all();
  o = run(R"(initialLength="0")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "initialLength"})) << o.all();
  o = run(R"(polynomialDegree="3" polynomialStiffness="1 2")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "polynomialStiffness"})) << o.all();
  o = run("");
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_TRUE(o.finite);
}

}  // namespace sinew::polynomial_rest_shape_springs_test
