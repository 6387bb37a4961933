// VariationalSymplecticSolver: implicit midpoint in momentum form, and its explicit variant.
#include <gtest/gtest.h>

#include <cmath>

#include "oscillator.h"
#include "solver/ode/variational_symplectic_solver.h"

namespace sinew {
namespace {

const char* kCG = "<CGLinearSolver iterations=\"25\" tolerance=\"1e-20\" threshold=\"1e-30\"/>";

std::string vs(const std::string& attrs = "") {
  return "<VariationalSymplecticSolver name=\"vs\" " + attrs + "/>" + kCG;
}

TEST(VariationalSymplecticSolver, FirstStepByHand) {
  // h = 0.1, m = k = 1, x0 = 1, v0 = 0, p0 = 0. Newton 1: b = f(x0) = −1, A = 4/h² + 1 = 401,
  // res = −1/401, change 1/401 = 0.0025 < newtonError 0.01: one iteration.
  // v1 = (2/h)·res = −20/401; x1 = x0 + h·v1 = 1 − 2/401;
  // p1 = (h/2)·f(x0 + res) + v1 = −0.05·400/401 − 20/401 = −40/401.
  test::Oscillator o(vs(), 0.1);
  auto* solver = test::get<VariationalSymplecticSolver>(*o.s.root, "vs");
  o.step();
  EXPECT_NEAR(o.x(), 1.0 - 2.0 / 401.0, 1e-15);
  EXPECT_NEAR(o.v(), -20.0 / 401.0, 1e-15);
  // Hamiltonian: ½p1² + (½ − 2·f(x0)·res) = ½(40/401)² + ½ − 2/401.
  EXPECT_NEAR(solver->hamiltonian_energy.value(), 0.5 * std::pow(40.0 / 401.0, 2) + 0.5 - 2.0 / 401.0, 1e-15);
}

TEST(VariationalSymplecticSolver, SecondOrderConvergence) {
  const std::string s = vs("newtonError=\"1e-14\"");
  const double e1 = test::oscillator_error(s, 0.01);
  const double e2 = test::oscillator_error(s, 0.005);
  EXPECT_LT(e1, 1e-4);
  EXPECT_NEAR(e1 / e2, 4.0, 0.2);  // 2^order
}

TEST(VariationalSymplecticSolver, HamiltonianIsConservedOnALinearOscillator) {
  // Converged Newton iterations: the last force is the midpoint force, and the midpoint rule
  // keeps ½p² + ½x² of a linear oscillator exactly.
  test::Oscillator o(vs("newtonError=\"1e-14\""), 0.2);
  auto* solver = test::get<VariationalSymplecticSolver>(*o.s.root, "vs");
  o.step();
  const double h0 = solver->hamiltonian_energy.value();
  EXPECT_NEAR(h0, 0.5, 1e-12);
  for (int i = 0; i < 500; ++i) {
    o.step();
    ASSERT_NEAR(solver->hamiltonian_energy.value(), 0.5, 1e-10) << "step " << i;
  }
}

TEST(VariationalSymplecticSolver, ExplicitIsSymplecticEuler) {
  // v1 = v0 + h·a(x0), x1 = x0 + h·v1: with x0 = 1, v0 = 0, h = 0.1: v1 = −0.1, x1 = 0.99.
  test::Oscillator o(vs("explicitIntegration=\"true\""), 0.1);
  o.step();
  EXPECT_NEAR(o.v(), -0.1, 1e-15);
  EXPECT_NEAR(o.x(), 0.99, 1e-15);
  o.step();  // p1 = −0.1: v2 = h·(f(x1) + p1/h) = −0.099 − 0.1
  EXPECT_NEAR(o.v(), -0.199, 1e-15);
  EXPECT_NEAR(o.x(), 0.99 - 0.0199, 1e-15);
  // First order.
  const double e1 = test::oscillator_error(vs("explicitIntegration=\"true\""), 0.01);
  const double e2 = test::oscillator_error(vs("explicitIntegration=\"true\""), 0.005);
  EXPECT_NEAR(e1 / e2, 2.0, 0.15);
}

}  // namespace
}  // namespace sinew
