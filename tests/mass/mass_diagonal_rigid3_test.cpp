// DiagonalMass on Rigid3d frames (TutorialMappingOctopusArticulated.scn): one
// RigidMass per frame in vertexMass, used as given (SOFA ignores massDensity and
// totalMass there); M = diag(m, m, m, m·I) per frame.
#include <gtest/gtest.h>

#include "core/matrix_sink.h"
#include "core/rigid_mass_text.h"
#include "mass/diagonal_rigid_mass.h"
#include "test_scene.h"

namespace sinew {
namespace diagonal_rigid_test {

TEST(RigidMassList, ReadsSofasVectorOfRigidMasses) {
  std::vector<double> v;
  // Brackets and commas (SOFA's output form), then the plain form.
  EXPECT_TRUE(parse::read_rigid3_mass_list("15 15 [20 0 0,0 20 0,0 0 20] 1 1 1 0 0 0 1 0 0 0 1", v));
  ASSERT_EQ(v.size(), 22u);
  EXPECT_EQ(v[0], 15);
  EXPECT_EQ(v[2], 20);
  EXPECT_EQ(v[10], 20);
  EXPECT_EQ(v[11], 1);
  EXPECT_EQ(v[21], 1);
  // An incomplete last mass is dropped and reported.
  EXPECT_FALSE(parse::read_rigid3_mass_list("2 1 [1 0 0,0 1 0,0 0 1] 3 1 [1 0", v));
  EXPECT_EQ(v.size(), 11u);
  EXPECT_FALSE(parse::read_rigid3_mass_list("2 1 [1 0 x]", v));
  EXPECT_TRUE(v.empty());
  EXPECT_TRUE(parse::read_rigid3_mass_list("  ", v));
  EXPECT_TRUE(v.empty());
}

const char* kFrames = R"(<Node name="root" gravity="0 -10 0" dt="0.1"><DefaultAnimationLoop/>
  <EulerExplicitSolver symplectic="true"/>
  <MechanicalObject name="dofs" template="Rigid3d" position="0 0 0 0 0 0 1  1 2 3 0 0 0 1"/>
  <MeshTopology name="topo" src="@dofs"/>
  <DiagonalMass name="mass" template="Rigid3,Rigid3" topology="@topo" geometryState="@dofs"
                vertexMass="2 1 [1 0 0,0 2 0,0 0 4] 0.5 1 1 0 0 0 3 0 0 0 1"/>
  <ConstantForceField template="Rigid3d" forces="0 0 0 0 0 8  0 3 0 0 6 0"/>
</Node>)";

TEST(DiagonalMassRigid3, MassMatrixIsMassThenMassTimesInertiaPerFrame) {
  scene::LoadedScene s = test::load(kFrames);
  auto* m = test::get<DiagonalRigidMass>(*s.root, "mass");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->state(), ComponentState::valid);
  EXPECT_DOUBLE_EQ(m->total(), 2.5);
  MatrixSink M;
  ASSERT_TRUE(m->build_mass(M));
  std::vector<double> diag(12, 0.0);
  for (const auto& e : M.entries())
    if (e.row == e.col) diag[e.row] += e.value;
  EXPECT_EQ(diag, (std::vector<double>{2, 2, 2, 2, 4, 8, 0.5, 0.5, 0.5, 0.5, 1.5, 0.5}));
}

TEST(DiagonalMassRigid3, OneExplicitStepGivesGravityAndAngularAccelerations) {
  scene::LoadedScene s = test::load(kFrames);
  animate(*s.root);
  auto* dofs = test::get<MechanicalState>(*s.root, "dofs");
  const std::vector<double>& v = dofs->read(kVelocity);
  ASSERT_EQ(v.size(), 12u);
  // Frame 0: gravity only on the centre; torque 8 about z over m·Izz = 8 → ω̇ = 1.
  EXPECT_NEAR(v[1], -1.0, 1e-15);
  EXPECT_NEAR(v[5], 0.1, 1e-15);
  // Frame 1: force 3 on mass 0.5 (+6) against gravity (−10) → −0.4; torque 6 about y over 1.5 → 4.
  EXPECT_NEAR(v[7], -0.4, 1e-15);
  EXPECT_NEAR(v[10], 0.4, 1e-15);
  // The potential energy is −Σ m g·c at the new centres.
  const std::vector<double>& x = dofs->read(kPosition);
  auto* m = test::get<DiagonalRigidMass>(*s.root, "mass");
  EXPECT_NEAR(*m->potential_energy(), 2 * 10 * x[1] + 0.5 * 10 * x[8], 1e-12);
}

TEST(DiagonalMassRigid3, WrongCountsAndSingularMassesAreRefused) {
  auto errors_of = [](const std::string& vertex_mass) {
    std::string xml = kFrames;
    const std::string from = "vertexMass=\"2 1 [1 0 0,0 2 0,0 0 4] 0.5 1 1 0 0 0 3 0 0 0 1\"";
    xml.replace(xml.find(from), from.size(), "vertexMass=\"" + vertex_mass + "\"");
    scene::LoadedScene s = test::build(xml);
    init_root(*s.root);
    return test::messages(s.root->diagnostics(), Severity::error);
  };
  EXPECT_TRUE(test::any_contains(errors_of("2 1 [1 0 0,0 2 0,0 0 4]"), "has 1 rigid masses for 2 frames"));
  EXPECT_TRUE(test::any_contains(errors_of("2 1 [1 0 0,0 2 0,0 0 4] 0 1 [1 0 0,0 1 0,0 0 1]"), "frame 1: mass 0"));
  EXPECT_TRUE(test::any_contains(errors_of("2 1 [1 0 0,0 2 0,0 0 4] 1 1 [1 0 0,0 0 0,0 0 1]"), "has no inverse"));
  EXPECT_TRUE(errors_of("2 1 [1 0 0,0 2 0,0 0 4] 1 1 1 0 0 0 1 0 0 0 1").empty());
}

TEST(DiagonalMassRigid3, UnreadableMassListIsReported) {
  std::string xml = kFrames;
  const std::string from = "0.5 1 1 0 0 0 3 0 0 0 1\"";
  xml.replace(xml.find(from), from.size(), "0.5 1 [1 0 x]\"");
  Diagnostics tree;
  scene::LoadedScene s = test::build(xml, &tree);
  std::vector<std::string> all = test::messages(tree, Severity::warning);
  for (const auto& m : test::messages(s.root->diagnostics(), Severity::warning)) all.push_back(m);
  EXPECT_TRUE(test::any_contains(all, "only 1 complete rigid masses could be read"));
}

}  // namespace diagonal_rigid_test
}  // namespace sinew
