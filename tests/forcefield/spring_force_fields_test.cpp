// Springs and loads (spec/mechanics.md §3.1–3.11): forces = −∇energy and
// add_dforce = finite differences of add_force, build_stiffness = add_dforce,
// spring generation rules, and the energy of an undamped explicit spring
// system over 10k steps.
#include <gtest/gtest.h>

#include <cmath>

#include "forcefield/load/constant_force_field.h"
#include "forcefield/spring/quadular_bending_springs.h"
#include "forcefield/load/interaction_ellipsoid_force_field.h"
#include "forcefield/spring/mesh_spring_force_field.h"
#include "forcefield/load/plane_force_field.h"
#include "forcefield/spring/quad_bending_springs.h"
#include "forcefield/spring/regular_grid_spring_force_field.h"
#include "forcefield/spring/rest_shape_springs_force_field.h"
#include "forcefield/spring/spring_force_field.h"
#include "forcefield/load/triangle_pressure_force_field.h"
#include "forcefield/load/uniform_velocity_damping_force_field.h"
#include "spring_helpers.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::dense_stiffness;
using sinew::test::dforce;
using sinew::test::expect_near_rel;
using sinew::test::fd_force;
using sinew::test::force_at;
using sinew::test::get;
using sinew::test::load;
using sinew::test::wiggle;

namespace {

const char* kTriangleOfSprings = R"(<Node gravity="0 0 0">
  <MechanicalObject name="dofs" position="0 0 0  1.2 0.1 0  0.3 1.1 0.2  -0.4 0.5 1.0"/>
  <SpringForceField name="ff" spring="0 1 50 0 1  1 2 30 0 1.5  0 2 20 0 0.8  2 3 40 0 0.9  0 3 10 0 1.3"/>
</Node>)";

// SpringForceField energy as written in the spec: Σ ½ ks (|x_b − x_a| − L0)².
double spring_energy(const SpringForceField& ff, const std::vector<double>& x) {
  double e = 0;
  for (const auto& s : ff.spring_list()) {
    const double d = std::sqrt(std::pow(x[3 * s.m2] - x[3 * s.m1], 2) + std::pow(x[3 * s.m2 + 1] - x[3 * s.m1 + 1], 2) +
                               std::pow(x[3 * s.m2 + 2] - x[3 * s.m1 + 2], 2));
    e += 0.5 * s.ks * (d - s.l0) * (d - s.l0);
  }
  return e;
}

}  // namespace

TEST(SpringForceField, ParsesTheFiveNumberSpringList) {
  auto s = load(kTriangleOfSprings);
  auto* ff = get<SpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->spring_list().size(), 5u);
  EXPECT_EQ(ff->spring_list()[1].m1, 1u);
  EXPECT_EQ(ff->spring_list()[1].m2, 2u);
  EXPECT_EQ(ff->spring_list()[1].ks, 30.0);
  EXPECT_EQ(ff->spring_list()[1].kd, 0.0);
  EXPECT_EQ(ff->spring_list()[1].l0, 1.5);
  EXPECT_TRUE(ff->is_interaction());
}

TEST(SpringForceField, ForceIsMinusTheGradientOfTheEnergy) {
  auto s = load(kTriangleOfSprings);
  auto* ff = get<SpringForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x = st.write(kPosition);
  const auto f = force_at(*ff, st, x);
  EXPECT_NEAR(ff->potential_energy().value(), spring_energy(*ff, x), 1e-12);
  const double h = 1e-6;
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const double g = (spring_energy(*ff, xp) - spring_energy(*ff, xm)) / (2 * h);
    EXPECT_NEAR(f[i], -g, 1e-6) << "dof " << i;
  }
}

TEST(SpringForceField, DForceMatchesFiniteDifferencesAndTheAssembledMatrix) {
  auto s = load(kTriangleOfSprings);
  auto* ff = get<SpringForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const std::vector<double> x = st.write(kPosition);
  const auto dx = wiggle(x.size(), 3);
  const auto fd = fd_force(*ff, st, x, dx, 1e-6);
  const auto df = dforce(*ff, st, dx);
  expect_near_rel(df, fd, 1e-6, "add_dforce vs FD");
  // kfactor scales linearly.
  const auto df2 = dforce(*ff, st, dx, -0.5);
  for (std::size_t i = 0; i < df.size(); ++i) EXPECT_NEAR(df2[i], -0.5 * df[i], 1e-12);
  // build_stiffness holds the same ∂f/∂x.
  const auto K = dense_stiffness(*ff, st);
  const std::size_t n = x.size();
  std::vector<double> Kdx(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) Kdx[r] += K[r * n + c] * dx[c];
  expect_near_rel(Kdx, df, 1e-12, "build_stiffness vs add_dforce");
}

// SOFA's tangent deliberately puts the whole force intensity (damping included)
// in the geometric term F/d·(I − ûûᵀ): with a relative velocity the tangent is
// not ∂f/∂x at fixed v.
TEST(SpringForceField, TangentIncludesTheDampingForce) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  2 0 0" velocity="0 0 0  3 0 0"/>
    <SpringForceField name="ff" spring="0 1 10 4 2"/>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  // At rest length: F = kd·(û·Δv) = 4·3 = 12 along x.
  EXPECT_DOUBLE_EQ(f[0], 12.0);
  EXPECT_DOUBLE_EQ(f[3], -12.0);
  // Transverse dx of point 1: SOFA's K·δ = F/d·δ = 6·δ.
  const auto df = dforce(*ff, st, {0, 0, 0, 0, 1, 0});
  EXPECT_DOUBLE_EQ(df[1], 6.0);
  EXPECT_DOUBLE_EQ(df[4], -6.0);
}

TEST(SpringForceField, SplitListsAreResizedWithTheirLastValue) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0"/>
    <SpringForceField name="ff" indices1="0 1" indices2="1 2" stiffness="7" damping="1 2 3" lengths="0.5"/>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  ASSERT_EQ(ff->spring_list().size(), 2u);
  EXPECT_EQ(ff->spring_list()[1].ks, 7.0);
  EXPECT_EQ(ff->spring_list()[1].kd, 2.0);
  EXPECT_EQ(ff->spring_list()[1].l0, 0.5);
}

TEST(SpringForceField, OutOfRangeIndexIsRefusedWithTheSpringNamed) {
  auto s = sinew::test::build(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <SpringForceField name="ff" spring="0 1 1 0 1  1 5 1 0 1"/>
  </Node>)");
  init_root(*s.root);
  auto* ff = get<SpringForceField>(*s.root, "ff");
  EXPECT_EQ(ff->state(), ComponentState::invalid);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(s.root->diagnostics(), Severity::error), "spring 1"));
}

TEST(SpringForceField, ActsBetweenTwoStates) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="A"><MechanicalObject name="a" position="0 0 0"/></Node>
    <Node name="B"><MechanicalObject name="b" position="0 3 0"/></Node>
    <SpringForceField name="ff" object1="@A/a" object2="@B/b" spring="0 0 10 0 1"/>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  auto states = ff->states();
  ASSERT_EQ(states.size(), 2u);
  for (auto* st : states) std::fill(st->write(kForce).begin(), st->write(kForce).end(), 0.0);
  ff->add_force(MechParams{});
  EXPECT_DOUBLE_EQ(states[0]->write(kForce)[1], 20.0);   // pulled towards b
  EXPECT_DOUBLE_EQ(states[1]->write(kForce)[1], -20.0);  // and b towards a
  MatrixSink sink;
  ff->build_stiffness(sink);
  bool cross = false;
  for (const auto& e : sink.entries())
    if (e.row_state == states[0] && e.col_state == states[1] && e.row == 1 && e.col == 1) {
      EXPECT_DOUBLE_EQ(e.value, 10.0);
      cross = true;
    }
  EXPECT_TRUE(cross);
}

// States sized at their own init (positions from the node's topology) in child
// nodes, which are initialised after the force field above them: the spring
// ends are checked once every state is initialised (SOFA's
// StiffSpringForceField.scn, whose cubes take their positions from loaders).
TEST(SpringForceField, StatesOfChildNodesSizedAtTheirInit) {
  auto s = load(R"(<Node gravity="0 0 0">
    <SpringForceField name="ff" object1="@A/a" object2="@B/b" spring="1 0 10 0.5 1"/>
    <Node name="A"><MeshTopology position="0 0 0  1 0 0"/><MechanicalObject name="a"/></Node>
    <Node name="B"><MeshTopology position="1 3 0  5 5 5"/><MechanicalObject name="b"/></Node>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  auto states = ff->states();
  ASSERT_EQ(states.size(), 2u);
  ASSERT_EQ(states[0]->size(), 2u);
  ASSERT_EQ(states[1]->size(), 2u);
  // u = b0 − a1 = (0, 3, 0): d = 3, e = 2; ė = û·(v_b0 − v_a1) = −2; F = 10·2 + 0.5·(−2) = 19.
  states[0]->write(kVelocity) = {0, 0, 0, 0, 1, 0};
  states[1]->write(kVelocity) = {0, -1, 0, 0, 0, 0};
  for (auto* st : states) std::fill(st->write(kForce).begin(), st->write(kForce).end(), 0.0);
  ff->add_force(MechParams{});
  EXPECT_EQ(states[0]->read(kForce), (std::vector<double>{0, 0, 0, 0, 19, 0}));
  EXPECT_EQ(states[1]->read(kForce), (std::vector<double>{0, -19, 0, 0, 0, 0}));
  // K = (ks − F/d)·ûûᵀ + (F/d)·I: the y entry is ks = 10, the others F/d = 19/3.
  MatrixSink sink;
  ff->build_stiffness(sink);
  for (const auto& e : sink.entries())
    if (e.row_state == states[0] && e.col_state == states[1] && e.row == 3 && e.col == 0) {
      EXPECT_NEAR(e.value, 19.0 / 3.0, 1e-15);
    }
  // An end still out of range once the states are initialised is refused.
  auto bad = sinew::test::build(R"(<Node gravity="0 0 0">
    <SpringForceField name="ff" object1="@A/a" object2="@B/b" spring="1 2 10 0.5 1"/>
    <Node name="A"><MeshTopology position="0 0 0  1 0 0"/><MechanicalObject name="a"/></Node>
    <Node name="B"><MeshTopology position="1 3 0  5 5 5"/><MechanicalObject name="b"/></Node>
  </Node>)");
  init_root(*bad.root);
  EXPECT_EQ(get<SpringForceField>(*bad.root, "ff")->state(), ComponentState::invalid);
  EXPECT_TRUE(sinew::test::any_contains(sinew::test::messages(bad.root->diagnostics(), Severity::error),
                                        "spring 0 (1, 2) refers to a point out of range (object1 has 2 points, "
                                        "object2 2)"));
}

// Within one solver scope an interaction spring is implicit: two states joined
// by springs step as the same points in one state with the same springs.
TEST(SpringForceField, InteractionSpringsInsideASolverScopeAreImplicit) {
  const std::string solver = R"(<DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <CGLinearSolver iterations="200" tolerance="1e-20" threshold="1e-30"/>)";
  auto two = load(R"(<Node gravity="0 -10 0" dt="0.05">)" + solver + R"(
    <SpringForceField name="ext" object1="@A/a" object2="@B/b" spring="1 0 2000 1 1  1 1 2000 1 1.2"/>
    <Node name="A"><MeshTopology position="0 0 0  1 0 0"/><MechanicalObject name="a"/>
      <UniformMass vertexMass="0.5"/><FixedProjectiveConstraint indices="0"/>
      <SpringForceField spring="0 1 2000 1 1"/></Node>
    <Node name="B"><MeshTopology position="1 -1 0  1.5 -1.5 0.5"/><MechanicalObject name="b"/>
      <UniformMass vertexMass="0.5"/><SpringForceField spring="0 1 2000 1 0.8"/></Node>
  </Node>)");
  auto one = load(R"(<Node gravity="0 -10 0" dt="0.05">)" + solver + R"(
    <MechanicalObject name="ab" position="0 0 0  1 0 0  1 -1 0  1.5 -1.5 0.5"/>
    <UniformMass vertexMass="0.5"/><FixedProjectiveConstraint indices="0"/>
    <SpringForceField spring="0 1 2000 1 1  2 3 2000 1 0.8  1 2 2000 1 1  1 3 2000 1 1.2"/>
  </Node>)");
  MechanicalState& a = *get<MechanicalState>(*two.root->children()[0], "a");
  MechanicalState& b = *get<MechanicalState>(*two.root->children()[1], "b");
  MechanicalState& ab = *one.root->mechanical_state;
  for (int step = 0; step < 100; ++step) {
    animate(*two.root);
    animate(*one.root);
  }
  const auto& x = ab.read(kPosition);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(a.read(kPosition)[i], x[i], 1e-9) << i;
    EXPECT_NEAR(b.read(kPosition)[i], x[6 + i], 1e-9) << i;
  }
  // dt·k/m = 200: an explicit treatment of the coupling springs would have diverged.
  EXPECT_TRUE(std::isfinite(x[9]));
  EXPECT_LT(std::abs(x[10]), 10.0);
}

// The issue's physics test: an undamped spring network integrated with
// symplectic Euler keeps its energy bounded over 10 000 steps.
TEST(SpringForceField, UndampedExplicitEnergyStaysBoundedOver10kSteps) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1.5 0 0  0.2 1.3 0  0.4 0.3 1.4"/>
    <SpringForceField name="ff" spring="0 1 100 0 1  0 2 100 0 1  0 3 100 0 1  1 2 100 0 1.4  1 3 100 0 1.4  2 3 100 0 1.4"/>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kPosition), v(x.size(), 0.0);
  const double dt = 1e-3, m = 1.0;
  auto energy = [&]() {
    double k = 0;
    for (double vi : v) k += 0.5 * m * vi * vi;
    return k + spring_energy(*ff, x);
  };
  const double e0 = energy();
  ASSERT_GT(e0, 1.0);
  double emin = e0, emax = e0;
  for (int step = 0; step < 10000; ++step) {
    const auto f = force_at(*ff, st, x);
    for (std::size_t i = 0; i < x.size(); ++i) v[i] += dt * f[i] / m;
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += dt * v[i];
    const double e = energy();
    emin = std::min(emin, e);
    emax = std::max(emax, e);
  }
  EXPECT_LT((emax - emin) / e0, 0.02) << "energy drifted: [" << emin << ", " << emax << "] from " << e0;
}

TEST(MeshSpringForceField, TetraSpringsDivideStiffnessByRestLength) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0  0 1 0  0 0 1" tetrahedra="0 1 2 3"/>
    <MechanicalObject name="dofs"/>
    <MeshSpringForceField name="ff" tetrasStiffness="1000" tetrasDamping="4"/>
  </Node>)");
  auto* ff = get<MeshSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->spring_list().size(), 6u);
  const auto& sp = ff->spring_list()[0];  // (0,1), length 2
  EXPECT_EQ(sp.m1, 0u);
  EXPECT_EQ(sp.m2, 1u);
  EXPECT_DOUBLE_EQ(sp.l0, 2.0);
  EXPECT_DOUBLE_EQ(sp.ks, 500.0);
  EXPECT_DOUBLE_EQ(sp.kd, 2.0);
  EXPECT_EQ(ff->spring_list()[5].m1, 2u);
  EXPECT_EQ(ff->spring_list()[5].m2, 3u);
}

TEST(MeshSpringForceField, StiffnessAliasSetsEveryElementKindAndFirstBlockWins) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  1 1 0  0 1 0" edges="0 1" quads="0 1 2 3"/>
    <MechanicalObject name="dofs"/>
    <MeshSpringForceField name="ff" stiffness="300" damping="0"/>
  </Node>)");
  auto* ff = get<MeshSpringForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  EXPECT_DOUBLE_EQ(ff->quads_stiffness.value(), 300.0);
  EXPECT_DOUBLE_EQ(ff->cubes_stiffness.value(), 300.0);
  // the listed edge (0,1) plus the 5 other quad pairs, diagonals included.
  EXPECT_EQ(ff->spring_list().size(), 6u);
  EXPECT_NEAR(ff->spring_list()[1].l0, std::sqrt(2.0), 1e-15);  // quad pair (0,2) follows the edge (0,1)
  EXPECT_NEAR(ff->spring_list()[1].ks, 300.0 / std::sqrt(2.0), 1e-12);
}

TEST(RegularGridSpringForceField, GeneratesLinesQuadsAndCubesInSofaOrder) {
  auto s = load(R"(<Node gravity="0 0 0">
    <RegularGridTopology name="grid" n="2 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <RegularGridSpringForceField name="ff" stiffness="100" damping="4"/>
  </Node>)");
  auto* ff = get<RegularGridSpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  // 12 lines + 6 faces × 2 + 4 cube diagonals
  ASSERT_EQ(ff->grid_springs().size(), 28u);
  const auto& first = ff->grid_springs()[0];  // x line (0,0,0)-(1,0,0), length 2
  EXPECT_EQ(first.m1, 0u);
  EXPECT_EQ(first.m2, 1u);
  EXPECT_DOUBLE_EQ(first.ks, 50.0);
  EXPECT_DOUBLE_EQ(first.kd, 2.0);
  const auto& cube = ff->grid_springs()[24];
  EXPECT_NEAR(cube.l0, std::sqrt(6.0), 1e-15);
  // At rest: no force; the tangent still matches finite differences.
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kPosition);
  const auto f0 = force_at(*ff, st, x);
  EXPECT_LT(sinew::test::max_abs(f0), 1e-12);
  const auto xw = wiggle(x.size(), 7);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.1 * xw[i];
  force_at(*ff, st, x);
  const auto dx = wiggle(x.size(), 8);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x, dx, 1e-6), 1e-6, "grid springs");
}

TEST(QuadBendingSprings, OneSpringPairAcrossEachSharedEdge) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0" quads="0 1 4 3  1 2 5 4"/>
    <MechanicalObject name="dofs"/>
    <QuadBendingSprings name="ff" stiffness="20" damping="0"/>
  </Node>)");
  auto* ff = get<QuadBendingSprings>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->spring_list().size(), 2u);
  // shared edge (1,4): opposite pairs (0,2) and (3,5)
  EXPECT_EQ(std::min(ff->spring_list()[0].m1, ff->spring_list()[0].m2), 0u);
  EXPECT_EQ(std::max(ff->spring_list()[0].m1, ff->spring_list()[0].m2), 2u);
  EXPECT_DOUBLE_EQ(ff->spring_list()[0].l0, 2.0);
  EXPECT_DOUBLE_EQ(ff->spring_list()[0].ks, 20.0);
}

TEST(RestShapeSpringsForceField, PullsBackToTheRestPositionWithExactTangent) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" template="Vec1" position="0 1 2"/>
    <RestShapeSpringsForceField name="ff" template="Vec1" stiffness="10 20"/>
  </Node>)");
  auto* ff = get<RestShapeSpringsForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, {0.5, 1.0, 1.0});
  EXPECT_DOUBLE_EQ(f[0], -5.0);
  EXPECT_DOUBLE_EQ(f[1], 0.0);
  EXPECT_DOUBLE_EQ(f[2], 10.0);  // i = 2 ≥ size of stiffness → stiffness[0] = 10
  const auto df = dforce(*ff, st, {1, 1, 1}, 2.0);
  EXPECT_DOUBLE_EQ(df[0], -20.0);
  EXPECT_DOUBLE_EQ(df[1], -40.0);
  EXPECT_DOUBLE_EQ(df[2], -20.0);
}

// Rigid3d: a linear spring on the centre and an angular one on the rotation
// from the rest orientation: turned by 0.3 rad about z, the torque is −ka·0.3 about z.
TEST(RestShapeSpringsForceField, RigidFramesGetALinearAndAnAngularSpring) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" template="Rigid3" position="0 0 0 0 0 0 1"/>
    <RestShapeSpringsForceField name="ff" stiffness="10" angularStiffness="4"/>
  </Node>)");
  auto* ff = get<RestShapeSpringsForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const double h = 0.15;  // half angle
  const auto f = force_at(*ff, st, {1, -2, 0.5, 0, 0, std::sin(h), std::cos(h)});
  EXPECT_DOUBLE_EQ(f[0], -10.0);
  EXPECT_DOUBLE_EQ(f[1], 20.0);
  EXPECT_DOUBLE_EQ(f[2], -5.0);
  EXPECT_NEAR(f[3], 0.0, 1e-15);
  EXPECT_NEAR(f[4], 0.0, 1e-15);
  EXPECT_NEAR(f[5], -4.0 * 0.3, 1e-14);
  const auto df = dforce(*ff, st, {1, 1, 1, 1, 1, 1}, 2.0);
  EXPECT_DOUBLE_EQ(df[0], -20.0);
  EXPECT_DOUBLE_EQ(df[5], -8.0);
}

TEST(ConstantForceField, TotalForceIsSharedByAllPoints) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
    <ConstantForceField name="ff" totalForce="0 0 -5.0"/>
  </Node>)");
  auto* ff = get<ConstantForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(f[3 * i + 2], -1.25);
}

// Rigid3d: a force is a force then a torque (6 values); Rigid2d: 3 values.
TEST(ConstantForceField, RigidForcesCarryTorques) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" template="Rigid3" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/>
    <ConstantForceField name="ff" indices="1" forces="1 -1 0 0 0 2"/>
  </Node>)");
  auto* ff = get<ConstantForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  ASSERT_EQ(f.size(), 12u);
  for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(f[c], 0.0);
  EXPECT_DOUBLE_EQ(f[6], 1.0);
  EXPECT_DOUBLE_EQ(f[7], -1.0);
  EXPECT_DOUBLE_EQ(f[11], 2.0);
  auto s2 = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" template="Rigid2" position="0 0 0  1 0 0"/>
    <ConstantForceField name="ff" totalForce="2 0 4"/>
  </Node>)");
  auto* ff2 = get<ConstantForceField>(*s2.root, "ff");
  ASSERT_EQ(ff2->state(), ComponentState::valid);
  MechanicalState& st2 = *s2.root->mechanical_state;
  const auto f2 = force_at(*ff2, st2, st2.write(kPosition));
  EXPECT_DOUBLE_EQ(f2[3], 1.0);
  EXPECT_DOUBLE_EQ(f2[5], 2.0);
}

TEST(ConstantForceField, ForcesPerIndexAndBadIndex) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  2 0 0"/>
    <ConstantForceField name="ff" indices="2 0" forces="1 0 0  0 2 0"/>
  </Node>)");
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*get<ConstantForceField>(*s.root, "ff"), st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[6], 1.0);
  EXPECT_DOUBLE_EQ(f[1], 2.0);
  auto bad = sinew::test::build(R"(<Node><MechanicalObject position="0 0 0"/>
    <ConstantForceField name="ff" indices="3" force="1 0 0"/></Node>)");
  init_root(*bad.root);
  EXPECT_EQ(get<ConstantForceField>(*bad.root, "ff")->state(), ComponentState::invalid);
}

TEST(PlaneForceField, PenaltyForceAndTangent) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 -3.5 0  0 -2 0" velocity="0 -1 0  0 0 0"/>
    <PlaneForceField name="ff" normal="0 1 0" d="-3" stiffness="100000" damping="5"/>
  </Node>)");
  auto* ff = get<PlaneForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  // s = −0.5: F = n·(−k·s) − v·(−c·s) = 50000 − (−1)·2.5
  EXPECT_DOUBLE_EQ(f[1], 100000 * 0.5 + 5 * 0.5);
  EXPECT_DOUBLE_EQ(f[4], 0.0);
  ASSERT_EQ(ff->contacts().size(), 1u);
  const auto df = dforce(*ff, st, {0.3, 1, 0, 0, 1, 0});
  EXPECT_DOUBLE_EQ(df[1], -100000.0);
  EXPECT_DOUBLE_EQ(df[0], 0.0);
  EXPECT_DOUBLE_EQ(df[4], 0.0);
}

// Rigid3d: the plane acts on the frame centres (SOFA's DPos); orientations and angular
// velocities play no part, no torque, and the tangent only has the translation block.
TEST(PlaneForceField, Rigid3dActsOnTheCentresOnly) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" template="Rigid3d" position="1 -3.5 2  0 0 0.6 0.8   0 -2 0  0 0 0 1"
        velocity="0.5 -1 0  3 4 5   0 0 0  1 1 1"/>
    <PlaneForceField name="ff" template="Rigid3d" normal="0 1 0" d="-3" stiffness="1000" damping="5"/>
  </Node>)");
  auto* ff = get<PlaneForceField>(*s.root, "ff");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  ASSERT_EQ(f.size(), 12u);
  // dist = −0.5: F = n·(−k·dist) − v·(−c·dist) = (0, 500, 0) − (0.5, −1, 0)·2.5 = (−1.25, 502.5, 0)
  EXPECT_DOUBLE_EQ(f[0], -1.25);
  EXPECT_DOUBLE_EQ(f[1], 500 + 2.5);
  EXPECT_DOUBLE_EQ(f[2], 0.0);
  for (int c = 3; c < 12; ++c) EXPECT_DOUBLE_EQ(f[c], 0.0) << c;
  ASSERT_EQ(ff->contacts(), (std::vector<unsigned>{0}));
  const auto df = dforce(*ff, st, {0.3, 1, 0, 7, 8, 9, 0, 1, 0, 1, 1, 1});
  for (int c = 0; c < 12; ++c) EXPECT_DOUBLE_EQ(df[c], c == 1 ? -1000.0 : 0.0) << c;
  MatrixSink K;
  ASSERT_TRUE(ff->build_stiffness(K));
  double sum = 0;
  for (const auto& e : K.entries()) {
    EXPECT_LT(e.row, 3u);
    EXPECT_LT(e.col, 3u);
    sum += e.value;
  }
  EXPECT_DOUBLE_EQ(sum, -1000.0);
}

TEST(UniformVelocityDampingForceField, DampsAndAddsTheDampingMatrixWhenImplicit) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0" velocity="1 -2 3"/>
    <UniformVelocityDampingForceField name="ff" implicit="true" dampingCoefficient="0.5"/>
  </Node>)");
  auto* ff = get<UniformVelocityDampingForceField>(*s.root, "ff");
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[0], -0.5);
  EXPECT_DOUBLE_EQ(f[1], 1.0);
  st.write(kDx) = {1, 1, 1};
  auto& df = st.write(kDforce);
  std::fill(df.begin(), df.end(), 0.0);
  MechParams p;
  p.b = 2.0;
  ff->add_dforce(p, 0.0);
  EXPECT_DOUBLE_EQ(st.write(kDforce)[2], -1.0);
  MatrixSink B;
  ff->build_damping(B);
  ASSERT_EQ(B.entries().size(), 3u);
  EXPECT_DOUBLE_EQ(B.entries()[0].value, -0.5);
}

TEST(InteractionEllipsoidForceField, PushesPointsOutOfTheRotatedEllipsoidWithExactTangent) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="R"><MechanicalObject name="frame" template="Rigid3" position="0.1 0.2 0.3  0 0 0.38268343236508978 0.92387953251128674"/></Node>
    <Node name="P">
      <MechanicalObject name="pts" position="0.5 0.3 0.2  1.5 0 0  0.2 -0.4 0.1"/>
      <InteractionEllipsoidForceField name="ff" template="Vec3,Rigid3" object1="@pts" object2="@../R/frame"
          stiffness="100" damping="0" center="0 0 0  5 5 5" vradius="1 0.8 0.6" object2_forces="false"/>
    </Node>
  </Node>)");
  Node& P = *s.root->find_child_named("P");
  auto* ff = get<InteractionEllipsoidForceField>(P, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *P.mechanical_state;
  const std::vector<double> x = st.write(kPosition);
  const auto f = force_at(*ff, st, x);
  ASSERT_EQ(ff->contacts().size(), 2u);  // the point at (1.5, 0, 0) is outside
  EXPECT_EQ(f[3], 0.0);
  // The force pushes outward: it increases the distance to the frame centre.
  const double out0 = f[0] * (x[0] - 0.1) + f[1] * (x[1] - 0.2) + f[2] * (x[2] - 0.3);
  EXPECT_GT(out0, 0.0);
  MatrixSink sink;
  ff->build_stiffness(sink);
  EXPECT_EQ(sink.entries().size(), 2u * 9u);  // one 3×3 block per contact (object2_forces off)
}

// SOFA's tangent keeps the first two terms of ∂f/∂x but writes the third one
// as −k·v·g_i·g_j/(r_j²·|g|²) instead of +k·v·g_i·g_j/(r_j²·|g|³): the
// finite difference of add_force differs from add_dforce by exactly that.
TEST(InteractionEllipsoidForceField, TangentDiffersFromTheDerivativeByTheDocumentedTerm) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="R"><MechanicalObject name="frame" template="Rigid3" position="0.1 0.2 0.3  0 0 0 1"/></Node>
    <Node name="P">
      <MechanicalObject name="pts" position="0.5 0.3 0.2"/>
      <InteractionEllipsoidForceField name="ff" template="Vec3,Rigid3" object1="@pts" object2="@../R/frame"
          stiffness="100" damping="0" center="0 0 0" vradius="1 0.8 0.6" object2_forces="false"/>
    </Node>
  </Node>)");
  Node& P = *s.root->find_child_named("P");
  auto* ff = get<InteractionEllipsoidForceField>(P, "ff");
  MechanicalState& st = *P.mechanical_state;
  const std::vector<double> x = st.write(kPosition);
  force_at(*ff, st, x);
  ASSERT_EQ(ff->contacts().size(), 1u);
  const double p[3] = {0.4, 0.1, -0.1}, r[3] = {1, 0.8, 0.6}, k = 100;
  double g[3], n2 = 0, G = 0;
  for (int j = 0; j < 3; ++j) {
    g[j] = p[j] / (r[j] * r[j]);
    n2 += p[j] * p[j] / (r[j] * r[j]);
    G += g[j] * g[j];
  }
  const double v = std::sqrt(n2) - 1;
  for (int j = 0; j < 3; ++j) {
    std::vector<double> e(3, 0.0);
    e[j] = 1;
    const auto fd = fd_force(*ff, st, x, e, 1e-7);
    const auto df = dforce(*ff, st, e);
    for (int i = 0; i < 3; ++i) {
      const double missing = k * v * g[i] * g[j] / (r[j] * r[j]) * (1 / (G * std::sqrt(G)) + 1 / G);
      EXPECT_NEAR(fd[i] - df[i], missing, 1e-5 * std::fabs(df[i]) + 1e-6) << "entry " << i << "," << j;
    }
  }
}

TEST(QuadularBendingSprings, TwoCrossingSpringsPerSharedEdgeWithExactTangent) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0" quads="0 1 4 3  1 2 5 4"/>
    <MechanicalObject name="dofs"/>
    <QuadularBendingSprings name="ff" stiffness="300" damping="0"/>
  </Node>)");
  auto* ff = get<QuadularBendingSprings>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->springs().size(), 2u);
  // Shared edge (1,4), built by quad 0: springs (t1[i1], t2[i2+3]) and (t1[i1+3], t2[i2]).
  EXPECT_EQ(ff->springs()[0].e0, 4u);
  EXPECT_EQ(ff->springs()[0].e1, 0u);
  EXPECT_EQ(ff->springs()[1].e0, 5u);
  EXPECT_EQ(ff->springs()[1].e1, 1u);
  EXPECT_NEAR(ff->springs()[0].rest_length, std::sqrt(2.0), 1e-15);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kRestPosition);
  EXPECT_LT(sinew::test::max_abs(force_at(*ff, st, x)), 1e-12);
  x[2] += 0.3;
  x[17] -= 0.2;
  force_at(*ff, st, x);
  const auto dx = wiggle(x.size(), 61);
  expect_near_rel(dforce(*ff, st, dx), fd_force(*ff, st, x, dx, 1e-6), 1e-6, "quadular tangent");
  const auto K = dense_stiffness(*ff, st);
  const std::size_t n = x.size();
  std::vector<double> Kdx(n, 0.0);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) Kdx[r] += K[r * n + c] * dx[c];
  expect_near_rel(Kdx, dforce(*ff, st, dx), 1e-12, "quadular matrix");
}

TEST(SpringForceField, StiffSpringForceFieldIsTheOldName) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <StiffSpringForceField name="ff" spring="0 1 10 0 2"/>
  </Node>)");
  auto* ff = get<SpringForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  MechanicalState& st = *s.root->mechanical_state;
  const auto f = force_at(*ff, st, st.write(kPosition));
  EXPECT_DOUBLE_EQ(f[0], -10.0);  // compressed by 1: pushes point 0 away from point 1
  EXPECT_DOUBLE_EQ(f[3], 10.0);
}

TEST(TrianglePressureForceField, ConstantForceIsPressureTimesRestAreaOverThree) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="topo" position="0 0 0  2 0 0  0 3 0  5 5 5" triangles="0 1 2  1 3 2"/>
    <MechanicalObject name="dofs"/>
    <TrianglePressureForceField name="ff" triangleList="0" pressure="0.3 0 -6"/>
  </Node>)");
  auto* ff = get<TrianglePressureForceField>(*s.root, "ff");
  ASSERT_NE(ff, nullptr);
  ASSERT_EQ(ff->state(), ComponentState::valid);
  MechanicalState& st = *s.root->mechanical_state;
  std::vector<double> x = st.write(kPosition);
  x[0] += 1.0;  // the force uses the rest area (3), not the current one
  const auto f = force_at(*ff, st, x);
  for (int v = 0; v < 3; ++v) {
    EXPECT_NEAR(f[3 * v], 0.3, 1e-15);
    EXPECT_DOUBLE_EQ(f[3 * v + 2], -6.0);
  }
  EXPECT_DOUBLE_EQ(f[9], 0.0);
}

// SOFA's stiff springs put their damping in the force only (addDForce ignores
// bFactor, no damping matrix): the damping is explicit inside the implicit
// step. With RegularGridSpringForceField's default damping 5 (kd = 5/L0) on
// 1/16 kg points, h·λmax(M⁻¹C) ≈ 5.1 at dt 0.01 and the step amplifies the
// stiffest mode by ≈ 2.4 (linearised): the scene diverges as it does in SOFA.
// The same scene with damping 0 (MeshSpringForceField's default) stays put.
TEST(RegularGridSpringForceField, DampingIsExplicitLikeSofaAndCanDestabiliseTheImplicitStep) {
  auto box = [](const char* damping) {
    return std::string(R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
      <DefaultAnimationLoop/>
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-12"/>
      <RegularGridTopology name="grid" nx="4" ny="2" nz="2" xmin="0" xmax="3" ymin="0" ymax="1" zmin="0" zmax="1"/>
      <MechanicalObject name="dofs"/>
      <UniformMass totalMass="1"/>
      <RegularGridSpringForceField stiffness="100")") +
           damping + R"(/>
      <FixedProjectiveConstraint indices="0 4 8 12 3 7 11 15"/>
    </Node>)";
  };
  auto max_disp = [](const std::string& xml, int steps) {
    auto s = load(xml);
    MechanicalState& st = *s.root->mechanical_state;
    const std::vector<double> x0 = st.write(kPosition);
    for (int i = 0; i < steps; ++i) animate(*s.root);
    const std::vector<double> x = st.write(kPosition);
    double m = 0;
    for (std::size_t i = 0; i < x.size(); ++i) m = std::max(m, std::abs(x[i] - x0[i]));
    return m;
  };
  EXPECT_GT(max_disp(box(""), 20), 1.0);             // default damping 5: diverges (≈16 after 20 steps)
  EXPECT_LT(max_disp(box(R"( damping="0")"), 100), 0.05);  // undamped: sags ≈ 0.02 and stays
}
