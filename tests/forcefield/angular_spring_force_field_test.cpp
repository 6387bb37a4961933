// AngularSpringForceField: torques from the rotation between consecutive
// frames, on numbers worked by hand; SOFA's tangent (−k on the rotational
// diagonal of every listed frame) and its assembled matrix; bad input; and an
// articulated chain (ArticulatedSystemMapping) settling under gravity at the
// static equilibrium worked out below.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/matrix_sink.h"
#include "core/node.h"
#include "forcefield/spring/angular_spring_force_field.h"
#include "test_scene.h"

using namespace sinew;

namespace {

// Frame 1 turned 0.3 rad about z; frame 2 turned a further 0.2 rad about the world x axis.
std::string three_frames(const std::string& attrs) {
  const double c = std::cos(0.15), s = std::sin(0.15), c2 = std::cos(0.1), s2 = std::sin(0.1);
  // q2 = rx(0.2)·rz(0.3) = (s2·c, −s2·s, c2·s, c2·c) (x, y, z, w).
  char q2[128];
  std::snprintf(q2, sizeof q2, "%.17g %.17g %.17g %.17g", s2 * c, -s2 * s, c2 * s, c2 * c);
  char q1[64];
  std::snprintf(q1, sizeof q1, "0 0 %.17g %.17g", s, c);
  return std::string("<Node name='root' gravity='0 0 0'><MechanicalObject name='dofs' template='Rigid3d' position='") +
         "0 0 0 0 0 0 1  1 0 0 " + q1 + "  2 0 0 " + q2 + "'/><AngularSpringForceField name='ff' " + attrs +
         "/></Node>";
}

}  // namespace

// τ₁ = −20·0.3·z (its own stiffness); τ₂ = −10·0.2·x (the list has two stiffnesses: the
// third point takes the first); frame 0 has no previous frame and gets nothing.
TEST(AngularSpringForceField, TorquesFromTheRotationToThePreviousFrame) {
  auto s = test::load(three_frames("indices='0 1 2' angularStiffness='10 20'"));
  ASSERT_TRUE(s.root);
  auto* ff = test::get<AngularSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  MechanicalState& st = *s.root->get_mechanical_state();
  st.write(kForce).assign(18, 0.0);
  ff->add_force(MechParams{});
  const std::vector<double> want = {0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, -6,  0, 0, 0, -2, 0, 0};
  const std::vector<double>& f = st.read(kForce);
  ASSERT_EQ(f.size(), want.size());
  for (std::size_t k = 0; k < f.size(); ++k) EXPECT_NEAR(f[k], want[k], 1e-14) << k;
}

// SOFA's tangent: −k_j·kfactor on the rotational entries of every listed point,
// the first one included; translations untouched. The matrix says the same.
TEST(AngularSpringForceField, DiagonalTangentAndItsMatrix) {
  auto s = test::load(three_frames("indices='0 1 2' angularStiffness='10 20'"));
  ASSERT_TRUE(s.root);
  auto* ff = test::get<AngularSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  MechanicalState& st = *s.root->get_mechanical_state();
  std::vector<double> dx(18);
  for (std::size_t k = 0; k < dx.size(); ++k) dx[k] = 0.1 * static_cast<double>(k + 1);
  st.write(kDx) = dx;
  st.write(kDforce).assign(18, 0.0);
  ff->add_dforce(MechParams{}, 0.5);
  const double k[3] = {10, 20, 10};
  const std::vector<double>& df = st.read(kDforce);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 6; ++c)
      EXPECT_DOUBLE_EQ(df[6 * i + c], c < 3 ? 0.0 : -k[i] * 0.5 * dx[6 * i + c]) << i << " " << c;
  MatrixSink K;
  ASSERT_TRUE(ff->build_stiffness(K));
  ASSERT_EQ(K.entries().size(), 9u);
  for (const MatrixSink::Entry& e : K.entries()) {
    EXPECT_EQ(e.row, e.col);
    EXPECT_EQ(e.row % 6 >= 3, true);
    EXPECT_EQ(e.value, -k[e.row / 6]);
  }
}

TEST(AngularSpringForceField, DefaultStiffnessIsOneHundred) {
  auto s = test::load(three_frames("indices='0 1'"));
  ASSERT_TRUE(s.root);
  auto* ff = test::get<AngularSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  MechanicalState& st = *s.root->get_mechanical_state();
  st.write(kForce).assign(18, 0.0);
  ff->add_force(MechParams{});
  EXPECT_NEAR(st.read(kForce)[11], -100 * 0.3, 1e-13);
  EXPECT_EQ(ff->angular_stiffness.get(), std::vector<double>{100.0});  // written back, as SOFA
}

TEST(AngularSpringForceField, BadIndicesAreRefused) {
  for (const char* attrs : {"indices='1 5'", "indices='1 0'"}) {
    auto s = test::build(three_frames(attrs));
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    auto* ff = test::get<AngularSpringForceField>(*s.root, "ff");
    ASSERT_NE(ff, nullptr);
    EXPECT_EQ(ff->state(), ComponentState::invalid) << attrs;
    EXPECT_FALSE(test::messages(s.root->diagnostics(), Severity::error).empty()) << attrs;
  }
}

// A chain of unit masses at x = 0, 1, 2, 3 (frame 0 fixed) with joints about z at
// a_j = j − ½, angular springs k between consecutive frames, gravity −g·y. The spring of
// frame i acts on every joint j ≤ i (Jᵀ), so at equilibrium
//   k·Σ_{i≥j} q_i = G_j = −g·Σ_{m≥j} (x_m − a_j),
// up to the lever arms' second-order change (relative 1e-7 at these angles).
namespace {
// The chain of the test below, solved by `linear_solver`; returns the joint coordinates after 2000 steps.
std::vector<double> settled_chain(const std::string& linear_solver) {
  std::string centers;
  for (int j = 1; j <= 3; ++j)
    centers += "<Node name='c" + std::to_string(j) + "'><ArticulationCenter parentIndex='" + std::to_string(j - 1) +
               "' childIndex='" + std::to_string(j) +
               "' posOnParent='0.5 0 0' posOnChild='-0.5 0 0'/><Node name='a'><Articulation articulationIndex='" +
               std::to_string(j - 1) + "' rotation='1' rotationAxis='0 0 1'/></Node></Node>";
  auto s = test::load(
      "<Node name='root' gravity='0 -0.01 0' dt='0.05'>"
      "<EulerImplicitSolver rayleighStiffness='0.1' rayleighMass='1'/>" + linear_solver +
      "<MechanicalObject name='q' template='Vec1d' position='0 0 0'/>"
      "<Node name='base'><MechanicalObject template='Rigid3d' position='0 0 0 0 0 0 1'/>"
      "<FixedProjectiveConstraint indices='0'/></Node>"
      "<Node name='body'><MechanicalObject name='frames' template='Rigid3d'"
      " position='0 0 0 0 0 0 1  1 0 0 0 0 0 1  2 0 0 0 0 0 1  3 0 0 0 0 0 1'/>"
      "<UniformMass vertexMass='1'/>"
      "<AngularSpringForceField angularStiffness='100' indices='0 1 2 3'/>"
      "<ArticulatedSystemMapping input1='@../q' input2='@../base' output='@frames'/></Node>"
      "<ArticulatedHierarchyContainer/><Node name='centers'>" + centers + "</Node></Node>");
  if (!s.root) return {};
  for (int step = 0; step < 2000; ++step) animate(*s.root);
  return s.root->get_mechanical_state()->read(kPosition);
}
}  // namespace

TEST(AngularSpringForceField, ArticulatedChainSettlesAtItsStaticEquilibrium) {
  const double g = 0.01, k = 100;
  double S[5] = {0, 0, 0, 0, 0};
  for (int j = 3; j >= 1; --j) {
    double G = 0;
    for (int m = j; m <= 3; ++m) G += -g * (m - (j - 0.5));
    S[j] = G / k;
  }
  // Matrix-free (CG, through J and Jᵀ) and assembled (the mapping's J, a direct solver).
  for (const char* solver : {"<CGLinearSolver iterations='100' tolerance='1e-20' threshold='1e-30'/>",
                             "<SparseLDLSolver/>"}) {
    const std::vector<double> q = settled_chain(solver);
    ASSERT_EQ(q.size(), 3u) << solver;
    for (int j = 1; j <= 3; ++j) {
      const double want = S[j] - S[j + 1];  // −2.5e-4, −1.5e-4, −5e-5
      EXPECT_NEAR(q[j - 1], want, 1e-5 * std::abs(want)) << "joint " << j << " with " << solver;
    }
  }
}
