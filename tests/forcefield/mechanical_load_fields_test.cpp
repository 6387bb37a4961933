// SphereForceField, EllipsoidForceField, ConicalForceField, LinearForceField,
// DiagonalVelocityDampingForceField, QuadPressureForceField and
// SurfacePressureForceField: forces against hand-computed values (SOFA's
// formulas, including their quirks), bad input, and SOFA's example scenes
// running 100 steps. Tangents and energies are checked by the force-field
// battery (tests/conformance).
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "forcefield/load/conical_force_field.h"
#include "forcefield/load/linear_force_field.h"
#include "forcefield/load/quad_pressure_force_field.h"
#include "forcefield/load/surface_pressure_force_field.h"
#include "test_scene.h"
#include "test_paths.h"

namespace sinew {
namespace {

// add_force of component `name` at the scene's state (velocities as set), zero force first.
std::vector<double> force_of(Node& root, const char* name, const char* state = "dofs") {
  auto* ff = test::get<ForceField>(root, name);
  auto* mo = test::get<MechanicalState>(root, state);
  EXPECT_NE(ff, nullptr);
  EXPECT_NE(mo, nullptr);
  if (!ff || !mo) return {};
  auto& f = mo->write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  ff->add_force(MechParams{});
  return mo->read(kForce);
}

// Errors of building and initialising `xml`.
std::vector<std::string> load_errors(const std::string& xml) {
  scene::LoadedScene s = test::build(xml);
  if (!s.root) return {"not built"};
  init_root(*s.root);
  return test::messages(s.root->diagnostics(), Severity::error);
}

std::string scene(const std::string& body) {
  return "<Node name='root' gravity='0 0 0' dt='0.1'>" + body + "</Node>";
}

TEST(SphereForceField, PushesInsidePointsOutWithSofasPenetrationDamping) {
  // Point 0 at distance 1 from the centre of a sphere of radius 3 (d = −2), moving at v;
  // point 1 outside.
  auto s = test::load(scene("<MechanicalObject name='dofs' position='1 0 0  5 0 0' velocity='0 2 0  1 1 1'/>"
                            "<SphereForceField name='ff' center='0 0 0' radius='3' stiffness='10' damping='0.5'/>"));
  const auto f = force_of(*s.root, "ff");
  // f = −k·d·n − (−c·d)·v = 20·(1,0,0) − (1)·(0,2,0)
  EXPECT_DOUBLE_EQ(f[0], 20.0);
  EXPECT_DOUBLE_EQ(f[1], -2.0);
  EXPECT_DOUBLE_EQ(f[2], 0.0);
  for (int c = 3; c < 6; ++c) EXPECT_EQ(f[c], 0.0);
}

TEST(EllipsoidForceField, NormalisedPenetrationAlongTheGradient) {
  // Ellipsoid radii (2, 1, 1): the point (1, 0, 0) has q = 1/4, v = −1/2, g = (1/4, 0, 0):
  // f = −k·v·g/|g| = (k/2, 0, 0).
  auto s = test::load(scene("<MechanicalObject name='dofs' position='1 0 0  3 0 0'/>"
                            "<EllipsoidForceField name='ff' center='0 0 0' vradius='2 1 1' stiffness='8' damping='0'/>"));
  const auto f = force_of(*s.root, "ff");
  EXPECT_DOUBLE_EQ(f[0], 4.0);
  EXPECT_EQ(f[3], 0.0);
  // Negative stiffness keeps points inside: only the outside point is pulled back.
  auto in = test::load(scene("<MechanicalObject name='dofs' position='1 0 0  4 0 0'/>"
                             "<EllipsoidForceField name='ff' vradius='2 1 1' stiffness='-8' damping='0'/>"));
  const auto g = force_of(*in.root, "ff");
  EXPECT_EQ(g[0], 0.0);
  EXPECT_DOUBLE_EQ(g[3], -8.0);  // q = 4, v = 1: −|k|·1
}

TEST(EllipsoidForceField, ZeroRadiusIsAnError) {
  const auto r = load_errors(scene("<MechanicalObject name='dofs' position='1 0 0'/>"
                                               "<EllipsoidForceField name='ff' vradius='2 0 1'/>"));
  EXPECT_TRUE(test::any_contains(r, "radii must be non-zero")) << ::testing::PrintToString(r);
}

TEST(ConicalForceField, PointsOutsideTheConeArePushedBack) {
  // Apex 0, axis z, height 2, half-angle 45°.
  auto s = test::load(
      scene("<MechanicalObject name='dofs' position='0 0 3  1.2 0 0.6  0 0 -1  0.1 0 1'/>"
            "<ConicalForceField name='ff' coneCenter='0 0 0' coneHeight='0 0 2' coneAngle='45' stiffness='10' "
            "damping='0'/>"));
  auto* cone = test::get<ConicalForceField>(*s.root, "ff");
  ASSERT_NE(cone, nullptr);
  EXPECT_TRUE(cone->is_in(Vec3(0.1, 0, 1)));
  const auto f = force_of(*s.root, "ff");
  // Beyond the base sphere: 1 past it, pushed towards the apex.
  EXPECT_NEAR(f[2], -10.0, 1e-12);
  // Beside the cone: (1.2, 0, 0.6) is 18.4° outside; its projection on the side line is
  // (0.9, 0, 0.9), at distance 0.3·√2 along (−1, 0, 1)/√2: f = k·(−0.3, 0, 0.3).
  EXPECT_NEAR(f[3], -3.0, 1e-12);
  EXPECT_NEAR(f[4], 0.0, 1e-12);
  EXPECT_NEAR(f[5], 3.0, 1e-12);
  // Behind the apex: pushed to it.
  EXPECT_NEAR(f[8], 10.0, 1e-12);
  EXPECT_EQ(f[9] + f[10] + f[11], 0.0);
}

TEST(LinearForceField, InterpolatesKeyForcesAndHoldsTheLastUnscaled) {
  const char* ff = "<LinearForceField name='ff' points='1' times='1 3' forces='2 0 0  4 0 0' force='10'/>";
  auto s = test::load(scene(std::string("<MechanicalObject name='dofs' position='0 0 0  1 1 1'/>") + ff));
  for (const auto& [time, expected] : std::vector<std::pair<double, double>>{
           {0.5, 0.0}, {1, 20.0}, {2, 30.0}, {3, 4.0}, {7, 4.0}}) {
    s.root->time.set(time);
    const auto f = force_of(*s.root, "ff");
    EXPECT_DOUBLE_EQ(f[3], expected) << "t = " << time;
    EXPECT_EQ(f[0], 0.0);
  }
}

TEST(LinearForceField, KeyCountsAndOrderAreChecked) {
  auto r = load_errors(scene("<MechanicalObject name='dofs' position='0 0 0'/>"
                                         "<LinearForceField name='ff' points='0' times='0 1' forces='1 2 3'/>"));
  EXPECT_TRUE(test::any_contains(r, "expected 3 per key time")) << ::testing::PrintToString(r);
  r = load_errors(scene("<MechanicalObject name='dofs' position='0 0 0'/>"
                                    "<LinearForceField name='ff' points='0' times='1 1' forces='1 2 3  1 2 3'/>"));
  EXPECT_TRUE(test::any_contains(r, "times must increase")) << ::testing::PrintToString(r);
  r = load_errors(scene("<MechanicalObject name='dofs' position='0 0 0'/>"
                                    "<LinearForceField name='ff' points='4' times='0' forces='1 2 3'/>"));
  EXPECT_TRUE(test::any_contains(r, "out of range")) << ::testing::PrintToString(r);
}

TEST(DiagonalVelocityDampingForceField, PerComponentCoefficientsLastOneRepeats) {
  auto s = test::load(scene("<MechanicalObject name='dofs' position='0 0 0  0 0 0  0 0 0' velocity='1 1 1  1 2 3  2 2 2'/>"
                            "<DiagonalVelocityDampingForceField name='ff' dampingCoefficient='0.5 0.2 0.1  1 2 3'/>"));
  const auto f = force_of(*s.root, "ff");
  const double expect[9] = {-0.5, -0.2, -0.1, -1, -4, -9, -2, -4, -6};
  for (int i = 0; i < 9; ++i) EXPECT_DOUBLE_EQ(f[i], expect[i]) << i;
  const auto r = load_errors(scene("<MechanicalObject name='dofs' position='0 0 0'/>"
                                               "<DiagonalVelocityDampingForceField name='ff' dampingCoefficient='1 2'/>"));
  EXPECT_TRUE(test::any_contains(r, "expected a multiple of 3")) << ::testing::PrintToString(r);
}

TEST(QuadPressureForceField, RestAreaTimesPressureSharedByTheFourCorners) {
  // Quads of area 2 and 1 (z = 0), pressure (0, 0, −6): 12/4 and 6/4 per corner.
  const std::string mesh =
      "<MeshTopology name='topo' position='0 0 0  2 0 0  2 1 0  0 1 0  3 0 0  3 1 0' quads='0 1 2 3  1 4 5 2'/>"
      "<MechanicalObject name='dofs'/>";
  auto s = test::load(scene(mesh + "<QuadPressureForceField name='ff' quadList='0 1' pressure='0 0 -6'/>"));
  const auto f = force_of(*s.root, "ff");
  EXPECT_DOUBLE_EQ(f[2], -3.0);           // point 0: first quad only
  EXPECT_DOUBLE_EQ(f[3 * 1 + 2], -4.5);   // point 1: both
  EXPECT_DOUBLE_EQ(f[3 * 4 + 2], -1.5);   // point 4: second only
  // Selection by planes: x between 2.5 and 3.5 has no whole quad; between −1 and 3.5 both.
  auto sel = test::load(scene(mesh + "<QuadPressureForceField name='ff' normal='1 0 0' dmin='-1' dmax='3.5' "
                                     "pressure='0 0 -6'/>"));
  EXPECT_EQ(test::get<QuadPressureForceField>(*sel.root, "ff")->loaded_quads().size(), 2u);
}

TEST(SurfacePressureForceField, ClosedSurfaceHasNoNetForceAndItsVolume) {
  // The unit cube as 6 quads, outward normals: V = 1, each face pushed outward by p·1.
  const std::string cube =
      "<MeshTopology name='topo' position='0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1'"
      " quads='0 3 2 1  4 5 6 7  0 1 5 4  1 2 6 5  2 3 7 6  3 0 4 7'/><MechanicalObject name='dofs'/>";
  auto s = test::load(scene(cube + "<SurfacePressureForceField name='ff' pressure='12'/>"));
  auto* sp = test::get<SurfacePressureForceField>(*s.root, "ff");
  ASSERT_NE(sp, nullptr);
  EXPECT_DOUBLE_EQ(sp->mesh_volume(test::get<MechanicalState>(*s.root, "dofs")->read(kPosition)), 1.0);
  const auto f = force_of(*s.root, "ff");
  double net[3] = {0, 0, 0}, total_z_top = 0;
  for (int i = 0; i < 8; ++i)
    for (int c = 0; c < 3; ++c) net[c] += f[3 * i + c];
  for (int i = 4; i < 8; ++i) total_z_top += f[3 * i + 2];
  for (double n : net) EXPECT_NEAR(n, 0.0, 1e-12);
  // The top face (z = 1) alone gives p·A = 12 upwards on its four corners; the side faces add
  // nothing along z: the top corners carry +12 in all.
  EXPECT_NEAR(total_z_top, 12.0, 1e-12);
}

TEST(SurfacePressureForceField, PulseModeRampsBetweenTheBounds) {
  auto s = test::load(scene("<MechanicalObject name='dofs' position='0 0 0  1 0 0  0 1 0'/>"
                            "<MeshTopology triangles='0 1 2'/>"
                            "<SurfacePressureForceField name='ff' pressure='10' pulseMode='1' pressureSpeed='40' "
                            "pressureLowerBound='2'/>"));
  auto* sp = test::get<SurfacePressureForceField>(*s.root, "ff");
  std::vector<double> seen;
  for (int i = 0; i < 7; ++i) {
    force_of(*s.root, "ff");
    seen.push_back(sp->last_pressure());
  }
  // dt = 0.1, 4 per evaluation: 4, 8, 10 (capped), 6, 2 (floor), 6, 10.
  const std::vector<double> expected = {4, 8, 10, 6, 2, 6, 10};
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(seen[i], expected[i], 1e-12) << i;
}

TEST(MechanicalLoadExamples, Run100Steps) {
  for (const char* rel : {"Component/MechanicalLoad/SphereForceField.scn", "Component/MechanicalLoad/EllipsoidForceField.scn",
                          "Component/MechanicalLoad/ConicalForceField.scn", "Component/MechanicalLoad/LinearForceField.scn",
                          "Component/MechanicalLoad/SurfacePressureForceField.scn",
                          "Component/SolidMechanics/FEM/DampingForceField.scn"}) {
    const test::Outcome o = test::run_sofa_example(rel, 100);
    if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
    EXPECT_EQ(o.steps, 100) << rel << "\n" << o.all();
    EXPECT_TRUE(o.errors.empty()) << rel << "\n" << o.all();
    EXPECT_TRUE(o.finite) << rel;
  }
}

}  // namespace
}  // namespace sinew
