// What the display flags add to pictures, as SOFA's components draw themselves: collision
// models (showCollisionModels), bounding trees (showBoundingCollisionModels), springs
// (showForceFields / showInteractionForceFields).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include <Eigen/Geometry>

#include "constraint/model/unilateral_lagrangian_constraint.h"
#include "render/draw_collision.h"
#include "render/offscreen.h"
#include "gl_skip.h"
#include "test_scene.h"

namespace sinew {
namespace {

// A 1 × 1 square at z = 0.5 (two triangles) with a triangle collision model, 4.5 in front of
// the camera; `flags` go to the root's VisualStyle.
std::string square_scene(const std::string& flags, const std::string& model_attrs = "") {
  return R"(<Node name="root" gravity="0 0 0">
      <VisualStyle displayFlags=")" + flags + R"("/>
      <InteractiveCamera position="0 0 5" lookAt="0 0 0"/>
      <CollisionPipeline/> <BruteForceBroadPhase/> <BVHNarrowPhase/>
      <MinProximityIntersection alarmDistance="0.1" contactDistance="0.05"/>
      <CollisionResponse/>
      <Node name="square">
        <MechanicalObject position="-0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5"/>
        <TriangleSetTopologyContainer triangles="0 1 2  0 2 3"/>
        <TriangleCollisionModel )" + model_attrs + R"(/>
      </Node>
    </Node>)";
}

// Batch `nth` (0: the first) that component `c` added to the list, or null.
const render::Batch* drawn_by(const render::DrawList& list, const Component* c, int nth = 0) {
  for (std::size_t i = 0; i < list.used; ++i)
    if (list.batches[i].source == c && nth-- == 0) return &list.batches[i];
  return nullptr;
}

TEST(CollisionColor, SofaDefaultsTellSimulatedMovingActiveApart) {
  const std::array<float, 4> red{1, 0, 0, 1};
  using A = std::array<float, 4>;
  EXPECT_EQ(render::collision_color(true, red, false, false, false), red);
  EXPECT_EQ(render::collision_color(false, red, true, true, true), (A{1, 0.5f, 0, 1}));
  EXPECT_EQ(render::collision_color(false, red, true, true, false), (A{0.5f, 0.25f, 0, 1}));
  EXPECT_EQ(render::collision_color(false, red, true, false, true), (A{1, 0, 0, 1}));
  EXPECT_EQ(render::collision_color(false, red, false, true, true), (A{0, 1, 0.5f, 1}));
  EXPECT_EQ(render::collision_color(false, red, false, false, true), (A{0.5f, 0.5f, 0.5f, 1}));
  EXPECT_EQ(render::collision_color(false, red, false, false, false), (A{0.25f, 0.25f, 0.25f, 1}));
}

TEST(CollisionDraw, TrianglesAndBoundingTreeInTheDrawList) {
  auto hidden = test::load(square_scene("showVisualModels"));
  render::DrawList list;
  render::gather(*hidden.root, list);
  EXPECT_EQ(list.used, 0u);  // the viewer's defaults hide collision models

  auto s = test::load(square_scene("showCollisionModels showBoundingCollisionModels"));
  animate(*s.root);  // the bounding tree is built by the collision stage
  render::gather(*s.root, list);
  ASSERT_EQ(list.used, 2u);
  const render::Batch& tris = list.batches[0];
  EXPECT_EQ(tris.kind, render::Batch::Kind::triangles);
  EXPECT_EQ(tris.vertex_count(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(tris.normals[3 * i + 2], 1.f);
  EXPECT_EQ(tris.shading.diffuse, (std::array<float, 4>{1, 0.5f, 0, 1}));  // simulated, moving, active
  const render::Batch& tree = list.batches[1];
  EXPECT_EQ(tree.kind, render::Batch::Kind::lines);
  EXPECT_EQ(tree.vertex_count() % 24, 0u);  // twelve edges per cube
  EXPECT_GE(tree.vertex_count(), 24u);
  // The root cube bounds the square (enlarged by the contact distance at most).
  EXPECT_NEAR(list.min[0], -0.5, 0.06);
  EXPECT_NEAR(list.max[1], 0.5, 0.06);
}

// An oriented box: six faces of two triangles, each normal the outward axis of its face.
TEST(CollisionDraw, OrientedBoxByItsSixFaces) {
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
      <VisualStyle displayFlags="showCollisionModels"/>
      <Node name="box">
        <MechanicalObject template="Rigid3d" position="1 2 3 0 0 0.3826834323650898 0.9238795325112867"/>
        <OBBCollisionModel extents="0.5 1 1.5"/>
      </Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  animate(*s.root);
  render::DrawList list;
  render::gather(*s.root, list);
  ASSERT_EQ(list.used, 1u);
  const render::Batch& b = list.batches[0];
  ASSERT_EQ(b.vertex_count(), 36u);
  const double h = std::sqrt(0.5);
  const Vec3 c(1, 2, 3);
  const Vec3 axes[3] = {{h, h, 0}, {-h, h, 0}, {0, 0, 1}};
  const double ext[3] = {0.5, 1, 1.5};
  for (std::size_t i = 0; i < 36; ++i) {
    const Vec3 p(b.positions[3 * i], b.positions[3 * i + 1], b.positions[3 * i + 2]);
    const Vec3 n(b.normals[3 * i], b.normals[3 * i + 1], b.normals[3 * i + 2]);
    // The normal is ±axis k, and the vertex lies on that face: (p − c)·axis k = ±ext k.
    int k = -1;
    for (int a = 0; a < 3; ++a)
      if (std::abs(std::abs(n.dot(axes[a])) - 1) < 1e-6) k = a;
    ASSERT_GE(k, 0) << "vertex " << i;
    EXPECT_NEAR((p - c).dot(n), ext[k], 1e-5) << "vertex " << i;
  }
  // Each triangle turns counter-clockwise seen from outside.
  for (std::size_t t = 0; t < 12; ++t) {
    Vec3 v[3], n(b.normals[9 * t], b.normals[9 * t + 1], b.normals[9 * t + 2]);
    for (int j = 0; j < 3; ++j) v[j] = Vec3(b.positions[9 * t + 3 * j], b.positions[9 * t + 3 * j + 1],
                                            b.positions[9 * t + 3 * j + 2]);
    EXPECT_GT((v[1] - v[0]).cross(v[2] - v[0]).dot(n), 0) << "triangle " << t;
  }
}

// showMappings: a barycentric mapping's output points (yellow, 7 px) and a green line to each
// input vertex weighing at least 1e-4 (a point on a face of the tetrahedron: three lines).
TEST(MappingDraw, BarycentricPointsAndTheirLinesToTheInputVertices) {
  const std::string xml = R"(<Node name="root" gravity="0 0 0">
      <VisualStyle displayFlags="showMappings"/>
      <Node name="body">
        <MechanicalObject position="0 0 0  1 0 0  0 1 0  0 0 1"/>
        <TetrahedronSetTopologyContainer tetrahedra="0 1 2 3"/>
        <Node name="mapped">
          <MechanicalObject position="0.25 0.25 0.25  0.5 0.25 0"/>
          <BarycentricMapping/>
        </Node>
      </Node>
    </Node>)";
  auto s = test::load(xml);
  ASSERT_TRUE(s.root);
  render::DrawList list;
  render::gather(*s.root, list);
  ASSERT_EQ(list.used, 2u);
  const render::Batch& points = list.batches[0];
  EXPECT_EQ(points.kind, render::Batch::Kind::points);
  EXPECT_EQ(points.vertex_count(), 2u);
  EXPECT_FLOAT_EQ(points.point_size, 7.f);
  EXPECT_EQ(points.shading.diffuse, (std::array<float, 4>{1, 1, 0, 1}));
  const render::Batch& lines = list.batches[1];
  EXPECT_EQ(lines.kind, render::Batch::Kind::lines);
  // Point 0 is inside (four weights 0.25), point 1 on the face z = 0 (weights 0.25, 0.5, 0.25, 0).
  ASSERT_EQ(lines.vertex_count(), 2u * (4 + 3));
  EXPECT_EQ(lines.shading.diffuse, (std::array<float, 4>{0, 1, 0, 1}));
  for (std::size_t k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(lines.positions[6 * k], 0.25f);  // starts at point 0
  for (std::size_t k = 4; k < 7; ++k) {
    EXPECT_FLOAT_EQ(lines.positions[6 * k], 0.5f);  // starts at point 1
    EXPECT_FLOAT_EQ(lines.positions[6 * k + 5], 0.f);  // ends on the face z = 0
  }
  // Without the flag, nothing.
  auto hidden = test::load(std::regex_replace(xml, std::regex("showMappings"), "showVisualModels"));
  render::gather(*hidden.root, list);
  EXPECT_EQ(list.used, 0u);
}

// SkinningMapping: a line from each frame's centre to each point it moves, coloured (w, w, 0).
// Point 0 at 0.5 from frame 0 and 1.5 from frame 1: weights 4 and 4/9, normalised (0.9, 0.1).
TEST(MappingDraw, SkinningLinesColouredByWeight) {
  auto s = test::load(R"(<Node name="root" gravity="0 0 0">
      <VisualStyle displayFlags="showMappings"/>
      <MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1  2 0 0 0 0 0 1  10 0 0 0 0 0 1"/>
      <Node name="skin"><MechanicalObject position="0.5 0 0"/><SkinningMapping nbRef="2"/></Node>
    </Node>)");
  ASSERT_TRUE(s.root);
  render::DrawList list;
  render::gather(*s.root, list);
  ASSERT_EQ(list.used, 1u);
  const render::Batch& b = list.batches[0];
  EXPECT_EQ(b.kind, render::Batch::Kind::lines);
  ASSERT_EQ(b.vertex_count(), 4u);
  EXPECT_FLOAT_EQ(b.positions[0], 0.f);  // frame 0
  EXPECT_FLOAT_EQ(b.positions[3], 0.5f);  // the point
  EXPECT_FLOAT_EQ(b.positions[6], 2.f);  // frame 1
  EXPECT_NEAR(b.colors[0], 0.9f, 1e-6);
  EXPECT_NEAR(b.colors[1], 0.9f, 1e-6);
  EXPECT_FLOAT_EQ(b.colors[2], 0.f);
  EXPECT_NEAR(b.colors[8], 0.1f, 1e-6);
}

TEST(CollisionDraw, PictureOfTheCollisionSquare) {
  std::string err;
  render::RenderOptions o;
  o.width = 200, o.height = 200, o.samples = 0;
  auto r = render::OffscreenRenderer::create(o, &err);
  if (!r) {
    ASSERT_TRUE(test::no_gl_context(err)) << "the renderer fails: " << err;
    GTEST_SKIP() << "no off-screen OpenGL here (" << err << "); install Mesa (scripts/setup)";
  }
  auto s = test::load(square_scene("showCollisionModels", "color=\"0 0 1 1\""));
  render::Image img;
  ASSERT_TRUE(r->render(*s.root, img, &err)) << err;
  // 1 × 1 at distance 4.5 with a 45° field of view: (100 / (4.5 tan 22.5°))² pixels.
  const double side = 100.0 / (4.5 * std::tan(M_PI / 8));
  long lit = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) {
      const auto c = img.rgb(x, y);
      lit += c[0] + c[1] + c[2] > 0;
    }
  EXPECT_NEAR(lit, side * side, 0.03 * side * side);
  // The colour set in the scene, lit head-on: diffuse 1 + ambient 0.2, clamped.
  const auto centre = img.rgb(100, 100);
  EXPECT_EQ(centre[2], 255);
  EXPECT_EQ(centre[0] + centre[1], 0);
}

TEST(SpringDraw, LinesColouredByCompressionAndByKind) {
  const std::string scene = R"(<Node name="root" gravity="0 0 0">
      <VisualStyle displayFlags="FLAGS"/>
      <Node name="a"><MechanicalObject name="a" position="0 0 0  1 0 0  3 0 0"/>
        <SpringForceField name="inner" spring="0 1 10 0 2"/></Node>
      <Node name="b"><MechanicalObject name="b" position="0 1 0  0 2 0"/></Node>
      <SpringForceField name="outer" object1="@a/a" object2="@b/b" spring="0 0 10 0 0.5  2 1 10 0 5"/>
    </Node>)";
  auto with = [&](const std::string& flags) {
    auto s = test::load(std::regex_replace(scene, std::regex("FLAGS"), flags));
    render::DrawList list;
    render::gather(*s.root, list);
    return std::make_pair(std::move(s), std::move(list));
  };
  {
    auto [s, list] = with("showForceFields");  // the spring within one state only
    ASSERT_EQ(list.used, 1u);
    const render::Batch& b = list.batches[0];
    EXPECT_EQ(b.kind, render::Batch::Kind::lines);
    ASSERT_EQ(b.vertex_count(), 2u);
    // Length 1 below its rest length 2: compressed, orange.
    EXPECT_EQ(std::vector<float>(b.colors.begin(), b.colors.begin() + 4), (std::vector<float>{1, 0.5f, 0, 1}));
    EXPECT_EQ(b.positions[3], 1.f);
  }
  {
    auto [s, list] = with("showInteractionForceFields");  // the two springs between states
    ASSERT_EQ(list.used, 1u);
    const render::Batch& b = list.batches[0];
    ASSERT_EQ(b.vertex_count(), 4u);
    // (0,0,0)–(0,1,0): length 1 over rest 0.5, stretched: green. (3,0,0)–(0,2,0): 3.6 < 5: red.
    EXPECT_EQ(std::vector<float>(b.colors.begin(), b.colors.begin() + 4), (std::vector<float>{0, 1, 0, 1}));
    EXPECT_EQ(std::vector<float>(b.colors.begin() + 8, b.colors.begin() + 12), (std::vector<float>{1, 0, 0, 1}));
  }
}

}  // namespace
}  // namespace sinew

namespace sinew {
namespace {

// RecordedCamera::draw: drawRotation's closed circle of 100 points and four lines to the
// point looked at, drawTranslation's open polyline through cameraPositions, both in
// (0, 1, 0.5) whatever the display flags.
TEST(CameraPathDraw, RotationCircleAndTranslationSegments) {
  auto s = test::load(R"(<Node name="root">
      <RecordedCamera name="cam" drawRotation="1" drawTranslation="1" rotationCenter="0 0 0"
                      rotationStartPoint="0 0 2" rotationLookAt="0 1 0" cameraPositions="0 0 0  1 0 0  1 1 0"/>
    </Node>)");
  render::DrawList list;
  render::gather(*s.root, list);
  std::vector<const render::Batch*> paths;
  for (std::size_t i = 0; i < list.used; ++i)
    if (list.batches[i].source && list.batches[i].source->name.get() == "cam") paths.push_back(&list.batches[i]);
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0]->kind, render::Batch::Kind::lines);
  EXPECT_EQ(paths[0]->vertex_count(), 2u * (100 + 4));
  const render::Batch& t = *paths[1];
  EXPECT_EQ(t.kind, render::Batch::Kind::lines);
  const std::vector<float> expected{0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1, 0};
  EXPECT_EQ(t.positions, expected);
  EXPECT_EQ(t.shading.diffuse, (std::array<float, 4>{0, 1, 0.5f, 1}));

  auto off = test::load(R"(<Node name="root">
      <RecordedCamera name="cam" cameraPositions="0 0 0  1 0 0"/><VisualStyle displayFlags="showAll"/></Node>)");
  render::gather(*off.root, list);
  for (std::size_t i = 0; i < list.used; ++i)
    EXPECT_TRUE(!list.batches[i].source || list.batches[i].source->name.get() != "cam");
}

// The scene's box as SOFA's UpdateBoundingBoxVisitor builds it: a child node with a fixed bbox
// gives its parent that box, not what its subtree holds (its points, however far); nodes
// without one give what they draw.
TEST(SceneBounds, ChildNodeWithFixedBboxGivesItsBoxNotItsContent) {
  const std::string square = R"(<OglModel position="-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0" quads="0 1 2 3"/>)";
  auto s = test::load(R"(<Node name="root"><Node name="a">)" + square + R"(</Node>
      <Node name="boxed" bbox="-3 -2 -1 3 2 1"><OglModel position="40 0 0  41 0 0  41 1 0" triangles="0 1 2"/></Node>
    </Node>)");
  render::DrawList list;
  render::gather(*s.root, list);
  ASSERT_TRUE(list.has_bounds);
  EXPECT_EQ(list.used, 2u);  // both models are drawn
  EXPECT_TRUE(list.min.isApprox(Vec3(-3, -2, -1))) << list.min.transpose();
  EXPECT_TRUE(list.max.isApprox(Vec3(3, 2, 1))) << list.max.transpose();
  // Without the bbox, the far triangle counts.
  auto open = test::load(R"(<Node name="root"><Node name="a">)" + square + R"(</Node>
      <Node name="free"><OglModel position="40 0 0  41 0 0  41 1 0" triangles="0 1 2"/></Node></Node>)");
  render::gather(*open.root, list);
  EXPECT_FLOAT_EQ(list.max[0], 41.f);
  // Points drawn only for want of anything else (no visual model) under a fixed box do not grow it.
  auto points = test::load(R"(<Node name="root"><VisualStyle displayFlags="showBehaviorModels"/>
      <Node name="boxed" bbox="0 0 0 1 1 1">
      <MechanicalObject position="0.5 0.5 0.5  90 0 0"/></Node></Node>)");
  render::gather(*points.root, list);
  ASSERT_EQ(list.used, 1u);
  EXPECT_TRUE(list.max.isApprox(Vec3(1, 1, 1))) << list.max.transpose();
}

// FixedProjectiveConstraint under showBehaviorModels, as SOFA's draw: its fixed DoFs as
// 10-pixel points in (1, 0.5, 0.5) (every DoF with fixAll), lit spheres of radius drawSize in
// (1, 0.35, 0.35) when drawSize > 0; nothing with showObject off or without the flag.
// FixedPlaneProjectiveConstraint: the points between its planes in (1, 1, 0.5).
TEST(ConstraintDraw, FixedDofsAsPointsOrSpheres) {
  auto scene = [](const std::string& flags, const std::string& attrs) {
    return test::load(R"(<Node name="root"><VisualStyle displayFlags=")" + flags + R"("/>
        <MechanicalObject position="0 0 0  1 0 0  2 0 0"/>
        <FixedProjectiveConstraint name="c" )" + attrs + R"(/></Node>)");
  };
  render::DrawList list;
  auto points = scene("showBehaviorModels", R"(indices="0 2")");
  render::gather(*points.root, list);
  const render::Batch* b = drawn_by(list, points.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, render::Batch::Kind::points);
  EXPECT_FLOAT_EQ(b->point_size, 10.f);
  EXPECT_FALSE(b->lit);
  EXPECT_EQ(b->shading.diffuse, (render::Rgba{1.f, 0.5f, 0.5f, 1.f}));
  EXPECT_EQ(b->positions, (std::vector<float>{0, 0, 0, 2, 0, 0}));
  auto all = scene("showBehaviorModels", R"(fixAll="1")");
  render::gather(*all.root, list);
  ASSERT_TRUE((b = drawn_by(list, all.root->find_object_named("c"))));
  EXPECT_EQ(b->vertex_count(), 3u);
  auto spheres = scene("showBehaviorModels", R"(indices="1" drawSize="0.25")");
  render::gather(*spheres.root, list);
  ASSERT_TRUE((b = drawn_by(list, spheres.root->find_object_named("c"))));
  EXPECT_EQ(b->kind, render::Batch::Kind::triangles);
  EXPECT_TRUE(b->lit);
  EXPECT_FLOAT_EQ(b->shading.diffuse[1], 0.35f);
  float lo = 1e9f, hi = -1e9f;
  for (std::size_t i = 0; i < b->positions.size(); i += 3) lo = std::min(lo, b->positions[i]), hi = std::max(hi, b->positions[i]);
  EXPECT_NEAR(lo, 0.75f, 1e-5);
  EXPECT_NEAR(hi, 1.25f, 1e-5);
  auto hidden = scene("showBehaviorModels", R"(indices="0" showObject="0")");
  render::gather(*hidden.root, list);
  EXPECT_FALSE(drawn_by(list, hidden.root->find_object_named("c")));
  auto plane = test::load(R"(<Node name="root"><VisualStyle displayFlags="showBehaviorModels"/>
      <MechanicalObject position="0 0 0  1 0 0  2 0 0"/>
      <FixedPlaneProjectiveConstraint name="c" direction="1 0 0" dmin="0.5" dmax="2.5"/></Node>)");
  render::gather(*plane.root, list);
  ASSERT_TRUE((b = drawn_by(list, plane.root->find_object_named("c"))));
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0, 2, 0, 0}));
  EXPECT_EQ(b->shading.diffuse, (render::Rgba{1.f, 1.f, 0.5f, 1.f}));
  auto off = scene("hideBehaviorModels", R"(indices="0")");
  render::gather(*off.root, list);
  EXPECT_FALSE(drawn_by(list, off.root->find_object_named("c")));
}

// LinearMovementProjectiveConstraint under showBehaviorModels: its DoFs as 10-pixel points;
// with showMovement the segments between consecutive key movements, 10 pixels wide, offset
// by each DoF's first position when relative.
TEST(ConstraintDraw, LinearMovementPointsOrItsPath) {
  auto scene = [](const std::string& attrs) {
    return test::load(R"(<Node name="root" dt="0.1"><VisualStyle displayFlags="showBehaviorModels"/>
        <EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-9" threshold="1e-9"/>
        <MechanicalObject position="0 0 0  1 0 0"/><UniformMass totalMass="1"/>
        <LinearMovementProjectiveConstraint name="c" indices="1" keyTimes="0 1 2" movements="0 0 0  0 1 0  0 1 1" )" +
                      attrs + R"(/></Node>)");
  };
  render::DrawList list;
  auto points = scene("");
  render::gather(*points.root, list);
  const render::Batch* b = drawn_by(list, points.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, render::Batch::Kind::points);
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0}));
  auto absolute = scene(R"(showMovement="1" relativeMovements="0")");
  render::gather(*absolute.root, list);
  ASSERT_TRUE((b = drawn_by(list, absolute.root->find_object_named("c"))));
  EXPECT_EQ(b->kind, render::Batch::Kind::lines);
  EXPECT_FLOAT_EQ(b->line_width, 10.f);
  EXPECT_EQ(b->positions, (std::vector<float>{0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 1}));
  auto relative = scene(R"(showMovement="1")");
  animate(*relative.root);  // the first position is taken at the first projection
  render::gather(*relative.root, list);
  ASSERT_TRUE((b = drawn_by(list, relative.root->find_object_named("c"))));
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0, 1, 1, 0, 1, 1, 0, 1, 1, 1}));
}


// Point, Line, Plane and Direction projective constraints draw as FixedProjectiveConstraint:
// 10-pixel points of their DoFs (every DoF for a point with fixAll), spheres when drawSize > 0.
TEST(ConstraintDraw, PointLinePlaneDirectionMarkTheirDofs) {
  render::DrawList list;
  auto with = [&](const std::string& constraint) {
    return test::load(R"(<Node name="root"><VisualStyle displayFlags="showBehaviorModels"/>
        <MechanicalObject position="0 0 0  1 0 0  2 0 0"/>)" + constraint + "</Node>");
  };
  auto point = with(R"(<PointProjectiveConstraint name="c" fixAll="1"/>)");
  render::gather(*point.root, list);
  const render::Batch* b = drawn_by(list, point.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->kind, render::Batch::Kind::points);
  EXPECT_EQ(b->vertex_count(), 3u);
  auto line = with(R"(<LineProjectiveConstraint name="c" indices="2" direction="1 0 0" drawSize="0.5"/>)");
  render::gather(*line.root, list);
  ASSERT_TRUE((b = drawn_by(list, line.root->find_object_named("c"))));
  EXPECT_EQ(b->kind, render::Batch::Kind::triangles);
  EXPECT_FLOAT_EQ(b->shading.diffuse[1], 0.35f);
  float lo = 1e9f;
  for (std::size_t i = 0; i < b->positions.size(); i += 3) lo = std::min(lo, b->positions[i]);
  EXPECT_NEAR(lo, 1.5f, 1e-5);
  auto plane = with(R"(<PlaneProjectiveConstraint name="c" indices="0 1" normal="0 0 1"/>)");
  render::gather(*plane.root, list);
  ASSERT_TRUE((b = drawn_by(list, plane.root->find_object_named("c"))));
  EXPECT_EQ(b->positions, (std::vector<float>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(b->shading.diffuse, (render::Rgba{1.f, 0.5f, 0.5f, 1.f}));
  auto direction = with(R"(<DirectionProjectiveConstraint name="c" indices="1" direction="0 1 0"/>)");
  render::gather(*direction.root, list);
  ASSERT_TRUE((b = drawn_by(list, direction.root->find_object_named("c"))));
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0}));
}

// AttachProjectiveConstraint: the attached points (10 px) and a line from each source point;
// LinearVelocityProjectiveConstraint: first position + key velocities.
TEST(ConstraintDraw, AttachPairsAndLinearVelocityKeys) {
  render::DrawList list;
  auto attach = test::load(R"(<Node name="root"><VisualStyle displayFlags="showBehaviorModels"/>
      <MechanicalObject position="0 0 0  1 0 0  2 0 0"/>
      <AttachProjectiveConstraint name="c" indices1="0" indices2="2"/></Node>)");
  render::gather(*attach.root, list);
  const Component* c = attach.root->find_object_named("c");
  const render::Batch* points = drawn_by(list, c, 0);
  const render::Batch* lines = drawn_by(list, c, 1);
  ASSERT_TRUE(points && lines);
  // Point 2 was drawn halfway to point 0 by the projection at init (positionFactor 1: ½ of the gap).
  EXPECT_EQ(points->positions, (std::vector<float>{1, 0, 0}));
  EXPECT_EQ(lines->kind, render::Batch::Kind::lines);
  EXPECT_EQ(lines->positions, (std::vector<float>{0, 0, 0, 1, 0, 0}));

  auto velocity = test::load(R"(<Node name="root" dt="0.1"><VisualStyle displayFlags="showBehaviorModels"/>
      <EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-9" threshold="1e-9"/>
      <MechanicalObject position="0 0 0  1 0 0"/><UniformMass totalMass="1"/>
      <LinearVelocityProjectiveConstraint name="c" indices="1" keyTimes="0 1" velocities="0 0 0  1 0 0"/></Node>)");
  render::gather(*velocity.root, list);  // the first position is taken by the projection at init
  const render::Batch* b = drawn_by(list, velocity.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_FLOAT_EQ(b->line_width, 1.f);
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0, 2, 0, 0}));
}

// HermiteSplineProjectiveConstraint: its spline sampled every dt (2 px), its ends (red, 5 px)
// and tangents; ParabolicProjectiveConstraint: its parabola one segment per step through P1,
// P2 and P3, and the three points.
TEST(ConstraintDraw, HermiteSplineAndParabolaPaths) {
  render::DrawList list;
  auto hermite = test::load(R"(<Node name="root" dt="0.25"><VisualStyle displayFlags="showBehaviorModels"/>
      <MechanicalObject position="0 0 0"/>
      <HermiteSplineProjectiveConstraint name="c" indices="0" BeginTime="0" EndTime="1" X0="0 0 0" X1="1 0 0"
          dX0="0 1 0" dX1="0 1 0"/></Node>)");
  render::gather(*hermite.root, list);
  const Component* c = hermite.root->find_object_named("c");
  const render::Batch* curve = drawn_by(list, c, 0);
  const render::Batch* ends = drawn_by(list, c, 1);
  const render::Batch* tangents = drawn_by(list, c, 2);
  ASSERT_TRUE(curve && ends && tangents);
  EXPECT_FLOAT_EQ(curve->line_width, 2.f);
  ASSERT_EQ(curve->vertex_count(), 6u);  // samples at 0, 0.25, 0.5, 0.75: three segments
  // Vertex 3 (the second segment's end) at s = 0.5: X0·½ + dX0·⅛ + X1·½ − dX1·⅛ = (0.5, 0, 0).
  EXPECT_NEAR(curve->positions[9], 0.5f, 1e-6);
  EXPECT_NEAR(curve->positions[10], 0.f, 1e-6);
  EXPECT_EQ(ends->positions, (std::vector<float>{0, 0, 0, 1, 0, 0}));
  EXPECT_FLOAT_EQ(ends->point_size, 5.f);
  EXPECT_EQ(ends->shading.diffuse, (render::Rgba{1.f, 0.f, 0.f, 1.f}));
  EXPECT_EQ(tangents->vertex_count(), 4u);
  EXPECT_NEAR(tangents->positions[4], 0.1f, 1e-6);

  auto parabola = test::load(R"(<Node name="root" dt="0.25"><VisualStyle displayFlags="showBehaviorModels"/>
      <MechanicalObject position="0 0 0"/>
      <ParabolicProjectiveConstraint name="c" indices="0" P1="0 0 0" P2="1 1 0" P3="2 0 0" BeginTime="0" EndTime="1"/>
      </Node>)");
  render::gather(*parabola.root, list);
  c = parabola.root->find_object_named("c");
  const render::Batch* path = drawn_by(list, c, 0);
  const render::Batch* controls = drawn_by(list, c, 1);
  ASSERT_TRUE(path && controls);
  ASSERT_EQ(path->vertex_count(), 8u);
  const std::vector<float>& p = path->positions;
  EXPECT_NEAR(p[0], 0.f, 1e-6);
  EXPECT_NEAR(p[9], 1.f, 1e-6);  // the end of the second segment: r = 0.5 at P2
  EXPECT_NEAR(p[10], 1.f, 1e-6);
  EXPECT_NEAR(p[21], 2.f, 1e-6);  // r = 1 at P3
  EXPECT_NEAR(p[22], 0.f, 1e-6);
  EXPECT_EQ(controls->vertex_count(), 3u);
}

// AffineMovementProjectiveConstraint with drawConstrainedPoints: its DoFs, whatever the flags.
TEST(ConstraintDraw, AffineMovementDrawsItsPointsWithoutFlags) {
  render::DrawList list;
  auto scene = [](const std::string& draw) {
    return test::load(R"(<Node name="root"><VisualStyle displayFlags="hideBehaviorModels"/>
        <MechanicalObject position="0 0 0  1 0 0"/>
        <AffineMovementProjectiveConstraint name="c" indices="1" drawConstrainedPoints=")" + draw + R"("/></Node>)");
  };
  auto shown = scene("1");
  render::gather(*shown.root, list);
  const render::Batch* b = drawn_by(list, shown.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0}));
  auto hidden = scene("0");
  render::gather(*hidden.root, list);
  EXPECT_FALSE(drawn_by(list, hidden.root->find_object_named("c")));
}

// Under showInteractionForceFields: BilateralLagrangianConstraint's pairs as 10-pixel points,
// magenta when active, green when not; SlidingLagrangianConstraint's point and axis; a collision
// response's contacts as 3-pixel lines along the normal from object2's point (white) and against
// it from object1's (0, 0.5, 0.5).
TEST(ConstraintDraw, BilateralPairsAndContacts) {
  render::DrawList list;
  auto scene = [](const std::string& flags, const std::string& activate) {
    return test::load(R"(<Node name="root"><VisualStyle displayFlags=")" + flags + R"("/>
        <MechanicalObject name="a" position="0 0 0  1 0 0"/>
        <Node name="b"><MechanicalObject name="b" position="0 2 0  1 2 0"/></Node>
        <BilateralLagrangianConstraint name="c" object1="@a" object2="@b/b" first_point="1" second_point="0"
            activate=")" + activate + R"("/></Node>)");
  };
  auto active = scene("showInteractionForceFields", "1");
  render::gather(*active.root, list);
  const render::Batch* b = drawn_by(list, active.root->find_object_named("c"));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->positions, (std::vector<float>{1, 0, 0, 0, 2, 0}));
  EXPECT_EQ(b->shading.diffuse, (render::Rgba{1.f, 0.f, 1.f, 1.f}));
  auto inactive = scene("showInteractionForceFields", "0");
  render::gather(*inactive.root, list);
  ASSERT_TRUE((b = drawn_by(list, inactive.root->find_object_named("c"))));
  EXPECT_EQ(b->shading.diffuse, (render::Rgba{0.f, 1.f, 0.f, 1.f}));
  auto hidden = scene("hideInteractionForceFields", "1");
  render::gather(*hidden.root, list);
  EXPECT_FALSE(drawn_by(list, hidden.root->find_object_named("c")));

  // SlidingLagrangianConstraint: point 0 of a sliding on b's segment; green until a build tied
  // it in three directions.
  auto sliding = test::load(R"(<Node name="root"><VisualStyle displayFlags="showInteractionForceFields"/>
      <MechanicalObject name="a" position="0.5 1 0"/>
      <Node name="b"><MechanicalObject name="b" position="0 0 0  1 0 0"/></Node>
      <SlidingLagrangianConstraint name="c" object1="@a" object2="@b/b" sliding_point="0" axis_1="0" axis_2="1"/>
      </Node>)");
  render::gather(*sliding.root, list);
  const Component* sc = sliding.root->find_object_named("c");
  const render::Batch* sp = drawn_by(list, sc, 0);
  const render::Batch* axis = drawn_by(list, sc, 1);
  ASSERT_TRUE(sp && axis);
  EXPECT_EQ(sp->positions, (std::vector<float>{0.5f, 1, 0}));
  EXPECT_EQ(sp->shading.diffuse, (render::Rgba{0.f, 1.f, 0.f, 1.f}));
  EXPECT_EQ(axis->positions, (std::vector<float>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(axis->shading.diffuse, (render::Rgba{0.f, 0.f, 1.f, 1.f}));

  // One contact between point 0 of a and point 1 of b, normal +y.
  auto* s1 = dynamic_cast<MechanicalState*>(active.root->find_object_named("a"));
  auto* s2 = dynamic_cast<MechanicalState*>(active.root->find_child_named("b")->find_object_named("b"));
  ASSERT_TRUE(s1 && s2);
  auto contact = std::make_unique<UnilateralLagrangianConstraint>(*s1, *s2);
  contact->add_contact(0.0, Vec3(0, 1, 0), 0.0, 0, 1, 1, 0);
  const Component* k = active.root->add_object(std::move(contact));
  render::gather(*active.root, list);
  const render::Batch* out = drawn_by(list, k, 0);
  const render::Batch* in = drawn_by(list, k, 1);
  ASSERT_TRUE(out && in);
  EXPECT_FLOAT_EQ(out->line_width, 3.f);
  EXPECT_EQ(out->positions, (std::vector<float>{1, 2, 0, 1, 3, 0}));
  EXPECT_EQ(out->shading.diffuse, (render::Rgba{1.f, 1.f, 1.f, 1.f}));
  EXPECT_EQ(in->positions, (std::vector<float>{0, 0, 0, 0, -1, 0}));
  EXPECT_EQ(in->shading.diffuse, (render::Rgba{0.f, 0.5f, 0.5f, 1.f}));
}

}  // namespace
}  // namespace sinew
