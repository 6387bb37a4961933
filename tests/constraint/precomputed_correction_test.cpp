// PrecomputedConstraintCorrection (spec/interaction.md §5.3): the compliance
// it precomputes against closed forms (a point on a spring, a rigid body, a
// Vec1d point) and against LinearSolverConstraintCorrection on an FEM beam,
// trajectories of a beam held by a bilateral constraint (Precomputed and
// LinearSolver; built and unbuilt solvers), the LCP path built and unbuilt,
// the cache file (round trip, corrupt or foreign files, the read-only
// fallback) and SOFA's DeformableOnRigidFrameMappingConstraints scene.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "constraint/correction/compliance_cache.h"
#include "constraint/correction/precomputed_constraint_correction.h"
#include "constraint/solver/lcp_constraint_solver.h"
#include "constraint/solver/constraint_system.h"
#include "constraint_test_helpers.h"
#include "core/node.h"
#include "core/simulation.h"
#include "mass/uniform_mass.h"
#include "solver/linear/cg_linear_solver.h"
#include "test_scene.h"
#include "test_paths.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;

PrecomputedConstraintCorrection* precomputed(Node& root, const char* node = "body") {
  return test::get<PrecomputedConstraintCorrection>(*root.find_child_named(node), "cc");
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// ---------------------------------------------------------------- closed forms

// A point of mass m on a spring k to its rest position, implicit Euler:
// A = m + h²k per axis, and C = h·A⁻¹ = 0.1 / (2 + 0.01·100) = 1/30 on the
// diagonal, nothing coupling the two points or the axes. The CG solver's
// settings, gravity, x and v are as before the precomputation.
TEST(PrecomputedCompliance, PointOnASpringIsHOverMPlusH2K) {
  test::TempDir dir;
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.1" gravity="0 -10 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver/>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver name="cg" iterations="3" tolerance="1e-5" threshold="1e-6"/>
      <MechanicalObject name="x" position="0 0 0  1 0 0" velocity="0 1 0  0 0 2"/>
      <UniformMass vertexMass="2"/>
      <RestShapeSpringsForceField stiffness="100"/>
      <PrecomputedConstraintCorrection name="cc" fileDir=")" + dir.dir() + R"("/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* cc = precomputed(*s.root);
  ASSERT_NE(cc, nullptr);
  ASSERT_EQ(cc->compliance_rows(), 6u);
  const auto C = cc->compliance();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(C[i * 6 + j], i == j ? 1.0 / 30 : 0.0, 1e-15) << i << " " << j;
  EXPECT_EQ(cc->source(), PrecomputedConstraintCorrection::Source::computed);
  auto* cg = test::get<CGLinearSolver>(*s.root->find_child_named("body"), "cg");
  EXPECT_EQ(cg->iterations.value(), 3u);
  EXPECT_EQ(cg->tolerance.value(), 1e-5);
  EXPECT_EQ(cg->threshold.value(), 1e-6);
  EXPECT_EQ(s.root->find_child_named("body")->gravity.value(), Vec3(0, -10, 0));
  auto* st = s.root->find_child_named("body")->get_mechanical_state();
  EXPECT_EQ(st->read(kPosition), (std::vector<double>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(st->read(kVelocity), (std::vector<double>{0, 1, 0, 0, 0, 2}));
  EXPECT_EQ(max_abs(st->read(kExternalForce)), 0.0);
}

// Rigid3d: A = M, so C = h·M⁻¹: h/m on the translations and h·(m·I)⁻¹ on the
// rotations (UniformMass's inertia), nothing between them. Vec1d: h/m.
TEST(PrecomputedCompliance, RigidAndVec1AreHTimesTheInverseMass) {
  test::TempDir dir;
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.05" gravity="0 -10 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver/>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <SparseLDLSolver/>
      <MechanicalObject template="Rigid3d" name="x" position="1 2 3 0 0 0.6 0.8"/>
      <UniformMass name="m" vertexMass="4"/>
      <PrecomputedConstraintCorrection name="cc" template="Rigid3d" fileDir=")" + dir.dir() + R"("/>
    </Node>
    <Node name="line">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <SparseLDLSolver/>
      <MechanicalObject template="Vec1d" name="x" position="0 1"/>
      <UniformMass vertexMass="0.5"/>
      <PrecomputedConstraintCorrection name="cc" template="Vec1d" fileDir=")" + dir.dir() + R"("/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  auto* cc = precomputed(*s.root);
  ASSERT_NE(cc, nullptr);
  ASSERT_EQ(cc->compliance_rows(), 6u);
  auto* mass = test::get<UniformMass>(*s.root->find_child_named("body"), "m");
  const Mat3 rot = mass->inv_inertia_mass() * 0.05;
  const auto C = cc->compliance();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double expected = 0;
      if (i < 3 && i == j) expected = 0.05 / 4;
      if (i >= 3 && j >= 3) expected = rot(i - 3, j - 3);
      EXPECT_NEAR(C[i * 6 + j], expected, 1e-15) << i << " " << j;
    }
  auto* line = precomputed(*s.root, "line");
  ASSERT_NE(line, nullptr);
  ASSERT_EQ(line->compliance_rows(), 2u);
  EXPECT_NEAR(line->compliance()[0], 0.1, 1e-15);
  EXPECT_NEAR(line->compliance()[3], 0.1, 1e-15);
  EXPECT_EQ(line->compliance()[1], 0.0);
}

// ---------------------------------------------------------------- against LinearSolverConstraintCorrection

// A 5×2×2 hexahedral beam clamped at x = 0, Rayleigh damping, SparseLDL.
std::string beam(const std::string& solver, const std::string& correction, const std::string& method,
                 const std::string& gravity = "0 -10 0", const std::string& extra = "") {
  return R"(<Node name="root" dt="0.01" gravity=")" + gravity + R"(">
    <FreeMotionAnimationLoop/>
    )" + solver + R"(
    <Node name="anchor"><MechanicalObject name="x" position="4 1.02 1"/></Node>
    <Node name="body">
      <EulerImplicitSolver rayleighMass="0.1" rayleighStiffness="0.05"/>
      <SparseLDLSolver/>
      <RegularGridTopology name="grid" nx="5" ny="2" nz="2" xmin="0" xmax="4" ymin="0" ymax="1" zmin="0" zmax="1"/>
      <MechanicalObject name="x"/>
      <UniformMass totalMass="2"/>
      <HexahedronFEMForceField youngModulus="2000" poissonRatio="0.3" method=")" + method + R"("/>
      <FixedProjectiveConstraint indices="0 5 10 15"/>
      )" + correction + R"(
    </Node>
    )" + extra + R"(
  </Node>)";
}

std::string precomputed_cc(const test::TempDir& dir, const std::string& more = "") {
  return R"(<PrecomputedConstraintCorrection name="cc" fileDir=")" + dir.dir() + "\" " + more + "/>";
}
const char* kLinearCC = R"(<LinearSolverConstraintCorrection name="cc"/>)";
const char* kBGS = R"(<BlockGaussSeidelConstraintSolver tolerance="1e-14" maxIterations="1000"/>)";

// W = J·C·Jᵀ from the precomputed C equals LinearSolverConstraintCorrection's
// dt·J·A⁻¹·Jᵀ (same A: the beam is at rest, no gravity) on rows that touch
// one point, two points, and a diagonal direction: W(0,0) = 0.0443, W(2,2) =
// 0.0826 (the twist of the tip), equal to 3e-17 (1e-12 relative asserted).
TEST(PrecomputedCompliance, MatchesLinearSolverCorrectionOnAnFEMBeam) {
  test::TempDir dir;
  std::vector<double> W[2];
  for (int k = 0; k < 2; ++k) {
    scene::LoadedScene s = test::load(beam(kBGS, k == 0 ? precomputed_cc(dir) : kLinearCC, "large", "0 0 0"));
    ASSERT_TRUE(s.root);
    animate(*s.root);  // LinearSolver's factorisation is made during the free motion
    Node* body = s.root->find_child_named("body");
    ConstraintMatrix& J = body->get_mechanical_state()->constraint_jacobian();
    J.clear(3);
    const double y[3] = {0, 1, 0}, d[3] = {0.6, 0.8, 0}, z[3] = {0, 0, 1}, mz[3] = {0, 0, -1};
    J.add(0, 4, y);    // the tip, vertically
    J.add(1, 19, d);   // the opposite tip corner, diagonally
    J.add(2, 4, z);    // the twist of the tip: two points
    J.add(2, 9, mz);
    J.add(3, 12, y);   // a point in the middle
    J.compress();
    ConstraintParams p;
    p.dt = 0.01;
    ConstraintProblem P;
    P.clear(4);
    ConstraintCorrection* cc = test::get<ConstraintCorrection>(*body, "cc");
    ASSERT_NE(cc, nullptr);
    cc->add_compliance(p, P);
    W[k] = P.W;
  }
  const double scale = max_abs(W[1]);
  ASSERT_GT(scale, 1e-4);
  for (std::size_t i = 0; i < W[0].size(); ++i)
    EXPECT_NEAR(W[0][i], W[1][i], 1e-12 * scale) << "W(" << i / 4 << ", " << i % 4 << ")";
  // Both are symmetric and the tip is the softest row.
  EXPECT_NEAR(W[0][1 * 4 + 3], W[0][3 * 4 + 1], 1e-12 * scale);
  EXPECT_GT(W[0][0], W[0][3 * 4 + 3]);
}

// Positions and velocities of every beam point after 30 steps with a
// bilateral constraint pulling the tip corner to an anchor 2 cm above it,
// under gravity: the same with either correction (small displacements: A is
// constant, so the precomputed compliance is exact; they agree to 1e-15),
// the constraint holding, the middle of the beam down by 7.7 cm.
TEST(PrecomputedTrajectory, SameAsLinearSolverCorrectionWithABilateralConstraint) {
  test::TempDir dir;
  const std::string bilateral =
      R"(<BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="19"/>)";
  scene::LoadedScene a = test::load(beam(kBGS, precomputed_cc(dir), "small", "0 -10 0", bilateral));
  scene::LoadedScene b = test::load(beam(kBGS, kLinearCC, "small", "0 -10 0", bilateral));
  ASSERT_TRUE(a.root && b.root);
  auto* sa = a.root->find_child_named("body")->get_mechanical_state();
  auto* sb = b.root->find_child_named("body")->get_mechanical_state();
  for (int step = 0; step < 30; ++step) {
    animate(*a.root);
    animate(*b.root);
  }
  const double vscale = max_abs(sb->read(kVelocity));
  for (std::size_t k = 0; k < sa->read(kPosition).size(); ++k) {
    EXPECT_NEAR(sa->read(kPosition)[k], sb->read(kPosition)[k], 1e-12) << k;
    EXPECT_NEAR(sa->read(kVelocity)[k], sb->read(kVelocity)[k], 1e-10 * std::max(vscale, 1.0)) << k;
  }
  const Vec3 tip = as_vec3(sa->read(kPosition))[19];
  EXPECT_NEAR(tip.x(), 4.0, 1e-9);
  EXPECT_NEAR(tip.y(), 1.02, 1e-9);
  EXPECT_NEAR(tip.z(), 1.0, 1e-9);
  // The middle of the beam sags under gravity.
  EXPECT_NEAR(as_vec3(sa->read(kPosition))[2].y(), -0.0769454457, 1e-9);
  EXPECT_TRUE(test::messages(a.root->diagnostics(), Severity::error).empty());
}

// The large-displacement FEM changes A as the beam bends: the precomputed
// compliance (A at rest) is then an approximation, close for a small sag.
TEST(PrecomputedTrajectory, CloseToLinearSolverCorrectionWithCorotationalFEM) {
  test::TempDir dir;
  const std::string bilateral =
      R"(<BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="19"/>)";
  scene::LoadedScene a =
      test::load(beam(kBGS, precomputed_cc(dir, R"(rotations="false")"), "large", "0 -10 0", bilateral));
  scene::LoadedScene b = test::load(beam(kBGS, kLinearCC, "large", "0 -10 0", bilateral));
  ASSERT_TRUE(a.root && b.root);
  for (int step = 0; step < 30; ++step) {
    animate(*a.root);
    animate(*b.root);
  }
  const auto xa = as_vec3(a.root->find_child_named("body")->get_mechanical_state()->read(kPosition));
  const auto xb = as_vec3(b.root->find_child_named("body")->get_mechanical_state()->read(kPosition));
  double sag = 0, diff = 0;
  for (std::size_t i = 0; i < xa.size(); ++i) {
    sag = std::max(sag, std::fabs(xb[i].y() - (i / 5 % 2 == 0 ? 0.0 : 1.0)));
    diff = std::max(diff, (xa[i] - xb[i]).norm());
  }
  // 6 mm apart for a 12 cm sag after 30 steps.
  EXPECT_GT(sag, 0.1);
  EXPECT_LT(diff, 0.1 * sag);
  EXPECT_NEAR(xa[19].y(), 1.02, 1e-9);
}

// The unbuilt solver (J·C·Jᵀ of the body's rows built at the reset, the
// displacement of a row from the rows with a force) finds the built answer.
TEST(PrecomputedTrajectory, UnbuiltGaussSeidelMatchesBuilt) {
  test::TempDir dir;
  const std::string constraints =
      R"(<BilateralLagrangianConstraint object1="@anchor/x" object2="@body/x" first_point="0" second_point="19"/>
         <BilateralLagrangianConstraint object1="@body/x" object2="@body/x" first_point="4" second_point="14"
                                        rest_vector="0 0 1"/>)";
  scene::LoadedScene a = test::load(beam(kBGS, precomputed_cc(dir), "small", "0 -10 0", constraints));
  scene::LoadedScene b = test::load(
      beam(R"(<UnbuiltGaussSeidelConstraintSolver tolerance="1e-15" maxIterations="20000"/>)", precomputed_cc(dir),
           "small", "0 -10 0", constraints));
  ASSERT_TRUE(a.root && b.root);
  for (int step = 0; step < 10; ++step) {
    animate(*a.root);
    animate(*b.root);
  }
  const auto& xa = a.root->find_child_named("body")->get_mechanical_state()->read(kPosition);
  const auto& xb = b.root->find_child_named("body")->get_mechanical_state()->read(kPosition);
  for (std::size_t k = 0; k < xa.size(); ++k) EXPECT_NEAR(xa[k], xb[k], 1e-9) << k;
  EXPECT_NEAR(as_vec3(xb)[19].y(), 1.02, 1e-9);
  EXPECT_TRUE(test::messages(b.root->diagnostics(), Severity::error).empty());
}

// ---------------------------------------------------------------- LCP

// Two points of mass 1 joined by a spring fall (g = −10) onto planes z ≥ 0:
// the compliance couples the two contacts. Built and unbuilt LCP, with and
// without friction, put both back on their planes (z = 0, v_z = 0), as
// LinearSolverConstraintCorrection does; the contact forces agree.
TEST(PrecomputedLcp, PointsOnPlanesBuiltAndUnbuilt) {
  test::TempDir dir;
  auto scene = [&](const std::string& lcp, const std::string& cc) {
    return R"(<Node name="root" dt="0.01" gravity="0 -3 -10">
      <FreeMotionAnimationLoop/>
      )" + lcp + R"(
      <Node name="body">
        <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
        <SparseLDLSolver/>
        <MechanicalObject name="x" position="0 0 0  1 0 0"/>
        <UniformMass totalMass="2"/>
        <MeshTopology edges="0 1"/>
        <MeshSpringForceField stiffness="300" damping="0"/>
        )" + cc + R"(
      </Node>
    </Node>)";
  };
  for (const char* mu : {"0", "0.5"}) {
    std::vector<double> forces[3];
    int k = 0;
    for (const std::string& variant :
         {std::string(R"(<LCPConstraintSolver name="lcp" tolerance="1e-14" maxIt="5000" build_lcp="1" mu=")") + mu +
              "\"/>|P",
          std::string(R"(<LCPConstraintSolver name="lcp" tolerance="1e-14" maxIt="5000" build_lcp="0" mu=")") + mu +
              "\"/>|P",
          std::string(R"(<LCPConstraintSolver name="lcp" tolerance="1e-14" maxIt="5000" build_lcp="1" mu=")") + mu +
              "\"/>|L"}) {
      const std::string lcp = variant.substr(0, variant.size() - 2);
      const bool linear = variant.back() == 'L';
      scene::LoadedScene s = test::load(scene(lcp, linear ? kLinearCC : precomputed_cc(dir)));
      ASSERT_TRUE(s.root);
      Node* body = s.root->find_child_named("body");
      auto c = std::make_unique<test::PlaneContacts>();
      c->name.set("contacts");
      c->state = body->get_mechanical_state();
      c->friction = std::string(mu) != "0";
      c->contacts.resize(2);
      c->contacts[0].dof = 0;
      c->contacts[1].dof = 1;
      body->add_object(std::move(c));
      for (int step = 0; step < 3; ++step) {
        animate(*s.root);
        const auto x = as_vec3(body->get_mechanical_state()->read(kPosition));
        const auto v = as_vec3(body->get_mechanical_state()->read(kVelocity));
        for (int p = 0; p < 2; ++p) {
          EXPECT_NEAR(x[p].z(), 0.0, 1e-12) << variant << " step " << step;
          EXPECT_NEAR(v[p].z(), 0.0, 1e-9) << variant << " step " << step;
        }
      }
      auto* lcps = test::get<LCPConstraintSolver>(*s.root, "lcp");
      ASSERT_NE(lcps, nullptr);
      EXPECT_TRUE(lcps->last_result().converged) << variant;
      forces[k++] = lcps->problem().f;
    }
    for (int v = 1; v < 3; ++v)
      for (std::size_t i = 0; i < forces[0].size(); ++i) EXPECT_NEAR(forces[v][i], forces[0][i], 1e-9) << mu << v;
    // Two falling points of mass 1 stopped in one step: λ ≈ m·|v_f| each.
    EXPECT_GT(forces[0][0], 0.09);
  }
}

// rotations on a Vec3d body without a corotational FEM: one warning, the
// compliance left alone (SOFA's rotation of J has no effect).
TEST(PrecomputedLcp, RotationsWithoutARotationFinderWarnOnce) {
  test::TempDir dir;
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.01" gravity="0 0 -10">
      <FreeMotionAnimationLoop/>
      <LCPConstraintSolver name="lcp" tolerance="1e-14" mu="0"/>
      <Node name="body">
        <EulerImplicitSolver/>
        <SparseLDLSolver/>
        <MechanicalObject name="x" position="0 0 0"/>
        <UniformMass totalMass="1"/>
        <PrecomputedConstraintCorrection name="cc" rotations="true" fileDir=")" + dir.dir() + R"("/>
      </Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  Node* body = s.root->find_child_named("body");
  auto c = std::make_unique<test::PlaneContacts>();
  c->state = body->get_mechanical_state();
  c->contacts.resize(1);
  body->add_object(std::move(c));
  for (int step = 0; step < 3; ++step) animate(*s.root);
  EXPECT_NEAR(as_vec3(body->get_mechanical_state()->read(kPosition))[0].z(), 0.0, 1e-12);
  int count = 0;
  for (const std::string& w : test::messages(s.root->diagnostics(), Severity::warning))
    if (w.find("no rotation finder") != std::string::npos) ++count;
  EXPECT_EQ(count, 1);
}

// ---------------------------------------------------------------- cache file

std::string point_scene(const std::string& cc_attrs) {
  return R"(<Node name="root" dt="0.02" gravity="0 -10 0">
    <FreeMotionAnimationLoop/>
    <BlockGaussSeidelConstraintSolver/>
    <Node name="Body">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <SparseLDLSolver/>
      <MechanicalObject name="x" position="0 0 0  1 0 0  0 1 0"/>
      <UniformMass totalMass="3"/>
      <MeshTopology edges="0 1  1 2"/>
      <MeshSpringForceField stiffness="50" damping="0"/>
      <PrecomputedConstraintCorrection name="cc" )" + cc_attrs + R"(/>
    </Node>
  </Node>)";
}

std::vector<double> compliance_of(scene::LoadedScene& s) {
  auto* cc = test::get<PrecomputedConstraintCorrection>(*s.root->find_child_named("Body"), "cc");
  EXPECT_NE(cc, nullptr);
  return cc ? std::vector<double>(cc->compliance().begin(), cc->compliance().end()) : std::vector<double>();
}

PrecomputedConstraintCorrection::Source source_of(scene::LoadedScene& s) {
  return test::get<PrecomputedConstraintCorrection>(*s.root->find_child_named("Body"), "cc")->source();
}

// Written as "<node>-<rows>-<dt>.comp" in fileDir (n·n doubles and Sinew's
// trailer), read back bit for bit; a corrupt, truncated or foreign-dt file is
// recomputed with a warning naming the reason; a bare SOFA file is accepted.
TEST(PrecomputedCache, RoundTripAndValidation) {
  test::TempDir dir;
  const std::string attrs = "fileDir=\"" + dir.dir() + "\"";
  const fs::path file = fs::path(dir.dir()) / "Body-9-0.02.comp";
  EXPECT_EQ(compliance_cache::file_name("Body", 9, 0.02), "Body-9-0.02.comp");
  EXPECT_EQ(compliance_cache::file_name("Liver", 543, 0.005), "Liver-543-0.005.comp");
  EXPECT_EQ(compliance_cache::file_name("N", 3, 1e-5), "N-3-1e-05.comp");

  std::vector<double> first;
  {
    scene::LoadedScene s = test::load(point_scene(attrs));
    ASSERT_TRUE(s.root);
    EXPECT_EQ(source_of(s), PrecomputedConstraintCorrection::Source::computed);
    first = compliance_of(s);
    ASSERT_EQ(first.size(), 81u);
    ASSERT_TRUE(fs::exists(file));
    EXPECT_EQ(fs::file_size(file), 81u * 8 + 32);
  }
  auto reload = [&](PrecomputedConstraintCorrection::Source expected, const char* warning) {
    scene::LoadedScene s = test::load(point_scene(attrs));
    ASSERT_TRUE(s.root);
    EXPECT_EQ(source_of(s), expected) << (warning ? warning : "");
    EXPECT_EQ(compliance_of(s), first);  // bit for bit, read or recomputed
    const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
    if (warning) EXPECT_TRUE(test::any_contains(warnings, warning)) << warning;
    else EXPECT_TRUE(warnings.empty());
    EXPECT_TRUE(test::messages(s.root->diagnostics(), Severity::error).empty());
  };
  reload(PrecomputedConstraintCorrection::Source::file, nullptr);

  // One flipped byte in the middle of the values.
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(8 * 40 + 3);
    f.put(static_cast<char>(0x5a));
  }
  reload(PrecomputedConstraintCorrection::Source::computed, "checksum does not match");
  reload(PrecomputedConstraintCorrection::Source::file, nullptr);  // rewritten

  fs::resize_file(file, 8 * 50);
  reload(PrecomputedConstraintCorrection::Source::computed, "it holds 400 bytes, expected 648");

  // Another dt in the trailer.
  {
    std::string why;
    ASSERT_TRUE(compliance_cache::write(file.string(), first.data(), 9, 0.01, why)) << why;
  }
  reload(PrecomputedConstraintCorrection::Source::computed, "computed for dt = 0.01");

  // SOFA's own format: the values only.
  {
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(first.data()), 81 * 8);
  }
  reload(PrecomputedConstraintCorrection::Source::file, nullptr);

  // A non-finite value in a SOFA file.
  {
    std::vector<double> bad = first;
    bad[7] = std::nan("");
    std::ofstream f(file, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(bad.data()), 81 * 8);
  }
  reload(PrecomputedConstraintCorrection::Source::computed, "value 7 is not finite");
}

// fileCompliance names a file to read (a SOFA file elsewhere); missing, it is
// recomputed with a warning (no error: the scene runs).
TEST(PrecomputedCache, FileComplianceReadOrRecomputed) {
  test::TempDir dir;
  const std::string attrs = "fileDir=\"" + dir.dir() + "\"";
  std::vector<double> first;
  {
    scene::LoadedScene s = test::load(point_scene(attrs));
    ASSERT_TRUE(s.root);
    first = compliance_of(s);
  }
  const fs::path moved = fs::path(dir.dir()) / "mine.comp";
  fs::rename(fs::path(dir.dir()) / "Body-9-0.02.comp", moved);
  {
    scene::LoadedScene s = test::load(point_scene("fileCompliance=\"" + moved.string() + "\""));
    ASSERT_TRUE(s.root);
    EXPECT_EQ(source_of(s), PrecomputedConstraintCorrection::Source::file);
    EXPECT_EQ(compliance_of(s), first);
  }
  {
    scene::LoadedScene s =
        test::load(point_scene("fileCompliance=\"" + (fs::path(dir.dir()) / "none.comp").string() + "\" " + attrs));
    ASSERT_TRUE(s.root);
    EXPECT_EQ(source_of(s), PrecomputedConstraintCorrection::Source::computed);
    EXPECT_EQ(compliance_of(s), first);
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "not found"));
    EXPECT_TRUE(fs::exists(fs::path(dir.dir()) / "Body-9-0.02.comp"));
  }
}

// Without fileDir SOFA writes to the first data folder; a read-only one (mode
// 0555, even for root) is left alone and the fallback folder in the system
// temp dir is used; recompute then ignores the fallback file, otherwise it is
// read back.
TEST(PrecomputedCache, ReadOnlyDataFolderFallsBackToTemp) {
  test::TempDir dir;
  const fs::path data = fs::path(dir.dir()) / "data";
  fs::create_directories(data);
  ::chmod(data.c_str(), 0555);
  EXPECT_FALSE(compliance_cache::writable_dir(data.string()));
  EXPECT_FALSE(compliance_cache::writable_dir((data / "missing").string()));
  EXPECT_TRUE(compliance_cache::writable_dir(dir.dir()));
  // A unique node name so that runs in parallel do not share the fallback file.
  const std::string node = "Body" + std::to_string(::getpid());
  std::string xml = point_scene("recompute=\"true\"");
  xml.replace(xml.find("\"Body\""), 6, "\"" + node + "\"");
  const fs::path fallback = fs::path(compliance_cache::fallback_dir()) / (node + "-9-0.02.comp");
  fs::remove(fallback);
  for (int run = 0; run < 3; ++run) {
    std::string text = xml;
    if (run == 2) text.replace(text.find("recompute=\"true\""), 16, "recompute=\"false\"");
    scene::LoadedScene s = test::build(text);
    ASSERT_TRUE(s.root);
    s.root->data_dirs = {data.string()};
    init_root(*s.root);
    auto* cc = test::get<PrecomputedConstraintCorrection>(*s.root->find_child_named(node), "cc");
    ASSERT_NE(cc, nullptr);
    EXPECT_EQ(cc->cache_path(), fallback.string());
    EXPECT_EQ(cc->source(), run < 2 ? PrecomputedConstraintCorrection::Source::computed
                                    : PrecomputedConstraintCorrection::Source::file);
    EXPECT_TRUE(fs::is_empty(data));
  }
  fs::remove(fallback);
  ::chmod(data.c_str(), 0755);
}

// Two corrections of one simulation with the same file name share one
// compliance (SOFA's map of inverses): the second is not recomputed.
TEST(PrecomputedCache, SharedInMemoryWithinOneSimulation) {
  test::TempDir dir;
  const std::string cc = R"(<PrecomputedConstraintCorrection name="cc" recompute="1" fileDir=")" +
                         dir.dir() + R"("/>)";
  const std::string body = R"(<EulerImplicitSolver/><SparseLDLSolver/>
      <MechanicalObject name="x" position="0 0 0"/><UniformMass totalMass="1"/>)" + cc;
  scene::LoadedScene s = test::load(R"(<Node name="root" dt="0.01">
    <FreeMotionAnimationLoop/><BlockGaussSeidelConstraintSolver/>
    <Node name="a"><Node name="Same">)" + body + R"(</Node></Node>
    <Node name="b"><Node name="Same">)" + body + R"(</Node></Node></Node>)");
  ASSERT_TRUE(s.root);
  auto* first = test::get<PrecomputedConstraintCorrection>(
      *s.root->find_child_named("a")->find_child_named("Same"), "cc");
  auto* second = test::get<PrecomputedConstraintCorrection>(
      *s.root->find_child_named("b")->find_child_named("Same"), "cc");
  ASSERT_TRUE(first && second);
  // Computed in graph order at the end of the initialisation: a's computes, b's shares it.
  EXPECT_EQ(first->source(), PrecomputedConstraintCorrection::Source::computed);
  EXPECT_EQ(second->source(), PrecomputedConstraintCorrection::Source::memory);
  EXPECT_EQ(first->compliance().data(), second->compliance().data());
}

// Bad input: no ODE solver, an empty state: errors, the component is
// invalid, nothing crashes when stepping. (A body without mass is the linear
// solver's error: a singular system.)
TEST(PrecomputedCache, BadInputIsAnErrorNotACrash) {
  test::TempDir dir;
  const std::string d = dir.dir();
  for (const std::string& body :
       {std::string(R"(<MechanicalObject name="x" position="0 0 0"/><UniformMass totalMass="1"/>)"
                    R"(<PrecomputedConstraintCorrection name="cc" fileDir=")") + d + "\"/>",
        std::string(R"(<EulerImplicitSolver/><SparseLDLSolver/><MechanicalObject name="x" size="0"/>)"
                    R"(<PrecomputedConstraintCorrection name="cc" fileDir=")") + d + "\"/>"}) {
    scene::LoadedScene s = test::build(R"(<Node name="root" dt="0.01"><FreeMotionAnimationLoop/>
      <BlockGaussSeidelConstraintSolver/><Node name="Body">)" + body + "</Node></Node>");
    ASSERT_TRUE(s.root);
    EXPECT_FALSE(init_root(*s.root));
    auto* cc = test::get<PrecomputedConstraintCorrection>(*s.root->find_child_named("Body"), "cc");
    ASSERT_NE(cc, nullptr);
    EXPECT_EQ(cc->state(), ComponentState::invalid);
    EXPECT_FALSE(test::messages(s.root->diagnostics(), Severity::error).empty());
    animate(*s.root);
  }
}

// ---------------------------------------------------------------- SOFA's example

// DeformableOnRigidFrameMappingConstraints.scn: a rigid torus with a
// deformable skin (PrecomputedConstraintCorrection through
// DeformableOnRigidFrameMapping) falls onto a fixed torus (LCP friction
// contacts). 100 steps: everything finite, the torus stopped by the fixed one
// (its fall of 2 s would be 19.6 m), the skin deformed by millimetres, the
// cache written outside the read-only data tree.
TEST(PrecomputedScene, DeformableOnRigidFrameMappingConstraints) {
  const fs::path data = fs::path(SINEW_DATA_DIR);
  const fs::path file = data / "examples/Component/Mapping/Linear/DeformableOnRigidFrameMappingConstraints.scn";
  if (!fs::exists(file)) GTEST_SKIP() << "SOFA data not found at " << data;
  register_all_components();
  scene::LoadOptions opts;
  opts.data_paths = {(data / "share").string(), (data / "examples").string()};
  opts.use_sofa_data_path = false;
  Diagnostics diag;
  scene::LoadedScene s = scene::load_scene(file.string(), opts, diag);
  ASSERT_TRUE(s.root);
  ASSERT_TRUE(s.ok());
  ASSERT_TRUE(init_root(*s.root));
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'FreeMotionAnimationLoop1' (FreeMotionAnimationLoop) replaced by component "
                             "'FreeMotionAnimationLoop2' (FreeMotionAnimationLoop)"),
            std::string::npos)
      << warnings[0];
  Node* local = s.root->find_child_named("ChainRigid")->find_child_named("TorusDeformLocal");
  auto* cc = test::get<PrecomputedConstraintCorrection>(*local, "PrecomputedConstraintCorrection1");
  ASSERT_NE(cc, nullptr);
  EXPECT_EQ(cc->compliance_rows(), 168u);  // 56 grid points
  EXPECT_EQ(fs::path(cc->cache_path()).filename(), "TorusDeformLocal-168-0.02.comp");
  EXPECT_EQ(cc->cache_path().find(data.string()), std::string::npos);
  MechanicalState* rigid =
      s.root->find_child_named("ChainRigid")->find_child_named("TorusRigid")->get_mechanical_state();
  MechanicalState* skin = local->get_mechanical_state();
  const std::vector<double> skin0 = skin->read(kPosition);
  for (int step = 0; step < 100; ++step) animate(*s.root);
  for (MechanicalState* st : {rigid, skin})
    for (double v : st->read(kPosition)) ASSERT_TRUE(std::isfinite(v));
  const double y = rigid->read(kPosition)[1];
  EXPECT_LT(y, 1.6);  // it fell onto the fixed torus ...
  EXPECT_GT(y, 0.0);  // ... which held it
  double deformation = 0;
  for (std::size_t k = 0; k < skin0.size(); ++k)
    deformation = std::max(deformation, std::fabs(skin->read(kPosition)[k] - skin0[k]));
  EXPECT_GT(deformation, 1e-4);
  EXPECT_LT(deformation, 0.05);
  EXPECT_TRUE(test::messages(s.root->diagnostics(), Severity::error).empty());
}

}  // namespace
}  // namespace sinew
