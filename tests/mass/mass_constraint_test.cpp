// UniformMass (spec/mechanics.md §1.1, framework.md §6.7, T12) and
// FixedProjectiveConstraint (mechanics.md §4, framework.md §6.5).
#include "mass/uniform_mass.h"
#include "projective/fixed_projective_constraint.h"

#include <gtest/gtest.h>

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

// 8 DoFs (2×2×2 grid), gravity (1, -2, 3), then `extra` components.
std::string scene8(const std::string& extra, const std::string& mo_template = "") {
  return R"(<Node gravity="1 -2 3">
    <RegularGridTopology n="2 2 2" min="0 0 0" max="1 1 1"/>
    <MechanicalObject name="dofs" )" +
         mo_template + R"(/>
    )" + extra +
         R"(
  </Node>)";
}

template <class T>
T& must(scene::LoadedScene& s, std::string_view name) {
  T* c = get<T>(*s.root, name);
  if (!c) throw std::runtime_error("missing component " + std::string(name));
  return *c;
}

}  // namespace

// ---------------------------------------------------------------- UniformMass

// §1.1 rule 2: totalMass wins over vertexMass (with a warning): m = totalMass / N.
TEST(UniformMass, TotalMassWinsOverVertexMass) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="4" vertexMass="3"/>)"));
  auto& m = must<UniformMass>(s, "mass");
  EXPECT_EQ(m.state(), ComponentState::valid);
  EXPECT_EQ(m.mass(), 0.5);
  EXPECT_EQ(m.total(), 4.0);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "totalMass"));
}

// §1.1 rule 3: only vertexMass → totalMass = vertexMass · N.
TEST(UniformMass, VertexMassOnlyGivesTotalMassTimesN) {
  auto s = load(scene8(R"(<UniformMass name="mass" vertexMass="3"/>)"));
  auto& m = must<UniformMass>(s, "mass");
  EXPECT_EQ(m.mass(), 3.0);
  EXPECT_EQ(m.total_mass.value(), 24.0);
}

// §1.1 rule 4: only totalMass → vertexMass = totalMass / N.
TEST(UniformMass, TotalMassOnlyIsSplitOverTheDofs) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="2"/>)"));
  EXPECT_EQ(must<UniformMass>(s, "mass").mass(), 0.25);
}

// §1.1 rule 5: neither → invalid component with an error.
TEST(UniformMass, NeitherMassGivenMakesTheComponentInvalid) {
  auto s = sinew::test::build(scene8(R"(<UniformMass name="mass"/>)"));
  EXPECT_FALSE(init_root(*s.root));
  auto& m = must<UniformMass>(s, "mass");
  EXPECT_EQ(m.state(), ComponentState::invalid);
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "mass"));
}

// §1.1: negative values are rejected.
TEST(UniformMass, NegativeTotalMassIsAnError) {
  auto s = sinew::test::build(scene8(R"(<UniformMass name="mass" totalMass="-1"/>)"));
  EXPECT_FALSE(init_root(*s.root));
  EXPECT_EQ(must<UniformMass>(s, "mass").state(), ComponentState::invalid);
}

// §1.1 rule 1: localRange [a, b] restricts the DoFs (when b + 1 < size).
TEST(UniformMass, LocalRangeRestrictsTheDofs) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="6" localRange="1 3"/>)"));
  EXPECT_EQ(must<UniformMass>(s, "mass").mass(), 2.0);
}

// §6.7 / T12: gravity is f_i += m·g on every DoF, added once although the mass is also a force field.
TEST(UniformMass, GravityForceIsMassTimesGravityOnEveryDof) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="4"/>)"));
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  const auto& f = must<MechanicalObject>(s, "dofs").read(kForce);
  ASSERT_EQ(f.size(), 24u);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(f[i * 3 + 0], 0.5) << i;
    EXPECT_EQ(f[i * 3 + 1], -1.0) << i;
    EXPECT_EQ(f[i * 3 + 2], 1.5) << i;
  }
}

// §1.1: `indices` restricts which DoFs receive a mass (and gravity).
TEST(UniformMass, IndicesSubsetGetsGravityOnly) {
  auto s = load(scene8(R"(<UniformMass name="mass" vertexMass="2" indices="1 6"/>)"));
  auto& m = must<UniformMass>(s, "mass");
  EXPECT_EQ(m.total_mass.value(), 4.0);
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  const auto& f = must<MechanicalObject>(s, "dofs").read(kForce);
  EXPECT_EQ(f[0 * 3 + 1], 0.0);
  EXPECT_EQ(f[1 * 3 + 1], -4.0);
  EXPECT_EQ(f[6 * 3 + 1], -4.0);
  EXPECT_EQ(f[7 * 3 + 1], 0.0);
}

// §6.7: separateGravity → no gravity force; addGravityToV adds g·dt to v.
TEST(UniformMass, SeparateGravityGoesToTheVelocity) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="8" separateGravity="1"/>)"));
  auto& mo = must<MechanicalObject>(s, "dofs");
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  EXPECT_EQ(mo.write(kForce), std::vector<double>(24, 0.0));
  ops.add_separate_gravity(0.5, kVelocity);
  EXPECT_EQ(mo.write(kVelocity)[0], 0.5);
  EXPECT_EQ(mo.write(kVelocity)[1], -1.0);
  EXPECT_EQ(mo.write(kVelocity)[23], 1.5);
}

// §1.1: addMDx: res_i += factor · m · dx_i.
TEST(UniformMass, AddMdxScalesByMassAndFactor) {
  auto s = load(scene8(R"(<UniformMass name="mass" totalMass="4"/>)"));
  auto& m = must<UniformMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  auto& dx = mo.write(kDx);
  for (std::size_t i = 0; i < dx.size(); ++i) dx[i] = static_cast<double>(i);
  auto& res = mo.write(kDforce);
  res.assign(24, 1.0);
  m.add_mdx(MechParams{}, kDforce, kDx, 3.0);
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(res[i], 1.0 + 1.5 * static_cast<double>(i)) << i;
}

// §1.1: accFromF: a_i = f_i / m.
TEST(UniformMass, AccFromForceDividesByMass) {
  auto s = load(scene8(R"(<UniformMass name="mass" vertexMass="4"/>)"));
  auto& mo = must<MechanicalObject>(s, "dofs");
  auto& f = mo.write(kForce);
  f.assign(24, 2.0);
  const int a = kFirstDynamicVec + 50;
  must<UniformMass>(s, "mass").acc_from_f(MechParams{}, a, kForce);
  EXPECT_EQ(mo.write(a), std::vector<double>(24, 0.5));
}

// §1.1 Rigid3: M·dx = (m·v, inertia·m·ω); vertexMass = "mass volume I00 … I22"; gravity on the linear part.
TEST(UniformMass, RigidMassUsesTheInertiaTimesMass) {
  auto s = load(R"(<Node gravity="0 -10 0">
    <MechanicalObject name="dofs" template="Rigid3d" position="0 0 0 0 0 0 1"/>
    <UniformMass name="mass" vertexMass="2 1  1 0 0  0 3 0  0 0 5"/>
  </Node>)");
  auto& m = must<UniformMass>(s, "mass");
  auto& mo = must<MechanicalObject>(s, "dofs");
  EXPECT_EQ(m.template_name(), "Rigid3d");
  mo.write(kDx) = {1, 1, 1, 1, 1, 1};
  mo.write(kDforce).assign(6, 0.0);
  m.add_mdx(MechParams{}, kDforce, kDx, 1.0);
  EXPECT_EQ(mo.write(kDforce), (std::vector<double>{2, 2, 2, 2, 6, 10}));
  MechanicalOps ops(*s.root);
  ops.compute_force(kForce);
  EXPECT_EQ(mo.write(kForce), (std::vector<double>{0, -20, 0, 0, 0, 0}));
}

// ---------------------------------------------------------------- FixedProjectiveConstraint

// §4: indices default to [0] when the attribute is absent.
TEST(FixedProjectiveConstraint, DefaultIndicesAreZero) {
  auto s = load(scene8(R"(<FixedProjectiveConstraint name="fix"/>)"));
  auto& fix = must<FixedProjectiveConstraint>(s, "fix");
  EXPECT_EQ(fix.indices.get(), (std::vector<unsigned>{0}));
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kDx).assign(24, 1.0);
  fix.project_response(kDx);
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(mo.write(kDx)[i], i < 3 ? 0.0 : 1.0) << i;
}

// §4: projectResponse sets dx_i = 0 for the listed DoFs only.
TEST(FixedProjectiveConstraint, ProjectResponseZeroesTheListedDofs) {
  auto s = load(scene8(R"(<FixedProjectiveConstraint name="fix" indices="1 3-4"/>)"));
  auto& fix = must<FixedProjectiveConstraint>(s, "fix");
  auto& mo = must<MechanicalObject>(s, "dofs");
  auto& dx = mo.write(kDx);
  for (std::size_t i = 0; i < dx.size(); ++i) dx[i] = static_cast<double>(i + 1);
  fix.project_response(kDx);
  for (std::size_t d = 0; d < 8; ++d)
    for (std::size_t c = 0; c < 3; ++c) {
      const bool fixed = d == 1 || d == 3 || d == 4;
      EXPECT_EQ(dx[d * 3 + c], fixed ? 0.0 : static_cast<double>(d * 3 + c + 1)) << d;
    }
}

// §4: invalid indices (≥ size) are removed with a warning at init.
TEST(FixedProjectiveConstraint, OutOfRangeIndicesAreDroppedWithAWarning) {
  auto s = load(scene8(R"(<FixedProjectiveConstraint name="fix" indices="2 99"/>)"));
  auto& fix = must<FixedProjectiveConstraint>(s, "fix");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "99"));
  EXPECT_EQ(fix.state(), ComponentState::valid);
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kDx).assign(24, 1.0);
  fix.project_response(kDx);
  EXPECT_EQ(mo.write(kDx).size(), 24u);
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(mo.write(kDx)[i], (i / 3 == 2) ? 0.0 : 1.0) << i;
}

// §4: fixAll zeroes every DoF.
TEST(FixedProjectiveConstraint, FixAllZeroesEverything) {
  auto s = load(scene8(R"(<FixedProjectiveConstraint name="fix" fixAll="1" indices="3"/>)"));
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kDx).assign(24, 1.0);
  must<FixedProjectiveConstraint>(s, "fix").project_response(kDx);
  EXPECT_EQ(mo.write(kDx), std::vector<double>(24, 0.0));
}

// §4 / framework §6.5: projectVelocity is a no-op unless activate_projectVelocity.
TEST(FixedProjectiveConstraint, ProjectVelocityOnlyWhenActivated) {
  auto s = load(scene8(R"(<FixedProjectiveConstraint name="off" indices="0"/>
                          <FixedProjectiveConstraint name="on" indices="1" activate_projectVelocity="1"/>)"));
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kVelocity).assign(24, 1.0);
  must<FixedProjectiveConstraint>(s, "off").project_velocity(kVelocity, 0);
  EXPECT_EQ(mo.write(kVelocity), std::vector<double>(24, 1.0));
  must<FixedProjectiveConstraint>(s, "on").project_velocity(kVelocity, 0);
  EXPECT_EQ(mo.write(kVelocity)[3], 0.0);
  EXPECT_EQ(mo.write(kVelocity)[5], 0.0);
  EXPECT_EQ(mo.write(kVelocity)[6], 1.0);
}

// Rigid: the whole 6-scalar derivative of a fixed DoF is zeroed.
TEST(FixedProjectiveConstraint, RigidDofsZeroAllSixComponents) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" template="Rigid3d" position="0 0 0 0 0 0 1  1 0 0 0 0 0 1"/>
    <FixedProjectiveConstraint name="fix" indices="1"/>
  </Node>)");
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kDx).assign(12, 1.0);
  must<FixedProjectiveConstraint>(s, "fix").project_response(kDx);
  EXPECT_EQ(mo.write(kDx), (std::vector<double>{1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0}));
}

// mechanics §0.8 (BoxConstraint pattern): indices linked to a BoxROI's output.
TEST(FixedProjectiveConstraint, IndicesFromABoxROI) {
  auto s = load(scene8(R"(<BoxROI name="roi" box="-0.1 -0.1 -0.1 1.1 1.1 0.1"/>
                          <FixedProjectiveConstraint name="fix" indices="@roi.indices"/>)"));
  auto& fix = must<FixedProjectiveConstraint>(s, "fix");
  EXPECT_EQ(fix.indices.get(), (std::vector<unsigned>{0, 1, 2, 3}));
  auto& mo = must<MechanicalObject>(s, "dofs");
  mo.write(kDx).assign(24, 1.0);
  fix.project_response(kDx);
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(mo.write(kDx)[i], i < 12 ? 0.0 : 1.0) << i;
}
