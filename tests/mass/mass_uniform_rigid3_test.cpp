// UniformMass on Rigid3d: vertexMass written in SOFA's Rigid3Mass syntax,
// "mass volume [I00 I01 I02,I10 I11 I12,I20 I21 I22]" (brackets and commas
// between rows optional), as in BarycentricMappingTrussBeam.scn.
#include <gtest/gtest.h>

#include "core/matrix_sink.h"
#include "mass/uniform_mass.h"
#include "test_scene.h"

namespace sinew {
namespace {

// Diagonal of the mass matrix of one Rigid3d DoF: m, m, m, then m·I.
std::vector<double> mass_diagonal(const std::string& vertex_mass, std::vector<std::string>* warnings = nullptr) {
  scene::LoadedScene s = test::load(R"(<Node name="root"><DefaultAnimationLoop/>
    <MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <UniformMass name="mass" vertexMass=")" + vertex_mass + R"("/></Node>)");
  if (warnings) *warnings = test::messages(s.root->diagnostics(), Severity::warning);
  auto* m = test::get<UniformMass>(*s.root, "mass");
  MatrixSink M;
  EXPECT_TRUE(m && m->build_mass(M));
  std::vector<double> diag(6, 0.0);
  for (const auto& e : M.entries())
    if (e.row == e.col) diag[e.row] += e.value;
  return diag;
}

TEST(UniformMassRigid3, VertexMassWithABracketedInertiaMatrix) {
  std::vector<std::string> warnings;
  // The scene's own value: mass 0.001, volume 0.001, inertia 1e-4·I → m·I = 1e-7.
  const auto d = mass_diagonal("0.001 0.001 [0.0001 0 0 0 0.0001 0 0 0 0.0001]", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const std::vector<double> want = {0.001, 0.001, 0.001, 1e-7, 1e-7, 1e-7};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(d[k], want[k], 1e-20) << k;
  // SOFA's output form: rows separated by commas.
  const auto c = mass_diagonal("2 1 [1 0 0,0 3 0,0 0 5]", &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(c, (std::vector<double>{2, 2, 2, 2, 6, 10}));
  // And the plain form.
  EXPECT_EQ(mass_diagonal("2 1 1 0 0 0 3 0 0 0 5"), (std::vector<double>{2, 2, 2, 2, 6, 10}));
  // The mass alone keeps the identity inertia.
  EXPECT_EQ(mass_diagonal("4"), (std::vector<double>{4, 4, 4, 4, 4, 4}));
}

TEST(UniformMassRigid3, UnreadableVertexMassIsReported) {
  std::vector<std::string> warnings;
  mass_diagonal("1 1 [1 0 x]", &warnings);
  EXPECT_TRUE(test::any_contains(warnings, "could not read value for field 'vertexMass'"));
}

}  // namespace
}  // namespace sinew
