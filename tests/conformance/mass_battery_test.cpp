// Mass battery: every registered mass is checked on a small scene of its own,
// one line in kCases below (spec/mechanics.md §1, framework.md §6.4):
//
// * build_mass (through MatrixSink) is symmetric and add_mdx = factor·M·dx on
//   every unit vector and on a random vector;
// * total() = the sum of the assembled mass over one translation direction
//   (kTotal);
// * acc_from_f inverts add_mdx for diagonal (lumped) masses (kDiagonal), and
//   is_diagonal() says which masses are diagonal, as the case line does.
//
// The masses also run the force-field battery (gravity as a force and its
// energy). A new mass joins with one line; EveryRegisteredMassHasACase fails
// until it does.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "components/register_all.h"
#include "conformance.h"
#include "core/registry.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::conformance;

namespace {

enum Check : unsigned {
  kDiagonal = 1u << 0,  // lumped: is_diagonal() and acc_from_f = M⁻¹ (else is_diagonal() is false)
  kTotal = 1u << 1,     // total() = Σ M over one translation direction
};

struct MassCase {
  const char* name;   // test name: the class, then the variant
  std::string scene;  // the mass under test is named "mass"
  unsigned checks;
};
void PrintTo(const MassCase& c, std::ostream* os) { *os << c.name; }

std::string node(const std::string& body) { return "<Node name='root' gravity='0 -9.81 0'>" + body + "</Node>"; }
// The mass under test: <cls name='mass' attrs/>.
std::string mass(const std::string& cls, const std::string& attrs = "") {
  return "<" + cls + " name='mass' " + attrs + "/>";
}
// Two tetrahedra sharing the face (1, 2, 3).
std::string tetras(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  0 0 1  0.9 1.1 1.2'"
              " tetrahedra='0 1 2 3  1 2 3 4'/><MechanicalObject name='dofs'/>" + body);
}
// Two hexahedra (a 3×2×2 regular grid).
std::string hexas(const std::string& body) {
  return node("<RegularGridTopology name='grid' n='3 2 2' min='0 0 0' max='2 1 1'/><MechanicalObject name='dofs'/>" +
              body);
}
// Two hexahedra of a sparse grid over a closed 2×1×1 box, with one virtual finer level.
std::string sparse_hexas(const std::string& body) {
  return node("<SparseGridTopology name='grid' n='3 2 2' nbVirtualFinerLevels='1'"
              " position='0 0 0  2 0 0  2 1 0  0 1 0  0 0 1  2 0 1  2 1 1  0 1 1'"
              " triangles='0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7'/>"
              "<MechanicalObject name='dofs'/>" + body);
}
// The same box on a ramified sparse grid (the composite homogenization follows ramifications).
std::string ramified_hexas(const std::string& body) {
  return node("<SparseGridRamificationTopology name='grid' n='3 2 2' nbVirtualFinerLevels='1'"
              " position='0 0 0  2 0 0  2 1 0  0 1 0  0 0 1  2 0 1  2 1 1  0 1 1'"
              " triangles='0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7'/>"
              "<MechanicalObject name='dofs'/>" + body);
}
// Two triangles in the plane, as Vec2d points.
std::string triangles2d(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  1.1 0.9 0' triangles='0 1 2  1 3 2'/>"
              "<MechanicalObject name='dofs' template='Vec2d' position='0 0  1 0  0 1  1.1 0.9'/>" + body);
}
// Three points on a line as Vec1d, joined by edges.
std::string edges1d(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  2.5 0 0' edges='0 1  1 2'/>"
              "<MechanicalObject name='dofs' template='Vec1d' position='0  1  2.5'/>" + body);
}
const std::string kDensity = "<NodalMassDensity property='3'/>";
// Two prisms sharing the quad (1, 2, 5, 4), and two pyramids sharing the apex 4.
const std::string kPrisms = "<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  0 0 1  1 0 1.1  0 1 1"
                            "  1.2 1.1 0  1.1 1 1' prisms='0 1 2 3 4 5  1 6 2 4 7 5'/><MechanicalObject name='dofs'/>";
const std::string kPyramids = "<MeshTopology name='topo' position='0 0 0  1 0 0  1 1 0  0 1 0  0.5 0.5 1  0.4 0.6 -1'"
                              " pyramids='0 1 2 3 4  3 2 1 0 5'/><MechanicalObject name='dofs'/>";

// ---------------------------------------------------------------- cases: one line per mass (variant)
const std::vector<MassCase> kCases = {
    {"UniformMass", tetras(mass("UniformMass", "totalMass='2.5'")), kDiagonal | kTotal},
    {"UniformMass_Vec1d", edges1d(mass("UniformMass", "vertexMass='0.7'")), kDiagonal | kTotal},
    {"UniformMass_Rigid3d",
     node("<MechanicalObject name='dofs' template='Rigid3d' position='0 0 0 0 0 0 1  1 2 0 0 0 0.6 0.8'/>" +
          mass("UniformMass", "vertexMass='2 1 1 0.1 0 0.1 2 0 0 0 3'")),
     kDiagonal | kTotal},
    {"DiagonalMass", tetras(mass("DiagonalMass", "massDensity='3'")), kDiagonal | kTotal},
    {"DiagonalMass_Vec2d", triangles2d(mass("DiagonalMass", "massDensity='3'")), kDiagonal | kTotal},
    // Two frames of different masses and a non-diagonal inertia (MeshTopology of the frames, as SOFA's example).
    {"DiagonalMass_Rigid3d",
     node("<MechanicalObject name='dofs' template='Rigid3d' position='0 0 0 0 0 0 1  1 2 0 0 0 0.6 0.8'/>"
          "<MeshTopology name='topo' src='@dofs'/>" +
          mass("DiagonalMass", "template='Rigid3d,Rigid3d' vertexMass='2 1 [1 0.1 0,0.1 2 0,0 0 3] 0.5 1 1 0 0 0 1 0 0 0 4'")),
     kDiagonal | kTotal},
    {"DiagonalMass_Vec1d", edges1d(mass("DiagonalMass", "massDensity='3'")), kDiagonal | kTotal},
    {"MeshMatrixMass", tetras(mass("MeshMatrixMass", "massDensity='3'")), kTotal},
    {"MeshMatrixMass_lumped", tetras(mass("MeshMatrixMass", "massDensity='3' lumping='true'")), kDiagonal | kTotal},
    {"MeshMatrixMass_Vec2d", triangles2d(mass("MeshMatrixMass", "massDensity='3'")), kTotal},
    {"FEMMass_Tetrahedron", tetras(kDensity + mass("FEMMass")), kTotal},
    {"FEMMass_Hexahedron", hexas(kDensity + mass("FEMMass", "template='Vec3d,Hexahedron'")), kTotal},
    {"FEMMass_Prism", node(kPrisms + kDensity + mass("FEMMass", "template='Vec3d,Prism'")), kTotal},
    {"FEMMass_Pyramid", node(kPyramids + kDensity + mass("FEMMass", "template='Vec3d,Pyramid'")), kTotal},
    // SOFA's element mass couples every node pair by ρ·V·8/27 (hexa_fem_and_mass_test.cpp): Σ M ≠ ρ·V = total().
    {"HexahedronFEMForceFieldAndMass",
     hexas(mass("HexahedronFEMForceFieldAndMass", "youngModulus='1000' poissonRatio='0.3' density='2'")), 0},
    // The same mass condensed from the grid's finer level (SOFA's rule for gravity: ρ·V per cell).
    {"NonUniformHexahedronFEMForceFieldAndMass",
     sparse_hexas(mass("NonUniformHexahedronFEMForceFieldAndMass",
                       "youngModulus='1000' poissonRatio='0.3' density='2' nbVirtualFinerLevels='1'")),
     0},
    {"HexahedronCompositeFEMForceFieldAndMass",
     ramified_hexas(mass("HexahedronCompositeFEMForceFieldAndMass",
                         "youngModulus='1000' poissonRatio='0.3' density='2' nbVirtualFinerLevels='1'")),
     0},
};

// Registered masses without a case, and why.
const std::map<std::string, std::string> kExcluded = {
    // SOFA's addMDx couples all 8 nodes of an element while its assembled mass (the
    // addMToMatrix compatibility path) keeps the diagonal blocks only: build_mass ≠ add_mdx by
    // design (hexahedral_fem_and_mass_test.cpp checks both against SOFA's formulas).
    {"HexahedralFEMForceFieldAndMass", "SOFA's assembled mass keeps the diagonal blocks of its M·dx"},
};

std::string case_name(const ::testing::TestParamInfo<MassCase>& info) { return info.param.name; }
std::vector<MassCase> cases_with(unsigned checks) {
  std::vector<MassCase> out;
  for (const auto& c : kCases)
    if ((c.checks & checks) != 0) out.push_back(c);
  return out;
}

Mass* find_mass(Node& root, std::string_view name) {
  std::vector<Mass*> all;
  root.collect_down(all);
  for (Mass* m : all)
    if (m->name.value() == name) return m;
  return nullptr;
}

class MassBattery : public ::testing::TestWithParam<MassCase> {
 protected:
  void SetUp() override {
    scene_ = test::load(GetParam().scene);
    ASSERT_TRUE(scene_.root) << "the scene does not load";
    mass_ = find_mass(*scene_.root, "mass");
    ASSERT_NE(mass_, nullptr) << "the scene has no mass named 'mass'";
    ASSERT_EQ(mass_->state(), ComponentState::valid) << mass_->class_name() << " is not valid after init";
    state_ = mass_->mstate.get();
    ASSERT_NE(state_, nullptr);
    set_ = StateSet({state_});
    n_ = set_.size();
  }
  // res = factor · M · dx through add_mdx (res starts at 0).
  std::vector<double> mdx(const std::vector<double>& dx, double factor = 1.0) const {
    const int res = scratch_vec(1), in = scratch_vec(2);
    set_.set(in, dx);
    set_.fill(res, 0.0);
    mass_->add_mdx(MechParams{}, res, in, factor);
    return set_.get(res);
  }
  // Dense M from build_mass (row-major n×n).
  std::vector<double> assembled() const {
    MatrixSink sink;
    EXPECT_TRUE(mass_->build_mass(sink)) << "build_mass returned false";
    std::vector<double> M(n_ * n_, 0.0);
    for (const MatrixSink::Entry& e : sink.entries()) {
      EXPECT_TRUE(e.row_state == state_ && e.col_state == state_) << "an entry refers to another state";
      if (e.row < n_ && e.col < n_) M[e.row * n_ + e.col] += e.value;
      else ADD_FAILURE() << "entry (" << e.row << ", " << e.col << ") out of range";
    }
    return M;
  }

  scene::LoadedScene scene_;
  Mass* mass_ = nullptr;
  MechanicalState* state_ = nullptr;
  StateSet set_;
  std::size_t n_ = 0;
};

}  // namespace

TEST_P(MassBattery, AddMdxMatchesTheAssembledMass) {
  const auto M = assembled();
  std::vector<double> Mt(n_ * n_);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j) Mt[i * n_ + j] = M[j * n_ + i];
  EXPECT_TRUE(near_rel(M, Mt, 1e-14, "build_mass", "its transpose"));
  for (std::size_t j = 0; j < n_; ++j) {
    std::vector<double> ej(n_, 0.0);
    ej[j] = 1.0;
    std::vector<double> col(n_);
    for (std::size_t i = 0; i < n_; ++i) col[i] = M[i * n_ + j];
    EXPECT_TRUE(near_rel(mdx(ej), col, 1e-13, "add_mdx", "build_mass", &set_)) << "column " << set_.describe(j);
  }
  // A random vector and a factor.
  const auto u = random_vector(n_, 3);
  std::vector<double> Mu(n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j) Mu[i] += -2.5 * M[i * n_ + j] * u[j];
  EXPECT_TRUE(near_rel(mdx(u, -2.5), Mu, 1e-13, "add_mdx(factor = −2.5)", "−2.5 · build_mass · dx", &set_));
  EXPECT_EQ(mass_->is_diagonal(), (GetParam().checks & kDiagonal) != 0) << "is_diagonal() disagrees with the case line";
}

INSTANTIATE_TEST_SUITE_P(Battery, MassBattery, ::testing::ValuesIn(kCases), case_name);

class MassTotal : public MassBattery {};
TEST_P(MassTotal, IsTheAssembledMassAlongOneTranslation) {
  const auto M = assembled();
  const int w = state_->info().deriv_width;
  double along_x = 0;
  for (std::size_t i = 0; i < state_->size(); ++i)
    for (std::size_t j = 0; j < state_->size(); ++j) along_x += M[(i * w) * n_ + j * w];
  EXPECT_NEAR(mass_->total(), along_x, 1e-12 * std::fabs(along_x))
      << "total() against Σ M[(i, x), (j, x)] of the assembled mass";
  EXPECT_GT(along_x, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Battery, MassTotal, ::testing::ValuesIn(cases_with(kTotal)), case_name);

class MassAccFromF : public MassBattery {};
TEST_P(MassAccFromF, InvertsAddMdx) {
  const int a = scratch_vec(0), f = scratch_vec(1);
  const auto force = random_vector(n_, 5);
  set_.set(f, force);
  set_.fill(a, 0.0);
  mass_->acc_from_f(MechParams{}, a, f);
  const auto acc = set_.get(a);
  EXPECT_TRUE(near_rel(mdx(acc), force, 1e-13, "add_mdx(acc_from_f(f))", "f", &set_));
}
INSTANTIATE_TEST_SUITE_P(Battery, MassAccFromF, ::testing::ValuesIn(cases_with(kDiagonal)), case_name);

TEST(MassBatteryEnrolment, EveryRegisteredMassHasACase) {
  register_all_components();
  std::set<std::string> enrolled;
  for (const auto& c : kCases) {
    auto s = test::load(c.scene);
    ASSERT_TRUE(s.root) << c.name;
    Mass* m = find_mass(*s.root, "mass");
    ASSERT_NE(m, nullptr) << c.name;
    enrolled.insert(m->class_name());
  }
  int masses = 0;
  for (const auto& [name, info] : registry().all()) {
    auto obj = info.create(info.default_template);
    if (!dynamic_cast<Mass*>(obj.get())) continue;
    ++masses;
    EXPECT_TRUE(enrolled.count(name) || kExcluded.count(name))
        << name << " is a registered mass without a line in kCases (mass_battery_test.cpp)";
  }
  EXPECT_GE(masses, 5);
}
