// FixedPlaneProjectiveConstraint (spec/mechanics.md §4): selection of the
// points between the two planes, projection of dx along the direction, the
// Dirichlet rows of assembled systems, agreement with the Fixed and
// PartialFixed constraints on the same DoFs, and bad input.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "projective/fixed_plane_projective_constraint.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/matrix_linear_system.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

// A 3×3×4 hexahedral block, z in [0, 3]; gravity has lateral components so
// that in-plane motion of the constrained points shows.
std::string block(const std::string& solver, const std::string& constraint) {
  return R"(<Node name="root" dt="0.02" gravity="2 -1 -10">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    )" + solver + R"(
    <MechanicalObject name="dofs"/>
    <UniformMass totalMass="10"/>
    <RegularGridTopology name="grid" nx="3" ny="3" nz="4" xmin="0" xmax="2" ymin="0" ymax="2" zmin="0" zmax="3"/>
    )" + constraint + R"(
    <HexahedronFEMForceField youngModulus="1000" poissonRatio="0.3" method="large"/>
  </Node>)";
}

const char* kCG = R"(<CGLinearSolver iterations="200" tolerance="1e-14" threshold="1e-20"/>)";
const char* kLDL = R"(<SparseLDLSolver/>)";

// A chain of 5 points along z joined by springs, pulled down by gravity:
// every force is along z, so fixing z only or fixing all components agree.
std::string chain(const std::string& solver, const std::string& constraint) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 -10">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    )" + solver + R"(
    <MechanicalObject name="dofs" position="0 0 0  0 0 1  0 0 2  0 0 3  0 0 4"/>
    <UniformMass totalMass="5"/>
    <SpringForceField spring="0 1 200 1 1  1 2 200 1 1  2 3 200 1 1  3 4 200 1 1"/>
    )" + constraint + R"(
  </Node>)";
}

std::vector<double> positions(Node& root) {
  MechanicalOps ops(root);
  return ops.independent_states().front()->write(kPosition);
}

std::vector<std::vector<double>> trajectory(const std::string& xml, int steps) {
  auto s = load(xml);
  std::vector<std::vector<double>> out;
  if (!s.root) return out;
  for (int i = 0; i < steps; ++i) {
    animate(*s.root);
    out.push_back(positions(*s.root));
  }
  return out;
}

double max_difference(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  EXPECT_EQ(a.size(), b.size());
  double m = 0.0;
  for (std::size_t s = 0; s < a.size() && s < b.size(); ++s) {
    EXPECT_EQ(a[s].size(), b[s].size());
    for (std::size_t i = 0; i < a[s].size() && i < b[s].size(); ++i) m = std::max(m, std::abs(a[s][i] - b[s][i]));
  }
  return m;
}

MatrixLinearSolver* matrix_solver(Node& root) {
  for (LinearSolver* s : root.linear_solvers)
    if (auto* m = dynamic_cast<MatrixLinearSolver*>(s)) return m;
  return nullptr;
}

const char* kBottom = R"(<FixedPlaneProjectiveConstraint name="fp" direction="0 0 1" dmin="-0.1" dmax="0.1"/>)";

}  // namespace

TEST(FixedPlaneConstraint, SelectsThePointsBetweenThePlanesAfterTheExplicitIndices) {
  auto s = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" indices="35" direction="0 0 1"
                                 dmin="0.5" dmax="1.5"/>)"));
  auto* fp = get<FixedPlaneProjectiveConstraint>(*s.root, "fp");
  ASSERT_NE(fp, nullptr);
  // Layer z = 1 holds the grid points 9..17; strict bounds leave z = 0 and z = 2 out.
  std::vector<unsigned> expected{35};
  for (unsigned i = 9; i < 18; ++i) expected.push_back(i);
  EXPECT_EQ(fp->constrained(), expected);
  EXPECT_EQ(fp->indices.get(), expected);  // written back, as SOFA's addConstraint does
}

TEST(FixedPlaneConstraint, SelectionIsStrictAndNeedsTwoDistinctPlanes) {
  // A plane exactly through a layer (dmin = 0) selects nothing below it, dmin = dmax selects nothing.
  auto s1 = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" direction="0 0 1" dmin="0" dmax="1"/>)"));
  EXPECT_TRUE(get<FixedPlaneProjectiveConstraint>(*s1.root, "fp")->constrained().empty());
  auto s2 = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" direction="0 0 1" dmin="1" dmax="1"
                                  indices="4"/>)"));
  EXPECT_EQ(get<FixedPlaneProjectiveConstraint>(*s2.root, "fp")->constrained(), std::vector<unsigned>{4});
  // The old name is accepted.
  auto s3 = load(block(kCG, R"(<FixedPlaneConstraint name="fp" direction="0 0 1" dmin="-0.1" dmax="0.1"/>)"));
  auto* fp = get<FixedPlaneProjectiveConstraint>(*s3.root, "fp");
  ASSERT_NE(fp, nullptr);
  EXPECT_EQ(fp->constrained().size(), 9u);
}

TEST(FixedPlaneConstraint, StepsKeepTheSelectedPointsOnTheirPlaneWhileOthersMove) {
  for (const char* solver : {kCG, kLDL}) {
    auto s = load(block(solver, kBottom));
    ASSERT_TRUE(s.root);
    const std::vector<double> x0 = positions(*s.root);
    for (int i = 0; i < 10; ++i) animate(*s.root);
    const std::vector<double> x = positions(*s.root);
    double lateral = 0.0;
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(x[3 * i + 2], x0[3 * i + 2]) << solver << " point " << i;
      lateral = std::max(lateral, std::abs(x[3 * i] - x0[3 * i]));
    }
    EXPECT_GT(lateral, 1e-3) << solver;  // the direction only constrains z
    for (int i = 9; i < 36; ++i) EXPECT_LT(x[3 * i + 2], x0[3 * i + 2] - 1e-4) << solver << " point " << i;
  }
}

TEST(FixedPlaneConstraint, AssembledRowsOfTheConstrainedComponentsAreIdentity) {
  auto s = load(block(kLDL, kBottom));
  ASSERT_TRUE(s.root);
  animate(*s.root);
  MechanicalOps ops(*s.root);
  MatrixLinearSolver* solver = matrix_solver(*s.root);
  ASSERT_NE(solver, nullptr);
  solver->build_system(ops, 1, -0.002, -0.0024);
  const Eigen::MatrixXd A = solver->system()->matrix().to_dense();
  ASSERT_EQ(A.rows(), 108);
  for (int i = 0; i < 36; ++i)
    for (int c = 0; c < 3; ++c) {
      const int r = 3 * i + c;
      if (i < 9 && c == 2) {
        EXPECT_EQ(A(r, r), 1.0);
        EXPECT_EQ(A.row(r).cwiseAbs().sum(), 1.0);
        EXPECT_EQ(A.col(r).cwiseAbs().sum(), 1.0);
      } else {
        EXPECT_GT(A.row(r).cwiseAbs().sum(), 1.0) << "row " << r << " should be left alone";
      }
    }
}

TEST(FixedPlaneConstraint, MatchesPartialFixedOnTheSameComponents) {
  const std::string partial =
      R"(<PartialFixedProjectiveConstraint indices="0 1 2 3 4 5 6 7 8" fixedDirections="0 0 1"/>)";
  for (const char* solver : {kCG, kLDL}) {
    const double d = max_difference(trajectory(block(solver, kBottom), 20), trajectory(block(solver, partial), 20));
    EXPECT_EQ(d, 0.0) << solver;
    std::printf("[fixed-plane] %s: max |x_plane - x_partial| over 20 steps = %g\n",
                solver == kCG ? "CG" : "SparseLDL", d);
  }
}

TEST(FixedPlaneConstraint, MatchesFixedWhenTheMotionIsAlongTheDirection) {
  const std::string plane = R"(<FixedPlaneProjectiveConstraint direction="0 0 1" dmin="-0.5" dmax="0.5"/>)";
  const std::string fixed = R"(<FixedProjectiveConstraint indices="0"/>)";
  for (const char* solver : {kCG, kLDL}) {
    const auto a = trajectory(chain(solver, plane), 50), b = trajectory(chain(solver, fixed), 50);
    const double d = max_difference(a, b);
    EXPECT_EQ(d, 0.0) << solver;
    ASSERT_EQ(a.size(), 50u);
    EXPECT_EQ(a.back()[2], 0.0);              // point 0 stays
    EXPECT_LT(a.back()[14], 4.0 - 1e-3);     // the free end falls
    std::printf("[fixed-plane] chain %s: max |x_plane - x_fixed| over 50 steps = %g, z4 = %.9f\n",
                solver == kCG ? "CG" : "SparseLDL", d, a.back()[14]);
  }
}

TEST(FixedPlaneConstraint, ProjectsOnlyTheComponentAlongTheDirection) {
  // Not normalised, as in SOFA: dx − d (d·dx).
  auto s = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" indices="0" direction="0.6 0 0.8"/>)"));
  auto* fp = get<FixedPlaneProjectiveConstraint>(*s.root, "fp");
  ASSERT_NE(fp, nullptr);
  std::vector<double>& v = fp->mstate->write(kVelocity);
  v[0] = 1.0, v[1] = 2.0, v[2] = 3.0, v[3] = 4.0;
  fp->project_response(kVelocity);
  const double dot = 0.6 * 1.0 + 0.8 * 3.0;
  EXPECT_DOUBLE_EQ(v[0], 1.0 - 0.6 * dot);
  EXPECT_EQ(v[1], 2.0);
  EXPECT_DOUBLE_EQ(v[2], 3.0 - 0.8 * dot);
  EXPECT_NEAR(0.6 * v[0] + 0.8 * v[2], 0.0, 1e-15);
  EXPECT_EQ(v[3], 4.0);  // other DoFs untouched
  std::vector<std::size_t> rows;
  EXPECT_TRUE(fp->dirichlet_indices(rows));
  EXPECT_EQ(rows, (std::vector<std::size_t>{0, 2}));  // components with a non-zero direction entry
}

TEST(FixedPlaneConstraint, RigidAndVec6Templates) {
  auto s = load(R"(<Node name="root">
    <Node name="r">
      <MechanicalObject name="dofs" template="Rigid3d" position="0 0 0 0 0 0 1  1 2 3 0 0 0 1"/>
      <FixedPlaneProjectiveConstraint name="fp" template="Rigid3d" direction="0 0 1" dmin="-1" dmax="1"/>
    </Node>
    <Node name="s">
      <MechanicalObject name="dofs" template="Vec6d" position="0 0 0 0 0 5  0 0 0 0 0 0"/>
      <FixedPlaneProjectiveConstraint name="fp6" template="Vec6d" direction="0 0 0 0 0 1" dmin="4" dmax="6"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* fp = dynamic_cast<FixedPlaneProjectiveConstraint*>(s.root->children()[0]->find_object_named("fp"));
  ASSERT_NE(fp, nullptr);
  EXPECT_EQ(fp->constrained(), std::vector<unsigned>{0});
  std::vector<double>& v = fp->mstate->write(kVelocity);
  ASSERT_EQ(v.size(), 12u);
  for (int i = 0; i < 12; ++i) v[i] = i + 1;
  fp->project_response(kVelocity);
  EXPECT_EQ(v[2], 0.0);                      // translation along z removed
  EXPECT_EQ(v[0], 1.0);
  EXPECT_EQ(v[5], 6.0);                      // rotations untouched
  EXPECT_EQ(v[8], 9.0);                      // the other rigid untouched
  std::vector<std::size_t> rows;
  fp->dirichlet_indices(rows);
  EXPECT_EQ(rows, std::vector<std::size_t>{2});  // the identity orientation flags no rotation row

  auto* fp6 = dynamic_cast<FixedPlaneProjectiveConstraint*>(s.root->children()[1]->find_object_named("fp6"));
  ASSERT_NE(fp6, nullptr);
  EXPECT_EQ(fp6->constrained(), std::vector<unsigned>{0});
  std::vector<double>& w = fp6->mstate->write(kVelocity);
  for (int i = 0; i < 12; ++i) w[i] = 1.0;
  fp6->project_response(kVelocity);
  EXPECT_EQ(w[5], 0.0);
  EXPECT_EQ(w[4], 1.0);
  EXPECT_EQ(w[11], 1.0);
}

TEST(FixedPlaneConstraint, BadInputWarnsAndKeepsRunning) {
  {
    auto s = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" direction="0 0 0" dmin="-0.1" dmax="0.1"/>)"));
    const auto w = messages(s.root->diagnostics(), Severity::warning);
    EXPECT_TRUE(any_contains(w, "direction is zero")) << ::testing::PrintToString(w);
    auto* fp = get<FixedPlaneProjectiveConstraint>(*s.root, "fp");
    std::vector<std::size_t> rows;
    fp->dirichlet_indices(rows);
    EXPECT_TRUE(rows.empty());
    for (int i = 0; i < 3; ++i) animate(*s.root);
    for (double x : positions(*s.root)) EXPECT_TRUE(std::isfinite(x));
  }
  {
    auto s = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" direction="0 0 1" dmin="1" dmax="-1"/>)"));
    const auto w = messages(s.root->diagnostics(), Severity::warning);
    EXPECT_TRUE(any_contains(w, "dmin (1.000000) is greater than dmax (-1.000000)")) << ::testing::PrintToString(w);
    EXPECT_TRUE(get<FixedPlaneProjectiveConstraint>(*s.root, "fp")->constrained().empty());
    for (int i = 0; i < 3; ++i) animate(*s.root);
  }
  {
    auto s = load(block(kCG, R"(<FixedPlaneProjectiveConstraint name="fp" indices="3 99" direction="0 0 1 5"/>)"));
    const auto w = messages(s.root->diagnostics(), Severity::warning);
    EXPECT_TRUE(any_contains(w, "index 99 is out of range")) << ::testing::PrintToString(w);
    EXPECT_TRUE(any_contains(w, "direction has 4 values")) << ::testing::PrintToString(w);
    EXPECT_EQ(get<FixedPlaneProjectiveConstraint>(*s.root, "fp")->constrained(), std::vector<unsigned>{3});
    for (int i = 0; i < 3; ++i) animate(*s.root);
  }
}
