// Assembled systems on real scenes (spec/solvers.md §0.2, §2.1–§2.5):
// assembled A against the matrix-free product on the FEMBAR grid, zero-factor
// skipping, mapped contributions JᵀKJ, automatic creation of linear systems,
// and whole-step agreement between direct, assembled CG and matrix-free CG.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "solver/system/constant_sparsity_pattern_system.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/matrix_linear_system.h"
#include "forcefield/spring/spring_force_field.h"
#include "solver/linear/sparse_ldl_solver.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::load;

namespace {

std::string fembar(const std::string& solver, const std::string& extra = "") {
  return R"(<Node name="root" dt="0.02" gravity="0 -10 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver name="ode" rayleighStiffness="0.1" rayleighMass="0.1"/>
    )" + extra + solver +
         R"(
    <MechanicalObject name="DoFs"/>
    <UniformMass name="mass" totalMass="320"/>
    <RegularGridTopology name="grid" nx="4" ny="4" nz="20" xmin="-9" xmax="-6" ymin="0" ymax="3" zmin="0" zmax="19"/>
    <BoxROI name="box" box="-10 -1 -0.0001  -5 4 0.0001"/>
    <FixedProjectiveConstraint name="fixed" indices="@box.indices"/>
    <HexahedronFEMForceField name="FEM" youngModulus="4000" poissonRatio="0.3" method="large"/>
  </Node>)";
}

MatrixLinearSolver* matrix_solver(Node& root) {
  for (LinearSolver* s : root.linear_solvers)
    if (auto* m = dynamic_cast<MatrixLinearSolver*>(s)) return m;
  return nullptr;
}

// Fills vector `id` of the independent states with random values (fixed DoFs zeroed by projection).
void randomize(MechanicalOps& ops, int id, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (MechanicalState* s : ops.independent_states())
    for (double& x : s->write(id)) x = u(rng);
}

Eigen::VectorXd gather(MechanicalOps& ops, int id) {
  std::vector<double> all;
  for (MechanicalState* s : ops.independent_states()) {
    const auto& v = s->read(id);
    all.insert(all.end(), v.begin(), v.end());
  }
  return Eigen::Map<Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size()));
}

// Compares the assembled A·dx with the matrix-free product P·(mM + bB + kK)·dx on a projected dx.
void expect_assembled_equals_matrix_free(Node& root, double m, double b, double k, unsigned seed) {
  MechanicalOps ops(root);
  MatrixLinearSolver* solver = matrix_solver(root);
  ASSERT_NE(solver, nullptr);
  solver->build_system(ops, m, b, k);
  const BlockCsrMatrix& A = solver->system()->matrix();
  const int dx = MechanicalOps::alloc_vec(), df = MechanicalOps::alloc_vec();
  randomize(ops, dx, seed);
  ops.project_response(dx);
  ops.propagate_dx_and_reset_df(dx, df);
  ops.add_mbk_dx(df, m, b, k, dx, /*clear=*/false);
  ops.project_response(df);
  const Eigen::VectorXd x = gather(ops, dx), ref = gather(ops, df);
  ASSERT_EQ(static_cast<std::size_t>(x.size()), A.size());
  Eigen::VectorXd y(x.size());
  A.mult(x.data(), y.data());
  EXPECT_LT((y - ref).norm(), 1e-12 * ref.norm()) << "m=" << m << " b=" << b << " k=" << k;
  EXPECT_GT(ref.norm(), 0.0);
}

std::vector<double> positions(Node& root) {
  MechanicalOps ops(root);
  return ops.independent_states().front()->write(kPosition);
}

}  // namespace

// ---------------------------------------------------------------- assembled vs matrix-free

TEST(LinsysAssembly, FembarMatrixEqualsMatrixFreeProductForBothStorages) {
  for (const char* tmpl : {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"}) {
    auto s = load(fembar(std::string("<SparseLDLSolver template=\"") + tmpl + "\"/>"));
    ASSERT_TRUE(s.root);
    Node& root = *s.root;
    for (int step = 0; step < 5; ++step) animate(root, 0.0);  // non-trivial corotational frames
    const double h = 0.02;
    expect_assembled_equals_matrix_free(root, 1 + h * 0.1, -h, -h * (h + 0.1), 1);
    expect_assembled_equals_matrix_free(root, 1, 0, 0, 2);   // mass only (stiffness skipped)
    expect_assembled_equals_matrix_free(root, 0, 0, -1, 3);  // stiffness only (mass skipped)
    EXPECT_EQ(matrix_solver(root)->system()->matrix().block_size(), std::string(tmpl).find("Mat3x3") != std::string::npos ? 3 : 1);
  }
}

TEST(LinsysAssembly, DirichletRowsAreIdentityAndPatternIsBuiltOnce) {
  auto s = load(fembar("<SparseLDLSolver template=\"CompressedRowSparseMatrixMat3x3\"/>"));
  Node& root = *s.root;
  for (int step = 0; step < 3; ++step) animate(root, 0.0);
  MatrixLinearSystem* sys = matrix_solver(root)->system();
  EXPECT_EQ(sys->assembler().pattern_builds(), 1);
  const Eigen::MatrixXd A = sys->matrix().to_dense();
  EXPECT_EQ(A.rows(), 960);
  EXPECT_EQ(sys->matrix_size.value(), VecNi<2>(960, 960));
  // The 16 points of the z = 0 face are fixed.
  MechanicalOps ops(root);
  const auto& x = ops.independent_states().front()->read(kPosition);
  int fixed = 0;
  for (int i = 0; i < 320; ++i) {
    if (std::abs(x[3 * i + 2]) > 1e-4) continue;
    ++fixed;
    for (int c = 0; c < 3; ++c) {
      const int r = 3 * i + c;
      EXPECT_EQ(A(r, r), 1.0);
      EXPECT_EQ(A.row(r).cwiseAbs().sum(), 1.0);
      EXPECT_EQ(A.col(r).cwiseAbs().sum(), 1.0);
    }
  }
  EXPECT_EQ(fixed, 16);
  EXPECT_LT((A - A.transpose()).cwiseAbs().maxCoeff(), 1e-12);
}

// Both storages: scalar CSR replays entry by entry, 3×3 block CSR block by
// block (MatrixSink::add_block), and both must notice the new entries.
TEST(LinsysAssembly, AChangedSequenceOfEntriesRebuildsThePattern) {
  for (const char* tmpl : {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"}) {
  SCOPED_TRACE(tmpl);
  auto s = load(fembar(std::string("<SparseLDLSolver template=\"") + tmpl + "\"/>"));
  ASSERT_TRUE(s.root);
  Node& root = *s.root;
  // A spring between two far points, added after the first assembly: its
  // entries are not in the recorded sequence, the replay must notice.
  auto springs = std::make_unique<SpringForceField>();
  SpringForceField* sp = springs.get();
  sp->name.set("late");
  MechanicalOps ops0(root);
  MatrixLinearSolver* solver = matrix_solver(root);
  solver->build_system(ops0, 1, 0, -1);
  EXPECT_EQ(solver->system()->assembler().pattern_builds(), 1);
  solver->build_system(ops0, 1, 0, -1);
  EXPECT_EQ(solver->system()->assembler().pattern_builds(), 1);  // replayed
  sp->spring.set(std::vector<double>{100, 300, 1000, 0, 4});
  root.add_object(std::move(springs));
  sp->init();
  animate(root, 0.0);  // the step's assembly meets the new entries (and the spring gets its stiffness)
  EXPECT_EQ(solver->system()->assembler().pattern_builds(), 2);
  MechanicalOps ops(root);
  solver->build_system(ops, 1, 0, -1);
  EXPECT_EQ(solver->system()->assembler().pattern_builds(), 2);  // replayed again
  expect_assembled_equals_matrix_free(root, 1, 0, -1, 5);
  EXPECT_NE(solver->system()->matrix().coeff(301, 902), 0.0);  // y–z coupling along the spring
  }
}

// ---------------------------------------------------------------- whole steps

TEST(LinsysAssembly, DirectAssembledCgAndMatrixFreeCgAgreeOverSteps) {
  auto run = [](const std::string& solver) {
    auto s = load(fembar(solver));
    for (int step = 0; step < 10; ++step) animate(*s.root, 0.0);
    return positions(*s.root);
  };
  const auto ldl = run("<NaturalOrderingMethod/><SparseLDLSolver template=\"CompressedRowSparseMatrixMat3x3\"/>");
  const auto ldl_scalar = run("<AMDOrderingMethod/><SparseLDLSolver/>");
  const auto llt = run("<EigenSimplicialLLT template=\"CompressedRowSparseMatrixMat3x3\"/>");
  const auto cg = run("<CGLinearSolver template=\"CompressedRowSparseMatrixMat3x3\" iterations=\"3000\" "
                      "tolerance=\"1e-14\" threshold=\"1e-30\"/>");
  const auto mf = run("<CGLinearSolver iterations=\"3000\" tolerance=\"1e-14\" threshold=\"1e-30\"/>");
  const auto start = [] {
    auto s = load(fembar("<SparseLDLSolver/>"));
    return positions(*s.root);
  }();
  double moved = 0;
  for (std::size_t i = 0; i < ldl.size(); ++i) {
    moved = std::max(moved, std::abs(ldl[i] - start[i]));
    EXPECT_NEAR(ldl_scalar[i], ldl[i], 1e-9);
    EXPECT_NEAR(llt[i], ldl[i], 1e-9);
    EXPECT_NEAR(cg[i], ldl[i], 1e-8);
    EXPECT_NEAR(mf[i], ldl[i], 1e-8);
  }
  EXPECT_GT(moved, 1e-3);  // the bar did bend
}

// ---------------------------------------------------------------- automatic linear systems (§2.2)

TEST(LinsysAutoSystem, CreatedWithTheSolverTemplateWhenAbsent) {
  auto s = load(fembar("<SparseLDLSolver name=\"ldl\" template=\"CompressedRowSparseMatrixMat3x3\"/>"));
  auto* sys = s.root->find_local<MatrixLinearSystem>();
  ASSERT_NE(sys, nullptr);
  EXPECT_EQ(sys->template_name(), "CompressedRowSparseMatrixMat3x3d");
  EXPECT_EQ(matrix_solver(*s.root)->system(), sys);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::info), "is created"));
}

TEST(LinsysAutoSystem, LinksAnExistingSystemOfTheSameTypeOnly) {
  auto s = load(fembar("<SparseLDLSolver name=\"ldl\"/>",
                       "<ConstantSparsityPatternSystem name=\"cs\"/>"));
  auto* cs = test::get<ConstantSparsityPatternSystem>(*s.root, "cs");
  ASSERT_NE(cs, nullptr);
  EXPECT_EQ(matrix_solver(*s.root)->system(), cs);

  auto t = load(fembar("<SparseLDLSolver name=\"ldl\" template=\"CompressedRowSparseMatrixMat3x3\"/>",
                       "<MatrixLinearSystem name=\"scalar\" template=\"CompressedRowSparseMatrix\"/>"));
  auto* scalar = test::get<MatrixLinearSystem>(*t.root, "scalar");
  ASSERT_NE(scalar, nullptr);
  EXPECT_NE(matrix_solver(*t.root)->system(), scalar);
  EXPECT_TRUE(test::any_contains(test::messages(t.root->diagnostics(), Severity::warning), "other linear systems"));
}

TEST(LinsysAutoSystem, ConstantPatternSystemGivesTheSameResultAsTheDefault) {
  auto a = load(fembar("<SparseLDLSolver/>", "<ConstantSparsityPatternSystem/>"));
  auto b = load(fembar("<SparseLDLSolver/>"));
  for (int step = 0; step < 5; ++step) {
    animate(*a.root, 0.0);
    animate(*b.root, 0.0);
  }
  const auto pa = positions(*a.root), pb = positions(*b.root);
  for (std::size_t i = 0; i < pa.size(); ++i) EXPECT_NEAR(pa[i], pb[i], 1e-12);
}

TEST(LinsysAutoSystem, AssemblyCanBeDisabledPerContribution) {
  auto s = load(fembar("<SparseLDLSolver/>", "<MatrixLinearSystem assembleStiffness=\"false\"/>"));
  MechanicalOps ops(*s.root);
  matrix_solver(*s.root)->build_system(ops, 2.0, 0.0, -1.0);
  const Eigen::MatrixXd A = matrix_solver(*s.root)->system()->matrix().to_dense();
  // Mass only: 2·m on free diagonals, 1 on fixed ones, nothing else.
  EXPECT_EQ((A - Eigen::MatrixXd(A.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_DOUBLE_EQ(A.diagonal().maxCoeff(), 2.0 * 1.0);
  EXPECT_DOUBLE_EQ(A.diagonal().minCoeff(), 1.0);
}

// ---------------------------------------------------------------- mapped contributions

TEST(LinsysMapped, MassOnARigidlyMappedStateIsProjectedAsJtMJ) {
  auto s = load(R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/>
    <SparseLDLSolver/>
    <MechanicalObject name="rigid" template="Rigid3d" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/>
    <UniformMass name="rmass" vertexMass="1 1 1 0 0 0 1 0 0 0 1"/>
    <Node name="child">
      <MechanicalObject name="points" position="1 0 0  0 2 0  0 0 3  1 1 1"/>
      <RigidMapping name="map" globalToLocalCoords="false" rigidIndexPerPoint="0 0 1 1"/>
      <UniformMass name="pmass" vertexMass="0.5"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  expect_assembled_equals_matrix_free(*s.root, 1.0, 0.0, 0.0, 4);
  // The rigid translational block holds the rigid mass plus the mapped point masses.
  const Eigen::MatrixXd A = matrix_solver(*s.root)->system()->matrix().to_dense();
  ASSERT_EQ(A.rows(), 12);
  EXPECT_NEAR(A(0, 0), 1.0 + 2 * 0.5, 1e-12);
  EXPECT_NEAR(A(6, 6), 1.0 + 2 * 0.5, 1e-12);
}

// SOFA's MatrixProjectionMethod projects a block between a mapped state and a
// state outside the system (an obstacle's contact points) over the independent
// states the mapped side reaches, with no Jacobian on the outside side: K₁₂ and
// K₂₁ land at the outside state's own indices, K₂₂ nowhere.
// BeamFEMForceField.scn (floor contacts, BTD solver) matches SOFA through this.
TEST(LinsysMapped, CouplingWithAStateOutsideTheSystemLandsAtThatStatesOwnIndices) {
  auto s = load(R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <Node name="sim">
      <EulerImplicitSolver/>
      <SparseLDLSolver/>
      <MechanicalObject name="top" position="0 0 0  1 0 0  2 0 0"/>
      <UniformMass vertexMass="1"/>
      <Node name="child">
        <MechanicalObject name="m" position="0 0 0  1 0 0  2 0 0"/>
        <IdentityMapping/>
      </Node>
      <SpringForceField name="spring" object1="@child/m" object2="@../obstacle/o" spring="2 0 100 0 1"/>
    </Node>
    <Node name="obstacle">
      <MechanicalObject name="o" position="2 2 1"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  Node* sim = s.root->find_child_named("sim");
  ASSERT_NE(sim, nullptr);
  MechanicalOps ops(*sim);
  MatrixLinearSolver* solver = matrix_solver(*sim);
  ASSERT_NE(solver, nullptr);
  ops.compute_force(MechanicalOps::alloc_vec());  // the spring's tangent is that of its last force
  solver->build_system(ops, 0.0, 0.0, 1.0);
  const Eigen::MatrixXd A = solver->system()->matrix().to_dense();
  ASSERT_EQ(A.rows(), 9);
  const Eigen::Matrix3d k11 = A.block<3, 3>(6, 6);  // spring end on the top's point 2
  EXPECT_GT(k11.cwiseAbs().maxCoeff(), 10.0);
  // K₁₂ = −K₁₁ at columns 0..2 (the obstacle's point 0), K₂₁ at rows 0..2.
  EXPECT_LT((A.block<3, 3>(6, 0) + k11).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((A.block<3, 3>(0, 6) + k11).cwiseAbs().maxCoeff(), 1e-12);
  // No K₂₂, nothing on point 1.
  EXPECT_EQ((A.block<3, 3>(0, 0).cwiseAbs().maxCoeff()), 0.0);
  EXPECT_EQ((A.block<3, 9>(3, 0).cwiseAbs().maxCoeff()), 0.0);
}

// The same rule between two bodies (SOFA 2a278d8, fixed upstream later): a
// block between states mapped from different independent states P1 and P2 is
// projected for every pair of {P1, P2}; a side that does not reach a state
// takes no Jacobian. With identity mappings each coupling block K₁₂ and K₂₁
// lands in all four blocks of the system.
TEST(LinsysMapped, CouplingBetweenStatesOfTwoBodiesIsProjectedOverBothBodies) {
  auto s = load(R"(<Node name="root" dt="0.01" gravity="0 0 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver/>
    <SparseLDLSolver/>
    <Node name="P1">
      <MechanicalObject name="dofs" position="0 0 0"/>
      <UniformMass vertexMass="1"/>
      <Node name="M1"><MechanicalObject name="dofs" position="0 0 0"/><IdentityMapping/></Node>
    </Node>
    <Node name="P2">
      <MechanicalObject name="dofs" position="2 1 0"/>
      <UniformMass vertexMass="1"/>
      <Node name="M2"><MechanicalObject name="dofs" position="2 1 0"/><IdentityMapping/></Node>
    </Node>
    <SpringForceField object1="@P1/M1/dofs" object2="@P2/M2/dofs" spring="0 0 100 0 1"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  MechanicalOps ops(*s.root);
  MatrixLinearSolver* solver = matrix_solver(*s.root);
  ASSERT_NE(solver, nullptr);
  ops.compute_force(MechanicalOps::alloc_vec());
  solver->build_system(ops, 0.0, 0.0, 1.0);
  const Eigen::MatrixXd A = solver->system()->matrix().to_dense();
  ASSERT_EQ(A.rows(), 6);
  // K₁₁ = K₂₂ = k, K₁₂ = K₂₁ = −k: each block holds its own term plus K₁₂ + K₂₁.
  const Eigen::Matrix3d k = -A.block<3, 3>(0, 3) / 2;
  EXPECT_GT(k.cwiseAbs().maxCoeff(), 10.0);
  EXPECT_LT((A.block<3, 3>(0, 0) - (k - 2 * k)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((A.block<3, 3>(3, 0) + 2 * k).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((A.block<3, 3>(3, 3) - (k - 2 * k)).cwiseAbs().maxCoeff(), 1e-12);
}
