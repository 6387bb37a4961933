// TetrahedronDiffusionFEMForceField: the edge coefficients are the off-diagonal
// entries D·V·∇N_k·∇N_l of the P1 finite-element Laplacian (hand-computed on
// the unit tetrahedron), a linear field is in equilibrium at interior points
// (patch test), the fluxes are pairwise (they sum to zero), add_dforce and the
// assembled matrix apply the same coefficients; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "badinput_helpers.h"
#include "core/simulation.h"
#include "forcefield/diffusion/tetrahedron_diffusion_fem_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

namespace sinew::tetrahedron_diffusion_test {

using test::dforce;
using test::force_at;
using test::get;
using test::load;

namespace {
// Geometry (tagged "mechanics") in the root, the Vec1 field in a child node.
std::string diffusion_scene(const std::string& geometry, const std::string& attrs, const std::string& field) {
  return R"(<Node name="root" gravity="0 0 0">)" + geometry + R"(
    <Node name="heat"><MechanicalObject template="Vec1" name="u" position=")" + field + R"("/>
      <TetrahedronDiffusionFEMForceField template="Vec1" name="ff" topology="@../topo" tagMechanics="mechanics" )" +
         attrs + R"(/></Node></Node>)";
}
const char* kUnitTet = R"(<MechanicalObject name="geo" tags="mechanics" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
    <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3"/>)";
}  // namespace

TEST(TetrahedronDiffusion, EdgeCoefficientsAreTheP1Laplacian) {
  auto s = load(diffusion_scene(kUnitTet, R"(constantDiffusionCoefficient="3")", "0 0 0 0"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TetrahedronDiffusionFEMForceField>(*s.root->find_child_named("heat"), "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  // ∇N0 = (−1,−1,−1), ∇N1 = x̂, ∇N2 = ŷ, ∇N3 = ẑ, V = 1/6: edges from 0 get 3·(−1)/6,
  // edges between 1, 2, 3 get 0.
  const auto& edges = ff.topology->edges();
  ASSERT_EQ(ff.edge_coefficients().size(), 6u);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool from0 = edges[e][0] == 0 || edges[e][1] == 0;
    EXPECT_NEAR(ff.edge_coefficients()[e], from0 ? -0.5 : 0.0, 1e-15) << "edge " << e;
  }
  // Field u = (0, 1, 0, 0): only edge (0, 1) carries a flux: f1 = c·(u1 − u0) = −0.5, f0 = +0.5.
  MechanicalState& st = *s.root->find_child_named("heat")->mechanical_state;
  const auto f = force_at(ff, st, {0, 1, 0, 0});
  EXPECT_NEAR(f[0], 0.5, 1e-15);
  EXPECT_NEAR(f[1], -0.5, 1e-15);
  EXPECT_NEAR(f[2], 0.0, 1e-15);
  EXPECT_NEAR(f[3], 0.0, 1e-15);
}

TEST(TetrahedronDiffusion, LinearFieldIsInEquilibriumInside) {
  const std::string geometry = R"(<RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 1.5 1"/>
    <MechanicalObject name="geo" tags="mechanics"/>
    <TetrahedronSetTopologyContainer name="topo"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topo"/>)";
  // u = 2x − y + 3z at the 27 grid points (x fastest).
  std::string field;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) field += std::to_string(2 * (i * 1.0) - j * 0.75 + 3 * (k * 0.5)) + " ";
  auto s = load(diffusion_scene(geometry, R"(constantDiffusionCoefficient="7")", field));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TetrahedronDiffusionFEMForceField>(*s.root->find_child_named("heat"), "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  MechanicalState& st = *s.root->find_child_named("heat")->mechanical_state;
  const auto f = force_at(ff, st, st.read(kPosition));
  EXPECT_NEAR(f[13], 0.0, 1e-12);  // the centre point (1, 1, 1) of the grid
  double sum = 0, largest = 0;
  for (double v : f) {
    sum += v;
    largest = std::max(largest, std::fabs(v));
  }
  EXPECT_NEAR(sum, 0.0, 1e-12);  // pairwise fluxes
  EXPECT_GT(largest, 1.0);       // the boundary points do receive flux
  // add_dforce (linear: the same operator) and the assembled matrix.
  std::vector<double> du(27);
  for (int i = 0; i < 27; ++i) du[i] = std::sin(0.7 * i);
  const auto df = dforce(ff, st, du, 2.0);
  const auto fu = force_at(ff, st, du);
  for (int i = 0; i < 27; ++i) EXPECT_NEAR(df[i], 2.0 * fu[i], 1e-12);
  const auto K = sinew::test::dense_stiffness(ff, st);
  for (int r = 0; r < 27; ++r) {
    double kdu = 0;
    for (int c = 0; c < 27; ++c) kdu += K[r * 27 + c] * du[c];
    EXPECT_NEAR(kdu, fu[r], 1e-12);
  }
}

TEST(TetrahedronDiffusion, BadInputIsAnError) {
  using namespace sinew::test;
  TempDir dir;
  auto run = [&](const std::string& geometry, const std::string& attrs) {
    return run_xml(dir, R"(<Node name="root" gravity="0 0 0" dt="0.01"><DefaultAnimationLoop/>)" + geometry +
                            R"(<Node name="heat"><EulerImplicitSolver/><CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject template="Vec1" position="0 0 0 0"/><UniformMass template="Vec1" totalMass="1"/>
      <TetrahedronDiffusionFEMForceField template="Vec1" name="df" topology="@../topo" )" + attrs +
                            "/></Node></Node>");
  };
  Outcome o = run(kUnitTet, R"(tagMechanics="nothing")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'df'", "nothing"})) << o.all();
  o = run(kUnitTet, R"(tagMechanics="mechanics" tetraDiffusionCoefficient="1 2")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'df'", "tetraDiffusionCoefficient"})) << o.all();
  o = run(R"(<MechanicalObject name="geo" tags="mechanics" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
    <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3"/>)", R"(tagMechanics="mechanics")");
  EXPECT_TRUE(any_contains_all(o.errors, {"'df'", "degenerate"})) << o.all();
  o = run(kUnitTet, R"(tagMechanics="mechanics")");
  EXPECT_TRUE(o.init_ok) << o.all();
}

}  // namespace sinew::tetrahedron_diffusion_test
