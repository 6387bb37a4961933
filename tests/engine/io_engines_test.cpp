// BoxROI oriented boxes and *OutROI outputs, SphereROI, TransformEngine (spec/mechanics.md §7.7, §7.8).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/box_roi.h"
#include "engine/sphere_roi.h"
#include "engine/transform_engine.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using Idx = std::vector<unsigned>;
}

// Parallelogram p0=(0,0,0), p1=(2,0,0), p2=(2,1,0) extruded by ±depth/2 along z: x∈[0,2], y∈[0,1], |z|≤0.5.
TEST(IoBoxROI, OrientedBox) {
  auto s = load(R"(<Node><BoxROI name="roi" orientedBox="0 0 0  2 0 0  2 1 0  1"
      position="1 0.5 0  1 0.5 0.6  2.1 0.5 0  0 0 0.5  1 -0.1 0  1 1 -0.5"/></Node>)");
  auto* r = get<BoxROI>(*s.root, "roi");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->indices.get(), (Idx{0, 3, 5}));
  EXPECT_EQ(r->indices_out.get(), (Idx{1, 2, 4}));
  EXPECT_TRUE(r->box.get().empty());  // no default unit box when an oriented box is given
}

TEST(IoBoxROI, OutputsOutsideTheRoi) {
  auto s = load(R"(<Node>
    <BoxROI name="strict" box="-1 -1 -1 1 1 1" position="0 0 0  5 5 5  0.5 0 0" edges="0 1  0 2" triangles="0 1 2"/>
    <BoxROI name="loose" strict="0" box="-1 -1 -1 1 1 1" position="0 0 0  5 5 5  0.5 0 0" edges="0 1  0 2"/>
  </Node>)");
  auto* r = get<BoxROI>(*s.root, "strict");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->indices.get(), (Idx{0, 2}));
  EXPECT_EQ(r->nb_indices.get(), 2u);
  EXPECT_EQ(r->points_out_roi.get().data, (std::vector<double>{5, 5, 5}));
  EXPECT_EQ(r->points_in_roi.get().data, (std::vector<double>{0, 0, 0, 0.5, 0, 0}));
  EXPECT_EQ(r->edge_indices.get(), (Idx{1}));
  EXPECT_EQ(r->edge_out_indices.get(), (Idx{0}));
  EXPECT_EQ(r->edges_out_roi.get(), (std::vector<Edge>{{0, 1}}));
  EXPECT_EQ(r->triangle_out_indices.get(), (Idx{0}));
  EXPECT_TRUE(r->triangles_in_roi.get().empty());
  // Non-strict: the centroid of (0,1) is (2.5, 2.5, 2.5), outside.
  auto* l = get<BoxROI>(*s.root, "loose");
  EXPECT_EQ(l->edge_indices.get(), (Idx{1}));
}

TEST(IoBoxROI, ViewerAttributesAccepted) {
  auto s = test::build(R"(<Node><MechanicalObject position="0 0 0"/>
    <BoxROI name="roi" box="0 0 0 1 1 1" drawBoxes="1" drawSize="2" drawPoints="0" drawTriangles="1" computeQuad="0"/>
  </Node>)");
  EXPECT_FALSE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "unused attribute"));
}

TEST(IoSphereROI, PointsInsideSpheres) {
  auto s = load(R"(<Node>
    <SphereROI name="a" centers="0 0 0" radii="1" position="0 0 0  1 0 0  1.01 0 0  0 0.5 0.5"/>
    <SphereROI name="b" centers="0 0 0  10 0 0" radii="1" position="0 0 0  5 0 0  10 0 0.5"/>
    <SphereROI name="c" centers="0 0 0" radii="2" edgeAngle="45" direction="3 0 0"
               position="0 0 0  1 0 0  0 0.5 0.5" edges="0 1  0 2"/>
  </Node>)");
  auto* a = get<SphereROI>(*s.root, "a");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->indices.get(), (Idx{0, 1, 3}));
  auto* b = get<SphereROI>(*s.root, "b");
  EXPECT_EQ(b->indices.get(), (Idx{0, 2}));
  EXPECT_EQ(b->radii.get(), (std::vector<double>{1, 1}));  // one radius applies to every centre
  // SOFA keeps edges whose direction makes MORE than edgeAngle with `direction`.
  auto* c = get<SphereROI>(*s.root, "c");
  EXPECT_EQ(c->edge_indices.get(), (Idx{1}));
  EXPECT_EQ(c->direction.get(), Vec3(1, 0, 0));
}

// §7.8: scale → rotation → translation; inverse reverses and inverts.
TEST(IoTransformEngine, VecOperationsAndInverse) {
  auto s = load(R"(<Node>
    <TransformEngine name="t" input_position="1 0 0  0 1 0" scale="2 2 2" rotation="0 0 90" translation="1 2 3"/>
    <TransformEngine name="i" input_position="@t.output_position" scale="2 2 2" rotation="0 0 90"
                     translation="1 2 3" inverse="1"/>
  </Node>)");
  auto* t = get<TransformEngine>(*s.root, "t");
  ASSERT_TRUE(t);
  const auto& o = t->output_position.get().data;
  ASSERT_EQ(o.size(), 6u);
  const double want[6] = {1, 4, 3, -1, 2, 3};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(o[k], want[k], 1e-12) << k;
  const auto& back = get<TransformEngine>(*s.root, "i")->output_position.get().data;
  const double orig[6] = {1, 0, 0, 0, 1, 0};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(back[k], orig[k], 1e-12) << k;
}

TEST(IoTransformEngine, RigidOrientationIsRotated) {
  auto s = load(R"(<Node>
    <TransformEngine name="t" template="Rigid3d" input_position="1 0 0 0 0 0 1" quaternion="0 0 0.7071067811865476 0.7071067811865476"/>
  </Node>)");
  auto* t = get<TransformEngine>(*s.root, "t");
  ASSERT_TRUE(t);
  const auto& o = t->output_position.get().data;
  ASSERT_EQ(o.size(), 7u);
  EXPECT_NEAR(o[0], 0, 1e-12);
  EXPECT_NEAR(o[1], 1, 1e-12);
  EXPECT_NEAR(o[5], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(o[6], std::sqrt(0.5), 1e-12);
}

// The DistanceMultiMapping pattern: a state fed by a TransformEngine fed by another state.
TEST(IoTransformEngine, FeedsAState) {
  auto s = load(R"(<Node>
    <MechanicalObject name="a" position="0 0 0  1 0 0"/>
    <TransformEngine name="t" input_position="@a.position" translation="1.2 0 0"/>
    <MechanicalObject name="b" position="@t.output_position"/>
  </Node>)");
  auto* b = get<MechanicalObject>(*s.root, "b");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->position.get().data, (std::vector<double>{1.2, 0, 0, 2.2, 0, 0}));
}
