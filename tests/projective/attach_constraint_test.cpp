// AttachProjectiveConstraint: SOFA's projections for vector DoFs (object2's position moved
// half-way to object1's, velocities averaged, one-way responses zeroed / two-way averaged),
// constraintFactor, minDistance, lastPos/lastDir with clamp, the Dirichlet rows, bad input,
// and SOFA's two example scenes.
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"
#include "core/mechanical_ops.h"
#include "core/node.h"
#include "test_scene.h"
#include "test_paths.h"

using namespace sinew;

namespace {

struct Pair {
  scene::LoadedScene s;
  MechanicalState* a = nullptr;
  MechanicalState* b = nullptr;
  ProjectiveConstraint* c = nullptr;
};

Pair make(const std::string& attrs) {
  Pair p;
  p.s = test::load(R"(<Node gravity="0 0 0"><DefaultAnimationLoop/>
    <Node name="A"><MechanicalObject name="a" position="0 0 0  1 0 0" velocity="1 0 0  2 0 0"/></Node>
    <Node name="B"><MechanicalObject name="b" position="5 5 5  2 2 2" velocity="3 0 0  0 4 0"/></Node>
    <AttachProjectiveConstraint name="c" object1="@A" object2="@B" )" +
                   attrs + "/></Node>");
  p.a = test::get<MechanicalState>(*p.s.root->find_child_named("A"), "a");
  p.b = test::get<MechanicalState>(*p.s.root->find_child_named("B"), "b");
  p.c = test::get<ProjectiveConstraint>(*p.s.root, "c");
  // Init already projected once: back to the given values.
  p.a->write(kPosition) = {0, 0, 0, 1, 0, 0};
  p.a->write(kVelocity) = {1, 0, 0, 2, 0, 0};
  p.b->write(kPosition) = {5, 5, 5, 2, 2, 2};
  p.b->write(kVelocity) = {3, 0, 0, 0, 4, 0};
  return p;
}

TEST(AttachConstraint, OneWayProjections) {
  auto p = make("indices1=\"1\" indices2=\"0\"");
  ASSERT_NE(p.c, nullptr);
  p.c->project_position(kPosition, 0);
  EXPECT_EQ(p.b->read(kPosition), (std::vector<double>{3, 2.5, 2.5, 2, 2, 2}));  // (5,5,5) half-way to (1,0,0)
  EXPECT_EQ(p.a->read(kPosition), (std::vector<double>{0, 0, 0, 1, 0, 0}));      // untouched
  p.c->project_velocity(kVelocity, 0);
  EXPECT_EQ(p.a->read(kVelocity), (std::vector<double>{1, 0, 0, 2.5, 0, 0}));  // both to the mean
  EXPECT_EQ(p.b->read(kVelocity), (std::vector<double>{2.5, 0, 0, 0, 4, 0}));
  const int dx = MechanicalOps::alloc_vec();
  p.a->write(dx) = {1, 1, 1, 1, 1, 1};
  p.b->write(dx) = {7, 7, 7, 7, 7, 7};
  p.c->project_response(dx);
  EXPECT_EQ(p.a->read(dx), (std::vector<double>{1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(p.b->read(dx), (std::vector<double>{0, 0, 0, 7, 7, 7}));
  std::vector<std::size_t> rows;
  EXPECT_TRUE(p.c->dirichlet_indices(rows));
  EXPECT_EQ(rows, (std::vector<std::size_t>{0, 1, 2}));
}

TEST(AttachConstraint, TwoWayFactorsAndRelease) {
  auto p = make("indices1=\"0 1\" indices2=\"0 1\" twoWay=\"1\" constraintFactor=\"0.5 1\" minDistance=\"3\"");
  ASSERT_NE(p.c, nullptr);
  p.c->project_position(kPosition, 0);
  // Pair 0 is √75 apart: released. Pair 1: (2,2,2) − ((2,2,2) − (1,0,0))·½.
  EXPECT_EQ(p.b->read(kPosition), (std::vector<double>{5, 5, 5, 1.5, 1, 1}));
  const int dx = MechanicalOps::alloc_vec();
  p.a->write(dx) = {1, 1, 1, 1, 1, 1};
  p.b->write(dx) = {7, 7, 7, 5, 5, 5};
  p.c->project_response(dx);
  EXPECT_EQ(p.a->read(dx), (std::vector<double>{1, 1, 1, 3, 3, 3}));  // pair 1 averaged, pair 0 released
  EXPECT_EQ(p.b->read(dx), (std::vector<double>{7, 7, 7, 3, 3, 3}));
  std::vector<std::size_t> rows;
  EXPECT_TRUE(p.c->dirichlet_indices(rows));
  EXPECT_TRUE(rows.empty());  // two-way: nothing in the matrix
}

TEST(AttachConstraint, ClampAtLastPos) {
  // Object1's point 1 is past the plane x = 0.5 along +x: its partner is held at lastPos.
  auto p = make("indices1=\"0 1\" indices2=\"0 1\" lastPos=\"0.5 0 0\" lastDir=\"1 0 0\" clamp=\"1\"");
  ASSERT_NE(p.c, nullptr);
  p.c->project_position(kPosition, 0);
  EXPECT_EQ(p.b->read(kPosition), (std::vector<double>{2.5, 2.5, 2.5, 1.25, 1, 1}));
  p.c->project_velocity(kVelocity, 0);
  EXPECT_EQ(p.b->read(kVelocity), (std::vector<double>{2, 0, 0, 0, 2, 0}));  // clamped: v2 halved towards 0
}

TEST(AttachConstraint, OutOfRangeIndicesAreErrors) {
  auto s = test::build(R"(<Node gravity="0 0 0"><DefaultAnimationLoop/>
    <Node name="A"><MechanicalObject position="0 0 0"/></Node>
    <Node name="B"><MechanicalObject position="0 0 0"/></Node>
    <AttachProjectiveConstraint name="c" object1="@A" object2="@B" indices1="0" indices2="3"/></Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "pair 0 (0, 3) is out of range: object1 has 1 points, object2 1"));
  EXPECT_EQ(test::get<Component>(*s.root, "c")->state(), ComponentState::invalid);
}

class AttachExample : public ::testing::TestWithParam<const char*> {};

TEST_P(AttachExample, RunsAndKeepsTheBarsTogether) {
  double gap = -1;
  const test::Outcome o = test::run_sofa_example(GetParam(), 20, [&](runner::Session& s) {
    Node* n = s.root().find_child_named("AttachOneWay");
    if (!n) return;
    std::vector<MechanicalState*> st1, st2;
    n->find_child_named("M1")->collect_down(st1);
    n->find_child_named("M2")->collect_down(st2);
    const auto& x1 = st1.at(0)->read(kPosition);
    const auto& x2 = st2.at(0)->read(kPosition);
    gap = 0;
    for (int k = 0; k < 16; ++k)
      for (int c = 0; c < 3; ++c) gap = std::max(gap, std::abs(x1[(144 + k) * 3 + c] - x2[k * 3 + c]));
  });
  if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR << " (set SINEW_DATA_DIR)";
  ASSERT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 20);
  EXPECT_TRUE(o.errors.empty()) << o.all();
  EXPECT_TRUE(o.finite);
  EXPECT_GE(gap, 0.0);
  EXPECT_LT(gap, 0.05) << "the attached points drifted apart";
}

INSTANTIATE_TEST_SUITE_P(Scenes, AttachExample,
                         ::testing::Values("Component/Constraint/Projective/AttachProjectiveConstraint.scn",
                                           "Component/Constraint/Projective/AttachProjectiveConstraintMatrix.scn"));

}  // namespace
