// ArticulatedSystemMapping with its hierarchy components, on a two-joint arm
// worked by hand: the base frame at (2, 0, 0); joint 1 turns frame 1 about z
// at (3, 0, 0) by π/2 (frame 1 ends at (3, 1, 0)); joint 2 slides frame 2
// along frame 1's x axis (world y) by 0.5 from (3, 2, 0). Velocities, forces
// and constraint rows on the same arm; the incremental processes 1 and 2; bad
// input. (Jᵀ as the adjoint of J, and J against finite differences of apply,
// are in the conformance battery.) The chain's statics under gravity with
// angular springs is in tests/forcefield/angular_spring_force_field_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "badinput_helpers.h"
#include "core/constraint_matrix.h"
#include "core/node.h"
#include "mapping/articulated/articulated_system_mapping.h"
#include "test_scene.h"

using namespace sinew;

namespace {

constexpr double kS = 0.70710678118654752;  // sin 45° = cos 45°

// `q` holds the joint coordinates; centre 2 (joint 2) carries `art2`.
const std::string kSlider = "articulationIndex='1' translation='1' axis='1 0 0'";

std::string arm(const std::string& q, int process = 0, const std::string& art2 = kSlider,
                const std::string& map_attrs = "", const std::string& container = "<ArticulatedHierarchyContainer/>") {
  const std::string p = " articulationProcess='" + std::to_string(process) + "'";
  return "<Node name='root' gravity='0 0 0'>"
         "<MechanicalObject name='q' template='Vec1d' position='" + q + "'/>"
         "<Node name='base'><MechanicalObject name='frame' template='Rigid3d' position='2 0 0 0 0 0 1'/></Node>"
         "<Node name='body'><MechanicalObject name='frames' template='Rigid3d'"
         " position='0 0 0 0 0 0 1  0 0 0 0 0 0 1  0 0 0 0 0 0 1'/>"
         "<ArticulatedSystemMapping name='map' input1='@../q' input2='@../base/frame' output='@frames' " +
         map_attrs + "/></Node>" + container +
         "<Node name='centers'>"
         "<Node name='c1'><ArticulationCenter name='center' parentIndex='0' childIndex='1' posOnParent='1 0 0'"
         " posOnChild='-1 0 0'" + p + "/>"
         "<Node name='a'><Articulation name='joint' articulationIndex='0' rotation='1' rotationAxis='0 0 2'/></Node>"
         "</Node>"
         "<Node name='c2'><ArticulationCenter name='center' parentIndex='1' childIndex='2' posOnParent='1 0 0'"
         " posOnChild='0 0 0'" + p + "/>"
         "<Node name='a'><Articulation " + art2 + "/></Node></Node>"
         "</Node></Node>";
}

struct Parts {
  scene::LoadedScene s;
  ArticulatedSystemMapping* map = nullptr;
  MechanicalState *q = nullptr, *base = nullptr, *frames = nullptr;
};

Parts load_arm(const std::string& xml) {
  Parts p;
  p.s = test::load(xml);
  if (!p.s.root) return p;
  p.map = test::get<ArticulatedSystemMapping>(*p.s.root->find_child_named("body"), "map");
  p.q = p.s.root->get_mechanical_state();
  p.base = p.s.root->find_child_named("base")->get_mechanical_state();
  p.frames = p.s.root->find_child_named("body")->get_mechanical_state();
  return p;
}

void expect_vec(const std::vector<double>& v, const std::vector<double>& want, double tol, const char* what) {
  ASSERT_EQ(v.size(), want.size()) << what;
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_NEAR(v[k], want[k], tol) << what << "[" << k << "]";
}

const std::string kQuarterTurn = "1.5707963267948966 0.5";

}  // namespace

TEST(ArticulatedSystemMapping, PlacesTheFramesJointByJoint) {
  Parts p = load_arm(arm(kQuarterTurn));
  ASSERT_NE(p.map, nullptr);
  ASSERT_EQ(p.map->state(), ComponentState::valid);
  expect_vec(p.frames->read(kPosition),
             {2, 0, 0, 0, 0, 0, 1,     // the base frame
              3, 1, 0, 0, 0, kS, kS,   // turned about z at (3, 0, 0)
              3, 2.5, 0, 0, 0, kS, kS}, // slid along its parent's x (world y)
             1e-15, "frames");
  // The joint positions, and the axis normalised in place (SOFA's process 0).
  Node& centers = *p.s.root->find_child_named("centers");
  auto* c2 = test::get<ArticulationCenter>(*centers.find_child_named("c2"), "center");
  ASSERT_NE(c2, nullptr);
  EXPECT_NEAR((c2->global_position.value() - Vec3(3, 2, 0)).norm(), 0.0, 1e-15);
  auto* joint = test::get<Articulation>(*centers.find_child_named("c1")->find_child_named("a"), "joint");
  ASSERT_NE(joint, nullptr);
  EXPECT_EQ(joint->axis.value(), Vec3(0, 0, 1));
}

// ω₁ = z·q̇₀; v₁ = v_base + ω₁ × (C₁ − A₁) = (0.1, 0, 0) + z × (0, 1, 0) = (−0.9, 0, 0);
// v₂ = v₁ + ω₁ × (C₂ − C₁) + y·q̇₁ = (−0.9, 0, 0) + (−1.5, 0, 0) + (0, 0.2, 0).
TEST(ArticulatedSystemMapping, VelocitiesFromTheJointRates) {
  Parts p = load_arm(arm(kQuarterTurn));
  ASSERT_NE(p.map, nullptr);
  p.q->write(kVelocity) = {1.0, 0.2};
  p.base->write(kVelocity) = {0.1, 0, 0, 0, 0, 0};
  p.map->apply_j(kVelocity, kVelocity);
  expect_vec(p.frames->read(kVelocity),
             {0.1, 0, 0, 0, 0, 0,  -0.9, 0, 0, 0, 0, 1,  -2.4, 0.2, 0, 0, 0, 1}, 1e-15, "v");
}

// F = (1, 1, 0) on frame 2 and a torque (0, 0, 2) on frame 1: joint 2 (sliding along y) gets
// F·y = 1; joint 1 gets the torque about (3, 0, 0): 2 + ((0, 2.5, 0) × F)·z = 2 − 2.5; the base
// gets F and the torque about its centre, 2 + ((1, 2.5, 0) × F)·z = 0.5.
TEST(ArticulatedSystemMapping, ForcesToTheJointsAndTheBase) {
  Parts p = load_arm(arm(kQuarterTurn));
  ASSERT_NE(p.map, nullptr);
  p.frames->write(kForce) = {0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 2,  1, 1, 0, 0, 0, 0};
  p.q->write(kForce) = {10, 20};  // added to
  p.base->write(kForce) = {0, 0, 0, 0, 0, 0};
  p.map->apply_jt(kForce, kForce);
  expect_vec(p.q->read(kForce), {10 - 0.5, 21}, 1e-15, "joint forces");
  expect_vec(p.base->read(kForce), {1, 1, 0, 0, 0, 0.5}, 1e-15, "base force");
}

// A constraint row on frame 2 goes to every joint between frame 2 and the base
// (SOFA's ancestor list), and to the base with the torque about the base's centre.
TEST(ArticulatedSystemMapping, ConstraintRowsWalkTheChain) {
  Parts p = load_arm(arm(kQuarterTurn));
  ASSERT_NE(p.map, nullptr);
  ConstraintMatrix& c = p.frames->constraint_jacobian();
  c.clear(6);
  const double row[6] = {1, 1, 0, 0, 0, 2};
  c.add(7, 2, row);
  p.q->constraint_jacobian().clear(1);
  p.base->constraint_jacobian().clear(6);
  ASSERT_TRUE(p.map->apply_jt_constraints());
  ConstraintMatrix& jq = p.q->constraint_jacobian();
  jq.compress();
  const ConstraintMatrix::Row* r = jq.find_row(7);
  ASSERT_NE(r, nullptr);
  ASSERT_EQ(r->end - r->begin, 2);
  // Joint 0 (rotation about z at (3, 0, 0)): 2 + ((0, 2.5, 0) × (1, 1, 0))·z; joint 1: (1, 1, 0)·y.
  EXPECT_EQ(jq.entries()[r->begin].dof, 0);
  EXPECT_NEAR(*jq.value(r->begin), -0.5, 1e-15);
  EXPECT_EQ(jq.entries()[r->begin + 1].dof, 1);
  EXPECT_NEAR(*jq.value(r->begin + 1), 1.0, 1e-15);
  ConstraintMatrix& jb = p.base->constraint_jacobian();
  jb.compress();
  const ConstraintMatrix::Row* rb = jb.find_row(7);
  ASSERT_NE(rb, nullptr);
  ASSERT_EQ(rb->end - rb->begin, 1);
  const double* v = jb.value(rb->begin);
  expect_vec(std::vector<double>(v, v + 6), {1, 1, 0, 0, 0, 0.5}, 1e-15, "base row");
}

// Process 1 counts rotations by increments from the coordinates seen at init
// (SOFA maps once before it knows the centres): the initial 0.3 is the zero.
TEST(ArticulatedSystemMapping, ProcessOneRotatesByIncrements) {
  Parts p = load_arm(arm("0.3 0", 1));
  ASSERT_NE(p.map, nullptr);
  ASSERT_EQ(p.map->state(), ComponentState::valid);
  // The arm straight: frame 1 at (2, 0, 0) + (1, 0, 0) + (1, 0, 0).
  expect_vec(p.frames->read(kPosition),
             {2, 0, 0, 0, 0, 0, 1,  4, 0, 0, 0, 0, 0, 1,  5, 0, 0, 0, 0, 0, 1}, 1e-15, "at init");
  p.q->write(kPosition) = {0.3 + std::numbers::pi / 2, 0.5};
  p.map->apply(kPosition);
  const std::vector<double> turned = {2, 0, 0, 0, 0, 0, 1,  3, 1, 0, 0, 0, kS, kS,  3, 2.5, 0, 0, 0, kS, kS};
  expect_vec(p.frames->read(kPosition), turned, 1e-14, "turned");
  // Unchanged coordinates: no increment, the same frames.
  p.map->apply(kPosition);
  expect_vec(p.frames->read(kPosition), turned, 1e-14, "again");
}

// Process 2 takes its axes from the child's previous orientation and applies
// the translation whole (not by increments), after the rotation.
TEST(ArticulatedSystemMapping, ProcessTwoSlidesByTheWholeCoordinate) {
  Parts p = load_arm(arm("0 0.5", 2));
  ASSERT_NE(p.map, nullptr);
  expect_vec(p.frames->read(kPosition),
             {2, 0, 0, 0, 0, 0, 1,  4, 0, 0, 0, 0, 0, 1,  5.5, 0, 0, 0, 0, 0, 1}, 1e-15, "at init");
  p.q->write(kPosition) = {std::numbers::pi / 2, 0.5};
  p.map->apply(kPosition);
  // Frame 2's slide axis is its orientation before this apply (world x).
  expect_vec(p.frames->read(kPosition),
             {2, 0, 0, 0, 0, 0, 1,  3, 1, 0, 0, 0, kS, kS,  3.5, 2, 0, 0, 0, kS, kS}, 1e-14, "turned");
}

// SOFA's example: ten beam frames on nine ball joints (two rotations each), angular springs
// between them, gravity along the beam. The gravity has no lever arm about any joint, so the
// beam stays straight: every coordinate stays 0 and frame i sits at i·(0.714285714286 · 2)
// (the scene's own positions, rounded to 11 digits, are replaced by the mapping's at init);
// the collision skin follows its frames (BeamLinearMapping).
TEST(ArticulatedSystemMapping, SofaExampleBeamStaysStraightUnderAxialGravity) {
  std::vector<double> q, frames, skin;
  const test::Outcome o = test::run_sofa_example(
      "Component/SolidMechanics/Spring/angularSpringForceField.scn", 100, [&](runner::Session& s) {
        Node* beam = s.root().find_child_named("ArticulatedSoftBeam");
        q = beam->mechanical_state->read(kPosition);
        Node* mech = beam->find_child_named("Mechanics");
        frames = mech->mechanical_state->read(kPosition);
        skin = mech->find_child_named("Collision")->mechanical_state->read(kPosition);
      });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 100);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  ASSERT_EQ(q.size(), 20u);
  for (double v : q) EXPECT_EQ(v, 0.0);
  ASSERT_EQ(frames.size(), 70u);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(frames[7 * i], i * (0.714285714286 * 2), 1e-12) << "frame " << i;
    for (int c = 1; c < 6; ++c) EXPECT_EQ(frames[7 * i + c], 0.0) << "frame " << i;
    EXPECT_EQ(frames[7 * i + 6], 1.0);
  }
  // The skin: CubeTopology points (x in 0..9.2, y and z ±0.05) in BeamLinearMapping's local
  // coordinates (x counts frames, lengths in beam lengths L): a straight box from 0 to 9.2·L,
  // ±0.05·L across. L is measured at init on the scene's positions (rounded to 11 digits: the
  // articulated mapping only places the frames after every init, as SOFA's bwdInit), hence 1e-10.
  const double L = 0.714285714286 * 2;
  ASSERT_EQ(skin.size(), 70u * 2 * 2 * 3);
  double max_x = 0;
  for (std::size_t k = 0; k < skin.size(); k += 3) {
    max_x = std::max(max_x, skin[k]);
    EXPECT_NEAR(std::fabs(skin[k + 1]), 0.05 * L, 1e-10);
    EXPECT_NEAR(std::fabs(skin[k + 2]), 0.05 * L, 1e-10);
  }
  EXPECT_NEAR(max_x, 9.2 * L, 1e-9);
}

// ------------------------------------------------------------------ bad input

TEST(ArticulatedSystemMapping, CoordinateIndexOutOfRangeIsRefused) {
  auto s = test::build(arm(kQuarterTurn, 0, "translation='1' articulationIndex='5'"));
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto* map = test::get<ArticulatedSystemMapping>(*s.root->find_child_named("body"), "map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "articulationIndex 5 but input1 has 2 coordinates"));
}

TEST(ArticulatedSystemMapping, MissingContainerIsAnError) {
  auto s = test::build(arm(kQuarterTurn, 0, kSlider, "", ""));
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto* map = test::get<ArticulatedSystemMapping>(*s.root->find_child_named("body"), "map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "no ArticulatedHierarchyContainer"));
}

TEST(ArticulatedSystemMapping, BvhFilesAreRefused) {
  auto s = test::build(arm(kQuarterTurn, 0, kSlider, "",
                           "<ArticulatedHierarchyContainer filename='walk.bvh'/>"));
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "BVH file is not supported"));
  EXPECT_TRUE(test::any_contains(errors, "ArticulatedHierarchyContainer is invalid"));
}

TEST(ArticulatedSystemMapping, FramesOutOfRangeAreRefused) {
  std::string xml = arm(kQuarterTurn);
  xml.replace(xml.find("childIndex='2'"), 14, "childIndex='3'");
  auto s = test::build(xml);
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto* map = test::get<ArticulatedSystemMapping>(*s.root->find_child_named("body"), "map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "joins frames 1 and 3 but the output has 3"));
}
