// NonUniformHexahedronFEMForceFieldAndMass: element matrices condensed from a
// sparse grid's virtual finer levels (spec/mechanics.md §2.4).
#include <gtest/gtest.h>

#include <cmath>

#include "core/mechanical_ops.h"
#include "forcefield/fem/hexahedron_fem_force_field.h"
#include "forcefield/fem/nonuniform/nonuniform_hexahedron_fem_force_field_and_mass.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/grid/sparse_grid_topology.h"

namespace sinew {
namespace {

// A closed cube [-1, 1]³ as a surface; the grid's box is the cube's.
constexpr const char* kCubeSurface =
    R"(position="-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  -1 -1 1  1 -1 1  1 1 1  -1 1 1"
      triangles="0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7")";

std::string grid_scene(const std::string& grid_attrs, const std::string& ff) {
  return "<Node dt=\"0.01\" gravity=\"0 -10 0\"><DefaultAnimationLoop/>"
         "<EulerImplicitSolver/><CGLinearSolver iterations=\"100\" tolerance=\"1e-12\" threshold=\"1e-20\"/>"
         "<SparseGridTopology name=\"g\" " +
         grid_attrs + " " + kCubeSurface + "/><MechanicalObject name=\"dofs\"/>" + ff + "</Node>";
}

std::string nonuniform(int levels, const std::string& extra = "") {
  return "<NonUniformHexahedronFEMForceFieldAndMass name=\"fem\" youngModulus=\"1000\" poissonRatio=\"0.3\" "
         "density=\"2\" nbVirtualFinerLevels=\"" +
         std::to_string(levels) + "\" " + extra + "/>";
}

// The corners of a hexahedron in SOFA's order, and of its octants numbered x + 2y + 4z.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

TEST(NonUniformHexahedronFEM, OctantWeightsAreSofasTable) {
  // Rows of SOFA's FINE_TO_COARSE, copied by hand: octant 0, fine corners 1, 2 and 6.
  const float o0k1[8] = {0.5f, 0.5f, 0, 0, 0, 0, 0, 0};
  const float o0k2[8] = {0.25f, 0.25f, 0.25f, 0.25f, 0, 0, 0, 0};
  const float o0k6[8] = {0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f, 0.125f};
  // Octant 3 (x and y high) corner 0 is the centre of the bottom face; octant 6 (y and z
  // high) corner 0 the centre of the x = 0 face; octant 7 corner 6 is coarse corner 6.
  const float o3k0[8] = {0.25f, 0.25f, 0.25f, 0.25f, 0, 0, 0, 0};
  const float o6k0[8] = {0.25f, 0, 0, 0.25f, 0.25f, 0, 0, 0.25f};
  const float o7k6[8] = {0, 0, 0, 0, 0, 0, 1, 0};
  for (int j = 0; j < 8; ++j) {
    EXPECT_EQ(fem::hexa_octant_weight(0, 1, j), o0k1[j]) << j;
    EXPECT_EQ(fem::hexa_octant_weight(0, 2, j), o0k2[j]) << j;
    EXPECT_EQ(fem::hexa_octant_weight(0, 6, j), o0k6[j]) << j;
    EXPECT_EQ(fem::hexa_octant_weight(3, 0, j), o3k0[j]) << j;
    EXPECT_EQ(fem::hexa_octant_weight(6, 0, j), o6k0[j]) << j;
    EXPECT_EQ(fem::hexa_octant_weight(7, 6, j), o7k6[j]) << j;
  }
  // Every row is a partition of unity that reproduces the fine corner's position.
  for (int c = 0; c < 8; ++c)
    for (int k = 0; k < 8; ++k) {
      double sum = 0, p[3] = {0, 0, 0};
      for (int j = 0; j < 8; ++j) {
        const double w = fem::hexa_octant_weight(c, k, j);
        sum += w;
        for (int a = 0; a < 3; ++a) p[a] += w * kCorner[j][a];
      }
      EXPECT_EQ(sum, 1.0);
      const int oct[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
      for (int a = 0; a < 3; ++a) EXPECT_EQ(p[a], 0.5 * (oct[a] + kCorner[k][a])) << c << " " << k;
    }
}

// Trilinear fields are trilinear on each octant and 2×2×2 Gauss integrates their energy
// exactly, on the whole cell as on its octants: a full cell's stiffness condensed from any
// number of finer levels is its classical stiffness. fillWeighted="0" gives every fine cell
// coefficient 1.
TEST(NonUniformHexahedronFEM, FullCellCondensesToItsClassicalStiffness) {
  auto classical = test::load(grid_scene(R"(n="2 2 2" fillWeighted="0")",
                                    "<HexahedronFEMForceFieldAndMass name=\"fem\" youngModulus=\"1000\" "
                                    "poissonRatio=\"0.3\" density=\"2\"/>"));
  auto* ref = test::get<HexahedronFEMForceFieldAndMass>(*classical.root, "fem");
  ASSERT_NE(ref, nullptr);
  ASSERT_EQ(ref->kernel().size(), 1u);
  const fem::Mat24& K0 = ref->kernel().K[0];
  for (int levels = 1; levels <= 3; ++levels) {
    SCOPED_TRACE(levels);
    auto s = test::load(grid_scene("n=\"2 2 2\" fillWeighted=\"0\" nbVirtualFinerLevels=\"" + std::to_string(levels) + "\"",
                              nonuniform(levels)));
    auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
    ASSERT_NE(ff, nullptr);
    ASSERT_EQ(ff->kernel().size(), 1u);
    const fem::Mat24& K = ff->kernel().K[0];
    const double scale = K0.cwiseAbs().maxCoeff();
    EXPECT_LT((K - K0).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

// SOFA's mass gives every node pair of a fine cell the same entry m_f; one level of
// condensation gives M(i, j) = m_f·Σ_octants s(i)·s(j), s(j) the sum of coarse corner j's
// weights over the octant's corners: per axis 3/2 on the octant's side, 1/2 on the other.
TEST(NonUniformHexahedronFEM, OneLevelMassIsTheSumOfTheOctantsMasses) {
  auto s = test::load(grid_scene(R"(n="2 2 2" fillWeighted="0" nbVirtualFinerLevels="1")", nonuniform(1)));
  auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_NE(ff, nullptr);
  auto* grid = test::get<SparseGridTopology>(*s.root, "g");
  const auto fine = grid->level(1);
  ASSERT_EQ(fine.hexas.size(), 8u);
  const Vec3 e = fine.points[fine.hexas[0][6]] - fine.points[fine.hexas[0][0]];
  const double m_f = e[0] * e[1] * e[2] * 2.0 * 8.0 / 27.0;  // vol·ρ·8/27
  const auto& M = ff->element_mass(0);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      double expected = 0;
      for (int c = 0; c < 8; ++c) {
        double si = 1, sj = 1;
        for (int a = 0; a < 3; ++a) {
          const int oct = (c >> a) & 1;
          si *= kCorner[i][a] == oct ? 1.5 : 0.5;
          sj *= kCorner[j][a] == oct ? 1.5 : 0.5;
        }
        expected += m_f * si * sj;
      }
      EXPECT_NEAR(M[8 * i + j], expected, 1e-12 * expected) << i << " " << j;
    }
  // The corner's own entry: 2.5³·m_f; opposite corners: 1.5³·m_f.
  EXPECT_NEAR(M[0], 15.625 * m_f, 1e-12);
  EXPECT_NEAR(M[8 * 0 + 6], 3.375 * m_f, 1e-12);
}

// A cell the object fills only in part: the condensed matrices come from the fine cells
// that exist. The grid spans [-1, 5] along x (one mechanical cell, fine cells 1.5 wide), the
// cube [-1, 1]: the fine cells beyond x = 2 are empty, the total mass is that of the fine
// cells (coefficients included) and the cell is stiffer on its x = −1 side.
TEST(NonUniformHexahedronFEM, HalfFilledCellIsStifferOnItsFilledSide) {
  auto s = test::load(grid_scene(R"(n="2 2 2" min="-1 -1 -1" max="5 1 1" nbVirtualFinerLevels="2")", nonuniform(2)));
  auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_NE(ff, nullptr);
  auto* grid = test::get<SparseGridTopology>(*s.root, "g");
  ASSERT_EQ(ff->kernel().size(), 1u);
  const auto fine = grid->level(2);
  double fine_mass = 0;
  for (std::size_t h = 0; h < fine.hexas.size(); ++h) {
    const Vec3 e = fine.points[fine.hexas[h][6]] - fine.points[fine.hexas[h][0]];
    EXPECT_LT(fine.points[fine.hexas[h][0]][0], 1.0);  // no fine cell beyond the cube's
    fine_mass += 64 * e[0] * e[1] * e[2] * 2.0 * 8.0 / 27.0 * fine.stiffness[h];
  }
  double total = 0;
  for (double m : ff->element_mass(0)) total += m;
  EXPECT_NEAR(total, fine_mass, 1e-12 * fine_mass);
  // Diagonal stiffness of corner 0 (x = −1) against corner 1 (x = 3), along x.
  const fem::Mat24& K = ff->kernel().K[0];
  EXPECT_GT(K(0, 0), 2 * K(3, 3));
  // Gravity still acts on the mechanical cell's own volume and coefficient (SOFA's rule).
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  auto& f = mo->write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  ff->add_force(p);
  double weight = 0;
  for (std::size_t i = 0; i < mo->size(); ++i) weight += f[3 * i + 1];
  const auto coarse = grid->level(0);
  const Vec3 ec = coarse.points[coarse.hexas[0][6]] - coarse.points[coarse.hexas[0][0]];
  EXPECT_NEAR(weight, -10 * 2 * ec[0] * ec[1] * ec[2] * grid->mass_coef(0), 1e-9);
}

// Without virtual levels the element matrices are the classical ones of the grid's cells:
// the same forces as HexahedronFEMForceFieldAndMass, with a warning.
TEST(NonUniformHexahedronFEM, ZeroLevelsIsHexahedronFEMForceFieldAndMass) {
  auto a = test::load(grid_scene(R"(n="3 3 3")", nonuniform(0)));
  auto b = test::load(grid_scene(R"(n="3 3 3")",
                            "<HexahedronFEMForceFieldAndMass name=\"fem\" youngModulus=\"1000\" "
                            "poissonRatio=\"0.3\" density=\"2\"/>"));
  auto* fa = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*a.root, "fem");
  auto* fb = test::get<HexahedronFEMForceFieldAndMass>(*b.root, "fem");
  ASSERT_NE(fa, nullptr);
  ASSERT_NE(fb, nullptr);
  EXPECT_TRUE(test::any_contains(test::messages(a.root->diagnostics(), Severity::warning),
                                 "nbVirtualFinerLevels is 0"));
  ASSERT_EQ(fa->kernel().size(), fb->kernel().size());
  for (std::size_t e = 0; e < fa->kernel().size(); ++e) EXPECT_EQ(fa->kernel().K[e], fb->kernel().K[e]) << e;
  for (int i = 0; i < 50; ++i) {
    animate(*a.root);
    animate(*b.root);
  }
  auto* ma = test::get<MechanicalObject>(*a.root, "dofs");
  auto* mb = test::get<MechanicalObject>(*b.root, "dofs");
  EXPECT_EQ(ma->read(kPosition), mb->read(kPosition));
}

TEST(NonUniformHexahedronFEM, UseMassOffSpreadsTotalMassPerElementOnEveryPoint) {
  auto s = test::load(grid_scene(R"(n="3 3 3" nbVirtualFinerLevels="1")", nonuniform(1, "useMass=\"0\" totalMass=\"16\"")));
  auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_NE(ff, nullptr);
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  ASSERT_EQ(ff->kernel().size(), 8u);
  EXPECT_DOUBLE_EQ(ff->total(), 27 * 16.0 / 8);  // 27 points, 2 each
  const int dx = MechanicalOps::alloc_vec(), res = MechanicalOps::alloc_vec();
  auto& d = mo->write(dx);
  d[3 * 5 + 2] = 1.0;
  MechParams p;
  ff->add_mdx(p, res, dx, 0.5);
  EXPECT_DOUBLE_EQ(mo->read(res)[3 * 5 + 2], 1.0);
  EXPECT_EQ(mo->read(res)[3 * 4 + 2], 0.0);
}

TEST(NonUniformHexahedronFEM, FallsSymmetrically) {
  auto s = test::load(grid_scene(R"(n="3 3 3" nbVirtualFinerLevels="2")", nonuniform(2)));
  auto* mo = test::get<MechanicalObject>(*s.root, "dofs");
  const auto x0 = as_vec3(mo->read(kPosition));
  const std::vector<Vec3> start(x0.begin(), x0.end());
  for (int i = 0; i < 20; ++i) animate(*s.root);
  const auto x = as_vec3(mo->read(kPosition));
  // The cube and its grid are symmetric about x = 0 and z = 0: so is the motion.
  Vec3 mean = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_TRUE(x[i].allFinite());
    mean += x[i] - start[i];
  }
  mean /= static_cast<double>(x.size());
  EXPECT_NEAR(mean[0], 0.0, 1e-12);
  EXPECT_NEAR(mean[2], 0.0, 1e-12);
  EXPECT_LT(mean[1], -1e-3);
}

TEST(NonUniformHexahedronFEM, RefusesWhatItCannotCondense) {
  struct Case {
    std::string scene, message;
  };
  const Case cases[] = {
      {"<Node><RegularGridTopology n=\"2 2 2\"/><MechanicalObject/>" + nonuniform(1) + "</Node>",
       "is not a sparse grid"},
      {grid_scene(R"(n="2 2 2" nbVirtualFinerLevels="1")", nonuniform(1, "method=\"small\"")), "method small"},
      {grid_scene(R"(n="2 2 2" nbVirtualFinerLevels="1")", nonuniform(1, "updateStiffnessMatrix=\"1\"")),
       "updateStiffnessMatrix"},
      {grid_scene(R"(n="2 2 2" nbVirtualFinerLevels="1")", nonuniform(-1)), "must be >= 0"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.message);
    auto s = test::load(c.scene);
    auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
    ASSERT_NE(ff, nullptr);
    EXPECT_EQ(ff->state(), ComponentState::invalid);
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), c.message));
  }
  // More levels than the grid keeps: a warning, and the classical matrices.
  auto s = test::load(grid_scene(R"(n="2 2 2" nbVirtualFinerLevels="1")", nonuniform(2)));
  auto* ff = test::get<NonUniformHexahedronFEMForceFieldAndMass>(*s.root, "fem");
  ASSERT_NE(ff, nullptr);
  EXPECT_EQ(ff->state(), ComponentState::valid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning),
                                 "fewer than nbVirtualFinerLevels"));
}

}  // namespace
}  // namespace sinew
