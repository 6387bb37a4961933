// TetrahedronFEMForceField and TetrahedralCorotationalFEMForceField as scene
// components (spec/mechanics.md §2.1, §2.2, §0.4): topology look-up, hexa
// split, material broadcast and validation, matrix assembly.
#include "forcefield/fem/tetrahedral_corotational_fem_force_field.h"
#include "forcefield/fem/tetrahedron_fem_force_field.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "core/mechanical_ops.h"
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

std::string beam(const std::string& ff) {
  return R"(<Node gravity="0 0 0">
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronSetTopologyContainer name="tetras"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@tetras" swapping="true"/>
    )" + ff + R"(
  </Node>)";
}

void displace(MechanicalObject& mo) {
  std::vector<double>& x = mo.write(kPosition);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.01 * std::sin(3.0 * static_cast<double>(i));
}

}  // namespace

// §0.1: the force field uses the tetrahedra of the last topology.
TEST(TetrahedronFEMForceField, UsesTheTetrahedraOfTheLastTopology) {
  auto s = load(beam(R"(<TetrahedronFEMForceField name="fem" youngModulus="1000" poissonRatio="0.3" method="large"/>)"));
  auto& fem = must<TetrahedronFEMForceField>(s, "fem");
  EXPECT_EQ(fem.kernel().size(), 12u);
  EXPECT_NEAR(fem.kernel().rest_volume, 2.0, 1e-12);
  EXPECT_EQ(fem.state(), ComponentState::valid);
}

// §2.1: a hexahedral topology alone is split into 6 tetrahedra per cell.
TEST(TetrahedronFEMForceField, HexahedraAreSplitWhenThereAreNoTetrahedra) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="4 3 2" min="0 0 0" max="3 2 1"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronFEMForceField name="fem" method="small"/>
  </Node>)");
  auto& fem = must<TetrahedronFEMForceField>(s, "fem");
  EXPECT_EQ(fem.kernel().size(), 6u * 6u);
  EXPECT_NEAR(fem.kernel().rest_volume, 6.0, 1e-12);
}

// §2.2: TetrahedralCorotational has no hexa fallback: clear error.
TEST(TetrahedralCorotationalFEMForceField, HexahedraOnlyIsAnError) {
  auto s = test::build(R"(<Node>
    <RegularGridTopology name="grid" n="3 2 2" min="0 0 0" max="2 1 1"/>
    <MechanicalObject name="dofs"/>
    <TetrahedralCorotationalFEMForceField name="fem"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  const auto errs = messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(any_contains(errs, "TetrahedralCorotationalFEMForceField"));
  EXPECT_TRUE(any_contains(errs, "no tetrahedra"));
}

// §0.4: out-of-range material values are replaced with a warning naming the element.
TEST(TetrahedronFEMForceField, InvalidMaterialValuesAreReplaced) {
  auto s = load(beam(R"(<TetrahedronFEMForceField name="fem" youngModulus="-5" poissonRatio="0.5"/>)"));
  auto& fem = must<TetrahedronFEMForceField>(s, "fem");
  const auto warns = messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(any_contains(warns, "youngModulus of element 0"));
  EXPECT_TRUE(any_contains(warns, "poissonRatio of element 0"));
  const fem::TetraMaterial ref = fem::tetra_material(5000, 0.45, 1.0);
  // element volumes vary; compare K.d·V (independent of V)
  const auto& k = fem.kernel();
  const double V0 = k.rest_volume / 12;  // all 12 tets of this split have the same volume
  EXPECT_NEAR(k.K[0].d * V0, ref.d, 1e-9 * ref.d);
}

// §2.1: per-element Young's modulus and localStiffnessFactor[i·M/N].
TEST(TetrahedronFEMForceField, PerElementYoungModulusAndLocalFactor) {
  auto s = load(beam(
      R"(<TetrahedronFEMForceField name="fem" youngModulus="100 200" poissonRatio="0.3" localStiffnessFactor="1 3"/>)"));
  const auto& k = must<TetrahedronFEMForceField>(s, "fem").kernel();
  const double V = k.rest_volume / 12;
  auto E_of = [&](int e) { return k.K[e].d * V * 36 / fem::tetra_material(1, 0.3, 1.0 / 36).d; };
  EXPECT_NEAR(E_of(0), 100, 1e-9);       // value 0, factor lsf[0]
  EXPECT_NEAR(E_of(1), 200, 1e-9);       // value 1, factor lsf[0]
  EXPECT_NEAR(E_of(2), 100, 1e-9);       // broadcast value 0
  EXPECT_NEAR(E_of(6), 300, 1e-9);       // factor lsf[6·2/12] = lsf[1]
  EXPECT_NEAR(E_of(11), 300, 1e-9);
}

// Degenerate rest element: error naming the element, component invalid, no crash.
TEST(TetrahedronFEMForceField, DegenerateElementIsAnError) {
  auto s = test::build(R"(<Node>
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  1 1 0  0 0 1" tetrahedra="0 1 2 4  0 1 2 3"/>
    <MechanicalObject name="dofs"/>
    <TetrahedronFEMForceField name="fem"/>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  const auto errs = messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(any_contains(errs, "element 1"));
  EXPECT_TRUE(any_contains(errs, "degenerate"));
}

TEST(TetrahedronFEMForceField, UnknownMethodIsReported) {
  auto s = test::build(beam(R"(<TetrahedronFEMForceField name="fem" method="bogus"/>)"));
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "unknown method 'bogus'"));
}

// The assembled stiffness reproduces add_dforce (what the assembled solvers need),
// for every method of both components.
TEST(TetrahedronFEMForceField, BuildStiffnessMatchesAddDForce) {
  const char* ffs[] = {
      R"(<TetrahedronFEMForceField name="fem" method="small"/>)",
      R"(<TetrahedronFEMForceField name="fem" method="large"/>)",
      R"(<TetrahedronFEMForceField name="fem" method="polar"/>)",
      R"(<TetrahedronFEMForceField name="fem" method="svd"/>)",
      R"(<TetrahedralCorotationalFEMForceField name="fem" method="small"/>)",
      R"(<TetrahedralCorotationalFEMForceField name="fem" method="large"/>)",
      R"(<TetrahedralCorotationalFEMForceField name="fem" method="polar"/>)",
  };
  for (const char* ff : ffs) {
    auto s = load(beam(ff));
    auto& mo = must<MechanicalObject>(s, "dofs");
    auto* f = get<ForceField>(*s.root, "fem");
    ASSERT_TRUE(f) << ff;
    displace(mo);
    MechanicalOps ops(*s.root);
    ops.compute_force(kForce);  // sets rotations
    const std::size_t n = mo.size();
    MatrixSink K;
    ASSERT_TRUE(f->build_stiffness(K));
    Eigen::MatrixXd Kd = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (const auto& e : K.entries()) Kd(e.row, e.col) += e.value;
    std::vector<double>& dx = mo.write(kDx);
    Eigen::VectorXd d(3 * n);
    for (std::size_t i = 0; i < 3 * n; ++i) dx[i] = d[i] = std::cos(1.7 * static_cast<double>(i));
    std::vector<double>& df = mo.write(kDforce);
    std::fill(df.begin(), df.end(), 0.0);
    MechParams p;
    f->add_dforce(p, 0.5);
    const Eigen::VectorXd ref = 0.5 * Kd * d;
    for (std::size_t i = 0; i < 3 * n; ++i) EXPECT_NEAR(df[i], ref[i], 1e-9 * (1 + ref.norm())) << ff << " " << i;
  }
}

// Rest state: no force; translated state: no force for the corotational methods.
TEST(TetrahedralCorotationalFEMForceField, NoForceAtRestOrUnderTranslation) {
  auto s = load(beam(R"(<TetrahedralCorotationalFEMForceField name="fem" method="large"/>)"));
  auto& mo = must<MechanicalObject>(s, "dofs");
  std::vector<double>& x = mo.write(kPosition);
  for (std::size_t i = 0; i < x.size(); i += 3) x[i] += 5.0;
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  for (double v : mo.read(kForce)) EXPECT_NEAR(v, 0.0, 1e-9);
}
