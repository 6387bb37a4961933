// FastTetrahedralCorotationalForceField: method linear against the small-strain
// tetrahedron of TetrahedralCorotationalFEMForceField (an independently tested
// kernel), add_dforce against the assembled matrix and finite differences,
// invariance under rigid motions for the three rotations, polar vs qr on a
// rotated element, per-element material, and bad input.
#include "forcefield/fem/fast_tetrahedral_corotational_force_field.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <cmath>

#include "badinput_helpers.h"
#include "forcefield/fem/tetrahedral_corotational_fem_force_field.h"
#include "spring_helpers.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;
using namespace sinew::test;

namespace {

// Two irregular tetrahedra sharing a face (edges shared with both orientations).
const char* kPoints = "0 0 0  1.1 0.05 0  0.1 0.9 0.05  0.05 0.1 1.2  0.9 0.8 0.9";
const char* kTets = "0 1 2 3  2 1 4 3";

std::string fast_scene(const std::string& ff_attrs,
                  const std::string& material = "youngModulus='1000' poissonRatio='0.3'") {
  return std::string(R"(<Node gravity="0 0 0" dt="0.01">
  <MechanicalObject name="dofs" position=")") + kPoints + R"("/>
  <TetrahedronSetTopologyContainer name="topo" tetrahedra=")" + kTets + R"("/>
  <FastTetrahedralCorotationalForceField name="ff" )" + material + " " + ff_attrs + R"(/>
</Node>)";
}

struct Loaded {
  scene::LoadedScene s;
  FastTetrahedralCorotationalForceField* ff = nullptr;
  MechanicalObject* mo = nullptr;
  explicit Loaded(const std::string& attrs, const std::string& material = "youngModulus='1000' poissonRatio='0.3'")
      : s(load(fast_scene(attrs, material))) {
    ff = get<FastTetrahedralCorotationalForceField>(*s.root, "ff");
    mo = get<MechanicalObject>(*s.root, "dofs");
  }
};

std::vector<double> rest() {
  Loaded l("");
  return l.mo->read(kRestPosition);
}

// x0 + a·(pseudo-random displacement).
std::vector<double> deformed(double a, unsigned seed = 3) {
  std::vector<double> x = rest();
  const auto w = wiggle(x.size(), seed);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += a * w[i];
  return x;
}

Mat3 rotation() { return Eigen::AngleAxisd(0.9, Vec3(1, -2, 0.5).normalized()).toRotationMatrix(); }

std::vector<double> rotate(const std::vector<double>& x, const Mat3& Q, const Vec3& shift = Vec3::Zero()) {
  std::vector<double> y(x.size());
  for (std::size_t i = 0; i < x.size(); i += 3) {
    const Vec3 p = Q * Vec3(x[i], x[i + 1], x[i + 2]) + shift;
    for (int k = 0; k < 3; ++k) y[i + k] = p[k];
  }
  return y;
}

const char* kMethods[] = {"qr", "polar", "polar2"};

}  // namespace

TEST(FastTetrahedralCorotational, LinearMethodIsTheSmallStrainTetrahedron) {
  Loaded fast("method='linear'");
  auto ref_s = load(std::string(R"(<Node gravity="0 0 0">
  <MechanicalObject name="dofs" position=")") + kPoints + R"("/>
  <TetrahedronSetTopologyContainer name="topo" tetrahedra=")" + kTets + R"("/>
  <TetrahedralCorotationalFEMForceField name="ff" youngModulus="1000" poissonRatio="0.3" method="small"/>
</Node>)");
  auto* ref = get<TetrahedralCorotationalFEMForceField>(*ref_s.root, "ff");
  auto* ref_mo = get<MechanicalObject>(*ref_s.root, "dofs");
  ASSERT_TRUE(fast.ff && ref);
  const auto x = deformed(0.05);
  expect_near_rel(force_at(*fast.ff, *fast.mo, x), force_at(*ref, *ref_mo, x), 1e-12, "force");
  expect_near_rel(dense_stiffness(*fast.ff, *fast.mo), dense_stiffness(*ref, *ref_mo), 1e-12, "stiffness");
  // One element's matrix: each block row sums to zero (translations cost nothing).
  const auto K = dense_stiffness(*fast.ff, *fast.mo);
  const std::size_t n = 15;
  for (std::size_t r = 0; r < n; ++r)
    for (int c = 0; c < 3; ++c) {
      double sum = 0, scale = 0;
      for (std::size_t j = c; j < n; j += 3) {
        sum += K[r * n + j];
        scale = std::max(scale, std::fabs(K[r * n + j]));
      }
      EXPECT_NEAR(sum, 0.0, 1e-12 * scale);
    }
}

TEST(FastTetrahedralCorotational, DForceEqualsTheAssembledMatrixForEveryMethod) {
  for (const char* m : {"qr", "polar", "polar2", "linear"}) {
    Loaded l(std::string("method='") + m + "'");
    const auto x = deformed(0.1);
    force_at(*l.ff, *l.mo, x);
    const auto K = dense_stiffness(*l.ff, *l.mo);
    const auto dx = wiggle(x.size(), 11);
    const auto df = dforce(*l.ff, *l.mo, dx, 0.7);
    std::vector<double> Kdx(x.size(), 0.0);
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = 0; j < x.size(); ++j) Kdx[i] += 0.7 * K[i * x.size() + j] * dx[j];
    expect_near_rel(df, Kdx, 1e-12, m);
  }
}

// Linear: K is the exact derivative. Corotational: K leaves out the change of
// the rotation (as SOFA), exact for a rigidly rotated, unstrained element and
// close at small strain.
TEST(FastTetrahedralCorotational, DForceMatchesFiniteDifferences) {
  {
    Loaded l("method='linear'");
    const auto x = deformed(0.2);
    const auto dx = wiggle(x.size(), 5);
    force_at(*l.ff, *l.mo, x);
    expect_near_rel(dforce(*l.ff, *l.mo, dx), fd_force(*l.ff, *l.mo, x, dx, 1e-6), 1e-7, "linear");
  }
  for (const char* m : kMethods) {
    Loaded l(std::string("method='") + m + "'");
    const auto x = rotate(deformed(1e-4), rotation(), Vec3(0.3, -1, 2));
    const auto dx = wiggle(x.size(), 5);
    force_at(*l.ff, *l.mo, x);
    expect_near_rel(dforce(*l.ff, *l.mo, dx), fd_force(*l.ff, *l.mo, x, dx, 1e-7), 2e-3, m);
  }
}

TEST(FastTetrahedralCorotational, ForcesRotateWithTheBody) {
  const Mat3 Q = rotation();
  for (const char* m : kMethods) {
    Loaded l(std::string("method='") + m + "'");
    const auto x = deformed(0.1);
    const auto f = force_at(*l.ff, *l.mo, x);
    const auto fr = force_at(*l.ff, *l.mo, rotate(x, Q, Vec3(5, 1, -2)));
    expect_near_rel(fr, rotate(f, Q), 1e-10, m);
    // A rigid motion of the rest shape costs no force.
    const auto f0 = force_at(*l.ff, *l.mo, rotate(rest(), Q, Vec3(5, 1, -2)));
    EXPECT_LT(max_abs(f0), 1e-10 * max_abs(f)) << m;
    // Net force and torque vanish.
    Vec3 net = Vec3::Zero();
    for (std::size_t i = 0; i < f.size(); i += 3) net += Vec3(f[i], f[i + 1], f[i + 2]);
    EXPECT_LT(net.norm(), 1e-12 * max_abs(f)) << m;
  }
  // The linear method does not follow rotations.
  Loaded lin("method='linear'");
  EXPECT_GT(max_abs(force_at(*lin.ff, *lin.mo, rotate(rest(), Q))), 1.0);
}

TEST(FastTetrahedralCorotational, PolarAndQrAgreeOnARotatedSlightlyStrainedElement) {
  const auto x = rotate(deformed(1e-4, 8), rotation());
  Loaded qr("method='qr'"), polar("method='polar'"), polar2("method='polar2'"), large("method='large'");
  const auto fq = force_at(*qr.ff, *qr.mo, x);
  const auto fp = force_at(*polar.ff, *polar.mo, x);
  expect_near_rel(fp, fq, 2e-2, "polar vs qr");
  expect_near_rel(force_at(*polar2.ff, *polar2.mo, x), fq, 2e-2, "polar2 vs qr");
  // "large" is SOFA's other name of qr.
  EXPECT_EQ(force_at(*large.ff, *large.mo, x), fq);
}

TEST(FastTetrahedralCorotational, PerElementYoungModulus) {
  Loaded both("method='linear'");
  Loaded split("method='linear'", "youngModulus='1000 0' poissonRatio='0.3'");
  const auto x = deformed(0.05);
  const auto fb = force_at(*both.ff, *both.mo, x);
  const auto fs = force_at(*split.ff, *split.mo, x);
  // With the second element at zero stiffness, point 4 (only in it) feels nothing.
  for (int k = 0; k < 3; ++k) EXPECT_EQ(fs[12 + k], 0.0);
  EXPECT_GT(max_abs(fs), 1.0);
  EXPECT_NE(fs, fb);
}

TEST(FastTetrahedralCorotational, RunsTheBeamWithEveryMethodAndADirectSolver) {
  TempDir dir;
  for (const char* m : {"small", "large", "polar", "polar2"}) {
    const Outcome o = run_xml(dir, std::string(R"(<Node gravity="0 -9 0" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
  <EigenSimplicialLDLT template="CompressedRowSparseMatrixMat3x3"/>
  <RegularGridTopology name="grid" min="-1 -1 0" max="1 1 6" n="3 3 7"/>
  <MechanicalObject/>
  <TetrahedronSetTopologyContainer name="tetra"/>
  <TetrahedronSetTopologyModifier/>
  <Hexa2TetraTopologicalMapping input="@grid" output="@tetra" swapping="true"/>
  <DiagonalMass massDensity="0.2"/>
  <FastTetrahedralCorotationalForceField youngModulus="1000" poissonRatio="0.4" method=")") + m + R"("/>
  <BoxROI name="box" box="-2 -2 -1 2 2 0.1"/>
  <FixedProjectiveConstraint indices="@box.indices"/>
</Node>)", 20);
    EXPECT_TRUE(o.init_ok) << m << "\n" << o.all();
    EXPECT_EQ(o.steps, 20) << m;
    EXPECT_TRUE(o.finite) << m;
    EXPECT_TRUE(o.problems().empty()) << m << "\n" << o.all();
  }
}

TEST(FastTetrahedralCorotational, BadInputGivesClearMessages) {
  TempDir dir;
  const std::string who = "component 'ff' (FastTetrahedralCorotationalForceField)";
  {
    const Outcome o = run_xml(dir, fast_scene("method='rotated'"));
    EXPECT_TRUE(any_contains_all(o.errors, {who, "unknown method 'rotated'"})) << o.all();
    EXPECT_FALSE(o.init_ok);
  }
  {
    const Outcome o = run_xml(dir, fast_scene("", "youngModulus='1000' poissonRatio='0.5'"));
    EXPECT_TRUE(any_contains_all(o.warnings, {who, "poissonRatio 0.5", "replaced by 0.45"})) << o.all();
    EXPECT_TRUE(o.init_ok) << o.all();
  }
  {
    // Point 4 moved onto point 1: the second element is flat.
    std::string xml = fast_scene("");
    xml.replace(xml.find("0.9 0.8 0.9"), 11, "1.1 0.05 0");
    const Outcome o = run_xml(dir, xml);
    EXPECT_TRUE(any_contains_all(o.errors, {who, "tetrahedron 1", "flat"})) << o.all();
    EXPECT_FALSE(o.init_ok);
  }
  {
    std::string xml = fast_scene("");
    xml.replace(xml.find(kTets), std::string(kTets).size(), "0 1 2 7");
    const Outcome o = run_xml(dir, xml);
    EXPECT_FALSE(o.errors.empty()) << o.all();
    EXPECT_FALSE(o.init_ok);
  }
}

// SOFA's example scenes with this component run without any error.
TEST(FastTetrahedralCorotational, ExampleScenesRun) {
  namespace fs = std::filesystem;
  const fs::path data = SINEW_DATA_DIR;
  const std::pair<const char*, long> scenes[] = {
      {"Component/SolidMechanics/FEM/FastTetrahedralCorotationalForceField.scn", 100},
      {"Component/SolidMechanics/FEM/FastTetrahedronCorotationalForceField_validation.scn", 5},
  };
  for (const auto& [rel, steps] : scenes) {
    const fs::path path = data / "examples" / rel;
    if (!fs::exists(path)) GTEST_SKIP() << "SOFA data not found at " << data;
    runner::SessionOptions opts;
    opts.data_paths = {(data / "share").string(), (data / "examples").string()};
    runner::Session session(path.string(), opts);
    ASSERT_TRUE(session.ok()) << rel;
    for (long i = 0; i < steps; ++i) ASSERT_TRUE(session.step()) << rel << " step " << i;
    EXPECT_TRUE(all_finite(session.root())) << rel;
    EXPECT_TRUE(messages(session.diagnostics(), Severity::error).empty()) << rel;
  }
}
