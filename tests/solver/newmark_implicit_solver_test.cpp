// NewmarkImplicitSolver: SOFA's acceleration formulation (a kept between steps).
#include <gtest/gtest.h>

#include <cmath>

#include "oscillator.h"

namespace sinew {
namespace {

const char* kCG = "<CGLinearSolver iterations=\"25\" tolerance=\"1e-20\" threshold=\"1e-30\"/>";

std::string newmark(const std::string& attrs = "") { return "<NewmarkImplicitSolver " + attrs + "/>" + kCG; }

TEST(NewmarkImplicitSolver, FirstStepByHand) {
  // h = 0.1, γ = ½, β = ¼, m = k = 1, x0 = 1, v0 = 0: a0 = −1;
  // b = f + h²(1−2β)/2·K·a0 + (h·K)·v0 = −1 + 0.0025;  A = M − h²β·K = 1.0025;
  // a1 = −0.9975/1.0025; x1 = x0 + h²/4·(a0 + a1) = 0.9975/1.0025; v1 = h/2·(a0 + a1).
  test::Oscillator o(newmark(), 0.1);
  o.step();
  const double a1 = -0.9975 / 1.0025;
  EXPECT_NEAR(o.x(), 0.9975 / 1.0025, 1e-14);
  EXPECT_NEAR(o.v(), 0.05 * (-1.0 + a1), 1e-14);
  // Second step, with the stored acceleration a1: the trapezoidal rule's closed form,
  // (x2, v2) = rotation-like map of (x1, v1) with c = (1 − h²/4)/(1 + h²/4), s = h/(1 + h²/4).
  o.step();
  const double c = (1 - 0.0025) / (1 + 0.0025), s = 0.1 / (1 + 0.0025);
  const double x1 = 0.9975 / 1.0025, v1 = 0.05 * (-1.0 + a1);
  EXPECT_NEAR(o.x(), c * x1 + s * v1, 1e-14);
  EXPECT_NEAR(o.v(), -s * x1 + c * v1, 1e-14);
}

TEST(NewmarkImplicitSolver, SecondOrderConvergence) {
  const double e1 = test::oscillator_error(newmark(), 0.01);
  const double e2 = test::oscillator_error(newmark(), 0.005);
  EXPECT_LT(e1, 1e-4);
  EXPECT_NEAR(e1 / e2, 4.0, 0.2);  // 2^order
}

TEST(NewmarkImplicitSolver, AverageAccelerationConservesEnergy) {
  // γ = ½, β = ¼ on an undamped linear oscillator: ½v² + ½x² is kept exactly (up to rounding),
  // even with a large step.
  test::Oscillator o(newmark(), 0.5);
  const double e0 = o.energy();
  for (int i = 0; i < 1000; ++i) {
    o.step();
    ASSERT_NEAR(o.energy(), e0, 1e-12) << "step " << i;
  }
}

TEST(NewmarkImplicitSolver, NumericalDampingWithGammaAboveHalf) {
  // γ > ½ (β = (γ + ½)²/4) dissipates: the energy decreases at every step.
  test::Oscillator o(newmark("gamma=\"0.6\" beta=\"0.3025\""), 0.1);
  double e = o.energy();
  for (int i = 0; i < 100; ++i) {
    o.step();
    EXPECT_LT(o.energy(), e) << "step " << i;
    e = o.energy();
  }
}

TEST(NewmarkImplicitSolver, RayleighMassDampsAndVdampingScales) {
  test::Oscillator o(newmark("rayleighMass=\"0.5\""), 0.1);
  o.step(100);
  EXPECT_LT(o.energy(), 0.5 * std::exp(-0.5 * 10.0) * 1.5);
  EXPECT_GT(o.energy(), 0.0);

  // vdamping multiplies the new velocity by exp(−h·vdamping) after the step.
  test::Oscillator a(newmark(), 0.1), b(newmark("vdamping=\"2\""), 0.1);
  a.step();
  b.step();
  EXPECT_NEAR(b.v(), a.v() * std::exp(-0.2), 1e-15);
  EXPECT_DOUBLE_EQ(b.x(), a.x());
}

TEST(NewmarkImplicitSolver, FreeFallIsExact) {
  // Constant acceleration: x = x0 + g t²/2 exactly for any γ, β.
  auto s = test::load(
      "<Node dt=\"0.1\" gravity=\"0 -10 0\"><DefaultAnimationLoop/><NewmarkImplicitSolver/>"
      "<CGLinearSolver iterations=\"25\" tolerance=\"1e-20\" threshold=\"1e-30\"/>"
      "<MechanicalObject name=\"dofs\" position=\"1 2 3\"/><UniformMass totalMass=\"2\"/></Node>");
  for (int i = 0; i < 10; ++i) animate(*s.root);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  EXPECT_NEAR(mo->read(kPosition)[1], 2.0 - 5.0, 1e-12);
  EXPECT_NEAR(mo->read(kVelocity)[1], -10.0, 1e-12);
}

TEST(NewmarkImplicitSolver, WithoutLinearSolverIsAnError) {
  scene::LoadedScene s = test::build(test::oscillator_scene("<NewmarkImplicitSolver name=\"nm\"/>", 0.1));
  init_root(*s.root);
  bool found = false;
  for (const std::string& m : test::messages(s.root->diagnostics(), Severity::error))
    if (m.find("no linear solver") != std::string::npos) found = true;
  EXPECT_TRUE(found);
  animate(*s.root);  // no crash
}

}  // namespace
}  // namespace sinew
