// TriangularBiquadraticSpringsForceField: the per-triangle constants from the
// rest cotangents (hand-computed on a right isosceles triangle), forces =
// −∇E by central differences, add_dforce = the derivative of the forces
// (exactly for the springs; SOFA's regularised compression tangent close to
// it), build_stiffness = add_dforce, and edge/triangle data following
// triangle removal and addition as SOFA's topology data do.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/node.h"
#include "core/simulation.h"
#include "badinput_helpers.h"
#include "forcefield/spring/triangular_biquadratic_springs_force_field.h"
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
    <TriangularBiquadraticSpringsForceField name="ff" youngModulus="60" poissonRatio="0.3" )" + attrs + R"(/>
  </Node>)";
}

double energy_at(ForceField& ff, MechanicalState& s, const std::vector<double>& x) {
  force_at(ff, s, x);
  return *ff.potential_energy();
}
}  // namespace

TEST(TriangularBiquadraticSprings, ConstantsFromTheRestCotangents) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto* ff = get<TriangularBiquadraticSpringsForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  const double E = 60, nu = 0.3, lambda = E * nu / (1 - nu * nu), mu = E * (1 - nu) / (1 - nu * nu);
  EXPECT_DOUBLE_EQ(ff->lambda(), lambda);
  EXPECT_DOUBLE_EQ(ff->mu(), mu);
  // Triangle 0 = (0,0,0) (1,0,0) (0,1,0): area 1/2; cotangents 0 at vertex 0, 1 at vertices 1 and 2.
  const auto& t = ff->triangle_info()[0];
  EXPECT_DOUBLE_EQ(t.rest_area, 0.5);
  const double lm = lambda + mu;
  EXPECT_NEAR(t.stiffness[0], (0 + mu) / 8, 1e-12);
  EXPECT_NEAR(t.stiffness[1], (2 * lm + mu) / 8, 1e-12);
  EXPECT_NEAR(t.gamma[0], (2 * lm - mu) / 8, 1e-12);  // c1·c2 = 1
  EXPECT_NEAR(t.gamma[1], -mu / 8, 1e-12);            // c2·c0 = 0
  // At rest nothing moves.
  MechanicalState& st = *s.root->mechanical_state;
  for (double f : force_at(*ff, st, st.read(kRestPosition))) EXPECT_EQ(f, 0.0);
}

TEST(TriangularBiquadraticSprings, ForceIsMinusTheEnergyGradientAndDForceItsDerivative) {
  for (const char* attrs : {"compressible='0'", "useAngularSprings='0' compressible='0'", ""}) {
    SCOPED_TRACE(attrs);
    auto s = load(two_triangles(attrs));
    ASSERT_TRUE(s.root);
    auto& ff = *get<TriangularBiquadraticSpringsForceField>(*s.root, "ff");
    MechanicalState& st = *s.root->mechanical_state;
    std::vector<double> x = st.read(kRestPosition);
    const auto w = wiggle(x.size(), 3);
    // Stretched (so that the compression term is off) and out of plane.
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.3 * x[i] + 0.08 * w[i];
    const auto f = force_at(ff, st, x);
    // −∂E/∂x_i by central differences.
    const double h = 1e-6;
    std::vector<double> g(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      auto xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      g[i] = -(energy_at(ff, st, xp) - energy_at(ff, st, xm)) / (2 * h);
    }
    expect_near_rel(f, g, 1e-7, "force vs -dE/dx");
    // Without angular springs SOFA never updates the per-triangle edge vectors its tangent reads
    // (only the angular pass computes them), so its tangent keeps the −s·δ·I part alone.
    if (std::string(attrs).find("useAngularSprings='0'") != std::string::npos) continue;
    force_at(ff, st, x);
    const auto dx = wiggle(x.size(), 11);
    expect_near_rel(dforce(ff, st, dx), fd_force(ff, st, x, dx, 1e-6), 1e-7, "add_dforce vs finite differences");
  }
}

TEST(TriangularBiquadraticSprings, CompressionTermAndItsRegularisedTangent) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularBiquadraticSpringsForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kRestPosition);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] *= 0.9;  // J = 0.81
  force_at(ff, st, x);
  EXPECT_TRUE(ff.triangle_info()[0].compressed);
  EXPECT_NEAR(ff.triangle_info()[0].J, 0.81, 1e-12);
  // Energy gradient still exact; the tangent is SOFA's blend, close to the derivative.
  const auto f = force_at(ff, st, x);
  const double h = 1e-6;
  std::vector<double> g(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    g[i] = -(energy_at(ff, st, xp) - energy_at(ff, st, xm)) / (2 * h);
  }
  expect_near_rel(f, g, 1e-7, "force vs -dE/dx");
  force_at(ff, st, x);
  const auto dx = wiggle(x.size(), 5);
  // The blend weight is h = 1 − J = 0.19 here: entries are off by up to ~15% of the largest one.
  expect_near_rel(dforce(ff, st, dx), fd_force(ff, st, x, dx, 1e-6), 0.2, "regularised tangent");
}

TEST(TriangularBiquadraticSprings, EdgeAndTriangleDataFollowRemovalAndAddition) {
  auto s = load(two_triangles(""));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularBiquadraticSpringsForceField>(*s.root, "ff");
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
  const auto& te = topo.edges_in_triangle()[0];
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(ff.edge_info()[te[j]].stiffness, before.stiffness[j], 1e-12) << "edge " << j;
  // The remaining triangle still works: a step runs and stays finite.
  MechanicalState& st = *s.root->mechanical_state;
  ASSERT_EQ(st.size(), 4u);
  auto x = st.read(kRestPosition);
  x[3] += 0.1;
  const auto f = force_at(ff, st, x);
  for (double v : f) EXPECT_TRUE(std::isfinite(v));
  // Adding it back (with its two edges): the new edges get rest lengths, the triangle adds its
  // stiffness to its edges (the shared one now has both contributions).
  mod.add_triangles({{0, 1, 2}});
  ASSERT_EQ(ff.triangle_info().size(), 2u);
  ASSERT_EQ(ff.edge_info().size(), topo.edges().size());
  const auto& t1 = ff.triangle_info()[1];
  const auto& te1 = topo.edges_in_triangle()[1];
  for (int j = 0; j < 3; ++j) {
    const auto& e = topo.edges()[te1[j]];
    const double* r = st.read(kRestPosition).data();
    const double d0 = r[3 * e[0]] - r[3 * e[1]], d1 = r[3 * e[0] + 1] - r[3 * e[1] + 1];
    EXPECT_NEAR(ff.edge_info()[te1[j]].rest_square_length, d0 * d0 + d1 * d1, 1e-12);
  }
  EXPECT_GT(t1.rest_area, 0.0);
}

// ν = ±1 makes the Lamé pair of the triangle-edge force fields infinite: an error naming the
// component, which is switched off (the three share triangle_edge_lame).
TEST(TriangleEdgeForceFields, PoissonRatioOfOneIsAnError) {
  using namespace sinew::test;
  TempDir dir;
  for (const char* cls : {"TriangularBiquadraticSpringsForceField", "TriangularQuadraticSpringsForceField",
                          "TriangularTensorMassForceField"})
    for (const char* nu : {"1", "-1"}) {
      const Outcome o = run_xml(dir, std::string(R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
        <DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
        <MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
        <TriangleSetTopologyContainer triangles="0 1 2"/>
        <UniformMass totalMass="1"/>
        <)") + cls + R"( name="ff" poissonRatio=")" + nu + R"("/></Node>)");
      EXPECT_TRUE(any_contains_all(o.errors, {"'ff'", cls, "infinite Lamé"})) << cls << " ν=" << nu << o.all();
      EXPECT_FALSE(o.init_ok) << cls;
    }
}

// A triangle of zero rest area is an error naming it, for the three (triangle_rest_cotangents).
TEST(TriangleEdgeForceFields, DegenerateTriangleIsAnErrorNamingIt) {
  using namespace sinew::test;
  TempDir dir;
  for (const char* cls : {"TriangularBiquadraticSpringsForceField", "TriangularQuadraticSpringsForceField",
                          "TriangularTensorMassForceField"}) {
    const Outcome o = run_xml(dir, std::string(R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
        <DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
        <MechanicalObject position="0 0 0  1 0 0  0 1 0  2 0 0"/>
        <TriangleSetTopologyContainer triangles="0 1 2  0 1 3"/>
        <UniformMass totalMass="1"/>
        <)") + cls + R"( name="ff"/></Node>)");
    EXPECT_TRUE(any_contains_all(o.errors, {"'ff'", cls, "triangle 1", "degenerate"})) << cls << o.all();
    EXPECT_FALSE(o.init_ok) << cls;
  }
}
