// SubsetTopologicalMapping: the maps it builds at init between a topology and
// a part of it (same points, or points paired by position), and the output
// following the input's removals.
#include "topology/mapping/subset_topological_mapping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "badinput_helpers.h"
#include "runner/session.h"
#include "test_paths.h"
#include "topology/dynamic/triangle_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;

namespace {

constexpr unsigned kNone = SubsetTopologicalMapping::kNone;

// A strip of six points and four triangles:
//   1---3---5
//   | \ | \ |      triangles 0 (0 1 2), 1 (1 3 2), 2 (2 3 4), 3 (3 5 4)
//   0---2---4
const char* kStrip = R"(position="0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0" triangles="0 1 2  1 3 2  2 3 4  3 5 4")";

std::string strip_scene(const std::string& output_topology, const std::string& mapping_attrs) {
  return std::string("<Node><DefaultAnimationLoop/>"
                     "<TriangleSetTopologyContainer name='src' ") +
         kStrip +
         "/><TriangleSetTopologyModifier name='mod'/>"
         "<Node name='part'><TriangleSetTopologyContainer name='out' " +
         output_topology +
         "/><TriangleSetTopologyModifier/>"
         "<SubsetTopologicalMapping name='map' input='@../src' output='@out' " +
         mapping_attrs + "/></Node></Node>";
}

}  // namespace

// Same points: triangles pair by their vertices whatever their order in the triangle.
TEST(SubsetTopologicalMapping, SamePointsPairsTrianglesByVertices) {
  auto s = test::load(strip_scene(R"(position="0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0" triangles="4 3 2  0 2 1")",
                            "samePoints='1' handleTriangles='1'"));
  ASSERT_TRUE(s.root);
  auto* map = get<SubsetTopologicalMapping>(*s.root->find_child_named("part"), "map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2, 0}));
  EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{1, kNone, 0, kNone}));
  EXPECT_TRUE(map->point_s2d.value().empty());  // samePoints: no point maps
  EXPECT_TRUE(map->edge_s2d.value().empty());   // edges not handled
  std::vector<unsigned> in;
  ASSERT_TRUE(map->input_elements(1, in));
  EXPECT_EQ(in, (std::vector<unsigned>{0}));
}

// Other points: each output point pairs with the input point at the same position, and the
// triangles pair through that map.
TEST(SubsetTopologicalMapping, PointsPairByPosition) {
  auto s = test::load(strip_scene(R"(position="2 0 0  1 0 0  1 1 0" triangles="1 2 0")", "handleTriangles='1'"));
  ASSERT_TRUE(s.root);
  auto* map = get<SubsetTopologicalMapping>(*s.root->find_child_named("part"), "map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->point_d2s.value(), (std::vector<unsigned>{4, 2, 3}));
  EXPECT_EQ(map->point_s2d.value(), (std::vector<unsigned>{kNone, kNone, 1, 2, 0, kNone}));
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2}));
  EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{kNone, kNone, 0, kNone}));
}

TEST(SubsetTopologicalMapping, UnpairedTriangleIsReported) {
  auto s = test::load(strip_scene(R"(position="0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0" triangles="0 1 4")",
                            "samePoints='1' handleTriangles='1'"));
  ASSERT_TRUE(s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("Triangle 0 not found in source topology"), std::string::npos) << errors[0];
  auto* map = get<SubsetTopologicalMapping>(*s.root->find_child_named("part"), "map");
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{kNone}));
}

// The input loses triangle 2, whose partner leaves the output; the input's last triangle (3)
// takes slot 2 and its partner follows it in the maps.
TEST(SubsetTopologicalMapping, RemovedInputTrianglesLeaveTheOutput) {
  auto s = test::load(strip_scene(R"(position="0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0" triangles="2 3 4  3 5 4")",
                            "samePoints='1' handleTriangles='1'"));
  ASSERT_TRUE(s.root);
  Node& part = *s.root->find_child_named("part");
  auto* map = get<SubsetTopologicalMapping>(part, "map");
  auto* out = get<TriangleSetTopologyContainer>(part, "out");
  auto* mod = get<TriangleSetTopologyModifier>(*s.root, "mod");
  ASSERT_TRUE(map && out && mod);
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2, 3}));

  mod->remove_triangles({2}, true, false);
  ASSERT_EQ(out->triangles().size(), 1u);
  EXPECT_EQ(out->triangles()[0], (Triangle{3, 5, 4}));
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2}));
  EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{kNone, kNone, 0}));

  // A triangle outside the subset goes: the output keeps its triangle, the maps follow the swap.
  mod->remove_triangles({0}, true, false);  // input: slot 0 takes triangle 2 (the subset's)
  ASSERT_EQ(out->triangles().size(), 1u);
  EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{0}));
  EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{0, kNone}));
}

// Triangles added to the input join the output when all their points are in it: with
// samePoints every point is; on a subset of points, only those over its points.
TEST(SubsetTopologicalMapping, AddedInputTrianglesJoinTheOutputWhenTheirPointsAreIn) {
  {
    auto s = test::load(strip_scene(R"(position="0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0" triangles="2 3 4")",
                                    "samePoints='1' handleTriangles='1'"));
    ASSERT_TRUE(s.root);
    Node& part = *s.root->find_child_named("part");
    auto* map = get<SubsetTopologicalMapping>(part, "map");
    auto* out = get<TriangleSetTopologyContainer>(part, "out");
    get<TriangleSetTopologyModifier>(*s.root, "mod")->add_triangles({Triangle{0, 2, 4}});
    ASSERT_EQ(out->triangles().size(), 2u);
    EXPECT_EQ(out->triangles()[1], (Triangle{0, 2, 4}));
    EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2, 4}));
    EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{kNone, kNone, 0, kNone, 1}));
  }
  {
    // Output points: input points 4, 2, 3.
    auto s = test::load(strip_scene(R"(position="2 0 0  1 0 0  1 1 0" triangles="1 2 0")", "handleTriangles='1'"));
    ASSERT_TRUE(s.root);
    Node& part = *s.root->find_child_named("part");
    auto* map = get<SubsetTopologicalMapping>(part, "map");
    auto* out = get<TriangleSetTopologyContainer>(part, "out");
    auto* mod = get<TriangleSetTopologyModifier>(*s.root, "mod");
    mod->add_triangles({Triangle{0, 2, 4}});  // point 0 is not in the subset
    EXPECT_EQ(out->triangles().size(), 1u);
    mod->add_triangles({Triangle{4, 3, 2}});  // the subset's own points, in output numbering 0 2 1
    ASSERT_EQ(out->triangles().size(), 2u);
    EXPECT_EQ(out->triangles()[1], (Triangle{0, 2, 1}));
    EXPECT_EQ(map->triangle_d2s.value(), (std::vector<unsigned>{2, 5}));
    EXPECT_EQ(map->triangle_s2d.value(), (std::vector<unsigned>{kNone, kNone, 0, kNone, kNone, 1}));
  }
}

// SOFA's two example scenes: a sphere whose two halves are subsets of its surface (the second
// one with handleTriangles, FEM and bending springs on each half). Every triangle of each half
// pairs with the sphere's triangle of the same vertices; 100 steps run with finite states.
TEST(SubsetTopologicalMapping, SofaExamplesPairEveryTriangleAndRun) {
  namespace fs = std::filesystem;
  const fs::path data = SINEW_DATA_DIR;
  for (const char* rel : {"Component/Topology/Mapping/SubsetTopologicalMapping.scn",
                          "Component/Topology/Mapping/SubsetTopologicalMapping2.scn"}) {
    if (!fs::exists(data / "examples" / rel)) GTEST_SKIP() << "SOFA data not found at " << data;
    runner::SessionOptions opts;
    opts.data_paths = {(data / "share").string(), (data / "examples").string()};
    runner::Session session((data / "examples" / rel).string(), opts);
    ASSERT_TRUE(session.ok()) << rel;
    std::vector<SubsetTopologicalMapping*> maps;
    session.root().collect_down(maps);
    ASSERT_EQ(maps.size(), 2u) << rel;
    for (SubsetTopologicalMapping* m : maps) {
      const auto& src = m->input->triangles();
      const auto& dst = m->output->triangles();
      ASSERT_GT(dst.size(), 50u);
      ASSERT_LT(dst.size(), src.size());
      EXPECT_EQ(m->output->nb_points(), m->input->nb_points());
      if (!m->handle_triangles.value()) continue;
      ASSERT_EQ(m->triangle_d2s.value().size(), dst.size());
      for (std::size_t d = 0; d < dst.size(); ++d) {
        const unsigned s = m->triangle_d2s.value()[d];
        ASSERT_LT(s, src.size()) << rel << " output triangle " << d;
        Triangle a = dst[d], b = src[s];
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_EQ(a, b) << rel << " output triangle " << d;
        EXPECT_EQ(m->triangle_s2d.value()[s], d);
      }
    }
    for (int i = 0; i < 100; ++i) ASSERT_TRUE(session.step()) << rel << " step " << i;
    EXPECT_TRUE(test::all_finite(session.root())) << rel;
    const auto errors = test::messages(session.diagnostics(), Severity::error);
    EXPECT_TRUE(errors.empty()) << errors.front();
  }
}
