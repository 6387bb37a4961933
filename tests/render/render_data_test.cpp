// What a picture is made of, without OpenGL: colours, materials, display flags,
// SOFA's normals, cameras and the default view, the draw list.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "render/camera_view.h"
#include "render/draw_list.h"
#include "render/material.h"
#include "test_scene.h"
#include "visual/camera.h"
#include "visual/visual_style.h"

#define SINEW_ALLOC_COUNTER_DECLARE_ONLY
#include "alloc_counter.h"

namespace sinew {
namespace {

using render::parse_color;

TEST(RenderColor, NamesHexAndNumbers) {
  EXPECT_EQ(*parse_color("red"), (render::Rgba{1, 0, 0, 1}));
  EXPECT_EQ(*parse_color("Gray"), (render::Rgba{0.5f, 0.5f, 0.5f, 1}));
  EXPECT_EQ(*parse_color("#00ff00"), (render::Rgba{0, 1, 0, 1}));
  EXPECT_EQ(*parse_color("#f00f"), (render::Rgba{1, 0, 0, 1}));
  EXPECT_EQ(*parse_color("0.1 0.2 0.3"), (render::Rgba{0.1f, 0.2f, 0.3f, 1}));
  EXPECT_EQ(*parse_color(" 1 0.5 0 0.25 "), (render::Rgba{1, 0.5f, 0, 0.25f}));
  EXPECT_FALSE(parse_color("notacolour"));
  EXPECT_FALSE(parse_color("1 2"));
  EXPECT_FALSE(parse_color("#12345"));
}

TEST(RenderMaterial, SofaTextAndSetColor) {
  render::Material m;
  ASSERT_TRUE(render::parse_material(
      "texture Diffuse 1 0.5 0.4 0.3 1 Ambient 1 0.1 0.1 0.1 1 Specular 1 1 1 1 1 Emissive 0 0 0 0 0 Shininess 1 20",
      m));
  EXPECT_FLOAT_EQ(m.diffuse[0], 0.5f);
  EXPECT_TRUE(m.use_specular);
  EXPECT_FALSE(m.use_emissive);
  EXPECT_FLOAT_EQ(m.shininess, 20.f);
  const render::Shading s = render::shading_of(m);
  EXPECT_FLOAT_EQ(s.specular[0], 1.f);
  EXPECT_FLOAT_EQ(s.emissive[0], 0.f);  // not used
  EXPECT_FLOAT_EQ(s.shininess, 20.f);

  // OglModel's color: Material::setColor (ambient 0.2·c); specular stays off by its flag.
  render::Material d;
  d.set_color({1, 0, 0, 1});
  const render::Shading ds = render::shading_of(d);
  EXPECT_FLOAT_EQ(ds.diffuse[0], 1.f);
  EXPECT_FLOAT_EQ(ds.ambient[0], 0.2f);
  EXPECT_FLOAT_EQ(ds.specular[0], 0.f);
  EXPECT_FLOAT_EQ(ds.shininess, 45.f);
}

TEST(RenderDisplayFlags, TreeInheritanceAndCase) {
  std::vector<std::string> warnings;
  auto warn = [&](const std::string& w) { warnings.push_back(w); };
  const DisplayFlags f = DisplayFlags::parse("showBehavior hideForceFields showWireFrame bogus", warn);
  EXPECT_TRUE(f.shown(DisplayFlags::behavior_models));
  EXPECT_TRUE(f.shown(DisplayFlags::interaction_force_fields));
  EXPECT_EQ(f.leaf[DisplayFlags::force_fields], DisplayFlags::State::hidden);  // later word wins
  EXPECT_TRUE(f.shown(DisplayFlags::wireframe));
  EXPECT_EQ(f.leaf[DisplayFlags::visual_models], DisplayFlags::State::neutral);
  ASSERT_EQ(warnings.size(), 2u);  // wrong case, unknown word
  EXPECT_NE(warnings[0].find("wrong case"), std::string::npos);
  EXPECT_NE(warnings[1].find("bogus"), std::string::npos);

  auto s = test::load(R"(<Node name="root">
      <VisualStyle displayFlags="showBehaviorModels"/>
      <Node name="a"><VisualStyle displayFlags="hideVisualModels"/><Node name="b"/></Node>
      <Node name="c"/>
    </Node>)");
  Node& a = *s.root->find_child_named("a");
  const DisplayFlags at_b = display_flags_at(*a.find_child_named("b"));
  EXPECT_FALSE(at_b.shown(DisplayFlags::visual_models));
  EXPECT_TRUE(at_b.shown(DisplayFlags::behavior_models));
  const DisplayFlags at_c = display_flags_at(*s.root->find_child_named("c"));
  EXPECT_TRUE(at_c.shown(DisplayFlags::visual_models));  // the viewer's default
  EXPECT_FALSE(at_c.shown(DisplayFlags::force_fields));
}

// VisualModelImpl::computeNormals: unnormalised face normals summed, quads per corner.
TEST(RenderNormals, SofaAreaWeightedSum) {
  // Two triangles sharing vertex 0: a big one in the xy plane, a small one in the xz plane.
  const std::vector<float> x = {0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 0.5f, 0.5f, 0, 0};
  const std::vector<Triangle> tris = {{0, 1, 2}, {0, 4, 3}};
  std::vector<float> n;
  render::compute_normals(x, tris, {}, n);
  // Vertex 0: (0,0,4) + (0,-0.25,0) normalised.
  const Vec3 n0 = Vec3(0, -0.25, 4).normalized();
  EXPECT_NEAR(n[0], n0[0], 1e-6);
  EXPECT_NEAR(n[1], n0[1], 1e-6);
  EXPECT_NEAR(n[2], n0[2], 1e-6);
  EXPECT_NEAR(n[5], 1.0, 1e-6);  // vertex 1: (0,0,1)

  // A unit quad, counter-clockwise seen from +z: every corner's normal is +z.
  const std::vector<float> q = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  render::compute_normals(q, {}, {Quad{0, 1, 2, 3}}, n);
  for (int v = 0; v < 4; ++v) EXPECT_NEAR(n[v * 3 + 2], 1.0, 1e-6) << v;
}

// A seam: vertices 0 and 3 are the same point split by a texture seam; with vertNormIdx
// naming them one normal, both get the sum of both faces (SOFA's second branch).
TEST(RenderNormals, SeamVerticesShareTheirNormalIndex) {
  const std::vector<float> x = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
  const std::vector<Triangle> tris = {{0, 1, 2}, {3, 4, 1}};  // xy plane (+z), xz plane (−y·…)
  std::vector<float> split, shared;
  render::compute_normals(x, tris, {}, split);
  EXPECT_NEAR(split[2], 1.0, 1e-6);  // vertex 0: only its own face
  const std::vector<unsigned> idx = {0, 1, 2, 0, 4};
  render::compute_normals(x, tris, {}, shared, &idx);
  const Vec3 n0 = (Vec3(0, 0, 1) + Vec3(0, 0, 1).cross(Vec3(1, 0, 0))).normalized();
  for (int v : {0, 3})
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shared[v * 3 + c], n0[c], 1e-6) << v;
}

TEST(RenderCamera, LookAtGivesOrientationAndDefaultViewAlongMinusZ) {
  auto s = test::load(R"(<Node name="root" gravity="0 -9.81 0">
      <InteractiveCamera name="cam" position="0 0 10" lookAt="0 0 0"/>
    </Node>)");
  auto* cam = test::get<InteractiveCamera>(*s.root, "cam");
  ASSERT_TRUE(cam);
  EXPECT_FALSE(cam->wants_default_view());
  EXPECT_NEAR(cam->distance.get(), 10.0, 1e-12);
  const Mat3 r = quat_matrix(cam->orientation.get());
  EXPECT_TRUE(r.isApprox(Mat3::Identity(), 1e-9)) << r;  // looking along −z, y up
  const render::View v = render::view_for(*s.root, Vec3(-1, -1, -1), Vec3(1, 1, 1), 100, 100);
  EXPECT_TRUE(v.from_scene_camera);
  EXPECT_TRUE(v.eye.isApprox(Vec3(0, 0, 10)));

  // No camera: SOFA's setDefaultView, up = −gravity, 3 half-diagonals from the centre.
  auto d = test::load(R"(<Node name="root" gravity="0 0 -9.81"/>)");
  const render::View dv = render::view_for(*d.root, Vec3(0, 0, 0), Vec3(2, 2, 2), 100, 100);
  EXPECT_FALSE(dv.from_scene_camera);
  EXPECT_TRUE(dv.eye.isApprox(Vec3(1, 1 - 3 * std::sqrt(3.0), 1), 1e-9)) << dv.eye.transpose();
  // The centre of the box projects to the centre of the picture.
  const Eigen::Vector4f c = dv.projection * dv.view * Eigen::Vector4f(1, 1, 1, 1);
  EXPECT_NEAR(c.x() / c.w(), 0.0, 1e-5);
  EXPECT_NEAR(c.y() / c.w(), 0.0, 1e-5);
  // Up in the picture is −gravity (+z).
  const Eigen::Vector4f top = dv.projection * dv.view * Eigen::Vector4f(1, 1, 1.5f, 1);
  EXPECT_GT(top.y() / top.w(), 0.1f);

  // Position and orientation without lookAt: lookAt = position + R·(0,0,−distance).
  auto q = test::load(R"(<Node name="root">
      <InteractiveCamera name="cam" position="1 2 3" orientation="0 0 0 1" distance="4"/>
    </Node>)");
  EXPECT_TRUE(test::get<InteractiveCamera>(*q.root, "cam")->look_at.get().isApprox(Vec3(1, 2, -1)));
}

const char* kTwoModels = R"(<Node name="root">
    <VisualStyle displayFlags="showVisual showBehaviorModels"/>
    <Node name="red"><OglModel name="m" color="red" position="0 0 0 1 0 0 1 1 0" triangles="0 1 2"/></Node>
    <Node name="hidden"><VisualStyle displayFlags="hideVisualModels"/>
      <OglModel name="m" position="0 0 5 1 0 5 1 1 5" triangles="0 1 2"/></Node>
    <Node name="body"><MechanicalObject position="0 0 0  3 0 0" showObject="1"/></Node>
    <Node name="other"><MechanicalObject position="0 0 0"/></Node>
  </Node>)";

TEST(RenderDrawList, FlagsChooseBatchesAndFramesAllocateNothing) {
  auto s = test::load(kTwoModels);
  render::DrawList list;
  render::gather(*s.root, list);
  // The red triangle and the body's points (showObject); the hidden model is skipped, and so
  // are the points of the other state since a surface is drawn.
  ASSERT_EQ(list.used, 2u);
  EXPECT_EQ(list.batches[0].kind, render::Batch::Kind::triangles);
  EXPECT_FLOAT_EQ(list.batches[0].shading.diffuse[0], 1.f);
  EXPECT_EQ(list.batches[0].indices.size(), 3u);
  EXPECT_EQ(list.batches[1].kind, render::Batch::Kind::points);
  EXPECT_EQ(list.batches[1].vertex_count(), 2u);
  EXPECT_TRUE(list.min.isApprox(Vec3(0, 0, 0)));
  EXPECT_TRUE(list.max.isApprox(Vec3(3, 1, 0)));
#if SINEW_COUNT_ALLOCATIONS
  const long before = test::g_allocations.load();
  render::gather(*s.root, list);
  const render::View v = render::view_for(*s.root, list.min, list.max, 64, 64);
  EXPECT_EQ(test::g_allocations.load() - before, 0) << "a second frame allocated";
  (void)v;
#endif

  // Nothing but bodies under showBehaviorModels: their points are drawn.
  auto b = test::load(R"(<Node name="root"><VisualStyle displayFlags="showBehaviorModels"/>
      <MechanicalObject position="0 0 0  1 1 1"/></Node>)");
  render::gather(*b.root, list);
  ASSERT_EQ(list.used, 1u);
  EXPECT_EQ(list.batches[0].kind, render::Batch::Kind::points);
}

}  // namespace
}  // namespace sinew
