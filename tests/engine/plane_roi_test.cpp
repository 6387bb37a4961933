// PlaneROI: a slab over the unit square p0 (0,0,0), p1 (1,0,0), p2 (1,1,0),
// 0.2 thick (|z| <= 0.1): hand-checked membership of points and edges.
#include <gtest/gtest.h>

#include "core/engine.h"
#include "test_scene.h"

namespace sinew {
namespace {

TEST(PlaneROI, SelectsThePointsAndElementsInsideTheSlab) {
  const std::string xml = R"(<Node name="root">
    <MechanicalObject position="0.5 0.5 0  0.5 0.5 0.15  1.5 0.5 0  0.5 0.5 -0.05  0 0 0  0.5 -0.2 0"/>
    <MeshTopology edges="0 3  0 1  3 4  2 4" triangles="0 3 4  0 1 4"/>
    <PlaneROI name="roi" plane="0 0 0  1 0 0  1 1 0  0.2"/>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  Component* roi = s.root->find_object_named("roi");
  ASSERT_NE(roi, nullptr);
  auto get = [&](const char* name) {
    auto* f = dynamic_cast<Field<std::vector<unsigned>>*>(roi->find_field(name));
    return f ? f->get() : std::vector<unsigned>{99};
  };
  EXPECT_EQ(get("indices"), (std::vector<unsigned>{0, 3, 4}));
  EXPECT_EQ(get("edgeIndices"), (std::vector<unsigned>{0, 2}));  // edges with both ends inside
  EXPECT_EQ(get("triangleIndices"), (std::vector<unsigned>{0}));
}

TEST(PlaneROI, SeveralSlabsAndBadPlaneSize) {
  const std::string xml = R"(<Node name="root">
    <MechanicalObject position="0.5 0.5 0  5.5 0.5 0"/>
    <PlaneROI name="roi" plane="0 0 0  1 0 0  1 1 0  0.2   5 0 0  6 0 0  6 1 0  0.2"/>
  </Node>)";
  scene::LoadedScene s = test::load(xml);
  ASSERT_TRUE(s.root);
  auto* f = dynamic_cast<Field<std::vector<unsigned>>*>(s.root->find_object_named("roi")->find_field("indices"));
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->get(), (std::vector<unsigned>{0, 1}));

  scene::LoadedScene bad = test::build(R"(<Node name="root"><MechanicalObject position="0 0 0"/>
    <PlaneROI plane="0 0 0  1 0 0  1 1"/></Node>)");
  ASSERT_TRUE(bad.root);
  init_root(*bad.root);
  EXPECT_FALSE(test::messages(bad.root->diagnostics(), Severity::error).empty());
}

}  // namespace
}  // namespace sinew
