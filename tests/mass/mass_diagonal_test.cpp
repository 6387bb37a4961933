// DiagonalMass (spec/mechanics.md §1.2, §0.1 topology look-up, §8).
#include "mass/diagonal_mass.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

#include "core/mechanical_ops.h"
#include "forcefield/fem/tetra_fem.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

template <class T>
T& must(scene::LoadedScene& s, std::string_view name) {
  T* c = get<T>(*s.root, name);
  if (!c) throw std::runtime_error("missing component " + std::string(name));
  return *c;
}

// A 3×2×2-point grid (2 cells, box 2×1×1) split into tetrahedra, mass in the grid's node.
std::string tetra_beam(const std::string& mass) {
  return R"(<Node gravity="0 -10 0">
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="tetras"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@tetras" swapping="true"/>
    )" + mass + R"(
  </Node>)";
}

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

}  // namespace

// §1.2 + T2: the mass uses the LAST topology (the tetrahedra): ρV/4 per tetra vertex.
TEST(DiagonalMass, MassDensityLumpsTetraVolumesOfTheLastTopology) {
  auto s = load(tetra_beam(R"(<DiagonalMass name="mass" massDensity="2"/>)"));
  auto& m = must<DiagonalMass>(s, "mass");
  auto& topo = *get<MeshTopologyBase>(*s.root, "tetras");
  auto& mo = must<MechanicalObject>(s, "dofs");
  ASSERT_EQ(topo.tetrahedra().size(), 12u);
  const auto X = as_vec3(mo.read(kRestPosition));
  std::vector<double> expect(12, 0.0);
  for (const Tetra& t : topo.tetrahedra()) {
    const double v = fem::tetra_volume(X[t[0]], X[t[1]], X[t[2]], X[t[3]]);
    for (unsigned i : t) expect[i] += 2 * v / 4;
  }
  ASSERT_EQ(m.masses().size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_DOUBLE_EQ(m.masses()[i], expect[i]) << i;
  EXPECT_NEAR(m.total(), 2 * 2.0, 1e-12);  // ρ · box volume
  EXPECT_NEAR(sum(m.masses()), 4.0, 1e-12);
  // Tetra lumping differs from the hexa corner lumping (ρV/8 = 0.25 everywhere on the corners).
  bool differs = false;
  for (double v : m.masses()) differs |= std::fabs(v - 0.25) > 1e-9 && std::fabs(v - 0.5) > 1e-9;
  EXPECT_TRUE(differs);
}

// §1.2: totalMass wins over massDensity (warning); density is inferred.
TEST(DiagonalMass, TotalMassWinsOverMassDensity) {
  auto s = load(tetra_beam(R"(<DiagonalMass name="mass" massDensity="2" totalMass="3"/>)"));
  auto& m = must<DiagonalMass>(s, "mass");
  EXPECT_NEAR(sum(m.masses()), 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.total(), 3.0);
  EXPECT_NEAR(m.mass_density.value(), 1.5, 1e-12);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "totalMass value overriding"));
}

// §1.2: default (nothing set) is totalMass = 1.
TEST(DiagonalMass, DefaultIsUnitTotalMass) {
  auto s = load(tetra_beam(R"(<DiagonalMass name="mass"/>)"));
  EXPECT_NEAR(sum(must<DiagonalMass>(s, "mass").masses()), 1.0, 1e-12);
}

// Hexahedra win over tetrahedra: ρV/8 per corner with the 6-tetra volume.
TEST(DiagonalMass, HexahedraGiveOneEighthPerCorner) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <DiagonalMass name="mass" massDensity="4"/>
  </Node>)");
  auto& m = must<DiagonalMass>(s, "mass");
  // Corner nodes of the end cells get 4·1/8; the middle column belongs to both cells.
  EXPECT_NEAR(m.masses()[0], 0.5, 1e-12);
  EXPECT_NEAR(m.masses()[1], 1.0, 1e-12);
  EXPECT_NEAR(m.total(), 8.0, 1e-12);
}

// Triangles: ρA/3; edges: ρL/2.
TEST(DiagonalMass, TrianglesAndEdges) {
  auto s = load(R"(<Node>
    <Node name="tri">
      <MeshTopology position="0 0 0  2 0 0  0 3 0  2 3 0" triangles="0 1 2  1 3 2"/>
      <MechanicalObject name="dofs"/>
      <DiagonalMass name="mass" massDensity="3"/>
    </Node>
    <Node name="edge">
      <MeshTopology position="0 0 0  1 0 0  1 2 0" edges="0 1  1 2"/>
      <MechanicalObject name="dofs2"/>
      <DiagonalMass name="mass2" massDensity="0.5"/>
    </Node>
  </Node>)");
  auto* tri = get<DiagonalMass>(*s.root->find_child_named("tri"), "mass");
  ASSERT_TRUE(tri);
  EXPECT_NEAR(tri->masses()[0], 3 * 3.0 / 3, 1e-12);
  EXPECT_NEAR(tri->masses()[1], 2 * 3 * 3.0 / 3, 1e-12);
  EXPECT_NEAR(tri->total(), 3 * 6.0, 1e-12);
  auto* edge = get<DiagonalMass>(*s.root->find_child_named("edge"), "mass2");
  ASSERT_TRUE(edge);
  EXPECT_NEAR(edge->masses()[0], 0.25, 1e-12);
  EXPECT_NEAR(edge->masses()[1], 0.75, 1e-12);
  EXPECT_NEAR(edge->masses()[2], 0.5, 1e-12);
}

// §1.2 math: gravity, M·dx, a = f/m, assembled diagonal.
TEST(DiagonalMass, GravityMdxAccFromFAndMatrix) {
  auto s = load(tetra_beam(R"(<DiagonalMass name="mass" massDensity="2"/>)"));
  auto& m = must<DiagonalMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  const auto& f = mo.read(kForce);
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_DOUBLE_EQ(f[3 * i + 1], -10 * m.masses()[i]);
    EXPECT_EQ(f[3 * i], 0.0);
  }
  std::vector<double>& dx = mo.write(kDx);
  for (std::size_t i = 0; i < dx.size(); ++i) dx[i] = 0.1 * static_cast<double>(i);
  std::vector<double>& res = mo.write(kDforce);
  std::fill(res.begin(), res.end(), 1.0);
  m.add_mdx(MechParams{}, kDforce, kDx, 0.5);
  for (std::size_t i = 0; i < dx.size(); ++i) EXPECT_NEAR(res[i], 1.0 + 0.5 * m.masses()[i / 3] * dx[i], 1e-14);
  m.acc_from_f(MechParams{}, kDx, kForce);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_NEAR(mo.write(kDx)[3 * i + 1], -10.0, 1e-12);
  MatrixSink M;
  ASSERT_TRUE(m.build_mass(M));
  ASSERT_EQ(M.entries().size(), 36u);
  for (const auto& e : M.entries()) {
    EXPECT_EQ(e.row, e.col);
    EXPECT_DOUBLE_EQ(e.value, m.masses()[e.row / 3]);
  }
  EXPECT_TRUE(m.is_diagonal());
}

// Bad input: no topology → clear error naming the component, no crash.
TEST(DiagonalMass, MissingTopologyIsAnError) {
  auto s = test::build(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <DiagonalMass name="mass"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto errs = messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(any_contains(errs, "DiagonalMass")) << (errs.empty() ? "" : errs[0]);
  EXPECT_TRUE(any_contains(errs, "no topology"));
}

// Bad input: an element index beyond the state.
TEST(DiagonalMass, ElementIndexOutOfRangeIsAnError) {
  auto s = test::build(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0"/>
    <MeshTopology triangles="0 1 5"/>
    <DiagonalMass name="mass"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "uses point 5"));
}

// SOFA registers DiagonalMass<DataTypes, GeometricalTypes>: "Vec3,Vec3" (aliases resolved) is the
// Vec3d mass, created without a template error; a two-parameter name whose state part does not
// match the state still falls back with an error.
TEST(DiagonalMass, AcceptsTwoParameterTemplateNames) {
  for (const char* t : {"Vec3,Vec3", "Vec3d,Vec3d", "Vec3d"}) {
    Diagnostics diag;
    auto s = sinew::test::build(tetra_beam(std::string(R"(<DiagonalMass name="mass" massDensity="2" template=")") + t +
                                           R"("/>)"));
    ASSERT_TRUE(s.root);
    EXPECT_TRUE(messages(s.root->diagnostics(), Severity::error).empty()) << t;
    EXPECT_NE(get<DiagonalMass>(*s.root, "mass"), nullptr) << t;
  }
  auto s = sinew::test::build(tetra_beam(R"(<DiagonalMass name="mass" template="Vec2d,Vec3d"/>)"));
  ASSERT_TRUE(s.root);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "not compatible"));
}
