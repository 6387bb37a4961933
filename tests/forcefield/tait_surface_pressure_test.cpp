// TaitSurfacePressureForceField on a closed tetrahedral surface: volume, area and the
// volume gradient against closed forms, Tait's law, the injection ramp, the tangent
// (addDForce) against central differences of addForce, the assembled K against addDForce,
// and SOFA's example scene.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "badinput_helpers.h"
#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/simulation.h"
#include "test_scene.h"
#include "test_paths.h"

namespace sinew {
namespace {

// The unit corner tetrahedron, faces oriented outwards: V = 1/6, A = 3/2 + √3/2.
std::string tetra(const std::string& attrs) {
  return R"(<Node dt="0.02" gravity="0 0 0"><DefaultAnimationLoop/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1"/>
    <MeshTopology triangles="0 2 1  0 1 3  0 3 2  1 2 3"/>
    <TaitSurfacePressureForceField name="p" )" +
         attrs + "/></Node>";
}

double value(Component& c, const char* name) {
  const auto* f = dynamic_cast<const Field<double>*>(c.find_field(name));
  if (!f) throw std::runtime_error(std::string("no double field ") + name);
  return f->get();
}

std::vector<double> force_at(ForceField& ff, MechanicalState& mo, const std::vector<double>& x) {
  mo.write(kPosition) = x;
  auto& f = mo.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  ff.add_force(p);
  return mo.read(kForce);
}

TEST(TaitSurfacePressure, VolumeAreaAndConstantPressureForces) {
  auto s = test::load(tetra("p0=\"2\""));
  auto* ff = test::get<ForceField>(*s.root, "p");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  ASSERT_NE(ff, nullptr);
  EXPECT_NEAR(value(*ff, "initialVolume"), 1.0 / 6, 1e-15);
  EXPECT_NEAR(value(*ff, "initialSurfaceArea"), 1.5 + std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(value(*ff, "v0"), 1.0 / 6, 1e-15);
  EXPECT_EQ(value(*ff, "currentPressure"), 2.0);  // B = 0: P = p0
  const auto f = force_at(*ff, *mo, mo->read(kPosition));
  // ∂V/∂x of a vertex = (opposite face area / 3) along its outward normal: vertex 3 → (0, 0, 1/6),
  // vertex 0 → −(1/6, 1/6, 1/6).
  const double expect[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * i + c], 2.0 * expect[i][c] / 6, 1e-15) << i << "," << c;
}

TEST(TaitSurfacePressure, TaitLawAndInjectionRamp) {
  auto s = test::load(tetra("p0=\"1\" B=\"10\" gamma=\"5\" injectedVolume=\"0.05\" maxInjectionRate=\"1\""));
  auto* ff = test::get<ForceField>(*s.root, "p");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  ASSERT_NE(ff, nullptr);
  // 0.02 per step at 1 volume/s over dt = 0.02: 0.02, 0.04, then 0.05.
  const double ramp[] = {0.02, 0.04, 0.05, 0.05};
  for (double inj : ramp) {
    animate(*s.root);
    EXPECT_NEAR(value(*ff, "currentInjectedVolume"), inj, 1e-15);
    EXPECT_NEAR(value(*ff, "v0"), 1.0 / 6 + inj, 1e-15);
  }
  // No solver: the points did not move. P = p0 − B((V/V0)^γ − 1), dP/dV = −Bγ(V/V0)^γ / V.
  force_at(*ff, *mo, mo->read(kPosition));
  const double V = 1.0 / 6, V0 = V + 0.05, r = std::pow(V / V0, 5);
  EXPECT_NEAR(value(*ff, "currentVolume"), V, 1e-15);
  EXPECT_NEAR(value(*ff, "currentPressure"), 1 - 10 * (r - 1), 1e-12);
  EXPECT_NEAR(value(*ff, "currentStiffness"), -10 * 5 * r / V, 1e-12);
}

TEST(TaitSurfacePressure, TangentIsTheDerivativeOfTheForce) {
  auto s = test::load(tetra("p0=\"0.5\" B=\"10\" gamma=\"5\" injectedVolume=\"0\""));
  auto* ff = test::get<ForceField>(*s.root, "p");
  auto* mo = test::get<MechanicalState>(*s.root, "dofs");
  ASSERT_NE(ff, nullptr);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<double> x = mo->read(kPosition), dx(12);
  for (double& v : x) v += u(rng);
  for (double& v : dx) v = u(rng);
  const double h = 1e-6;
  std::vector<double> xp = x, xm = x;
  for (int i = 0; i < 12; ++i) xp[i] += h * dx[i], xm[i] -= h * dx[i];
  const auto fp = force_at(*ff, *mo, xp);
  const auto fm = force_at(*ff, *mo, xm);
  force_at(*ff, *mo, x);  // the tangent at x
  EXPECT_NE(value(*ff, "currentStiffness"), 0.0);
  const int did = MechanicalOps::alloc_vec(), dfid = MechanicalOps::alloc_vec();
  mo->write(did) = dx;
  mo->write(dfid).assign(12, 0.0);
  MechParams p;
  p.dx = did;
  p.df = dfid;
  ff->add_dforce(p, 1.0);
  const std::vector<double> df = mo->read(dfid);
  double scale = 0;
  for (double v : df) scale = std::max(scale, std::abs(v));
  EXPECT_GT(scale, 1e-3);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(df[i], (fp[i] - fm[i]) / (2 * h), 1e-7 * (1 + scale)) << i;
  // The assembled K (diagonal blocks of the pressure term left out: they cancel on a closed surface).
  MatrixSink K;
  ASSERT_TRUE(ff->build_stiffness(K));
  std::vector<double> kdx(12, 0.0);
  for (const auto& e : K.entries()) kdx[e.row] += e.value * dx[e.col];
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(kdx[i], df[i], 1e-12 * (1 + scale)) << i;
}

TEST(TaitSurfacePressure, BadInputIsReported) {
  auto s = test::build(R"(<Node><DefaultAnimationLoop/><MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
    <MeshTopology triangles="0 1 5"/><TaitSurfacePressureForceField name="p"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "pressure triangle 0 uses point 5 but the state has 3 points"));
  EXPECT_EQ(test::get<Component>(*s.root, "p")->state(), ComponentState::invalid);
}

TEST(TaitSurfacePressure, ExampleSceneInflatesTheSphere) {
  double v = 0, v_init = 0;
  const test::Outcome o =
      test::run_sofa_example("Component/MechanicalLoad/TaitSurfacePressureForceField.scn", 20, [&](runner::Session& s) {
        std::vector<ForceField*> ffs;
        s.root().collect_down(ffs);
        for (ForceField* f : ffs)
          if (f->name.value() == "Pressure") v = value(*f, "currentVolume"), v_init = value(*f, "initialVolume");
      });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  EXPECT_GT(v_init, 0.0);
  EXPECT_GT(v, v_init);  // 100 volume units injected: the surface expands
}

}  // namespace
}  // namespace sinew
