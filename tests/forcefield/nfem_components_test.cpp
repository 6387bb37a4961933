// FEMMass + NodalMassDensity (spec/mechanics.md §1.4) and the element-generic
// LinearSmallStrainFEMForceField / CorotationalFEMForceField (§2.5) as scene
// components: mass totals against analytic volumes, gravity, M·dx, material
// checks, error messages, and parallel == sequenced on a stepped scene.
#include "forcefield/fem/corotational_fem_force_field.h"
#include "forcefield/fem/linear_small_strain_fem_force_field.h"
#include "mass/fem_mass.h"
#include "mass/nodal_mass_density.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/mechanical_ops.h"
#include "core/simulation.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::build;
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

// Builds and initialises a scene expected to report errors; returns the error messages.
std::vector<std::string> init_errors(const std::string& xml) {
  auto s = build(xml);
  if (!s.root) return {"build failed"};
  init_root(*s.root);
  return messages(s.root->diagnostics(), Severity::error);
}

// Cantilever like the Validation scenes, smaller: grid 5×5×12 on [0,0.02]²×[0,0.1] (176 hexahedra:
// enough for the parallel path, which splits ranges of 64 elements).
std::string cantilever(const std::string& ff) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
    <DefaultAnimationLoop/>
    <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
    <CGLinearSolver iterations="100" tolerance="1e-12" threshold="1e-18"/>
    <RegularGridTopology name="grid" min="0 0 0" max="0.02 0.02 0.1" n="5 5 12"/>
    <MechanicalObject name="state"/>
    <NodalMassDensity property="1100"/>
    <FEMMass name="mass" template="Vec3,Hexahedron"/>
    <BoxROI name="roi" box="-0.001 -0.001 -0.001 0.021 0.021 0.001"/>
    <FixedProjectiveConstraint indices="@roi.indices"/>
    )" + ff + R"(
  </Node>)";
}

}  // namespace

// ---------------------------------------------------------------- FEMMass

// Hexahedral consistent mass on a box grid: Σ M_ij = ρV; a corner node's
// diagonal is ρ·V_cell·(2/6)³ = ρV_cell/27 (tensor product of the 1D h/6·[2 1; 1 2]).
TEST(NfemFEMMass, HexaTotalMassAndCornerEntry) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="0.2 0.3 0.4" n="3 4 5"/>
    <MechanicalObject name="state"/>
    <NodalMassDensity property="1100"/>
    <FEMMass name="mass" template="Vec3,Hexahedron"/>
  </Node>)");
  auto& m = must<FEMMass>(s, "mass");
  ASSERT_EQ(m.state(), ComponentState::valid);
  const double V = 0.2 * 0.3 * 0.4, Vcell = 0.1 * 0.1 * 0.1;
  EXPECT_NEAR(m.total(), 1100 * V, 1e-12 * 1100 * V);
  // Node 0 belongs to one cell only; first stored column of row 0 is column 0.
  ASSERT_EQ(m.columns()[m.row_begin()[0]], 0u);
  EXPECT_NEAR(m.values()[m.row_begin()[0]], 1100 * Vcell / 27, 1e-9 * 1100 * Vcell / 27);
  // Node 0 couples with its 8 cell nodes (columns 0,1,3,4,12,13,15,16), sorted.
  const std::vector<unsigned> cols(m.columns().begin() + m.row_begin()[0], m.columns().begin() + m.row_begin()[1]);
  EXPECT_EQ(cols, (std::vector<unsigned>{0, 1, 3, 4, 12, 13, 15, 16}));
}

// One-point rule on a tetrahedron: every entry ρV/16 (under-integrated, §1.4).
TEST(NfemFEMMass, TetraEveryEntryIsRhoVOver16) {
  auto s = load(R"(<Node>
    <MeshTopology name="topo" position="0 0 0  2 0 0  0 3 0  0 0 1" tetrahedra="0 1 2 3"/>
    <MechanicalObject name="state"/>
    <NodalMassDensity property="1000"/>
    <FEMMass name="mass" template="Vec3,Tetrahedron"/>
  </Node>)");
  auto& m = must<FEMMass>(s, "mass");
  ASSERT_EQ(m.state(), ComponentState::valid);
  const double rhoV = 1000 * (2.0 * 3.0 * 1.0 / 6.0);
  ASSERT_EQ(m.values().size(), 16u);
  for (double v : m.values()) EXPECT_NEAR(v, rhoV / 16, 1e-12 * rhoV);
  EXPECT_NEAR(m.total(), rhoV, 1e-12 * rhoV);
}

// Nodal density interpolated at the quadrature point: ρ(q) = Σ N_k ρ_k; the
// last value is used for nodes beyond the list.
TEST(NfemFEMMass, NodalDensityInterpolationAndBroadcast) {
  auto s = load(R"(<Node>
    <MeshTopology name="topo" position="0 0 0  1 0 0  0 1 0  0 0 1" tetrahedra="0 1 2 3"/>
    <MechanicalObject name="state"/>
    <NodalMassDensity name="rho" property="1000 2000"/>
    <FEMMass name="mass" template="Vec3,Tetrahedron"/>
  </Node>)");
  auto& rho = must<NodalMassDensity>(s, "rho");
  EXPECT_EQ(rho.node_property(0), 1000);
  EXPECT_EQ(rho.node_property(3), 2000);
  auto& m = must<FEMMass>(s, "mass");
  const double mean_rho = (1000 + 2000 + 2000 + 2000) / 4.0;  // N_k = ¼ at the centroid
  EXPECT_NEAR(m.total(), mean_rho / 6.0, 1e-12 * mean_rho);
}

// Gravity: Σ_i f_i = total·g; M·dx with dx = 1 gives the row sums (= total when summed).
TEST(NfemFEMMass, GravityAndMassProduct) {
  auto s = load(R"(<Node gravity="1 -2 3">
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 2" n="2 2 3"/>
    <MechanicalObject name="state"/>
    <NodalMassDensity property="3"/>
    <FEMMass name="mass" template="Vec3,Hexahedron"/>
  </Node>)");
  auto& m = must<FEMMass>(s, "mass");
  auto& st = must<MechanicalObject>(s, "state");
  MechParams p;
  std::fill(st.write(kForce).begin(), st.write(kForce).end(), 0.0);
  m.add_force(p);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& f : as_vec3(st.write(kForce))) sum += f;
  EXPECT_NEAR(m.total(), 6.0, 1e-12);
  EXPECT_LT((sum - 6.0 * Vec3(1, -2, 3)).norm(), 1e-12);
  std::vector<double>& dx = st.write(kDx);
  std::fill(dx.begin(), dx.end(), 1.0);
  std::vector<double>& df = st.write(kDforce);
  std::fill(df.begin(), df.end(), 0.0);
  m.add_mdx(p, kDforce, kDx, 2.0);
  double total = 0;
  for (std::size_t i = 0; i < df.size(); i += 3) total += df[i];
  EXPECT_NEAR(total, 2.0 * 6.0, 1e-12);
  // Assembled entries: 3 per scalar entry, summing to 3·total.
  MatrixSink M;
  ASSERT_TRUE(m.build_mass(M));
  double msum = 0;
  for (const auto& e : M.entries()) msum += e.value;
  EXPECT_NEAR(msum, 3 * 6.0, 1e-12);
}

TEST(NfemFEMMass, MissingDensityAndWrongElementsAreErrors) {
  auto e1 = init_errors(R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" n="2 2 2"/>
    <MechanicalObject/>
    <FEMMass template="Vec3,Hexahedron"/>
  </Node>)");
  EXPECT_TRUE(any_contains(e1, "No nodal mass density")) << (e1.empty() ? "" : e1[0]);
  auto e2 = init_errors(R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" n="2 2 2"/>
    <MechanicalObject/>
    <NodalMassDensity property="1"/>
    <FEMMass template="Vec3,Tetrahedron"/>
  </Node>)");
  EXPECT_TRUE(any_contains(e2, "has no tetrahedra"));
  auto e3 = init_errors(R"(<Node>
    <MeshTopology position="0 0 0  1 0 0  0 1 0  1 1 0" tetrahedra="0 1 2 3"/>
    <MechanicalObject/>
    <NodalMassDensity property="1"/>
    <FEMMass template="Vec3,Tetrahedron"/>
  </Node>)");
  EXPECT_TRUE(any_contains(e3, "element 0")) << (e3.empty() ? "" : e3[0]);
}

// ---------------------------------------------------------------- force fields

TEST(NfemForceField, DefaultsFollowTheElementType) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" n="2 2 2"/>
    <MechanicalObject/>
    <CorotationalFEMForceField name="ch" template="Vec3,Hexahedron" youngModulus="1000" poissonRatio="0.3"/>
    <LinearSmallStrainFEMForceField name="lh" template="Vec3,Hexahedron" youngModulus="1000" poissonRatio="0.3"/>
  </Node>)");
  auto& ch = must<CorotationalFEMForceField>(s, "ch");
  EXPECT_EQ(ch.rotation_method_f.value(), "hexahedron");
  EXPECT_EQ(ch.element_kind(), FemElementKind::hexahedron);
  EXPECT_EQ(ch.compute_force_strategy.value(), "parallel");
  EXPECT_EQ(ch.hexa_kernel().size(), 1u);
  EXPECT_EQ(ch.element_stiffness.value().size(), 24u * 24u);
  auto& lh = must<LinearSmallStrainFEMForceField>(s, "lh");
  EXPECT_EQ(lh.state(), ComponentState::valid);
  // Both fields have the same K; at rest no force.
  EXPECT_EQ(ch.element_stiffness.value(), lh.element_stiffness.value());
  CorotationalFEMForceField tet(FemElementKind::tetrahedron);
  EXPECT_EQ(tet.rotation_method_f.value(), "triangle");
}

// Poisson ratio ≥ 0.5 is replaced by 0.45 and E < 0 by 5000 (SOFA), with a warning.
TEST(NfemForceField, OutOfRangeMaterialIsReplacedWithWarning) {
  auto s = build(R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" n="2 2 2"/>
    <MechanicalObject/>
    <LinearSmallStrainFEMForceField name="a" template="Vec3,Hexahedron" youngModulus="-3" poissonRatio="0.5"/>
    <LinearSmallStrainFEMForceField name="b" template="Vec3,Hexahedron" youngModulus="5000" poissonRatio="0.45"/>
  </Node>)");
  init_root(*s.root);
  const auto w = messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(any_contains(w, "poissonRatio of element 0"));
  EXPECT_TRUE(any_contains(w, "youngModulus of element 0"));
  EXPECT_EQ(must<LinearSmallStrainFEMForceField>(s, "a").element_stiffness.value(),
            must<LinearSmallStrainFEMForceField>(s, "b").element_stiffness.value());
}

TEST(NfemForceField, BadSetupsAreClearErrors) {
  const std::string head = R"(<Node>
    <RegularGridTopology name="grid" min="0 0 0" max="1 1 1" n="2 2 2"/>
    <MechanicalObject/>
    )";
  EXPECT_TRUE(any_contains(
      init_errors(head + R"(<CorotationalFEMForceField template="Vec3,Hexahedron" rotationMethod="triangle"/></Node>)"),
      "unknown rotationMethod 'triangle'"));
  EXPECT_TRUE(init_errors(head + R"(<CorotationalFEMForceField template="Vec3,Hexahedron" rotationMethod="stable_polar"/></Node>)")
                  .empty());
  EXPECT_TRUE(any_contains(
      init_errors(head + R"(<CorotationalFEMForceField template="Vec3,Hexahedron" rotationMethod="svd"/></Node>)"),
      "unknown rotationMethod 'svd'"));
  EXPECT_TRUE(any_contains(
      init_errors(head + R"(<LinearSmallStrainFEMForceField template="Vec3,Tetrahedron"/></Node>)"),
      "has no tetrahedra"));
  EXPECT_TRUE(any_contains(
      init_errors(head + R"(<LinearSmallStrainFEMForceField template="Vec3,Hexahedron" computeForceStrategy="fast"/></Node>)"),
      "computeForceStrategy 'fast'"));
  EXPECT_TRUE(any_contains(init_errors(R"(<Node>
    <MeshTopology position="0 0 0  1 0 0  0 1 0  1 1 0" tetrahedra="0 1 2 3"/>
    <MechanicalObject/>
    <CorotationalFEMForceField template="Vec3,Tetrahedron"/></Node>)"),
                           "element 0: degenerate element"));
}

// The hexahedral cantilever sags under gravity, and the "parallel" strategy
// reproduces the "sequenced" one bit for bit, step after step.
TEST(NfemForceField, ParallelStrategyMatchesSequencedOnAScene) {
  for (const char* type : {"CorotationalFEMForceField", "LinearSmallStrainFEMForceField"}) {
    const std::string ff = std::string("<") + type +
                           R"( template="Vec3,Hexahedron" youngModulus="2e6" poissonRatio="0.45" )";
    auto seq = load(cantilever(ff + R"(computeForceStrategy="sequenced" computeForceDerivStrategy="sequenced"/>)"));
    auto par = load(cantilever(ff + R"(computeForceStrategy="parallel" computeForceDerivStrategy="parallel"/>)"));
    for (int k = 0; k < 5; ++k) {
      animate(*seq.root);
      animate(*par.root);
    }
    const auto& xs = must<MechanicalObject>(seq, "state").read(kPosition);
    const auto& xp = must<MechanicalObject>(par, "state").read(kPosition);
    const auto& x0 = must<MechanicalObject>(seq, "state").read(kRestPosition);
    ASSERT_EQ(xs.size(), xp.size());
    EXPECT_EQ(xs, xp) << type;
    // The free end (last point) moved down, the clamped one (point 0) did not.
    EXPECT_LT(xs[xs.size() - 2], x0[x0.size() - 2] - 1e-7) << type;
    EXPECT_EQ(xs[1], x0[1]);
  }
}
