// MechanicalObject init and state services (spec/framework.md §5, traps T2, T9, T10).
#include "state/mechanical_object.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

// The i-th element (3 scalars) of a Vec3d vector.
Vec3 at3(const FlatVec& v, std::size_t i) { return Vec3(v.data[i * 3], v.data[i * 3 + 1], v.data[i * 3 + 2]); }

MechanicalObject& mo_of(scene::LoadedScene& s, std::string_view name = "dofs") {
  auto* mo = get<MechanicalObject>(*s.root, name);
  if (!mo) throw std::runtime_error("no MechanicalObject named " + std::string(name));
  return *mo;
}

double f32(double x) { return static_cast<double>(static_cast<float>(x)); }

}  // namespace

// ---------------------------------------------------------------- sizes and sources (§5.2 steps 1–4)

// §5.2 step 1 / T2: positions come from the FIRST mesh topology of the node.
TEST(MechanicalObjectInit, PositionsComeFromTheFirstLocalTopology) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="first" n="2 1 1" min="0 0 0" max="4 0 0"/>
    <RegularGridTopology name="second" n="3 1 1" min="0 0 0" max="1 0 0"/>
    <MechanicalObject name="dofs"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 2u);
  EXPECT_EQ(at3(mo.position.get(), 0), Vec3(0, 0, 0));
  EXPECT_EQ(at3(mo.position.get(), 1), Vec3(4, 0, 0));
  EXPECT_EQ(mo.velocity.get().data.size(), 6u);
  EXPECT_EQ(mo.size_field.value(), 2);
}

// Topologies declared after the MechanicalObject are still used (first in object order).
TEST(MechanicalObjectInit, TopologyDeclaredAfterTheStateIsUsed) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs"/>
    <RegularGridTopology n="2 2 1" min="0 0 0" max="1 1 0"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 4u);
  EXPECT_EQ(at3(mo.position.get(), 3), Vec3(1, 1, 0));
}

// §5.2 step 1: no ancestor search for the initial positions.
TEST(MechanicalObjectInit, TopologyOfTheParentNodeIsNotUsed) {
  auto s = load(R"(<Node>
    <RegularGridTopology n="2 2 2"/>
    <Node name="child"><MechanicalObject name="dofs"/></Node>
  </Node>)");
  auto* mo = get<MechanicalObject>(*s.root->find_child_named("child"), "dofs");
  ASSERT_NE(mo, nullptr);
  EXPECT_EQ(mo->size(), 1u);
}

// T9: nothing defines positions → one DoF at the origin.
TEST(MechanicalObjectInit, DefaultIsOneDofAtTheOrigin) {
  auto s = load(R"(<Node><MechanicalObject name="dofs"/></Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 1u);
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(mo.velocity.get().data, (std::vector<double>{0, 0, 0}));
}

// §5.2 step 4 / T9: a single user-given position is overwritten by the local topology.
TEST(MechanicalObjectInit, SingleGivenPositionIsReplacedByTheTopology) {
  auto s = load(R"(<Node>
    <RegularGridTopology n="2 1 1" min="0 0 0" max="1 0 0"/>
    <MechanicalObject name="dofs" position="7 7 7"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 2u);
  EXPECT_EQ(at3(mo.position.get(), 0), Vec3(0, 0, 0));
  EXPECT_EQ(at3(mo.position.get(), 1), Vec3(1, 0, 0));
}

TEST(MechanicalObjectInit, SeveralGivenPositionsWinOverTheTopology) {
  auto s = load(R"(<Node>
    <RegularGridTopology n="2 2 2"/>
    <MechanicalObject name="dofs" position="1 2 3 4 5 6"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 2u);
  EXPECT_EQ(at3(mo.position.get(), 1), Vec3(4, 5, 6));
}

// §5.2 step 4: one velocity given with topology points is replicated to every point.
TEST(MechanicalObjectInit, OneVelocityIsReplicatedToAllTopologyPoints) {
  auto s = load(R"(<Node>
    <RegularGridTopology n="2 2 2"/>
    <MechanicalObject name="dofs" velocity="1 -2 3"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(at3(mo.velocity.get(), i), Vec3(1, -2, 3)) << "dof " << i;
}

// §5.2 step 4: with fewer velocities than positions, the last given one is replicated.
TEST(MechanicalObjectInit, LastGivenVelocityIsReplicatedUpToThePositionCount) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0 1 0 0 2 0 0" velocity="1 0 0 0 2 0"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 3u);
  EXPECT_EQ(at3(mo.velocity.get(), 0), Vec3(1, 0, 0));
  EXPECT_EQ(at3(mo.velocity.get(), 1), Vec3(0, 2, 0));
  EXPECT_EQ(at3(mo.velocity.get(), 2), Vec3(0, 2, 0));
}

// §5.1: size="n" resizes (n DoFs at the origin).
TEST(MechanicalObjectInit, SizeAttributeResizes) {
  auto s = load(R"(<Node><MechanicalObject name="dofs" size="4"/></Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.size(), 4u);
  EXPECT_EQ(mo.position.get().data, std::vector<double>(12, 0.0));
}

// §5.2 step 3: a longer rest_position becomes the position.
TEST(MechanicalObjectInit, LongerRestPositionBecomesThePosition) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" rest_position="1 1 1 2 2 2"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.size(), 2u);
  EXPECT_EQ(at3(mo.position.get(), 1), Vec3(2, 2, 2));
}

// ---------------------------------------------------------------- transform (§5.2 steps 5–7)

// §5.2 step 5 / T9: scale, then rotation, then translation.
TEST(MechanicalObjectTransform, ScaleThenRotateThenTranslate) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 0 0" scale3d="2 2 2" rotation="0 0 90" translation="1 2 3"/>
  </Node>)");
  const Vec3 p = at3(mo_of(s).position.get(), 0);
  // (1,0,0) ·2 → (2,0,0); Rz(90°) → (0,2,0); +t → (1,4,3).
  EXPECT_NEAR(p.x(), 1.0, 1e-15);
  EXPECT_NEAR(p.y(), 4.0, 1e-15);
  EXPECT_NEAR(p.z(), 3.0, 1e-15);
}

// §5.2 step 5: p ← Rz·Ry·Rx·p (x rotation first).
TEST(MechanicalObjectTransform, EulerAnglesInDegreesComposeAsRzRyRx) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 1 0" rotation="90 0 90"/>
  </Node>)");
  const Vec3 p = at3(mo_of(s).position.get(), 0);
  // Rx(90): (0,1,0) → (0,0,1); Rz(90) leaves (0,0,1). (Rx·Rz would give (-1,0,0).)
  EXPECT_NEAR(p.x(), 0.0, 1e-15);
  EXPECT_NEAR(p.y(), 0.0, 1e-15);
  EXPECT_NEAR(p.z(), 1.0, 1e-15);
}

// §5.1 / mechanics §0.3: dx dy dz are translation pseudo-attributes, read as float.
TEST(MechanicalObjectTransform, DxPseudoAttributesAreReadAsFloat) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 0 0" dx="0.1" dz="-0.3"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.translation.value(), Vec3(f32(0.1), 0.0, f32(-0.3)));
  EXPECT_NE(f32(0.1), 0.1);  // the test is meaningful only if float rounding shows
  EXPECT_EQ(at3(mo.position.get(), 0), Vec3(f32(0.1), 0.0, f32(-0.3)));
}

// §5.1: rx ry rz → rotation (degrees, float); missing ones are 0.
TEST(MechanicalObjectTransform, RxPseudoAttributesSetTheRotation) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="0 1 0" rx="90"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.rotation.value(), Vec3(90, 0, 0));
  const Vec3 p = at3(mo.position.get(), 0);
  EXPECT_NEAR(p.y(), 0.0, 1e-15);
  EXPECT_NEAR(p.z(), 1.0, 1e-15);
}

// §5.1: scale="s" → scale3d = s s s; sx alone leaves sy = sz = 1.
TEST(MechanicalObjectTransform, ScalePseudoAttributes) {
  auto s = load(R"(<Node>
    <MechanicalObject name="a" position="1 1 1" scale="3"/>
    <Node name="c"><MechanicalObject name="b" position="1 1 1" sx="2"/></Node>
  </Node>)");
  auto& a = mo_of(s, "a");
  EXPECT_EQ(a.scale3d.value(), Vec3(3, 3, 3));
  EXPECT_EQ(at3(a.position.get(), 0), Vec3(3, 3, 3));
  auto* b = get<MechanicalObject>(*s.root->find_child_named("c"), "b");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->scale3d.value(), Vec3(2, 1, 1));
}

// §5.2 step 6: rest_position := transformed position.
TEST(MechanicalObjectTransform, RestPositionIncludesTheInitialTransform) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 2 3 4 5 6" translation="10 0 0"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.rest_position.get().data, (std::vector<double>{11, 2, 3, 14, 5, 6}));
  EXPECT_EQ(mo.rest_position.get().data, mo.position.get().data);
}

// §5.2 step 6: an explicitly given rest_position of the right size is kept untransformed.
TEST(MechanicalObjectTransform, GivenRestPositionIsKeptUntransformed) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 2 3" rest_position="0 0 0" translation="10 0 0"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.rest_position.get().data, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{11, 2, 3}));
}

// §5.2 step 7: translation2 moves the position after rest_position was stored.
TEST(MechanicalObjectTransform, Translation2IsAppliedAfterRestPosition) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 0 0" translation="1 0 0" translation2="0 5 0"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.rest_position.get().data, (std::vector<double>{2, 0, 0}));
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{2, 5, 0}));
}

// §5.2 step 7: rotation2 then translation2, on positions only; dx2 is a pseudo-attribute.
TEST(MechanicalObjectTransform, Rotation2ThenTranslation2) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 0 0" rotation2="0 0 90" dx2="1"/>
  </Node>)");
  auto& mo = mo_of(s);
  const Vec3 p = at3(mo.position.get(), 0);
  EXPECT_NEAR(p.x(), 1.0, 1e-15);  // (1,0,0) → (0,1,0) → (1,1,0)
  EXPECT_NEAR(p.y(), 1.0, 1e-15);
  EXPECT_EQ(mo.rest_position.get().data, (std::vector<double>{1, 0, 0}));
}

// §5.1: restScale multiplies the derived rest_position.
TEST(MechanicalObjectTransform, RestScaleScalesTheDerivedRestPosition) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" position="1 2 3" restScale="0.5"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.rest_position.get().data, (std::vector<double>{0.5, 1, 1.5}));
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{1, 2, 3}));
}

// §5.2 step 5 (Rigid): the centre is rotated and the orientation becomes q ⊗ orientation.
TEST(MechanicalObjectTransform, RigidRotationTurnsCentreAndOrientation) {
  auto s = load(R"(<Node>
    <MechanicalObject name="dofs" template="Rigid3d" position="1 0 0  0 0 0 1" rotation="0 0 90"/>
  </Node>)");
  auto& mo = mo_of(s);
  ASSERT_EQ(mo.state_type(), StateType::rigid3);
  const auto& x = mo.position.get().data;
  ASSERT_EQ(x.size(), 7u);
  const double h = std::sqrt(0.5);
  EXPECT_NEAR(x[0], 0.0, 1e-15);
  EXPECT_NEAR(x[1], 1.0, 1e-15);
  EXPECT_NEAR(x[5], h, 1e-15);
  EXPECT_NEAR(x[6], h, 1e-15);
}

// Rigid states from a topology get identity orientations.
TEST(MechanicalObjectInit, RigidFromTopologyGetsIdentityOrientation) {
  auto s = load(R"(<Node>
    <RegularGridTopology n="2 1 1" min="0 0 0" max="1 0 0"/>
    <MechanicalObject name="dofs" template="Rigid3d"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(mo.velocity.get().data.size(), 12u);
}

// framework §2.4/§2.6: a Rigid3d state linked by src= to points takes them as centres with
// identity orientations.
TEST(MechanicalObjectInit, RigidLinkedToPointsGetsIdentityOrientation) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="2 1 1" min="0 0 0" max="1 0 0"/>
    <MechanicalObject name="dofs" template="Rigid3d" src="@grid"/>
  </Node>)");
  auto& mo = mo_of(s);
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1}));
}

// ---------------------------------------------------------------- state services (§5.3–§5.5)

// §5.5 / T10: Rigid coord += deriv·h: c += v·h, q ← exp(ω h / 2) ⊗ q (left multiplication).
TEST(MechanicalObjectRigid, CoordPlusDerivRotatesAboutTheWorldAxis) {
  MechanicalObject mo(StateType::rigid3);
  mo.resize(1);
  auto& x = mo.write(kPosition);
  ASSERT_EQ(x.size(), 7u);
  // Start rotated by 90° about x: q0 = (sin45, 0, 0, cos45).
  const double r = std::sqrt(0.5);
  x = {1, 2, 3, r, 0, 0, r};
  auto& v = mo.write(kVelocity);
  ASSERT_EQ(v.size(), 6u);
  v = {1, 0, -1, 0, 0, M_PI / 2};  // ω h = 90° about z with h = 1
  mo.add_deriv_to_coord(kPosition, kPosition, kVelocity, 1.0);
  const auto& y = mo.read(kPosition);
  EXPECT_EQ(y[0], 2.0);
  EXPECT_EQ(y[1], 2.0);
  EXPECT_EQ(y[2], 2.0);
  // e = (0,0,sin45,cos45); e ⊗ q0 = (0.5, 0.5, 0.5, 0.5) (q0 ⊗ e would give y = −0.5).
  EXPECT_NEAR(y[3], 0.5, 1e-15);
  EXPECT_NEAR(y[4], 0.5, 1e-15);
  EXPECT_NEAR(y[5], 0.5, 1e-15);
  EXPECT_NEAR(y[6], 0.5, 1e-15);
}

// §5.5: rotation by ω h about z from identity gives (0, 0, sin(ωh/2), cos(ωh/2)).
TEST(MechanicalObjectRigid, SmallStepFromIdentity) {
  MechanicalObject mo(StateType::rigid3);
  mo.resize(1);
  auto& v = mo.write(kVelocity);
  const double w = 0.3, h = 0.01;
  v = {0, 0, 0, 0, 0, w};
  mo.add_deriv_to_coord(kPosition, kPosition, kVelocity, h);
  const auto& y = mo.read(kPosition);
  EXPECT_EQ(y[3], 0.0);
  EXPECT_EQ(y[4], 0.0);
  EXPECT_NEAR(y[5], std::sin(w * h / 2), 1e-17);
  EXPECT_NEAR(y[6], std::cos(w * h / 2), 1e-16);
}

TEST(MechanicalObjectVec3, CoordPlusDerivIsComponentWise) {
  MechanicalObject mo(StateType::vec3);
  mo.resize(2);
  mo.write(kPosition) = {0, 1, 2, 3, 4, 5};
  mo.write(kVelocity) = {1, 1, 1, -1, 0, 2};
  mo.add_deriv_to_coord(kFreePosition, kPosition, kVelocity, 0.5);
  EXPECT_EQ(mo.write(kFreePosition), (std::vector<double>{0.5, 1.5, 2.5, 2.5, 4, 6}));
  EXPECT_EQ(mo.write(kPosition), (std::vector<double>{0, 1, 2, 3, 4, 5}));
}

// §5.3: endIntegration empties externalForce.
TEST(MechanicalObjectVec3, EndIntegrationEmptiesExternalForce) {
  MechanicalObject mo(StateType::vec3);
  mo.resize(2);
  mo.write(kExternalForce).assign(6, 1.0);
  mo.end_integration();
  EXPECT_TRUE(mo.external_force.value().data.empty());
}

// §5.3: reset restores the stored position and zero velocity.
TEST(MechanicalObjectVec3, ResetRestoresStoredPositions) {
  auto s = load(R"(<Node><MechanicalObject name="dofs" position="1 2 3"/></Node>)");
  auto& mo = mo_of(s);
  mo.write(kPosition) = {9, 9, 9};
  mo.write(kVelocity) = {1, 1, 1};
  mo.reset();
  EXPECT_EQ(mo.position.get().data, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(mo.velocity.get().data, (std::vector<double>{0, 0, 0}));
}

// Dynamic vectors are allocated zero-filled at the state's size and kept.
TEST(MechanicalObjectVec3, DynamicVectorsAreZeroFilledAndPersistent) {
  MechanicalObject mo(StateType::vec3);
  mo.resize(3);
  auto& t = mo.write(kFirstDynamicVec + 100);
  EXPECT_EQ(t, std::vector<double>(9, 0.0));
  t[4] = 5;
  EXPECT_EQ(mo.write(kFirstDynamicVec + 100)[4], 5.0);
}
