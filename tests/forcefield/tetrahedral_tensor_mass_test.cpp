// TetrahedralTensorMassForceField: the edge tensors give exactly linear
// elasticity (the forces of TetrahedronFEMForceField's small-strain method on
// the same mesh, E and ν), forces = −∇E, add_dforce = the derivative and
// build_stiffness = add_dforce; the tensors follow tetrahedron removal and
// addition (removal equals a rebuild, where SOFA adds terms back); bad input.
#include <gtest/gtest.h>

#include <string>

#include "badinput_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "forcefield/fem/tetrahedral_tensor_mass_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

namespace sinew::tetrahedral_tensor_mass_test {

using test::expect_near_rel;
using test::force_at;
using test::get;
using test::load;
using test::wiggle;

namespace {
const char* kPoints = "0 0 0  1 0 0  0 1 0  0 0 1  1.1 0.9 0.8  -0.3 0.4 1.2";

std::string mesh(const std::string& tetrahedra, const std::string& force_field) {
  return std::string(R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="dofs" position=")") + kPoints + R"("/>
    <TetrahedronSetTopologyContainer name="topo" position=")" + kPoints + R"(" tetrahedra=")" + tetrahedra + R"("/>
    <TetrahedronSetTopologyModifier name="mod"/>)" + force_field + "</Node>";
}
const char* kTensor = R"(<TetrahedralTensorMassForceField name="ff" youngModulus="60" poissonRatio="0.3"/>)";
const char* kFem = R"(<TetrahedronFEMForceField name="ff" method="small" youngModulus="60" poissonRatio="0.3"/>)";
const char* kThree = "0 1 2 3  3 2 1 4  0 2 3 5";  // the second one against the stored edges

// The tensor of the edge (a, b), oriented a → b; zero when `ff` has no such edge.
Mat3 tensor_of(const TetrahedralTensorMassForceField& ff, unsigned a, unsigned b) {
  const auto& edges = ff.topology->edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e][0] == a && edges[e][1] == b) return ff.edge_tensors()[e];
    if (edges[e][0] == b && edges[e][1] == a) return ff.edge_tensors()[e].transpose();
  }
  return Mat3::Zero();
}

// Every edge of `ff` has the tensor `ref` gives it (zero for an edge of no element of `ref`).
void expect_same_tensors(const TetrahedralTensorMassForceField& ff, const TetrahedralTensorMassForceField& ref) {
  ASSERT_EQ(ff.edge_tensors().size(), ff.topology->edges().size());
  ASSERT_GE(ff.topology->edges().size(), ref.topology->edges().size());
  for (std::size_t e = 0; e < ff.topology->edges().size(); ++e) {
    const auto& ed = ff.topology->edges()[e];
    const Mat3 r = tensor_of(ref, ed[0], ed[1]);
    for (int u = 0; u < 3; ++u)
      for (int v = 0; v < 3; ++v) EXPECT_NEAR(ff.edge_tensors()[e](u, v), r(u, v), 1e-12) << "edge " << e;
  }
}

std::vector<double> displaced(const MechanicalState& st, unsigned seed) {
  std::vector<double> x = st.read(kRestPosition);
  const auto w = wiggle(x.size(), seed);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.01 * w[i];
  return x;
}
}  // namespace

TEST(TetrahedralTensorMass, ForcesAreThoseOfLinearElasticity) {
  for (const char* tets : {"0 1 2 3", kThree}) {
    auto t = load(mesh(tets, kTensor));
    auto f = load(mesh(tets, kFem));
    ASSERT_TRUE(t.root && f.root);
    auto& tm = *get<TetrahedralTensorMassForceField>(*t.root, "ff");
    ASSERT_EQ(tm.state(), ComponentState::valid);
    MechanicalState& st = *t.root->mechanical_state;
    MechanicalState& sf = *f.root->mechanical_state;
    for (unsigned seed : {3u, 7u}) {
      const auto x = displaced(st, seed);
      const auto ft = force_at(tm, st, x);
      const auto ff = force_at(*get<ForceField>(*f.root, "ff"), sf, x);
      EXPECT_GT(sinew::test::max_abs(ft), 0.01);
      expect_near_rel(ft, ff, 1e-10, "tensor mass vs small-strain FEM");
    }
    // At rest: no force.
    for (double v : force_at(tm, st, st.read(kRestPosition))) EXPECT_EQ(v, 0.0);
  }
}

TEST(TetrahedralTensorMass, LinearForcesOfASymmetricTangent) {
  auto s = load(mesh(kThree, kTensor));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TetrahedralTensorMassForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kRestPosition);
  const auto w = wiggle(x.size(), 5);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.1 * x[i] + 0.1 * w[i];
  sinew::test::expect_consistent_energy_and_tangent(ff, st, x, 13, 1e-7, 1e-9);
}

TEST(TetrahedralTensorMass, EdgeTensorsFollowRemovalAndAddition) {
  auto s = load(mesh(kThree, kTensor));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TetrahedralTensorMassForceField>(*s.root, "ff");
  auto& mod = *get<TetrahedronSetTopologyModifier>(*s.root, "mod");
  // Removing tetrahedron 1 (its faces, edges and point 4 stay, isolated): the tensors are
  // those of the two others alone, zero on the edges of no tetrahedron.
  mod.remove_tetrahedra({1}, false);
  ASSERT_EQ(ff.edge_tensors().size(), ff.topology->edges().size());
  auto rest = load(mesh("0 1 2 3  0 2 3 5", kTensor));
  expect_same_tensors(ff, *get<TetrahedralTensorMassForceField>(*rest.root, "ff"));
  // Adding it back: the new edges start at 0 and the tetrahedron adds its terms.
  mod.add_tetrahedra({{3, 2, 1, 4}});
  auto all = load(mesh(kThree, kTensor));
  expect_same_tensors(ff, *get<TetrahedralTensorMassForceField>(*all.root, "ff"));
}

TEST(TetrahedralTensorMass, BadInputIsAnErrorNamingTheComponent) {
  using namespace sinew::test;
  TempDir dir;
  auto scene = [](const std::string& topo, const std::string& attrs) {
    return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
      <DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  2 0 0"/>)" +
           topo + R"(<UniformMass totalMass="1"/>
      <TetrahedralTensorMassForceField name="tm" )" + attrs + "/></Node>";
  };
  Outcome o = run_xml(dir, scene(R"(<TetrahedronSetTopologyContainer tetrahedra="0 1 2 3  0 1 4 2"/>)", ""));
  EXPECT_TRUE(any_contains_all(o.errors, {"'tm'", "TetrahedralTensorMassForceField", "tetrahedron 1", "degenerate"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
  o = run_xml(dir, scene(R"(<TetrahedronSetTopologyContainer tetrahedra="0 1 2 3"/>)", R"(poissonRatio="0.5")"));
  EXPECT_TRUE(any_contains_all(o.errors, {"'tm'", "poissonRatio", "infinite"})) << o.all();
  EXPECT_FALSE(o.init_ok);
  o = run_xml(dir, scene("", ""));
  EXPECT_TRUE(any_contains_all(o.errors, {"'tm'", "TetrahedralTensorMassForceField"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}

}  // namespace sinew::tetrahedral_tensor_mass_test
