// TriangleBendingSprings: which springs it builds (one across each shared
// edge, quads split along their first diagonal, SOFA's rule for an edge shared
// three times), their rest lengths and coefficients, and SOFA's example.
#include <gtest/gtest.h>

#include <cmath>

#include "badinput_helpers.h"
#include "core/node.h"
#include "forcefield/spring/triangle_bending_springs.h"
#include "test_scene.h"
#include "test_paths.h"

namespace sinew {
namespace {

std::vector<std::pair<unsigned, unsigned>> pairs(const SpringForceField& s) {
  std::vector<std::pair<unsigned, unsigned>> out;
  for (const auto& sp : s.spring_list()) out.emplace_back(sp.m1, sp.m2);
  return out;
}

TEST(TriangleBendingSprings, OneSpringAcrossEachSharedEdge) {
  auto s = test::load("<Node><MechanicalObject name='dofs' position='0 0 0  1 0 0  0 1 0  1 1 0.5'/>"
                      "<MeshTopology triangles='0 1 2  1 3 2'/>"
                      "<TriangleBendingSprings name='b' stiffness='30' damping='0.5'/></Node>");
  auto* b = test::get<TriangleBendingSprings>(*s.root, "b");
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->spring_list().size(), 1u);
  // Second triangle's edge (3, 2) meets the first's: opposite 1 of the new edge... the edge
  // (1, 2) is shared: its opposite vertices are 0 (first) and 3 (second): spring (3, 0).
  EXPECT_EQ(pairs(*b), (std::vector<std::pair<unsigned, unsigned>>{{3, 0}}));
  EXPECT_DOUBLE_EQ(b->spring_list()[0].l0, std::sqrt(2.25));
  EXPECT_EQ(b->spring_list()[0].ks, 30.0);
  EXPECT_EQ(b->spring_list()[0].kd, 0.5);
}

TEST(TriangleBendingSprings, QuadsAreSplitAndEdgesSharedThriceLinkToTheFirst) {
  // Two quads: inside each, the diagonal (0, 2) gives a spring; the shared edge (1, 4) another.
  auto s = test::load("<Node><MechanicalObject name='dofs' position='0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0'/>"
                      "<MeshTopology quads='0 1 4 3  1 2 5 4'/><TriangleBendingSprings name='b'/></Node>");
  auto* b = test::get<TriangleBendingSprings>(*s.root, "b");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->spring_list().size(), 3u);
  EXPECT_EQ(b->spring_list()[0].ks, 100.0);  // defaults
  EXPECT_EQ(b->spring_list()[0].kd, 5.0);
  // Three triangles on the edge (0, 1): the second and the third both link to the first's opposite.
  auto fan = test::load("<Node><MechanicalObject name='dofs' position='0 0 0  1 0 0  0 1 0  0 -1 0  0 0 1'/>"
                        "<MeshTopology triangles='0 1 2  1 0 3  0 1 4'/><TriangleBendingSprings name='b'/></Node>");
  EXPECT_EQ(pairs(*test::get<TriangleBendingSprings>(*fan.root, "b")),
            (std::vector<std::pair<unsigned, unsigned>>{{3, 2}, {4, 2}}));
}

TEST(TriangleBendingSprings, ExampleScenesRun100Steps) {
  for (const char* rel : {"Component/SolidMechanics/Spring/TriangleBendingSprings.scn"}) {
    const test::Outcome o = test::run_sofa_example(rel, 100);
    if (!o.loaded) GTEST_SKIP() << "SOFA data not found at " << SINEW_DATA_DIR;
    EXPECT_EQ(o.steps, 100) << o.all();
    EXPECT_TRUE(o.errors.empty()) << o.all();
    EXPECT_TRUE(o.finite);
  }
}

}  // namespace
}  // namespace sinew
