// HexahedralFEMForceFieldAndMass: SOFA's element masses by hand on a box
// (every node pair's block (ρV)·8/27, gravity on ρV/8 per corner), M·dx
// against the dense element matrix, the assembled mass (diagonal blocks only,
// as SOFA's compatibility path), lumped masses, separateGravity, and the same
// trajectory as HexahedronFEMForceFieldAndMass on cubes (the two share the
// mass formula; their stiffnesses differ by SOFA's float rounding).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "core/matrix_sink.h"
#include "core/simulation.h"
#include "forcefield/fem/hexahedral_fem_force_field.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew::hexahedral_fem_and_mass_test {

std::string box(const std::string& extra, const std::string& gravity = "0 -10 0") {
  return R"(<Node dt="0.01" gravity=")" + gravity +
         R"("><DefaultAnimationLoop/><RegularGridTopology n="2 2 2" min="0 0 0" max="2 1 0.5"/>
    <MechanicalObject name="dofs"/><HexahedralFEMForceFieldAndMass name="fem" youngModulus="1000"
    poissonRatio="0.3" density="3" )" + extra + "/></Node>";
}


TEST(HexahedralFEMForceFieldAndMass, ElementMassesOfABox) {
  auto s = test::load(box(""));
  ASSERT_TRUE(s.root);
  auto& fem = *test::get<HexahedralFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_EQ(fem.state(), ComponentState::valid);
  const double V = 2 * 1 * 0.5, rho = 3;
  ASSERT_EQ(fem.element_masses().size(), 1u);
  EXPECT_NEAR(fem.element_masses()[0], rho * V * 8.0 / 27.0, 1e-14);
  for (double m : fem.particle_masses()) EXPECT_NEAR(m, rho * V / 8, 1e-14);
  EXPECT_NEAR(fem.total(), rho * V, 1e-13);
  EXPECT_FALSE(fem.is_diagonal());

  // M·dx: every node gets m·Σ_j dx_j (all 8 nodes coupled).
  auto& mo = *test::get<MechanicalObject>(*s.root, "dofs");
  std::vector<double>& dx = mo.write(kDx);
  for (std::size_t i = 0; i < dx.size(); ++i) dx[i] = 0.1 * static_cast<double>(i % 7) - 0.2;
  std::vector<double>& f = mo.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  fem.add_mdx(MechParams{}, kForce, kDx, 2.0);
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    for (int j = 0; j < 8; ++j) sum += dx[3 * j + c];
    for (int w = 0; w < 8; ++w) EXPECT_NEAR(f[3 * w + c], 2.0 * fem.element_masses()[0] * sum, 1e-13);
  }

  // Assembled: the diagonal blocks only, m·I each.
  MatrixSink sink;
  ASSERT_TRUE(fem.build_mass(sink));
  std::map<std::pair<std::size_t, std::size_t>, double> M;
  for (const auto& e : sink.entries())
    if (e.value != 0) M[{e.row, e.col}] += e.value;
  EXPECT_EQ(M.size(), 24u);
  for (const auto& [rc, v] : M) {
    EXPECT_EQ(rc.first, rc.second);
    EXPECT_NEAR(v, fem.element_masses()[0], 1e-14);
  }

  // Gravity in add_force: ρV/8·g per corner at rest (no elastic force there).
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  fem.add_force(p);
  for (int w = 0; w < 8; ++w) {
    EXPECT_NEAR(f[3 * w + 1], -10 * rho * V / 8, 1e-12);
    EXPECT_NEAR(f[3 * w], 0.0, 1e-12);
  }
}

TEST(HexahedralFEMForceFieldAndMass, LumpedAndSeparateGravity) {
  auto s = test::load(box(R"(lumpedMass="1" separateGravity="1")"));
  ASSERT_TRUE(s.root);
  auto& fem = *test::get<HexahedralFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_EQ(fem.state(), ComponentState::valid);
  EXPECT_TRUE(fem.is_diagonal());
  auto& mo = *test::get<MechanicalObject>(*s.root, "dofs");
  std::vector<double>& dx = mo.write(kDx);
  for (std::size_t i = 0; i < dx.size(); ++i) dx[i] = 1.0 + static_cast<double>(i);
  std::vector<double>& f = mo.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  fem.add_mdx(MechParams{}, kForce, kDx, 1.0);
  // Row sums: 8 entries of m per row.
  for (std::size_t i = 0; i < dx.size(); ++i) EXPECT_NEAR(f[i], 8 * fem.element_masses()[0] * dx[i], 1e-12);
  // separateGravity: no gravity in the force; the solver adds g·dt to v instead.
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  fem.add_force(p);
  for (double v : f) EXPECT_NEAR(v, 0.0, 1e-12);
  std::vector<double>& v = mo.write(kVelocity);
  std::fill(v.begin(), v.end(), 0.0);
  fem.add_gravity_to_v(kVelocity, 0.5);
  for (int w = 0; w < 8; ++w) EXPECT_DOUBLE_EQ(v[3 * w + 1], -5.0);
}

// A clamped bar of cubes under gravity, CG matrix-free: the same motion as
// HexahedronFEMForceFieldAndMass (same masses; stiffness equal up to SOFA's
// float rounding of the closed form, relative 2e-8).
TEST(HexahedralFEMForceFieldAndMass, SameTrajectoryAsHexahedronAndMassOnCubes) {
  auto bar = [](const std::string& ff) {
    return R"(<Node name="root" dt="0.02" gravity="0 -10 0"><DefaultAnimationLoop/>
      <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
      <CGLinearSolver iterations="200" tolerance="1e-14" threshold="1e-30"/>
      <MechanicalObject name="dofs"/>
      <RegularGridTopology nx="3" ny="3" nz="6" xmin="0" xmax="2" ymin="0" ymax="2" zmin="0" zmax="5"/>
      <BoxROI name="box" box="-1 -1 -0.001 3 3 0.001"/><FixedProjectiveConstraint indices="@box.indices"/>
      <)" + ff + R"( name="fem" youngModulus="3000" poissonRatio="0.3" method="large" density="2"/></Node>)";
  };
  auto a = test::load(bar("HexahedralFEMForceFieldAndMass"));
  auto b = test::load(bar("HexahedronFEMForceFieldAndMass"));
  ASSERT_TRUE(a.root && b.root);
  auto* ma = test::get<MechanicalObject>(*a.root, "dofs");
  auto* mb = test::get<MechanicalObject>(*b.root, "dofs");
  double gap = 0, disp = 0;
  for (int step = 0; step < 40; ++step) {
    animate(*a.root);
    animate(*b.root);
    const auto &xa = ma->read(kPosition), &xb = mb->read(kPosition), &x0 = mb->read(kRestPosition);
    for (std::size_t i = 0; i < xa.size(); ++i) {
      gap = std::max(gap, std::fabs(xa[i] - xb[i]));
      disp = std::max(disp, std::fabs(xb[i] - x0[i]));
    }
  }
  EXPECT_GT(disp, 0.05);
  EXPECT_LT(gap, 1e-5 * disp) << "gap " << gap << " displacement " << disp;
}

TEST(HexahedralFEMForceFieldAndMass, NoHexahedraIsAnError) {
  Diagnostics d;
  auto s = test::build(R"(<Node><MechanicalObject position="0 0 0 1 0 0"/>
    <HexahedralFEMForceFieldAndMass name="fem"/></Node>)", &d);
  ASSERT_TRUE(s.root);
  EXPECT_FALSE(init_root(*s.root));
}

}  // namespace sinew::hexahedral_fem_and_mass_test
