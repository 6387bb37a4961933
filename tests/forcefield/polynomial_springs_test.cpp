// PolynomialSpringsForceField: the force of a stretched spring is P(strain)
// along the spring, by hand for a cubic; compressed springs give no force
// unless compressible (SOFA's flag); the tangent equals finite differences
// of the force and the assembled blocks; one polynomial per spring or the
// first for all; rest lengths computed or given; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "badinput_helpers.h"
#include "core/simulation.h"
#include "forcefield/spring/polynomial_springs_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

namespace sinew::polynomial_springs_test {

using test::dforce;
using test::expect_near_rel;
using test::fd_force;
using test::force_at;
using test::get;
using test::load;

namespace {
// Points 0, 1 (spring 0: 0 → 1, rest length 1) and 2, 3 (spring 1: 2 → 3, rest length 2).
std::string poly_scene(const std::string& attrs) {
  return R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 1 2"/>
    <PolynomialSpringsForceField name="ff" firstObjectPoints="0 2" secondObjectPoints="1 3" )" +
         attrs + "/></Node>";
}
}  // namespace

TEST(PolynomialSprings, StretchedSpringForceIsThePolynomialOfTheStrain) {
  auto s = load(poly_scene(R"(polynomialDegree="3 1" polynomialStiffness="20 10 50  7")"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialSpringsForceField>(*s.root, "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kPosition);
  force_at(ff, st, x);  // the first evaluation takes the rest lengths
  ASSERT_EQ(ff.rest_lengths().size(), 2u);
  EXPECT_DOUBLE_EQ(ff.rest_lengths()[0], 1.0);
  EXPECT_DOUBLE_EQ(ff.rest_lengths()[1], 2.0);
  // Spring 0 stretched to 1.5 along x: s = 0.5, P = 20·0.5 + 10·0.25 + 50·0.125 = 18.75.
  // Spring 1 stretched to 3 along z: s = 0.5, P = 7·0.5 = 3.5.
  x[3] = 1.5;
  x[11] = 3.0;
  const auto f = force_at(ff, st, x);
  EXPECT_NEAR(f[0], 18.75, 1e-12);   // point 0 pulled towards point 1
  EXPECT_NEAR(f[3], -18.75, 1e-12);
  EXPECT_NEAR(f[8], 3.5, 1e-12);
  EXPECT_NEAR(f[11], -3.5, 1e-12);
  for (int i : {1, 2, 4, 5, 6, 7, 9, 10}) EXPECT_EQ(f[i], 0.0) << i;
}

TEST(PolynomialSprings, CompressedSpringsPushOnlyWhenCompressible) {
  for (bool comp : {false, true}) {
    auto s = load(poly_scene(std::string(R"(polynomialDegree="1 1" polynomialStiffness="10 10" compressible=")") +
                        (comp ? "1" : "0") + "\""));
    ASSERT_TRUE(s.root);
    auto& ff = *get<PolynomialSpringsForceField>(*s.root, "ff");
    MechanicalState& st = *s.root->mechanical_state;
    std::vector<double> x = st.read(kPosition);
    force_at(ff, st, x);
    x[3] = 0.5;  // spring 0 compressed to half: s = 0.5, P = 5
    const auto f = force_at(ff, st, x);
    EXPECT_NEAR(f[0], comp ? -5.0 : 0.0, 1e-12) << "compressible " << comp;
    EXPECT_NEAR(f[3], comp ? 5.0 : 0.0, 1e-12);
  }
}

TEST(PolynomialSprings, TangentMatchesFiniteDifferencesAndAssembly) {
  auto s = load(poly_scene(R"(polynomialDegree="3 2" polynomialStiffness="20 10 50  7 3")"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialSpringsForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kPosition);
  force_at(ff, st, x);
  // Stretched in general directions.
  const double moved[12] = {0.1, -0.05, 0.02, 1.4, 0.3, -0.2, -0.1, 0.9, 0.1, 0.2, 1.3, 2.9};
  for (int i = 0; i < 12; ++i) x[i] = moved[i];
  force_at(ff, st, x);
  const auto dx = sinew::test::wiggle(x.size(), 5);
  const auto k = dforce(ff, st, dx);
  expect_near_rel(k, fd_force(ff, st, x, dx, 1e-6), 1e-6, "add_dforce vs finite differences");
  force_at(ff, st, x);
  const auto K = sinew::test::dense_stiffness(ff, st);
  const std::size_t n = x.size();
  std::vector<double> Kdx(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) Kdx[r] += K[r * n + c] * dx[c];
  expect_near_rel(Kdx, k, 1e-12, "build_stiffness vs add_dforce");
}

TEST(PolynomialSprings, OnePolynomialPerSpringOrTheFirstForAll) {
  // Two springs, one degree given: both use the first polynomial (with a warning).
  auto s = load(poly_scene(R"(polynomialDegree="1" polynomialStiffness="4" computeZeroLength="0" zeroLength="0.5")"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<PolynomialSpringsForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(ff, st, st.read(kPosition));
  // Given rest length 0.5: spring 0 (length 1) s = 1, P = 4; spring 1 (length 2) s = 3, P = 12.
  EXPECT_NEAR(f[0], 4.0, 1e-12);
  EXPECT_NEAR(f[8], 12.0, 1e-12);
}

TEST(PolynomialSprings, BadInputIsAnError) {
  using namespace sinew::test;
  TempDir dir;
  auto run = [&](const std::string& attrs) {
    return run_xml(dir, R"(<Node name="root" gravity="0 0 0" dt="0.01"><DefaultAnimationLoop/>
      <EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0"/><UniformMass totalMass="1"/>
      <PolynomialSpringsForceField name="ps" )" + attrs + "/></Node>");
  };
  Outcome o = run(R"(firstObjectPoints="0 1" secondObjectPoints="2")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "firstObjectPoints", "secondObjectPoints"})) << o.all();
  o = run(R"(firstObjectPoints="0" secondObjectPoints="7")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "secondObjectPoints", "7"})) << o.all();
  o = run(R"(firstObjectPoints="0" secondObjectPoints="1" computeZeroLength="0")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "zeroLength"})) << o.all();
  o = run(R"(firstObjectPoints="0" secondObjectPoints="1" polynomialDegree="3" polynomialStiffness="1 2")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'ps'", "polynomialStiffness"})) << o.all();
  // Coincident points: no NaN, a warning.
  o = run(R"(firstObjectPoints="0" secondObjectPoints="0")");
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"'ps'", "zero"})) << o.all();
}

}  // namespace sinew::polynomial_springs_test
