// Once warm, a constraint solve with the same constraints allocates nothing
// (SOFA's per-step work vectors are kept by the solvers and corrections).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "alloc_counter.h"
#include "constraint/solver/lcp_constraint_solver.h"
#include "constraint_test_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "test_scene.h"

namespace sinew {
namespace {

std::string chain(const std::string& solver) {
  return R"(<Node name="root" dt="0.01" gravity="0 -10 0">
    <FreeMotionAnimationLoop/>
    )" + solver + R"(
    <Node name="anchor"><MechanicalObject name="x" position="0 0 0"/></Node>
    <Node name="body">
      <EulerImplicitSolver/>
      <SparseLDLSolver/>
      <MechanicalObject name="x" position="0.1 0 0  0.3 0 0"/>
      <UniformMass totalMass="2"/>
      <UncoupledConstraintCorrection defaultCompliance="1"/>
    </Node>
    <BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="0"/>
    <BilateralLagrangianConstraint object1="@body/x" object2="@body/x" first_point="0" second_point="1"
                                   rest_vector="0.2 0 0"/>
  </Node>)";
}

long allocations_of_one_solve(Node& root, const char* solver_name) {
  auto* solver = dynamic_cast<ConstraintSolver*>(root.find_object_named(solver_name));
  EXPECT_NE(solver, nullptr);
  if (!solver) return -1;
  ConstraintParams p;
  p.dt = 0.01;
  solver->solve_constraint(p, kPosition, kVelocity);  // warm
  {
    // The counter works (else the test below would pass vacuously).
    const long c0 = test::g_allocations.load();
    auto probe = std::make_unique<std::vector<double>>(100);
    EXPECT_GT(test::g_allocations.load(), c0);
  }
  const long before = test::g_allocations.load();
  solver->solve_constraint(p, kPosition, kVelocity);
  return test::g_allocations.load() - before;
}

TEST(ConstraintAllocations, GenericSolversSteadyStateAllocateNothing) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counter not installed (sanitizer build)";
  for (const char* solver : {R"(<BlockGaussSeidelConstraintSolver name="s"/>)", R"(<NNCGConstraintSolver name="s"/>)",
                             R"(<UnbuiltGaussSeidelConstraintSolver name="s"/>)",
                             R"(<ImprovedJacobiConstraintSolver name="s"/>)"}) {
    scene::LoadedScene s = test::load(chain(solver));
    ASSERT_TRUE(s.root);
    for (int i = 0; i < 3; ++i) animate(*s.root);
    EXPECT_EQ(allocations_of_one_solve(*s.root, "s"), 0) << solver;
  }
}

TEST(ConstraintAllocations, LcpSteadyStateAllocatesNothing) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counter not installed (sanitizer build)";
  for (const char* build : {"1", "0"}) {
    scene::LoadedScene s = test::load(std::string(R"(<Node name="root" dt="0.01" gravity="0 0 -10">
      <FreeMotionAnimationLoop/>
      <LCPConstraintSolver name="s" build_lcp=")") + build + R"(" mu="0.5" initial_guess="1"/>
      <Node name="body">
        <EulerImplicitSolver/>
        <SparseLDLSolver/>
        <MechanicalObject name="x" position="0 0 0  1 0 0"/>
        <UniformMass totalMass="2"/>
        <UncoupledConstraintCorrection useOdeSolverIntegrationFactors="0"/>
      </Node>
    </Node>)");
    ASSERT_TRUE(s.root);
    Node* body = s.root->find_child_named("body");
    auto c = std::make_unique<test::PlaneContacts>();
    c->state = body->get_mechanical_state();
    c->friction = true;
    c->contacts.resize(2);
    c->contacts[1].dof = 1;
    c->contacts[0].id = 1;
    c->contacts[1].id = 2;
    body->add_object(std::move(c));
    for (int i = 0; i < 3; ++i) animate(*s.root);
    EXPECT_EQ(allocations_of_one_solve(*s.root, "s"), 0) << "build_lcp=" << build;
  }
}

}  // namespace
}  // namespace sinew
