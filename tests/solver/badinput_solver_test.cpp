// Bad-input audit, solvers: singular linear systems (nothing fixed, no mass,
// direct solvers), negative stiffness, diverging explicit integration. Each
// case: a message naming the solver, no NaNs in the states without an error,
// no crash.
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

// Two tetrahedra, nothing fixed, a constant force: K is singular (rigid modes).
std::string static_free(const std::string& linear_solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <StaticSolver name="static"/>
  <NewtonRaphsonSolver name="newton" maxNbIterationsNewton="3"/>
  )" + linear_solver + R"(
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 0  1 1 1"/>
  <MeshTopology name="topo" tetrahedra="0 1 2 3  1 4 2 5"/>
  <TetrahedronFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3" method="small"/>
  <ConstantForceField name="cf" indices="5" forces="0 0 1"/>
</Node>)";
}

// Implicit Euler without mass (vertexMass 0) and nothing fixed: singular too.
std::string implicit_massless(const std::string& linear_solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver name="ode" rayleighStiffness="0" rayleighMass="0"/>
  )" + linear_solver + R"(
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 0  1 1 1"/>
  <MeshTopology name="topo" tetrahedra="0 1 2 3  1 4 2 5"/>
  <UniformMass name="mass" vertexMass="0"/>
  <TetrahedronFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3" method="small"/>
  <ConstantForceField name="cf" indices="5" forces="0 0 1"/>
</Node>)";
}

struct SolverCase {
  const char* name;
  const char* xml;
};
std::ostream& operator<<(std::ostream& os, const SolverCase& c) { return os << c.name; }

class BadInputSolver : public ::testing::TestWithParam<SolverCase> {
 protected:
  TempDir dir;
};

bool mentions(const Outcome& o, std::string_view who) {
  for (const auto& s : o.problems())
    if (s.find(who) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_P(BadInputSolver, SingularStaticSystemGivesASolverMessageNotNaNs) {
  const SolverCase& c = GetParam();
  const Outcome o = run_xml(dir, static_free(c.xml), 3);
  EXPECT_TRUE(mentions(o, std::string("component 'lin' (") + c.name + ")") ||
              mentions(o, "component 'static' (StaticSolver)") || mentions(o, "(NewtonRaphsonSolver)"))
      << "a singular system must be reported:\n"
      << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputSolver, SingularImplicitSystemGivesASolverMessageNotNaNs) {
  const SolverCase& c = GetParam();
  const Outcome o = run_xml(dir, implicit_massless(c.xml), 3);
  EXPECT_TRUE(mentions(o, std::string("component 'lin' (") + c.name + ")") ||
              mentions(o, "component 'ode' (EulerImplicitSolver)") || mentions(o, "component 'mass' (UniformMass)"))
      << "a singular system must be reported:\n"
      << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputSolver, NegativeStiffnessIsNotSilentGarbage) {
  const SolverCase& c = GetParam();
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.1" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver name="ode" rayleighStiffness="0" rayleighMass="0"/>
  )" + std::string(c.xml) + R"(
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
  <UniformMass name="mass" totalMass="0.001"/>
  <FixedProjectiveConstraint indices="0"/>
  <SpringForceField name="springs" spring="0 1 -1e6 0 1  1 2 -1e6 0 1  2 3 -1e6 0 1"/>
</Node>)",
                            50);
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'springs' (SpringForceField)", "negative stiffness"}) ||
              mentions(o, std::string("component 'lin' (") + c.name + ")"))
      << "negative stiffness must be reported:\n"
      << o.all();
  expect_no_silent_garbage(o);
}

INSTANTIATE_TEST_SUITE_P(
    All, BadInputSolver,
    ::testing::Values(
        SolverCase{"SparseLDLSolver", R"(<SparseLDLSolver name="lin" template="CompressedRowSparseMatrixMat3x3d"/>)"},
        SolverCase{"EigenSimplicialLDLT", R"(<EigenSimplicialLDLT name="lin" template="CompressedRowSparseMatrixMat3x3d"/>)"},
        SolverCase{"EigenSparseLU", R"(<EigenSparseLU name="lin" template="CompressedRowSparseMatrixMat3x3d"/>)"},
        SolverCase{"CGLinearSolver", R"(<CGLinearSolver name="lin" iterations="100" tolerance="1e-12" threshold="1e-20"/>)"}),
    [](const ::testing::TestParamInfo<SolverCase>& info) { return std::string(info.param.name); });

TEST(BadInputExplicit, DivergingEulerExplicitStopsWithAnError) {
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.1" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <EulerExplicitSolver name="ode" symplectic="false"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
  <UniformMass name="mass" totalMass="0.001"/>
  <FixedProjectiveConstraint indices="0"/>
  <SpringForceField name="springs" spring="0 1 1e6 0 1  1 2 1e6 0 1  2 3 1e6 0 1"/>
</Node>)",
                            2000);
  // Named with the step where it happened (the last step done).
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'ode' (EulerExplicitSolver)",
                                          "diverged at step " + std::to_string(o.steps - 1) + ","}))
      << o.all();
  EXPECT_LT(o.steps, 2000);
  // Reported once, not once per step.
  int n = 0;
  for (const auto& e : o.errors) n += e.find("diverged") != std::string::npos;
  EXPECT_EQ(n, 1) << o.all();
}

TEST(BadInputExplicit, DivergingRungeKutta4StopsWithAnError) {
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.1" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <RungeKutta4Solver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
  <UniformMass name="mass" totalMass="0.001"/>
  <FixedProjectiveConstraint indices="0"/>
  <SpringForceField name="springs" spring="0 1 1e6 0 1  1 2 1e6 0 1  2 3 1e6 0 1"/>
</Node>)",
                            2000);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'ode' (RungeKutta4Solver)",
                                          "diverged at step " + std::to_string(o.steps - 1) + ","}))
      << o.all();
  EXPECT_LT(o.steps, 2000);
}

TEST(BadInputExplicit, DivergingRungeKutta2StopsWithAnError) {
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.1" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <RungeKutta2Solver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
  <UniformMass name="mass" totalMass="0.001"/>
  <FixedProjectiveConstraint indices="0"/>
  <SpringForceField name="springs" spring="0 1 1e6 0 1  1 2 1e6 0 1  2 3 1e6 0 1"/>
</Node>)",
                            2000);
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'ode' (RungeKutta2Solver)",
                                          "diverged at step " + std::to_string(o.steps - 1) + ","}))
      << o.all();
  EXPECT_LT(o.steps, 2000);
}

TEST(BadInputExplicit, DivergingImplicitWithNegativeDtIsNotSilent) {
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="-0.1" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver name="ode"/>
  <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
  <FixedProjectiveConstraint indices="0"/>
  <SpringForceField name="springs" spring="0 1 100 0 1  1 2 100 0 1  2 3 100 0 1"/>
</Node>)",
                            50);
  expect_no_silent_garbage(o);
}

TEST(BadInputExplicit, NonFiniteForceIsNotSilent) {
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <EulerExplicitSolver name="ode"/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
  <UniformMass name="mass" totalMass="1"/>
  <ConstantForceField name="cf" indices="1" forces="inf 0 0"/>
</Node>)",
                            5);
  // "inf" is not read (SOFA's stream would not read it either): a warning names the field.
  EXPECT_TRUE(any_contains_all(o.problems(), {"component 'cf' (ConstantForceField)", "forces", "inf"})) << o.all();
  expect_no_silent_garbage(o);
}
