// Iterative solvers (spec/solvers.md §3.2, §3.3) driven through the
// matrix-free mechanical operations: PCGLinearSolver (with every
// preconditioner) and MinResLinearSolver against a dense reference solve on
// random SPD systems, applied by a test force field holding a dense matrix.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/rotation_finder.h"
#include "solver/system/composite_linear_system.h"
#include "solver/linear/min_res_linear_solver.h"
#include "solver/linear/pcg_linear_solver.h"
#include "solver/preconditioner/precomputed_warp_preconditioner.h"
#include "solver/system/rotation_matrix_system.h"
#include "solver/preconditioner/warp_preconditioner.h"
#include "test_scene.h"

using namespace sinew;

namespace {

Eigen::MatrixXd random_spd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pick(0.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (pick(rng) < 0.2) A(i, j) = A(j, i) = u(rng);
  // Varied scales make preconditioning matter.
  for (int i = 0; i < n; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 0.1 + 10.0 * pick(rng);
  return A;
}

// A force field whose stiffness is a given dense matrix K (df += kfactor·K·dx);
// also a rotation finder with identity rotations (for the Warp preconditioner).
class DenseMatrixForceField final : public ForceField, public RotationFinder {
 public:
  Eigen::MatrixXd K;
  Mat3 rotation = Mat3::Identity();  // the same rotation for every point
  void node_rotations(std::span<Mat3> out) const override {
    for (Mat3& m : out) m = rotation;
  }
  MechanicalState* rotation_state() const override { return mstate.get(); }
  void add_force(const MechParams&) override {}
  void add_dforce(const MechParams& p, double kfactor) override {
    const auto& dx = mstate->read(p.dx);
    auto& df = mstate->write(p.df);
    const Eigen::Index n = K.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
      double s = 0;
      for (Eigen::Index j = 0; j < n; ++j) s += K(i, j) * dx[static_cast<std::size_t>(j)];
      df[static_cast<std::size_t>(i)] += kfactor * s;
    }
  }
  bool build_stiffness(MatrixSink& S) override {
    for (Eigen::Index i = 0; i < K.rows(); ++i)
      for (Eigen::Index j = 0; j < K.cols(); ++j)
        if (K(i, j) != 0.0) S.add(mstate.get(), static_cast<std::size_t>(i), mstate.get(), static_cast<std::size_t>(j), K(i, j));
    return true;
  }
};

std::string positions(int points) {
  std::string s;
  for (int i = 0; i < points; ++i) s += std::to_string(i) + " 0 0 ";
  return s;
}

// A scene with `points` Vec3d DoFs, the solver components of `solvers_xml` and
// a DenseMatrixForceField holding A; solves A·x = b with the first linear solver.
struct MatrixFreeScene {
  scene::LoadedScene s;
  DenseMatrixForceField* ff = nullptr;
  std::unique_ptr<MechanicalOps> ops;
  int x = -1, b = -1;

  MatrixFreeScene(const Eigen::MatrixXd& A, const std::string& solvers_xml, std::string extra_ff_xml = {},
                  std::string pos = {}) {
    const int points = static_cast<int>(A.rows() / 3);
    if (pos.empty()) pos = positions(points);
    s = test::build("<Node name='root' dt='0.01'><DefaultAnimationLoop/><MechanicalObject name='dofs' position='" +
                    pos + "'/>" + solvers_xml + extra_ff_xml + "</Node>");
    auto f = std::make_unique<DenseMatrixForceField>();
    f->K = A;
    f->set_type("DenseMatrixForceField", "");
    f->name.set("K");
    ff = static_cast<DenseMatrixForceField*>(s.root->add_object(std::move(f)));
    init_root(*s.root);
    ops = std::make_unique<MechanicalOps>(*s.root);
    x = MechanicalOps::alloc_vec();
    b = MechanicalOps::alloc_vec();
  }
  LinearSolver& solver() { return *s.root->linear_solvers.front(); }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs, const Eigen::VectorXd* guess = nullptr) {
    MechanicalState* st = s.root->mechanical_state;
    auto& bv = st->write(b);
    auto& xv = st->write(x);
    for (Eigen::Index i = 0; i < rhs.size(); ++i) {
      bv[static_cast<std::size_t>(i)] = rhs[i];
      xv[static_cast<std::size_t>(i)] = guess ? (*guess)[i] : 0.0;
    }
    solver().build_system(*ops, 0.0, 0.0, 1.0);
    solver().solve_system(*ops, x, b);
    Eigen::VectorXd out(rhs.size());
    for (Eigen::Index i = 0; i < rhs.size(); ++i) out[i] = xv[static_cast<std::size_t>(i)];
    return out;
  }
};

Eigen::VectorXd random_vec(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = g(rng);
  return v;
}

}  // namespace

class PcgPreconditioned : public ::testing::TestWithParam<std::string> {};

TEST_P(PcgPreconditioned, MatchesDenseSolveOnRandomSpdSystems) {
  const std::string& prec = GetParam();
  std::string xml;
  if (prec == "none") xml = "<PCGLinearSolver name='pcg' iterations='1000' tolerance='1e-26'/>";
  else if (prec == "use_precond_false")
    xml = "<PCGLinearSolver name='pcg' iterations='1000' tolerance='1e-26' preconditioner='@p' use_precond='false'/>"
          "<JacobiPreconditioner name='p'/>";
  else if (prec == "Warp")
    xml = "<PCGLinearSolver name='pcg' iterations='1000' tolerance='1e-26' preconditioner='@p'/>"
          "<RotationMatrixSystem name='R'/><WarpPreconditioner name='p' linearSystem='@R' linearSolver='@ldl'/>"
          "<MatrixLinearSystem template='CompressedRowSparseMatrixMat3x3' name='sys'/>"
          "<SparseLDLSolver name='ldl' template='CompressedRowSparseMatrixMat3x3' linearSystem='@sys'/>";
  else
    xml = "<PCGLinearSolver name='pcg' iterations='1000' tolerance='1e-26' preconditioner='@p'/><" + prec +
          " name='p'/>";
  for (int n : {3, 30, 90}) {
    const Eigen::MatrixXd A = random_spd(n, static_cast<unsigned>(n + 7));
    const Eigen::VectorXd b = random_vec(n, static_cast<unsigned>(n));
    const Eigen::VectorXd ref = A.ldlt().solve(b);
    MatrixFreeScene sc(A, xml);
    auto* pcg = dynamic_cast<PCGLinearSolver*>(&sc.solver());
    ASSERT_NE(pcg, nullptr);
    ASSERT_EQ(pcg->state(), ComponentState::valid);
    const Eigen::VectorXd x = sc.solve(b);
    EXPECT_LT((x - ref).norm(), 1e-9 * ref.norm()) << prec << " n=" << n;
    if (prec == "Warp") {
      EXPECT_EQ(pcg->last_iterations(), 1) << "an exact preconditioner converges in one step";
    }
    // Warm start: starting from the solution, no iteration is needed.
    const Eigen::VectorXd x2 = sc.solve(b, &ref);
    EXPECT_LE(pcg->last_iterations(), 1) << prec;
    EXPECT_LT((x2 - ref).norm(), 1e-9 * ref.norm());
  }
}

INSTANTIATE_TEST_SUITE_P(All, PcgPreconditioned,
                         ::testing::Values("none", "use_precond_false", "JacobiPreconditioner",
                                           "BlockJacobiPreconditioner", "SSORPreconditioner", "Warp"));

TEST(PcgSolver, PreconditioningReducesIterationsOnABadlyScaledSystem) {
  // Diagonal scaling over 6 orders of magnitude: Jacobi makes it trivial.
  const int n = 30;
  Eigen::MatrixXd A = random_spd(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = std::pow(10.0, (i % 7) - 3.0);
    A.row(i) *= s;
    A.col(i) *= s;
  }
  const Eigen::VectorXd b = random_vec(n, 5);
  MatrixFreeScene plain(A, "<PCGLinearSolver iterations='1000' tolerance='1e-20'/>");
  plain.solve(b);
  MatrixFreeScene jac(A, "<PCGLinearSolver iterations='1000' tolerance='1e-20' preconditioner='@p'/>"
                         "<JacobiPreconditioner name='p'/>");
  jac.solve(b);
  const int it_plain = dynamic_cast<PCGLinearSolver&>(plain.solver()).last_iterations();
  const int it_jac = dynamic_cast<PCGLinearSolver&>(jac.solver()).last_iterations();
  EXPECT_LT(it_jac, it_plain);
}

TEST(PcgSolver, StopsOnTheSquaredPreconditionedResidualRatio) {
  const int n = 30;
  const Eigen::MatrixXd A = random_spd(n, 11);
  const Eigen::VectorXd b = random_vec(n, 12);
  MatrixFreeScene sc(A, "<PCGLinearSolver iterations='1000' tolerance='1e-6'/>");
  const Eigen::VectorXd x = sc.solve(b);
  auto& pcg = dynamic_cast<PCGLinearSolver&>(sc.solver());
  const auto& err = pcg.last_errors();
  ASSERT_GE(err.size(), 2u);
  EXPECT_LE(err.back(), 1e-6);
  EXPECT_GT(err[err.size() - 2], 1e-6);  // the previous iterate had not converged
  const Eigen::VectorXd r = b - A * x;
  EXPECT_NEAR(r.squaredNorm() / b.squaredNorm(), err.back(), 1e-12);
  EXPECT_EQ(static_cast<int>(err.size()), pcg.last_iterations() + 1);
}

TEST(PcgSolver, ZeroPreconditionerStopsAtOnceAndLeavesTheGuess) {
  // PrecomputedWarpPreconditioner on its default (never assembled) system: z = 0 ⇒ zero iterations.
  const int n = 12;
  const Eigen::MatrixXd A = random_spd(n, 1);
  MatrixFreeScene sc(A, "<PCGLinearSolver iterations='1000' preconditioner='@p'/>"
                        "<PrecomputedWarpPreconditioner name='p' use_file='false'/>");
  const Eigen::VectorXd guess = random_vec(n, 2);
  const Eigen::VectorXd x = sc.solve(random_vec(n, 3), &guess);
  EXPECT_EQ(dynamic_cast<PCGLinearSolver&>(sc.solver()).last_iterations(), 0);
  EXPECT_EQ((x - guess).norm(), 0.0);
}

TEST(PcgSolver, RejectsAGraphScatteredPreconditioner) {
  auto s = test::build("<Node name='root'><MechanicalObject position='0 0 0'/>"
                       "<PCGLinearSolver name='pcg' preconditioner='@cg'/><CGLinearSolver name='cg' iterations='5' "
                       "tolerance='1e-5' threshold='1e-5'/></Node>");
  init_root(*s.root);
  auto* pcg = test::get<PCGLinearSolver>(*s.root, "pcg");
  ASSERT_NE(pcg, nullptr);
  EXPECT_EQ(pcg->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "GraphScattered"));
}

TEST(PcgSolver, AssemblingRateControlsPreconditionerAssembly) {
  const Eigen::MatrixXd A = random_spd(6, 4);
  MatrixFreeScene sc(A, "<PreconditionedMatrixFreeSystem name='sys' assemblingRate='3'/>"
                        "<PCGLinearSolver iterations='100' preconditioner='@p'/><JacobiPreconditioner name='p'/>");
  auto* sys = test::get<PreconditionedMatrixFreeSystem>(*sc.s.root, "sys");
  ASSERT_NE(sys, nullptr);
  for (int step = 0; step < 7; ++step) sc.solve(random_vec(6, static_cast<unsigned>(step)));
  EXPECT_EQ(sys->preconditioner_builds(), 3);  // builds 1, 4 and 7
}

// ---------------------------------------------------------------- MinRes

TEST(MinResSolver, MatchesDenseSolveOnRandomSpdSystems) {
  // Matrix-free (GraphScattered) and assembled templates.
  for (std::string tmpl : {"GraphScattered", "CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d",
                           "FullMatrix"})
    for (int n : {3, 30, 90}) {
      const Eigen::MatrixXd A = random_spd(n, static_cast<unsigned>(3 * n));
      const Eigen::VectorXd b = random_vec(n, static_cast<unsigned>(n + 1));
      const Eigen::VectorXd ref = A.ldlt().solve(b);
      MatrixFreeScene sc(A, "<MinResLinearSolver template='" + tmpl + "' iterations='1000' tolerance='1e-15'/>");
      const bool assembled = tmpl != "GraphScattered";
      ASSERT_EQ(dynamic_cast<AssembledMinResLinearSolver*>(&sc.solver()) != nullptr, assembled) << tmpl;
      const Eigen::VectorXd x = sc.solve(b);
      EXPECT_LT((x - ref).norm(), 1e-8 * ref.norm()) << tmpl << " n=" << n;
      // Warm start from a perturbed solution; still the same answer.
      const Eigen::VectorXd guess = ref + 1e-3 * random_vec(n, 9);
      const Eigen::VectorXd x2 = sc.solve(b, &guess);
      EXPECT_LT((x2 - ref).norm(), 1e-8 * ref.norm()) << tmpl << " n=" << n;
    }
}

TEST(MinResSolver, SymmetricIndefiniteSystemsAreSolved) {
  // MINRES handles indefinite symmetric matrices (CG does not).
  const int n = 24;
  Eigen::MatrixXd A = random_spd(n, 21);
  for (int i = 0; i < n; i += 2) A(i, i) = -A(i, i);
  const Eigen::VectorXd b = random_vec(n, 22);
  const Eigen::VectorXd ref = A.fullPivLu().solve(b);
  MatrixFreeScene sc(A, "<MinResLinearSolver iterations='2000' tolerance='1e-15'/>");
  const Eigen::VectorXd x = sc.solve(b);
  EXPECT_LT((x - ref).norm(), 1e-7 * ref.norm());
}

TEST(MinResSolver, IterationCountIsBounded) {
  const Eigen::MatrixXd A = random_spd(60, 8);
  MatrixFreeScene sc(A, "<MinResLinearSolver iterations='4' tolerance='1e-15'/>");
  sc.solve(random_vec(60, 1));
  EXPECT_EQ(dynamic_cast<MinResLinearSolver&>(sc.solver()).last_iterations(), 4);
}

TEST(MinResSolver, ZeroResidualLeavesTheGuess) {
  const Eigen::MatrixXd A = random_spd(9, 8);
  MatrixFreeScene sc(A, "<MinResLinearSolver iterations='10' tolerance='1e-15'/>");
  // b = 0 and x0 = 0: the residual is exactly zero.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(9);
  const Eigen::VectorXd x = sc.solve(zero, &zero);
  EXPECT_EQ(x.norm(), 0.0);
  EXPECT_EQ(dynamic_cast<MinResLinearSolver&>(sc.solver()).last_iterations(), 0);
}

// ---------------------------------------------------------------- linear systems

TEST(PcgRotationMatrixSystem, IdentityAfterEachMainAssembly) {
  const Eigen::MatrixXd A = random_spd(24, 6);
  MatrixFreeScene sc(A,
                     "<PCGLinearSolver iterations='100' preconditioner='@p'/>"
                     "<RotationMatrixSystem name='R' assemblingRate='2'/>"
                     "<WarpPreconditioner name='p' linearSystem='@R' linearSolver='@ldl'/>"
                     "<MatrixLinearSystem template='CompressedRowSparseMatrixMat3x3' name='sys'/>"
                     "<SparseLDLSolver name='ldl' template='CompressedRowSparseMatrixMat3x3' linearSystem='@sys'/>",
                     "<RegularGridTopology nx='2' ny='2' nz='2' xmin='0' xmax='1' ymin='0' ymax='1' zmin='0' zmax='1'/>"
                     "<HexahedronFEMForceField name='rot' youngModulus='0.001'/>",
                     "0 0 0  1 0 0  0 1 0  1 1 0  0 0 1  1 0 1  0 1 1  1 1 1");
  auto* R = test::get<RotationMatrixSystem>(*sc.s.root, "R");
  ASSERT_NE(R, nullptr);
  ASSERT_NE(R->finder(), nullptr);
  sc.solve(random_vec(24, 1));
  EXPECT_TRUE(R->main_assembled_last());
  const Eigen::MatrixXd Rd = R->matrix().to_dense();
  EXPECT_EQ((Rd - Eigen::MatrixXd::Identity(24, 24)).norm(), 0.0);
  sc.solve(random_vec(24, 2));
  EXPECT_FALSE(R->main_assembled_last());  // rate 2: rotations from the finder
  sc.solve(random_vec(24, 3));
  EXPECT_TRUE(R->main_assembled_last());
}

TEST(PcgRotationMatrixSystem, MissingRotationFinderIsAnError) {
  auto s = test::build("<Node name='root'><MechanicalObject position='0 0 0'/>"
                       "<RotationMatrixSystem name='R'/><MatrixLinearSystem name='sys'/></Node>");
  init_root(*s.root);
  auto* R = test::get<RotationMatrixSystem>(*s.root, "R");
  ASSERT_NE(R, nullptr);
  EXPECT_EQ(R->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "RotationFinder"));
}

TEST(PcgCompositeLinearSystem, BuildsEverySystemAndSolvesWithTheSolverSystem) {
  const int n = 12;
  const Eigen::MatrixXd A = random_spd(n, 31);
  MatrixFreeScene sc(A,
                     "<SparseLDLSolver name='ldl' linearSystem='@comp'/>"
                     "<MatrixLinearSystem name='sys'/>"
                     "<MatrixLinearSystem name='Konly' assembleMass='false'/>"
                     "<CompositeLinearSystem name='comp' linearSystems='@sys @Konly' solverLinearSystem='@sys'/>",
                     "<UniformMass vertexMass='2'/>");
  auto* comp = test::get<CompositeLinearSystem>(*sc.s.root, "comp");
  auto* K = test::get<MatrixLinearSystem>(*sc.s.root, "Konly");
  ASSERT_NE(comp, nullptr);
  ASSERT_EQ(comp->systems().size(), 2u);
  // A = 1·M + 1·K with M = 2·I.
  MechanicalState* st = sc.s.root->mechanical_state;
  const Eigen::VectorXd b = random_vec(n, 4);
  auto& bv = st->write(sc.b);
  for (int i = 0; i < n; ++i) bv[static_cast<std::size_t>(i)] = b[i];
  sc.solver().build_system(*sc.ops, 1.0, 0.0, 1.0);
  sc.solver().solve_system(*sc.ops, sc.x, sc.b);
  const Eigen::MatrixXd full = A + 2.0 * Eigen::MatrixXd::Identity(n, n);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = st->write(sc.x)[static_cast<std::size_t>(i)];
  EXPECT_LT((x - full.ldlt().solve(b)).norm(), 1e-10 * x.norm());
  EXPECT_LT((K->matrix().to_dense() - A).norm(), 1e-12 * A.norm());
  EXPECT_LT((comp->matrix().to_dense() - full).norm(), 1e-12 * A.norm());
}

TEST(PcgPrecomputedWarp, AssembledSystemGivesTheExactInverse) {
  // Linked to an assembled system (not the default PrecomputedMatrixSystem), Minv = A⁻¹ of the
  // first assembly (computed as A⁻¹·dt / dt) and PCG converges in one iteration.
  const int n = 24;
  const Eigen::MatrixXd A = random_spd(n, 17);
  MatrixFreeScene sc(A, "<PCGLinearSolver iterations='100' tolerance='1e-20' preconditioner='@p'/>"
                        "<MatrixLinearSystem name='ms'/>"
                        "<PrecomputedWarpPreconditioner name='p' linearSystem='@ms' use_file='false' "
                        "share_matrix='false' use_rotations='false'/>");
  auto* p = test::get<PrecomputedWarpPreconditioner>(*sc.s.root, "p");
  ASSERT_NE(p, nullptr);
  const Eigen::VectorXd b = random_vec(n, 2);
  const Eigen::VectorXd x = sc.solve(b);
  ASSERT_NE(p->inverse(), nullptr);
  ASSERT_EQ(p->system_size(), static_cast<std::size_t>(n));
  EXPECT_LT((Eigen::MatrixXd(*p->inverse()) - A.inverse()).norm(), 1e-10 * A.inverse().norm());
  EXPECT_LT((x - A.ldlt().solve(b)).norm(), 1e-10 * x.norm());
  EXPECT_EQ(dynamic_cast<PCGLinearSolver&>(sc.solver()).last_iterations(), 1);
}

TEST(PcgPrecomputedWarp, DefaultSystemIsNeverAssembled) {
  const Eigen::MatrixXd A = random_spd(6, 17);
  MatrixFreeScene sc(A, "<PCGLinearSolver iterations='100' preconditioner='@p'/>"
                        "<PrecomputedWarpPreconditioner name='p' use_file='false'/>");
  auto* p = test::get<PrecomputedWarpPreconditioner>(*sc.s.root, "p");
  ASSERT_NE(p, nullptr);
  sc.solve(random_vec(6, 1));
  EXPECT_EQ(p->system_size(), 0u);
  EXPECT_EQ(p->system()->matrix_size.value(), VecNi<2>(0, 0));
}

TEST(PcgWarpCompliance, JMinvJtMatchesDenseProduct) {
  // R = identity after an assembly: J·A⁻¹·Jᵀ through the inner direct solver;
  // PrecomputedWarp (identity rotations from the finder) gives the same with a float factor.
  const int n = 24;
  const Eigen::MatrixXd A = random_spd(n, 41);
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> J(4, n);
  std::vector<Eigen::Triplet<double, int>> tr = {{0, 0, 1.0}, {0, 5, -0.5}, {2, 7, 2.0}, {2, 8, 1.0}, {3, 23, 0.3}};
  J.setFromTriplets(tr.begin(), tr.end());
  const Eigen::MatrixXd Jd = J;
  const Eigen::MatrixXd ref = Jd * A.inverse() * Jd.transpose();

  MatrixFreeScene warp(A, "<PCGLinearSolver iterations='100' preconditioner='@p'/>"
                          "<RotationMatrixSystem name='R'/><WarpPreconditioner name='p' linearSystem='@R' "
                          "linearSolver='@ldl'/><MatrixLinearSystem template='CompressedRowSparseMatrixMat3x3' "
                          "name='sys'/><SparseLDLSolver name='ldl' template='CompressedRowSparseMatrixMat3x3' "
                          "linearSystem='@sys'/>");
  warp.solve(random_vec(n, 1));
  auto* wp = test::get<WarpPreconditioner>(*warp.s.root, "p");
  ASSERT_NE(wp, nullptr);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(4, 4);
  wp->add_jminvjt(W, J, 2.0);
  EXPECT_LT((W - 2.0 * ref).norm(), 1e-10 * ref.norm());

  MatrixFreeScene pre(A, "<PCGLinearSolver iterations='100' preconditioner='@p'/><MatrixLinearSystem name='ms'/>"
                         "<PrecomputedWarpPreconditioner name='p' linearSystem='@ms' use_file='false' "
                         "share_matrix='false'/>");  // (shared inverses are keyed by node name, size and dt only)
  pre.solve(random_vec(n, 1));
  auto* pp = test::get<PrecomputedWarpPreconditioner>(*pre.s.root, "p");
  ASSERT_NE(pp, nullptr);
  Eigen::MatrixXd W2 = Eigen::MatrixXd::Zero(4, 4);
  const double fact = 0.1;  // not exact in float
  pp->add_jminvjt(W2, J, fact);
  EXPECT_LT((W2 - static_cast<double>(static_cast<float>(fact)) * ref).norm(), 1e-10 * ref.norm());
  EXPECT_GT((W2 - fact * ref).norm(), 0.0);
}

TEST(PcgWarp, AppliesTheRotatedInverseBetweenAssemblies) {
  // assemblingRate 2: the second build keeps A₀ and fills R from the rotation finder,
  // so the preconditioner is z = R·A₀⁻¹·Rᵀ·r.
  const int n = 12;
  const Eigen::MatrixXd A = random_spd(n, 51);
  MatrixFreeScene sc(A, "<PCGLinearSolver iterations='100' preconditioner='@p'/>"
                        "<RotationMatrixSystem name='R' assemblingRate='2'/><WarpPreconditioner name='p' "
                        "linearSystem='@R' linearSolver='@ldl'/><MatrixLinearSystem name='sys'/>"
                        "<SparseLDLSolver name='ldl' linearSystem='@sys'/>");
  auto* wp = test::get<WarpPreconditioner>(*sc.s.root, "p");
  auto* R = test::get<RotationMatrixSystem>(*sc.s.root, "R");
  ASSERT_NE(wp, nullptr);
  ASSERT_NE(R, nullptr);
  sc.solve(random_vec(n, 1));  // assembles A₀, R = I
  const Mat3 Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  sc.ff->rotation = Q;
  sc.solver().build_system(*sc.ops, 0.0, 0.0, 1.0);  // R from the finder
  ASSERT_FALSE(R->main_assembled_last());
  Eigen::MatrixXd Rd = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n / 3; ++k) Rd.block<3, 3>(3 * k, 3 * k) = Q;
  const Eigen::VectorXd r = random_vec(n, 2);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  wp->solve_global(z, r);
  const Eigen::VectorXd ref = Rd * A.inverse() * Rd.transpose() * r;
  EXPECT_LT((z - ref).norm(), 1e-10 * ref.norm());
}

TEST(PcgPrecomputedWarp, InversesAreSharedByFileName) {
  const Eigen::MatrixXd A = random_spd(9, 3), B = random_spd(9, 4);
  const std::string xml = "<PCGLinearSolver iterations='100' preconditioner='@p'/><MatrixLinearSystem name='ms'/>"
                          "<PrecomputedWarpPreconditioner name='p' linearSystem='@ms' use_file='false'/>";
  MatrixFreeScene a(A, xml), b(B, xml);
  a.solve(random_vec(9, 1));
  b.solve(random_vec(9, 1));
  auto* pa = test::get<PrecomputedWarpPreconditioner>(*a.s.root, "p");
  auto* pb = test::get<PrecomputedWarpPreconditioner>(*b.s.root, "p");
  ASSERT_NE(pa->inverse(), nullptr);
  EXPECT_EQ(pa->inverse(), pb->inverse());  // same "<node>-<n>-<dt>" key: B's scene reuses A's inverse
}
