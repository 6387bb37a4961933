// VectorSpringForceField: springs towards a rest vector (SOFA's
// VectorSpringForceField.inl): analytic forces, add_dforce against finite
// differences, the assembled K against add_dforce, the default-spring rules.
#include <gtest/gtest.h>

#include "forcefield/spring/vector_spring_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

using namespace sinew;

namespace {

const char* kEdges =
    "<Node name='root' gravity='0 0 0'>"
    "<MeshTopology name='topo' position='0 0 0  1 0 0  0 2 0' edges='0 1  1 2'/>"
    "<MechanicalObject name='dofs' position='0 0 0  1 0 0  0 2 0'/>"
    "<VectorSpringForceField name='ff' useTopology='1' stiffness='10' viscosity='0.5'/>"
    "</Node>";

}  // namespace

TEST(VectorSpringForceField, TopologyDefaultsAndAnalyticForce) {
  auto s = test::load(kEdges);
  ASSERT_TRUE(s.root);
  auto* ff = test::get<VectorSpringForceField>(*s.root, "ff");
  auto* st = test::get<MechanicalState>(*s.root, "dofs");
  ASSERT_TRUE(ff && st);
  // One spring per edge, rest vector x0[e1] − x0[e0].
  ASSERT_EQ(ff->spring_list().size(), 2u);
  EXPECT_EQ(ff->spring_list()[1].m1, 1u);
  EXPECT_EQ(ff->spring_list()[1].m2, 2u);
  EXPECT_DOUBLE_EQ(ff->spring_list()[1].rest[0], -1.0);
  EXPECT_DOUBLE_EQ(ff->spring_list()[1].rest[1], 2.0);
  EXPECT_EQ(ff->springs.value(), (std::vector<double>{10, 0.5, 1, 0, 0, 10, 0.5, -1, 2, 0}));
  // Moved: x1 = (1.2, 0.1, -0.3), v1 = (0, 1, 0), others at rest.
  const std::vector<double> x = {0, 0, 0, 1.2, 0.1, -0.3, 0, 2, 0};
  const std::vector<double> v = {0, 0, 0, 0, 1, 0, 0, 0, 0};
  const auto f = test::force_at(*ff, *st, x, &v);
  // Spring 0 (0→1): ks·(x1 − x0 − r) + kd·(v1 − v0) = 10·(0.2, 0.1, −0.3) + 0.5·(0, 1, 0) = (2, 1.5, −3).
  // Spring 1 (1→2): 10·((−1.2, 1.9, 0.3) − (−1, 2, 0)) + 0.5·(0, −1, 0) = (−2, −1.5, 3).
  const std::vector<double> expected = {2, 1.5, -3, -2 - 2, -1.5 - 1.5, 3 + 3, 2, 1.5, -3};
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(f[i], expected[i], 1e-12) << i;
  // Energy Σ ½·ks·|x2 − x1 − r|² = 2·½·10·(0.04 + 0.01 + 0.09) = 1.4.
  EXPECT_NEAR(ff->potential_energy().value(), 1.4, 1e-12);
}

TEST(VectorSpringForceField, DforceMatchesFiniteDifferencesAndAssembledK) {
  auto s = test::load(kEdges);
  ASSERT_TRUE(s.root);
  auto* ff = test::get<VectorSpringForceField>(*s.root, "ff");
  auto* st = test::get<MechanicalState>(*s.root, "dofs");
  const std::vector<double> x = {0.1, -0.2, 0.05, 1.3, 0.2, -0.1, -0.2, 2.1, 0.4};
  const std::vector<double> dx = {0.3, -0.7, 0.2, 0.5, 0.1, -0.4, -0.6, 0.9, 0.8};
  test::force_at(*ff, *st, x);
  const auto df = test::dforce(*ff, *st, dx, 1.0);
  const auto fd = test::fd_force(*ff, *st, x, dx, 1e-6);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(df[i], fd[i], 1e-7) << i;
  const auto K = test::dense_stiffness(*ff, *st);
  for (std::size_t i = 0; i < 9; ++i) {
    double kdx = 0;
    for (std::size_t j = 0; j < 9; ++j) kdx += K[i * 9 + j] * dx[j];
    EXPECT_NEAR(kdx, df[i], 1e-12) << i;
  }
  // kfactor scales; no damping term (SOFA's addDForce).
  const auto df2 = test::dforce(*ff, *st, dx, -0.25);
  for (std::size_t i = 0; i < 9; ++i) EXPECT_NEAR(df2[i], -0.25 * df[i], 1e-12);
}

TEST(VectorSpringForceField, PairsWithoutTopologyBetweenTwoStates) {
  auto s = test::load(
      "<Node name='root' gravity='0 0 0'>"
      "<Node name='a'><MechanicalObject name='a' position='0 0 0  1 1 1'/></Node>"
      "<Node name='b'><MechanicalObject name='b' position='0 0 1  2 1 1  5 5 5'/></Node>"
      "<VectorSpringForceField name='ff' object1='@a/a' object2='@b/b' stiffness='3' viscosity='0'/>"
      "</Node>");
  ASSERT_TRUE(s.root);
  auto* ff = test::get<VectorSpringForceField>(*s.root, "ff");
  ASSERT_TRUE(ff);
  // Pairs (i, i) for every point of object1, rest vector 0.
  ASSERT_EQ(ff->spring_list().size(), 2u);
  EXPECT_EQ(ff->spring_list()[1].m1, 1u);
  EXPECT_EQ(ff->spring_list()[1].m2, 1u);
  EXPECT_EQ(ff->spring_list()[1].rest[0], 0.0);
  auto* a = s.root->children()[0]->get_mechanical_state();
  auto* b = s.root->children()[1]->get_mechanical_state();
  std::fill(a->write(kForce).begin(), a->write(kForce).end(), 0.0);
  std::fill(b->write(kForce).begin(), b->write(kForce).end(), 0.0);
  ff->add_force(MechParams{});
  // f_a = 3·(xb − xa): (0, 0, 3) and (3, 0, 0); f_b the opposite, point 2 untouched.
  EXPECT_EQ(a->read(kForce), (std::vector<double>{0, 0, 3, 3, 0, 0}));
  EXPECT_EQ(b->read(kForce), (std::vector<double>{0, 0, -3, -3, 0, 0, 0, 0, 0}));
}

TEST(VectorSpringForceField, BadInputIsRefusedWithTheField) {
  Diagnostics d;
  auto s = test::build(
      "<Node name='root'><MechanicalObject name='dofs' position='0 0 0'/>"
      "<VectorSpringForceField name='ff' useTopology='1'/></Node>");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "useTopology"));
  auto s2 = test::build(
      "<Node name='root'><Node name='a'><MechanicalObject name='a' position='0 0 0  1 1 1'/></Node>"
      "<Node name='b'><MechanicalObject name='b' position='0 0 1'/></Node>"
      "<VectorSpringForceField name='ff' object1='@a/a' object2='@b/b'/></Node>");
  init_root(*s2.root);
  EXPECT_TRUE(test::any_contains(test::messages(s2.root->diagnostics(), Severity::error), "object2 only 1"));
  for (int i = 0; i < 3; ++i) animate(*s2.root);  // no crash
}
