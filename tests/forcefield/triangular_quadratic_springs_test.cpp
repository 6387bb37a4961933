// TriangularQuadraticSpringsForceField: the per-triangle constants from the
// rest cotangents and edge lengths (hand-computed on a right isosceles
// triangle), forces = −∇E by central differences, add_dforce = the derivative
// of the forces (exactly without angular springs and at the rest shape; SOFA's
// edge-direction coefficient elsewhere), build_stiffness = add_dforce, edge and
// triangle data following triangle removal and addition as SOFA's topology
// data do, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "badinput_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "forcefield/spring/triangular_quadratic_springs_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

using namespace sinew;
using sinew::test::dforce;
using sinew::test::expect_near_rel;
using sinew::test::fd_force;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;
using sinew::test::wiggle;

namespace {
// Two triangles sharing the edge (1, 2) in the z = 0 plane, in a dynamic container.
std::string two_triangles(const std::string& attrs) {
  return R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0"/>
    <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0" triangles="0 1 2  1 3 2"/>
    <TriangleSetTopologyModifier name="mod"/>
    <TriangularQuadraticSpringsForceField name="ff" youngModulus="60" poissonRatio="0.3" )" + attrs + R"(/>
  </Node>)";
}

double energy_at(ForceField& ff, MechanicalState& s, const std::vector<double>& x) {
  force_at(ff, s, x);
  return *ff.potential_energy();
}

std::vector<double> minus_energy_gradient(ForceField& ff, MechanicalState& st, const std::vector<double>& x) {
  const double h = 1e-6;
  std::vector<double> g(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    g[i] = -(energy_at(ff, st, xp) - energy_at(ff, st, xm)) / (2 * h);
  }
  return g;
}
}  // namespace

TEST(TriangularQuadraticSprings, ConstantsFromTheRestCotangents) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto* ff = get<TriangularQuadraticSpringsForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  const double E = 60, nu = 0.3, lambda = E * nu / (1 - nu * nu), mu = E * (1 - nu) / (1 - nu * nu);
  EXPECT_DOUBLE_EQ(ff->lambda(), lambda);
  EXPECT_DOUBLE_EQ(ff->mu(), mu);
  // Triangle 0 = (0,0,0) (1,0,0) (0,1,0): area 1/2; cotangents 0 at vertex 0, 1 at vertices 1 and 2;
  // rest lengths √2 (edge opposite 0), 1, 1.
  const auto& t = ff->triangle_info()[0];
  const double lm = lambda + mu;
  EXPECT_NEAR(t.stiffness[0], 2 * mu / 4, 1e-12);
  EXPECT_NEAR(t.stiffness[1], (2 * lm + mu) / 4, 1e-12);
  EXPECT_NEAR(t.gamma[0], (2 * lm - mu) / 4, 1e-12);                  // l1·l2 = 1, c1·c2 = 1
  EXPECT_NEAR(t.gamma[1], -std::sqrt(2.0) * mu / 4, 1e-12);           // l2·l0 = √2, c2·c0 = 0
  // The edge stiffness is the sum over the triangles holding it.
  const auto& topo = *ff->topology;
  for (std::size_t e = 0; e < topo.edges().size(); ++e) {
    double sum = 0;
    for (std::size_t i = 0; i < topo.triangles().size(); ++i)
      for (int j = 0; j < 3; ++j)
        if (topo.edges_in_triangle()[i][j] == e) sum += ff->triangle_info()[i].stiffness[j];
    EXPECT_NEAR(ff->edge_info()[e].stiffness, sum, 1e-12) << "edge " << e;
  }
  // At rest nothing moves.
  MechanicalState& st = *s.root->mechanical_state;
  for (double f : force_at(*ff, st, st.read(kRestPosition))) EXPECT_EQ(f, 0.0);
}

TEST(TriangularQuadraticSprings, ForceIsMinusTheEnergyGradientAndDForceItsDerivative) {
  for (const char* attrs : {"useAngularSprings='0'", ""}) {
    SCOPED_TRACE(attrs);
    auto s = load(two_triangles(attrs));
    ASSERT_TRUE(s.root);
    auto& ff = *get<TriangularQuadraticSpringsForceField>(*s.root, "ff");
    MechanicalState& st = *s.root->mechanical_state;
    std::vector<double> x = st.read(kRestPosition);
    const auto w = wiggle(x.size(), 3);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.3 * x[i] + 0.08 * w[i];
    const auto f = force_at(ff, st, x);
    expect_near_rel(f, minus_energy_gradient(ff, st, x), 1e-7, "force vs -dE/dx");
    const auto dx = wiggle(x.size(), 11);
    force_at(ff, st, x);
    const auto exact = fd_force(ff, st, x, dx, 1e-6);
    const auto k = dforce(ff, st, dx);
    if (std::string(attrs).empty()) {
      // SOFA's angular tangent takes (c − s·l₀) where the derivative has (c − s·l): close, not exact.
      expect_near_rel(k, exact, 0.5, "SOFA's tangent with angular springs");
    } else {
      expect_near_rel(k, exact, 1e-7, "add_dforce vs finite differences");
    }
    // build_stiffness = add_dforce.
    const auto K = sinew::test::dense_stiffness(ff, st);
    std::vector<double> Kdx(x.size(), 0.0);
    for (std::size_t r = 0; r < x.size(); ++r)
      for (std::size_t c = 0; c < x.size(); ++c) Kdx[r] += K[r * x.size() + c] * dx[c];
    expect_near_rel(Kdx, k, 1e-12, "build_stiffness vs add_dforce");
  }
}

TEST(TriangularQuadraticSprings, TangentExactAtTheRestShape) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularQuadraticSpringsForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x = st.read(kRestPosition);
  force_at(ff, st, x);
  const auto dx = wiggle(x.size(), 7);
  const auto exact = fd_force(ff, st, x, dx, 1e-6);
  expect_near_rel(dforce(ff, st, dx), exact, 1e-7, "add_dforce at rest");
}

TEST(TriangularQuadraticSprings, EdgeAndTriangleDataFollowRemovalAndAddition) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularQuadraticSpringsForceField>(*s.root, "ff");
  auto& mod = *get<TriangleSetTopologyModifier>(*s.root, "mod");
  const auto& topo = *ff.topology;
  const auto before = ff.triangle_info()[1];
  // Removing triangle 0 (edges 0–1 and 0–2 go with it, the points stay): the shared edge keeps
  // the second triangle's stiffness only; triangle 1's data moves into slot 0.
  mod.remove_triangles({0}, true, false);
  ASSERT_EQ(topo.triangles().size(), 1u);
  ASSERT_EQ(ff.triangle_info().size(), 1u);
  ASSERT_EQ(ff.edge_info().size(), topo.edges().size());
  EXPECT_EQ(ff.triangle_info()[0].stiffness, before.stiffness);
  EXPECT_EQ(ff.triangle_info()[0].gamma, before.gamma);
  const auto& te = topo.edges_in_triangle()[0];
  const double* r = s.root->mechanical_state->read(kRestPosition).data();
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(ff.edge_info()[te[j]].stiffness, before.stiffness[j], 1e-12) << "edge " << j;
    const auto& e = topo.edges()[te[j]];
    const double d0 = r[3 * e[0]] - r[3 * e[1]], d1 = r[3 * e[0] + 1] - r[3 * e[1] + 1];
    EXPECT_NEAR(ff.edge_info()[te[j]].rest_length, std::sqrt(d0 * d0 + d1 * d1), 1e-12) << "edge " << j;
  }
  // The remaining triangle still works.
  MechanicalState& st = *s.root->mechanical_state;
  auto x = st.read(kRestPosition);
  x[3] += 0.1;
  for (double v : force_at(ff, st, x)) EXPECT_TRUE(std::isfinite(v));
  // Adding it back: the new edges get rest lengths, the triangle adds its stiffness to its edges.
  mod.add_triangles({{0, 1, 2}});
  ASSERT_EQ(ff.triangle_info().size(), 2u);
  ASSERT_EQ(ff.edge_info().size(), topo.edges().size());
  const auto& te1 = topo.edges_in_triangle()[1];
  for (int j = 0; j < 3; ++j) {
    const auto& e = topo.edges()[te1[j]];
    const double d0 = r[3 * e[0]] - r[3 * e[1]], d1 = r[3 * e[0] + 1] - r[3 * e[1] + 1];
    EXPECT_NEAR(ff.edge_info()[te1[j]].rest_length, std::sqrt(d0 * d0 + d1 * d1), 1e-12);
  }
  // Same constants as the fresh component (vertex order 0 1 2 kept).
  auto fresh = load(two_triangles(""));
  const auto& f0 = get<TriangularQuadraticSpringsForceField>(*fresh.root, "ff")->triangle_info()[0];
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(ff.triangle_info()[1].stiffness[j], f0.stiffness[j], 1e-12);
    EXPECT_NEAR(ff.triangle_info()[1].gamma[j], f0.gamma[j], 1e-12);
  }
  for (std::size_t e = 0; e < topo.edges().size(); ++e) {
    double sum = 0;
    for (std::size_t i = 0; i < topo.triangles().size(); ++i)
      for (int j = 0; j < 3; ++j)
        if (topo.edges_in_triangle()[i][j] == e) sum += ff.triangle_info()[i].stiffness[j];
    EXPECT_NEAR(ff.edge_info()[e].stiffness, sum, 1e-12) << "edge " << e;
  }
}

TEST(TriangularQuadraticSprings, BadInputIsAnErrorNamingTheComponent) {
  using namespace sinew::test;
  TempDir dir;
  auto scene = [](const std::string& topo) {
    return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
      <DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  2 0 0"/>)" +
           topo + R"(<UniformMass totalMass="1"/>
      <TriangularQuadraticSpringsForceField name="qs"/></Node>)";
  };
  // A flat triangle (0 1 3 are on a line).
  Outcome o = run_xml(dir, scene(R"(<TriangleSetTopologyContainer triangles="0 1 2  0 1 3"/>)"));
  EXPECT_TRUE(any_contains_all(o.errors, {"'qs'", "TriangularQuadraticSpringsForceField", "triangle 1", "degenerate"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
  // No topology.
  o = run_xml(dir, scene(""));
  EXPECT_TRUE(any_contains_all(o.errors, {"'qs'", "TriangularQuadraticSpringsForceField"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}
