// DataDisplay in the draw list (no OpenGL): the range it updates while drawn,
// its faces coloured through the OglColorMap, per face (own vertices) or per
// point (shared vertices).
#include <gtest/gtest.h>

#include "render/draw_list.h"
#include "test_scene.h"
#include "visual/drawing/data_display.h"

namespace sinew {
namespace {

const render::Batch* batch_of(const render::DrawList& list, const Component* c) {
  for (std::size_t i = 0; i < list.used; ++i)
    if (list.batches[i].source == c) return &list.batches[i];
  return nullptr;
}

std::string scene(const std::string& data) {
  return R"(<Node name="root"><VisualStyle displayFlags="showVisual"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  1 1 0"/>
      <MeshTopology name="mesh" triangles="0 1 2  1 3 2"/>
      <Node name="v"><DataDisplay name="dd" topology="@../mesh" )" +
         data + R"(/><OglColorMap colorScheme="Blue to Red"/>
        <IdentityMapping input="@../dofs" output="@dd"/></Node></Node>)";
}

TEST(DataDisplayDraw, TriangleDataColoursEachFace) {
  auto s = test::load(scene("triangleData='2 -1'"));
  ASSERT_TRUE(s.root);
  auto* dd = test::get<DataDisplay>(*s.root->find_child_named("v"), "dd");
  ASSERT_TRUE(dd);
  render::DrawList list;
  render::gather(*s.root, list);
  const render::Batch* b = batch_of(list, dd);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->kind, render::Batch::Kind::triangles);
  ASSERT_EQ(b->vertex_count(), 6u);  // two faces, three own vertices each
  ASSERT_EQ(b->colors.size(), 24u);
  EXPECT_TRUE(b->indices.empty());
  // Face 0 holds the maximum (red), face 1 the minimum (blue).
  EXPECT_FLOAT_EQ(b->colors[0], 1.f);
  EXPECT_FLOAT_EQ(b->colors[2], 0.f);
  EXPECT_FLOAT_EQ(b->colors[12], 0.f);
  EXPECT_FLOAT_EQ(b->colors[14], 1.f);
  // Drawing wrote the range SOFA's drawVisual writes.
  EXPECT_EQ(dd->current_min.get(), -1.0);
  EXPECT_EQ(dd->current_max.get(), 2.0);
}

TEST(DataDisplayDraw, PointDataSharesTheVertices) {
  auto s = test::load(scene("pointData='0 1 1 0'"));
  ASSERT_TRUE(s.root);
  auto* dd = test::get<DataDisplay>(*s.root->find_child_named("v"), "dd");
  render::DrawList list;
  render::gather(*s.root, list);
  const render::Batch* b = batch_of(list, dd);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->vertex_count(), 4u);
  EXPECT_EQ(b->indices, (std::vector<unsigned>{0, 1, 2, 1, 3, 2}));
  EXPECT_FLOAT_EQ(b->colors[2], 1.f);      // point 0: value 0, blue
  EXPECT_FLOAT_EQ(b->colors[4 + 0], 1.f);  // point 1: value 1, red
}

}  // namespace
}  // namespace sinew
