// Issue 4: "assembly must not allocate after the first step". The heap is
// observed by interposing malloc/calloc/realloc in this test binary (glibc
// exports the real allocator as __libc_*); operator new and Eigen's aligned
// allocations both go through malloc. Also checks mapped assembly (JᵀKJ
// through a chain of three mappings, with geometric stiffness) against the
// matrix-free product while the values change from step to step, and that
// whole implicit steps (matrix-free CG, assembled CG, SparseLDL) allocate
// nothing once settled.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdlib>
#include <random>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/matrix_linear_system.h"
#include "test_scene.h"

#include "alloc_counter.h"

using namespace sinew;
using sinew::test::g_allocations;
using sinew::test::load;

namespace {

MatrixLinearSolver* matrix_solver(Node& root) {
  for (LinearSolver* s : root.linear_solvers)
    if (auto* m = dynamic_cast<MatrixLinearSolver*>(s)) return m;
  return nullptr;
}

// Heap allocations made by one assembly of the solver's system.
long allocations_of_one_assembly(MatrixLinearSolver& solver, MechanicalOps& ops) {
  const long before = g_allocations.load();
  solver.build_system(ops, 1.01, -0.02, -0.0004);
  return g_allocations.load() - before;
}

// Two spinning rigid bodies; points attached by RigidMapping; a subset of
// them (SubsetMapping, a second mapping level) joined by springs across the
// bodies; three distances between them (DistanceMapping, a third level,
// non-linear: geometric stiffness) held at their rest lengths.
const char* kMappedScene = R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
  <SparseLDLSolver template="CompressedRowSparseMatrixd"/>
  <Node name="bodies">
    <MechanicalObject name="rigid" template="Rigid3d" position="0 0 0 0 0 0 1  2 0 0 0 0 0 1"
                      velocity="0 0 0 0.5 1 0.2  0 0 0 -0.3 0.4 1"/>
    <UniformMass name="rmass" vertexMass="1 1 1 0 0 0 1 0 0 0 1"/>
    <Node name="points">
      <MechanicalObject name="p" position="0.5 0 0  0 0.5 0  0 0 0.5  2.5 0 0  2 0.5 0  2 0 0.5"/>
      <RigidMapping globalToLocalCoords="false" rigidIndexPerPoint="0 0 0 1 1 1"/>
      <UniformMass vertexMass="0.1"/>
      <Node name="subset">
        <MechanicalObject name="s"/>
        <SubsetMapping indices="0 1 3 4"/>
        <SpringForceField spring="0 2 500 1 2  1 3 500 1 2"/>
        <EdgeSetTopologyContainer edges="0 2  1 3  0 1"/>
        <Node name="lengths">
          <MechanicalObject name="d" template="Vec1d"/>
          <DistanceMapping/>
          <RestShapeSpringsForceField stiffness="300"/>
        </Node>
      </Node>
    </Node>
  </Node>
</Node>)";

}  // namespace

TEST(LinsysAllocation, TheCounterSeesHeapAllocations) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "no allocation counter under AddressSanitizer";
  const long before = g_allocations.load();
  auto* p = new std::vector<double>(100);
  const long after = g_allocations.load();
  delete p;
  EXPECT_GE(after - before, 2);
}

TEST(LinsysAllocation, UnmappedAssemblyDoesNotAllocateAfterTheFirstStep) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "no allocation counter under AddressSanitizer";
  auto s = load(R"(<Node name="root" dt="0.02" gravity="0 -10 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <SparseLDLSolver template="CompressedRowSparseMatrixMat3x3d"/>
    <MechanicalObject/>
    <UniformMass totalMass="320"/>
    <RegularGridTopology nx="4" ny="4" nz="20" xmin="-9" xmax="-6" ymin="0" ymax="3" zmin="0" zmax="19"/>
    <BoxROI name="box" box="-10 -1 -0.0001  -5 4 0.0001"/>
    <FixedProjectiveConstraint indices="@box.indices"/>
    <HexahedronFEMForceField youngModulus="4000" poissonRatio="0.3" method="large"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  MatrixLinearSolver* solver = matrix_solver(*s.root);
  ASSERT_NE(solver, nullptr);
  MechanicalOps ops(*s.root);
  // The first assembly builds the pattern (and shows the counter works).
  EXPECT_GT(allocations_of_one_assembly(*solver, ops), 0);
  for (int step = 0; step < 3; ++step) {
    animate(*s.root, 0.0);
    EXPECT_EQ(allocations_of_one_assembly(*solver, ops), 0) << "step " << step;
  }
}

TEST(LinsysAllocation, MappedAssemblyDoesNotAllocateAfterTheFirstStepAndMatchesTheMatrixFreeProduct) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "no allocation counter under AddressSanitizer";
  auto s = load(kMappedScene);
  ASSERT_TRUE(s.root);
  MatrixLinearSolver* solver = matrix_solver(*s.root);
  ASSERT_NE(solver, nullptr);
  MechanicalOps ops(*s.root);
  const int dx = MechanicalOps::alloc_vec(), df = MechanicalOps::alloc_vec();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd previous;
  for (int step = 0; step < 6; ++step) {
    if (step > 0) animate(*s.root, 0.0);
    const long allocations = allocations_of_one_assembly(*solver, ops);
    if (step == 0) {
      EXPECT_GT(allocations, 0);  // patterns built
    } else {
      EXPECT_EQ(allocations, 0) << "step " << step;
    }
    const BlockCsrMatrix& A = solver->system()->matrix();
    ASSERT_EQ(A.size(), 12u);

    // A·dx against P·(mM + bB + kK)·dx through the mappings.
    for (MechanicalState* st : ops.independent_states())
      for (double& x : st->write(dx)) x = u(rng);
    ops.project_response(dx);
    ops.propagate_dx_and_reset_df(dx, df);
    ops.add_mbk_dx(df, 1.01, -0.02, -0.0004, dx, /*clear=*/false);
    ops.project_response(df);
    const auto& x = ops.independent_states().front()->read(dx);
    const auto& ref = ops.independent_states().front()->read(df);
    std::vector<double> y(12);
    A.mult(x.data(), y.data());
    double err = 0, norm = 0;
    for (int i = 0; i < 12; ++i) {
      err = std::max(err, std::abs(y[i] - ref[i]));
      norm = std::max(norm, std::abs(ref[i]));
    }
    EXPECT_LT(err, 1e-12 * norm) << "step " << step;
    EXPECT_GT(norm, 0.0);
    // The bodies spin: the mapped contributions change from step to step.
    const Eigen::MatrixXd dense = A.to_dense();
    if (step > 0) {
      EXPECT_GT((dense - previous).cwiseAbs().maxCoeff(), 1e-6) << "step " << step;
    }
    previous = dense;
  }
  EXPECT_EQ(solver->system()->assembler().mapped_pattern_builds(), 1);
}

// Whole implicit steps, once the pattern of the assembled matrix has settled
// (the first steps of a corotational beam turn exact zeros into non-zeros,
// which changes the filtered pattern SparseLDL factorises, as in SOFA).
TEST(LinsysAllocation, SteadyImplicitStepsDoNotAllocate) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "no allocation counter under AddressSanitizer";
  const std::string cg = R"(<CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-9"/>)";
  const std::string hexa = R"(<HexahedronFEMForceField youngModulus="4000" poissonRatio="0.3" method="large"/>)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {cg, hexa},
      {R"(<CGLinearSolver template="CompressedRowSparseMatrixMat3x3d" iterations="25" tolerance="1e-9" threshold="1e-9"/>)",
       hexa},
      {R"(<SparseLDLSolver template="CompressedRowSparseMatrixMat3x3d"/>)", hexa},
      // von Mises stresses are recomputed at the end of every step.
      {cg, R"(<TetrahedronFEMForceField youngModulus="4000" poissonRatio="0.3" computeVonMisesStress="1"/>)"}};
  for (const auto& [solver, forcefield] : cases) {
    auto s = load(R"(<Node name="root" dt="0.02" gravity="0 -10 0">
      <DefaultAnimationLoop/>
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>)" +
                  solver + R"(
      <MechanicalObject/>
      <UniformMass totalMass="320"/>
      <RegularGridTopology nx="4" ny="4" nz="20" xmin="-9" xmax="-6" ymin="0" ymax="3" zmin="0" zmax="19"/>
      <BoxROI name="box" box="-10 -1 -0.0001  -5 4 0.0001"/>
      <FixedProjectiveConstraint indices="@box.indices"/>
      )" + forcefield + R"(
    </Node>)");
    ASSERT_TRUE(s.root);
    for (int step = 0; step < 10; ++step) animate(*s.root, 0.0);
    for (int step = 10; step < 15; ++step) {
      const long before = g_allocations.load();
      animate(*s.root, 0.0);
      EXPECT_EQ(g_allocations.load() - before, 0) << solver << forcefield << " step " << step;
    }
  }
}
