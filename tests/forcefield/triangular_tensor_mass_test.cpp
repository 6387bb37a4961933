// TriangularTensorMassForceField: the edge tensors (hand-computed on a right
// isosceles triangle), linear forces with a symmetric tangent (forces = −∇E,
// add_dforce = the derivative, build_stiffness = add_dforce), edge tensors
// following triangle removal and addition as SOFA's edge data do, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "badinput_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "forcefield/fem/triangular_tensor_mass_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

using namespace sinew;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;
using sinew::test::wiggle;

namespace {
std::string mesh(const std::string& triangles) {
  return R"(<Node name="root" gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0.2"/>
    <TriangleSetTopologyContainer name="topo" position="0 0 0  1 0 0  0 1 0  1.1 0.9 0.2" triangles=")" +
         triangles + R"("/>
    <TriangleSetTopologyModifier name="mod"/>
    <TriangularTensorMassForceField name="ff" youngModulus="60" poissonRatio="0.3"/>
  </Node>)";
}

// The tensor of the edge (a, b) of `ff`, oriented as a → b (transposed when stored b → a).
Mat3 tensor_of(const TriangularTensorMassForceField& ff, unsigned a, unsigned b) {
  const auto& edges = ff.topology->edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e][0] == a && edges[e][1] == b) return ff.edge_tensors()[e];
    if (edges[e][0] == b && edges[e][1] == a) return ff.edge_tensors()[e].transpose();
  }
  ADD_FAILURE() << "no edge " << a << " " << b;
  return Mat3::Zero();
}

void expect_same_tensors(const TriangularTensorMassForceField& ff, const TriangularTensorMassForceField& ref) {
  ASSERT_EQ(ff.edge_tensors().size(), ff.topology->edges().size());
  ASSERT_EQ(ff.topology->edges().size(), ref.topology->edges().size());
  for (std::size_t e = 0; e < ff.topology->edges().size(); ++e) {
    const auto& ed = ff.topology->edges()[e];
    const Mat3 r = tensor_of(ref, ed[0], ed[1]);
    for (int u = 0; u < 3; ++u)
      for (int v = 0; v < 3; ++v) EXPECT_NEAR(ff.edge_tensors()[e](u, v), r(u, v), 1e-12) << "edge " << e;
  }
}
}  // namespace

TEST(TriangularTensorMass, EdgeTensorsOfARightTriangle) {
  auto s = load(mesh("0 1 2"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularTensorMassForceField>(*s.root, "ff");
  ASSERT_EQ(ff.state(), ComponentState::valid);
  const double E = 60, nu = 0.3, lambda = E * nu / (1 - nu * nu), mu = E * (1 - nu) / (1 - nu * nu);
  // Area 1/2: λ* = λ/2, μ* = μ/4; cotangents 0, 1, 1.
  // Edge opposite 0, oriented 2 → 1: λ*(p0−p1)(p0−p2)ᵀ + μ*(p0−p2)(p0−p1)ᵀ − 0·I.
  Mat3 d = tensor_of(ff, 2, 1);
  EXPECT_NEAR(d(0, 1), lambda / 2, 1e-12);
  EXPECT_NEAR(d(1, 0), mu / 4, 1e-12);
  EXPECT_NEAR(d(0, 0), 0, 1e-12);
  EXPECT_NEAR(d(2, 2), 0, 1e-12);
  // Edge opposite 1 (k = 2, l = 0), oriented 0 → 2: dpl = p1−p2 = (1,−1,0), dpk = p1−p0 = (1,0,0);
  // diagonal −c₁(λ+μ)/2 = −(λ+μ)/2.
  d = tensor_of(ff, 0, 2);
  EXPECT_NEAR(d(0, 0), lambda / 2 + mu / 4 - (lambda + mu) / 2, 1e-12);
  EXPECT_NEAR(d(1, 0), -lambda / 2, 1e-12);
  EXPECT_NEAR(d(0, 1), -mu / 4, 1e-12);
  EXPECT_NEAR(d(1, 1), -(lambda + mu) / 2, 1e-12);
  EXPECT_NEAR(d(2, 2), -(lambda + mu) / 2, 1e-12);
  MechanicalState& st = *s.root->mechanical_state;
  for (double f : force_at(ff, st, st.read(kRestPosition))) EXPECT_EQ(f, 0.0);
}

TEST(TriangularTensorMass, LinearForcesOfASymmetricTangent) {
  auto s = load(mesh("0 1 2  1 3 2"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularTensorMassForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.read(kRestPosition);
  const auto w = wiggle(x.size(), 3);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 1.2 * x[i] + 0.1 * w[i];
  sinew::test::expect_consistent_energy_and_tangent(ff, st, x, 11, 1e-7, 1e-12);
}

TEST(TriangularTensorMass, EdgeTensorsFollowRemovalAndAddition) {
  auto s = load(mesh("0 1 2  1 3 2"));
  ASSERT_TRUE(s.root);
  auto& ff = *get<TriangularTensorMassForceField>(*s.root, "ff");
  auto& mod = *get<TriangleSetTopologyModifier>(*s.root, "mod");
  // Removing triangle 0 (its two own edges go, the points stay): the tensors are those of
  // triangle 1 alone.
  mod.remove_triangles({0}, true, false);
  ASSERT_EQ(ff.edge_tensors().size(), ff.topology->edges().size());
  ASSERT_EQ(ff.edge_tensors().size(), 3u);
  auto alone = load(mesh("1 3 2"));
  expect_same_tensors(ff, *get<TriangularTensorMassForceField>(*alone.root, "ff"));
  // Adding it back: the new edges start at 0 and the triangle adds its terms.
  mod.add_triangles({{0, 1, 2}});
  ASSERT_EQ(ff.edge_tensors().size(), 5u);
  auto both = load(mesh("0 1 2  1 3 2"));
  expect_same_tensors(ff, *get<TriangularTensorMassForceField>(*both.root, "ff"));
}

TEST(TriangularTensorMass, BadInputIsAnErrorNamingTheComponent) {
  using namespace sinew::test;
  TempDir dir;
  auto scene = [](const std::string& topo) {
    return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
      <DefaultAnimationLoop/><EulerImplicitSolver/><CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  2 0 0"/>)" +
           topo + R"(<UniformMass totalMass="1"/>
      <TriangularTensorMassForceField name="tm"/></Node>)";
  };
  Outcome o = run_xml(dir, scene(R"(<TriangleSetTopologyContainer triangles="0 1 2  0 1 3"/>)"));
  EXPECT_TRUE(any_contains_all(o.errors, {"'tm'", "TriangularTensorMassForceField", "triangle 1", "degenerate"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
  o = run_xml(dir, scene(""));
  EXPECT_TRUE(any_contains_all(o.errors, {"'tm'", "TriangularTensorMassForceField"})) << o.all();
  EXPECT_FALSE(o.init_ok);
}
