// BDFOdeSolver: the BDF coefficients (known constant-step values, the
// variable-step BDF2 formula, exactness on polynomials), order 1 against
// EulerImplicitSolver and backward Euler by hand, first-order convergence,
// SOFA's history handling at orders 2 and 3, the example scenes, bad input.
#include "solver/ode/bdf_ode_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "badinput_helpers.h"
#include "oscillator.h"
#include "test_paths.h"

namespace sinew {
namespace {

const char* kLDLT = "<EigenSimplicialLDLT template=\"CompressedRowSparseMatrix\"/>";

std::string bdf(const std::string& attrs, const std::string& newton = "maxNbIterationsNewton=\"4\"") {
  return "<BDFOdeSolver " + attrs + "/><NewtonRaphsonSolver " + newton + "/>" + kLDLT;
}

TEST(BDFCoefficients, ConstantStepsGiveTheClassicalFormulas) {
  std::vector<double> a, b;
  for (double t0 : {0.0, 12.0, 900.0})
    for (double h : {1.0, 0.01, -1.0}) {
      bdf_coefficients({t0, t0 + h}, a, b);
      ASSERT_EQ(a.size(), 2u);
      EXPECT_NEAR(a[0], -1, 1e-12);
      EXPECT_EQ(a[1], 1);
      EXPECT_EQ(b[0], 0);
      EXPECT_NEAR(b[1], 1, 1e-12);
      bdf_coefficients({t0, t0 + h, t0 + 2 * h}, a, b);
      EXPECT_NEAR(a[0], 1.0 / 3, 1e-9);
      EXPECT_NEAR(a[1], -4.0 / 3, 1e-9);
      EXPECT_NEAR(b[2], 2.0 / 3, 1e-9);
      bdf_coefficients({t0, t0 + h, t0 + 2 * h, t0 + 3 * h}, a, b);
      EXPECT_NEAR(a[0], -2.0 / 11, 1e-8);
      EXPECT_NEAR(a[1], 9.0 / 11, 1e-8);
      EXPECT_NEAR(a[2], -18.0 / 11, 1e-8);
      EXPECT_EQ(a[3], 1);
      EXPECT_NEAR(b[3], 6.0 / 11, 1e-8);
      EXPECT_EQ(b[0], 0);
      EXPECT_EQ(b[1], 0);
      EXPECT_EQ(b[2], 0);
    }
}

TEST(BDFCoefficients, VariableStepBDF2) {
  // Steps h1 then h2, ω = h2/h1: a = (ω²/(1+2ω), −(1+ω)²/(1+2ω), 1), b_2 = (1+ω)/(1+2ω).
  std::vector<double> a, b;
  const double h1 = 0.3, h2 = 0.5, w = h2 / h1;
  bdf_coefficients({1.0, 1.0 + h1, 1.0 + h1 + h2}, a, b);
  EXPECT_NEAR(a[0], w * w / (1 + 2 * w), 1e-13);
  EXPECT_NEAR(a[1], -(1 + w) * (1 + w) / (1 + 2 * w), 1e-13);
  EXPECT_NEAR(b[2], (1 + w) / (1 + 2 * w), 1e-13);
}

// Order s differentiates polynomials of degree ≤ s exactly: Σ a_j p(t_j) = h b_s p'(t_s).
TEST(BDFCoefficients, ExactOnPolynomialsOfTheOrder) {
  const std::deque<double> all = {0.1, 0.35, 0.5, 0.9, 1.05, 1.4, 1.5};
  for (std::size_t s = 1; s <= 6; ++s) {
    const std::deque<double> t(all.begin(), all.begin() + s + 1);
    std::vector<double> a, b;
    bdf_coefficients(t, a, b);
    const double h = t[s] - t[s - 1];
    for (std::size_t deg = 0; deg <= s; ++deg) {
      double lhs = 0;
      for (std::size_t j = 0; j <= s; ++j) lhs += a[j] * std::pow(t[j], static_cast<double>(deg));
      const double rhs = deg == 0 ? 0.0 : h * b[s] * deg * std::pow(t[s], static_cast<double>(deg - 1));
      EXPECT_NEAR(lhs, rhs, 1e-9) << "order " << s << " degree " << deg;
    }
  }
}

// Backward Euler on m = k = 1 with Rayleigh damping, by hand: from
// v' − v = h(−x' − rM v' − rK v') and x' = x + h v',
// (1 + h·rM + h·rK + h²) v' = v − h x.
void backward_euler(double& x, double& v, double h, double rM = 0, double rK = 0) {
  v = (v - h * x) / (1 + h * rM + h * rK + h * h);
  x = x + h * v;
}

TEST(BDFOdeSolver, OrderOneIsEulerImplicit) {
  const std::string damping = "rayleighMass=\"0.1\" rayleighStiffness=\"0.05\"";
  test::Oscillator b(bdf("order=\"1\" " + damping), 0.1, 1.0);
  test::Oscillator e("<EulerImplicitSolver " + damping + "/>" + std::string(kLDLT), 0.1, 1.0);
  double x = 1, v = 0;
  for (int i = 0; i < 50; ++i) {
    b.step();
    e.step();
    backward_euler(x, v, 0.1, 0.1, 0.05);
    ASSERT_NEAR(b.x(), e.x(), 1e-12) << "step " << i;
    ASSERT_NEAR(b.v(), e.v(), 1e-12) << "step " << i;
    ASSERT_NEAR(b.x(), x, 1e-12) << "step " << i;
    ASSERT_NEAR(b.v(), v, 1e-12) << "step " << i;
  }
}

TEST(BDFOdeSolver, OrderOneConvergesAtFirstOrder) {
  const double e1 = test::oscillator_error(bdf("order=\"1\""), 0.01);
  const double e2 = test::oscillator_error(bdf("order=\"1\""), 0.005);
  EXPECT_LT(e1, 0.01);
  EXPECT_NEAR(e1 / e2, 2.0, 0.1);
}

// SOFA's history slots all name the current state from the second step on
// (header of bdf_ode_solver.h): order s is then backward Euler with the step
// h·b_s. Reproduced to round-off, step by step.
TEST(BDFOdeSolver, HigherOrdersFollowSofasHistoryHandling) {
  for (unsigned order : {2u, 3u}) {
    test::Oscillator o(bdf("order=\"" + std::to_string(order) + "\""), 0.05, 1.0);
    double x = 1, v = 0;
    for (int i = 0; i < 40; ++i) {
      o.step();
      const unsigned s = std::min<unsigned>(order, i + 1);
      const double bs = s == 1 ? 1.0 : s == 2 ? 2.0 / 3 : 6.0 / 11;
      backward_euler(x, v, 0.05 * bs);
      ASSERT_NEAR(o.x(), x, 1e-10) << "order " << order << " step " << i;
      ASSERT_NEAR(o.v(), v, 1e-10) << "order " << order << " step " << i;
    }
  }
}

TEST(BDFOdeSolver, NewtonConvergesOnANonlinearSpring) {
  // A stretched spring between two points (nonlinear in 3-D): several Newton
  // iterations, the squared residual decreasing quadratically.
  const std::string xml = R"(<Node gravity="0 -9.81 0" dt="0.01"><DefaultAnimationLoop/>
    <BDFOdeSolver order="2" rayleighMass="0.01" rayleighStiffness="0.01"/>
    <NewtonRaphsonSolver name="newton" maxNbIterationsNewton="10" absoluteResidualStoppingThreshold="1e-9"/>
    <EigenSimplicialLDLT template="CompressedRowSparseMatrix"/>
    <MechanicalObject name="dofs" position="0 0 0  1 1 0"/>
    <UniformMass totalMass="15"/>
    <SpringForceField spring="0 1 1000 0 1"/>
    <FixedProjectiveConstraint indices="0"/></Node>)";
  auto s = test::load(xml);
  auto* newton = test::get<NewtonRaphsonSolver>(*s.root, "newton");
  for (int i = 0; i < 20; ++i) animate(*s.root);
  EXPECT_NE(newton->status.value().find("Converged"), std::string::npos) << newton->status.value();
  const auto& graph = newton->residual_graph.value();
  ASSERT_GE(graph.size(), 3u);  // at least two iterations
  for (std::size_t i = 1; i < graph.size(); ++i) EXPECT_LT(graph[i], graph[i - 1]) << "iteration " << i;
  EXPECT_LT(graph.back(), 1e-10 * graph.front());
}

TEST(BDFOdeSolver, ExampleScenesRun) {
  namespace fs = std::filesystem;
  const fs::path data = SINEW_DATA_DIR;
  for (const char* rel : {"Component/ODESolver/Backward/BDFOdeSolver_spring1d.scn",
                          "Component/ODESolver/Backward/BDFOdeSolver_spring3d.scn"}) {
    const fs::path path = data / "examples" / rel;
    if (!fs::exists(path)) GTEST_SKIP() << "SOFA data not found at " << data;
    const test::Outcome o = test::run_scene_file(path.string(), 300);
    EXPECT_TRUE(o.init_ok) << rel << "\n" << o.all();
    EXPECT_EQ(o.steps, 300) << rel;
    EXPECT_TRUE(o.finite) << rel;
    EXPECT_TRUE(o.errors.empty()) << rel << "\n" << o.all();
  }
}

TEST(BDFOdeSolver, BadInputGivesClearMessages) {
  test::TempDir dir;
  auto scene = [](const std::string& solvers, const std::string& state = "") {
    return R"(<Node gravity="0 -9.81 0" dt="0.01"><DefaultAnimationLoop/>)" + solvers +
           (state.empty() ? std::string(R"(<MechanicalObject position="0 0 0  1 1 0"/>)") : state) +
           R"(<UniformMass totalMass="1"/></Node>)";
  };
  const std::string who = "(BDFOdeSolver)";
  {
    const auto o = test::run_xml(dir, scene(std::string("<BDFOdeSolver/>") + kLDLT));
    EXPECT_TRUE(test::any_contains_all(o.errors, {who, "NewtonRaphsonSolver is required"})) << o.all();
  }
  {
    const auto o = test::run_xml(dir, scene("<BDFOdeSolver/><NewtonRaphsonSolver/>"));
    EXPECT_TRUE(test::any_contains_all(o.errors, {who, "linear solver is required"})) << o.all();
  }
  {
    const auto o = test::run_xml(dir, scene(bdf("order=\"0\"")));
    EXPECT_TRUE(test::any_contains_all(o.warnings, {who, "order 0"})) << o.all();
    EXPECT_TRUE(o.errors.empty()) << o.all();
    EXPECT_EQ(o.steps, 5);
  }
  {
    const auto o = test::run_xml(
        dir, scene(bdf("order=\"2\""), R"(<MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>)"));
    EXPECT_TRUE(test::any_contains_all(o.errors, {who, "same layout"})) << o.all();
    test::expect_no_silent_garbage(o);
  }
}

}  // namespace
}  // namespace sinew
