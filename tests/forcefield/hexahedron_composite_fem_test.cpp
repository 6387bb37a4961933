// HexahedronCompositeFEMForceFieldAndMass and HexahedronCompositeFEMMapping (SOFA's
// FEM/NonUniform): cells homogenized from composite material on a ramified sparse grid.
// No closed form exists for the homogenized matrices; these tests check the properties
// the method guarantees (symmetry, rigid translations free of energy, mass kept, weights
// that move translations rigidly, a stiff inclusion stiffening its cell), the classical
// matrices without virtual levels, the mapping against rigid motions and its adjoint, the
// refused modes, and SOFA's two example scenes (a stiff seed in a soft grape stays round).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "badinput_helpers.h"
#include "forcefield/fem/nonuniform/hexahedron_composite_fem_force_field_and_mass.h"
#include "mapping/linear/hexahedron_composite_fem_mapping.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/grid/sparse_grid_ramification_topology.h"

namespace sinew {
namespace {

// A closed box as an OBJ surface.
std::string box_obj(const Vec3& lo, const Vec3& hi) {
  std::string s;
  for (int k = 0; k < 8; ++k) {
    const Vec3 p((k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]);
    s += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  }
  // Faces (1-based, corner code + 1), outward.
  s += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  return s;
}

// A grid of n points per axis over a 2×2×2 box, with an inclusion [0.3, 1.3]³ of stiffness `coef`.
std::string composite_scene(const test::TempDir& dir, double coef, int levels, const std::string& grid_extra = "",
                            const std::string& ff_extra = "") {
  const std::string out = dir.write("out.obj", box_obj(Vec3(0, 0, 0), Vec3(2, 2, 2)));
  const std::string in = dir.write("in.obj", box_obj(Vec3(0.3, 0.3, 0.3), Vec3(1.3, 1.3, 1.3)));
  return "<Node dt=\"0.01\" gravity=\"0 0 0\"><DefaultAnimationLoop/>"
         "<EulerImplicitSolver/><CGLinearSolver iterations=\"100\" tolerance=\"1e-12\" threshold=\"1e-20\"/>"
         "<SparseGridMultipleTopology name=\"g\" n=\"3 3 3\" fileTopology=\"" + out + "\" fileTopologies=\"" + out +
         " " + in + "\" stiffnessCoefs=\"1 " + std::to_string(coef) +
         "\" massCoefs=\"1 1\" nbVirtualFinerLevels=\"2\" finestConnectivity=\"false\" " + grid_extra +
         "/><MechanicalObject name=\"dofs\"/>"
         "<HexahedronCompositeFEMForceFieldAndMass name=\"fem\" youngModulus=\"1000\" poissonRatio=\"0.3\" "
         "density=\"2\" method=\"polar\" nbVirtualFinerLevels=\"" + std::to_string(levels) + "\" " + ff_extra + "/>";
}

fem::Mat24 stiffness(const HexahedronCompositeFEMForceFieldAndMass& ff, std::size_t e) {
  return ff.kernel().K[e].transpose();  // stored transposed (see NonUniformHexahedronFEMForceFieldAndMass)
}

TEST(HexahedronCompositeFEM, HomogenizedMatricesAreSymmetricAndFreeOfRigidTranslations) {
  test::TempDir dir;
  auto s = test::load(composite_scene(dir, 100, 2) + "</Node>");
  ASSERT_TRUE(s.root);
  auto* ff = test::get<HexahedronCompositeFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  ASSERT_EQ(ff->kernel().size(), 8u);
  ASSERT_EQ(ff->component_masses().size(), 8u);
  for (std::size_t e = 0; e < 8; ++e) {
    const fem::Mat24 K = stiffness(*ff, e);
    const double scale = K.cwiseAbs().maxCoeff();
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-9 * scale) << "element " << e;
    for (int c = 0; c < 3; ++c) {
      Eigen::Matrix<double, 24, 1> t = Eigen::Matrix<double, 24, 1>::Zero();
      for (int w = 0; w < 8; ++w) t[3 * w + c] = 1;
      EXPECT_LT((K * t).cwiseAbs().maxCoeff(), 1e-9 * scale) << "element " << e << ", translation " << c;
    }
    const Eigen::SelfAdjointEigenSolver<fem::Mat24> eig(0.5 * (K + K.transpose()));
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-9 * scale) << "element " << e;
    // The translations are the only modes without energy: the masked weights do not carry a
    // coarse rotation to a fine one exactly, so rotations cost a little (as in SOFA).
    int zero = 0;
    for (int i = 0; i < 24; ++i) zero += eig.eigenvalues()[i] < 1e-9 * scale;
    EXPECT_EQ(zero, 3) << "element " << e;
  }
}

// Rows of W that sum to 1 per component carry the mass of the fine cells to the coarse
// one untouched: 1ᵀ·Wᵀ·M·W·1 = 1ᵀ·M·1.
TEST(HexahedronCompositeFEM, MassOfTheFineCellsIsKept) {
  test::TempDir dir;
  auto s = test::load(composite_scene(dir, 100, 2) + "</Node>");
  ASSERT_TRUE(s.root);
  auto* ff = test::get<HexahedronCompositeFEMForceFieldAndMass>(*s.root, "fem");
  auto* grid = test::get<SparseGridRamificationTopology>(*s.root, "g");
  ASSERT_EQ(grid->ramified_levels(), 2);
  // The fine cells' classical masses: (vol·ρ·integral)·coef on every node pair, 64 pairs.
  const auto fine = grid->ramified_level(2);
  double expected = 0;
  for (std::size_t h = 0; h < fine.hexas.size(); ++h) {
    const auto& c = fine.hexas[h];
    const double vol = (fine.points[c[1]] - fine.points[c[0]]).norm() * (fine.points[c[3]] - fine.points[c[0]]).norm() *
                       (fine.points[c[4]] - fine.points[c[0]]).norm();
    expected += 64 * vol * hexa_mass_integral(2.0) * fine.stiffness[h];
  }
  for (int c = 0; c < 3; ++c) {
    double total = 0;
    for (const auto& m : ff->component_masses())
      for (double v : m[c]) total += v;
    EXPECT_NEAR(total, expected, 1e-9 * expected) << "component " << c;
  }
}

TEST(HexahedronCompositeFEM, FinalWeightsMoveTranslationsRigidly) {
  test::TempDir dir;
  auto s = test::load(composite_scene(dir, 100, 2) + "</Node>");
  ASSERT_TRUE(s.root);
  auto* ff = test::get<HexahedronCompositeFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_FALSE(ff->final_weights().empty());
  const Vec3 t(0.3, -0.7, 1.1);
  Eigen::Matrix<double, 24, 1> T;
  for (int w = 0; w < 8; ++w) T.segment<3>(3 * w) = t;
  for (const auto& fw : ff->final_weights()) {
    ASSERT_LT(fw.coarse, 8u);
    EXPECT_LT((fw.W * T - T).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// Energy of a shear of the whole block: the stiff inclusion (coefficient 100) makes the cells
// around it stiffer than the same grid of one material.
TEST(HexahedronCompositeFEM, StiffInclusionStiffensItsCells) {
  test::TempDir dir;
  auto soft = test::load(composite_scene(dir, 1, 2) + "</Node>");
  auto stiff = test::load(composite_scene(dir, 100, 2) + "</Node>");
  ASSERT_TRUE(soft.root && stiff.root);
  auto* a = test::get<HexahedronCompositeFEMForceFieldAndMass>(*soft.root, "fem");
  auto* b = test::get<HexahedronCompositeFEMForceFieldAndMass>(*stiff.root, "fem");
  auto* grid = test::get<SparseGridRamificationTopology>(*soft.root, "g");
  const auto top = grid->ramified_level(0);
  double ea = 0, eb = 0;
  for (std::size_t e = 0; e < 8; ++e) {
    Eigen::Matrix<double, 24, 1> u;
    for (int w = 0; w < 8; ++w) u.segment<3>(3 * w) = Vec3(0.01 * top.points[top.hexas[e][w]][1], 0, 0);
    const double ua = u.dot(stiffness(*a, e) * u), ub = u.dot(stiffness(*b, e) * u);
    ea += ua;
    eb += ub;
    EXPECT_GE(ub, ua * (1 - 1e-12)) << "element " << e;
  }
  EXPECT_GT(eb, 1.5 * ea);
}

// Without virtual levels: each cell's classical matrices, with its own stiffness and mass coefficients.
TEST(HexahedronCompositeFEM, ZeroLevelsGiveTheClassicalMatrices) {
  test::TempDir dir;
  auto s = test::load(composite_scene(dir, 100, 0) + "</Node>");
  ASSERT_TRUE(s.root);
  auto* ff = test::get<HexahedronCompositeFEMForceFieldAndMass>(*s.root, "fem");
  auto* grid = test::get<SparseGridRamificationTopology>(*s.root, "g");
  ASSERT_EQ(ff->state(), ComponentState::valid);
  EXPECT_TRUE(ff->component_masses().empty());
  const auto& pts = grid->position.value();
  for (std::size_t e = 0; e < ff->kernel().size(); ++e) {
    std::array<Vec3, 8> nodes;
    for (int w = 0; w < 8; ++w) nodes[w] = pts[grid->hexahedra()[e][w]];
    fem::Mat24 K;
    fem::hexa_element_stiffness(nodes, fem::hexa_material(1000, 0.3), grid->stiffness_coef(e), K);
    EXPECT_LT((stiffness(*ff, e) - K).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff()) << "element " << e;
    const double vol = (nodes[1] - nodes[0]).norm() * (nodes[3] - nodes[0]).norm() * (nodes[4] - nodes[0]).norm();
    EXPECT_DOUBLE_EQ(ff->element_mass(e)[9], vol * hexa_mass_integral(2.0) * grid->mass_coef(e));
  }
}

TEST(HexahedronCompositeFEM, UnsupportedModesAreRefused) {
  test::TempDir dir;
  test::Outcome o = test::run_xml(dir, composite_scene(dir, 100, 2, "", "finestToCoarse=\"1\"") + "</Node>");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"fem", "finestToCoarse"})) << o.all();
  o = test::run_xml(dir, composite_scene(dir, 100, 2, "", "useRamification=\"0\"") + "</Node>");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"fem", "useRamification=false"})) << o.all();
  o = test::run_xml(dir, composite_scene(dir, 100, 2, "computeRamifications=\"0\"") + "</Node>");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"fem", "computeRamifications=false", "not supported"})) << o.all();
}

// The mapping: initial points reproduced, rigid translations followed, Jᵀ the adjoint of J
// (to single precision: SOFA rounds the coarse displacements to float).
TEST(HexahedronCompositeFEMMapping, FollowsTranslationsAndJtIsTheAdjointOfJ) {
  test::TempDir dir;
  const std::string xml = composite_scene(dir, 100, 2) +
                          "<Node name=\"skin\"><MechanicalObject name=\"pts\" position=\"0.5 0.5 0.5  1.7 0.2 1.1  "
                          "0.05 1.95 1.0  1.31 1.29 0.33\"/><HexahedronCompositeFEMMapping name=\"map\"/></Node></Node>";
  auto s = test::load(xml);
  ASSERT_TRUE(s.root);
  Node* skin = s.root->find_child_named("skin");
  auto* map = test::get<HexahedronCompositeFEMMapping>(*skin, "map");
  auto* pts = test::get<MechanicalState>(*skin, "pts");
  auto* dofs = test::get<MechanicalState>(*s.root, "dofs");
  ASSERT_EQ(map->state(), ComponentState::valid);
  const std::vector<double> p0 = {0.5, 0.5, 0.5, 1.7, 0.2, 1.1, 0.05, 1.95, 1.0, 1.31, 1.29, 0.33};
  for (std::size_t i = 0; i < p0.size(); ++i) EXPECT_NEAR(pts->read(kPosition)[i], p0[i], 1e-12);
  // A translation exact in single precision.
  std::vector<double>& x = dofs->write(kPosition);
  for (std::size_t i = 0; i < x.size(); i += 3) x[i] += 0.5, x[i + 1] -= 0.25, x[i + 2] += 0.125;
  map->apply(kPosition);
  const Vec3 t(0.5, -0.25, 0.125);
  for (std::size_t i = 0; i < p0.size(); ++i) EXPECT_NEAR(pts->read(kPosition)[i], p0[i] + t[i % 3], 1e-12);
  // ⟨J·v, f⟩ = ⟨v, Jᵀ·f⟩.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double>& v = dofs->write(kVelocity);
  for (double& a : v) a = u(rng);
  map->apply_j(kVelocity, kVelocity);
  std::vector<double> Jv = pts->read(kVelocity);
  std::vector<double>& f = pts->write(kForce);
  for (double& a : f) a = u(rng);
  std::vector<double>& fin = dofs->write(kForce);
  std::fill(fin.begin(), fin.end(), 0.0);
  map->apply_jt(kForce, kForce);
  double lhs = 0, rhs = 0;
  for (std::size_t i = 0; i < Jv.size(); ++i) lhs += Jv[i] * pts->read(kForce)[i];
  for (std::size_t i = 0; i < v.size(); ++i) rhs += v[i] * dofs->read(kForce)[i];
  EXPECT_NEAR(lhs, rhs, 1e-6 * std::max(1.0, std::abs(lhs)));
  EXPECT_GT(std::abs(lhs), 1e-3);
}

TEST(HexahedronCompositeFEMMapping, NeedsTheCompositeForceField) {
  test::TempDir dir;
  const std::string out = dir.write("out.obj", box_obj(Vec3(0, 0, 0), Vec3(2, 2, 2)));
  const test::Outcome o = test::run_xml(dir, R"(<Node dt="0.01"><DefaultAnimationLoop/>
      <SparseGridRamificationTopology n="3 3 3" fileTopology=")" + out + R"(" nbVirtualFinerLevels="1"/>
      <MechanicalObject/>
      <Node name="skin"><MechanicalObject position="0.5 0.5 0.5"/><HexahedronCompositeFEMMapping name="map"/></Node>
    </Node>)");
  EXPECT_TRUE(test::any_contains_all(o.errors, {"map", "HexahedronCompositeFEMForceFieldAndMass"})) << o.all();
}

// Largest relative change of the distances between vertices of a visual model (0 for a rigid motion).
double distortion(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  const std::size_t n = a.size() / 3;
  for (std::size_t i = 0; i < n; i += 7)
    for (std::size_t j = i + 3; j < n; j += 11) {
      const Vec3 a0(&a[3 * i]), a1(&a[3 * j]), b0(&b[3 * i]), b1(&b[3 * j]);
      const double d = (a0 - a1).norm();
      if (d > 1e-9) worst = std::max(worst, std::abs((b0 - b1).norm() - d) / d);
    }
  return worst;
}

// SOFA's grape: one coarse cell with a very stiff seed, pulled at one point. Mapped with the
// composite weights the seed keeps its shape; mapped barycentrically it follows the cell.
TEST(HexahedronCompositeFEMMapping, SofaGrapeSeedStaysRoundWithTheCompositeWeights) {
  std::vector<double> composite0, composite1, bary0, bary1;
  auto seed = [](runner::Session& s, const char* node) {
    Node* n = s.root().find_child_named(node)->find_child_named("Visu1");
    auto* v = dynamic_cast<VisualState*>(n->find_object_named("VisualBody"));
    return v ? *v->visual_vec(kPosition) : std::vector<double>{};
  };
  const test::Outcome start =
      test::run_sofa_example("Component/SolidMechanics/FEM/HexahedronCompositeFEMMapping.scn", 0, [&](runner::Session& s) {
        composite0 = seed(s, "HexahedronCompositeFEMMapping");
        bary0 = seed(s, "BarycentricMapping");
      });
  if (!start.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  const test::Outcome o =
      test::run_sofa_example("Component/SolidMechanics/FEM/HexahedronCompositeFEMMapping.scn", 100, [&](runner::Session& s) {
        composite1 = seed(s, "HexahedronCompositeFEMMapping");
        bary1 = seed(s, "BarycentricMapping");
      });
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100);
  EXPECT_TRUE(o.finite);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  ASSERT_FALSE(composite0.empty());
  ASSERT_EQ(composite0.size(), composite1.size());
  ASSERT_EQ(bary0.size(), bary1.size());
  const double dc = distortion(composite0, composite1), db = distortion(bary0, bary1);
  EXPECT_GT(db, 0.05);
  EXPECT_LT(dc, 0.2 * db) << "composite " << dc << ", barycentric " << db;
}

TEST(HexahedronCompositeFEM, SofaGelatinExampleRuns) {
  const test::Outcome o =
      test::run_sofa_example("Component/SolidMechanics/FEM/HexahedronCompositeFEMForceFieldAndMass.scn", 100);
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100);
  EXPECT_TRUE(o.finite);
  EXPECT_TRUE(o.errors.empty()) << o.all();
}

}  // namespace
}  // namespace sinew
