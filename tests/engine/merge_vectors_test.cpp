// MergeVectors and MergeMeshes (SOFA's Engine/Generate): numbered inputs
// created from nbInputs / nbMeshes, concatenation, index shifts.
#include <gtest/gtest.h>

#include "engine/merge_meshes.h"
#include "engine/merge_vectors.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using D = std::vector<double>;
using I = std::vector<int>;
}  // namespace

TEST(MergeVectors, ConcatenatesInputsInOrder) {
  auto s = load(R"(<Node>
    <MergeVectors name="two" input1="1 2" input2="3"/>
    <MergeVectors name="four" template="Data<int>" nbInputs="4" input1="4" input3="7 8" input4="9" input2="5 6"/>
  </Node>)");
  auto* two = get<MergeVectors<D>>(*s.root, "two");
  ASSERT_TRUE(two);
  EXPECT_EQ(two->output.get(), (D{1, 2, 3}));
  two->inputs[0].set(D{});
  EXPECT_EQ(two->output.get(), (D{3}));
  auto* four = get<MergeVectors<I>>(*s.root, "four");
  ASSERT_TRUE(four);
  EXPECT_EQ(four->output.get(), (I{4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(four->output.text(), "4 5 6 7 8 9");
}

TEST(MergeVectors, DoubleTemplateFlattensLinkedPointLists) {
  // SOFA's MergeVectors.scn: Data<double> fed with positions gives the flat coordinate list.
  auto s = load(R"(<Node>
    <MechanicalObject name="a" position="0 1 2  3 4 5"/>
    <MechanicalObject name="b" position="6 7 8"/>
    <MergeVectors template="Data<double>" name="m" nbInputs="2" input1="@a.position" input2="@b.position"/>
    <Node><MechanicalObject name="c" position="@../m.output"/></Node>
  </Node>)");
  auto* m = get<MergeVectors<D>>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->output.get(), (D{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(MergeVectors, ReportsInputsBeyondTheCountAndHugeCounts) {
  Diagnostics tree;
  auto s = test::build(R"(<Node>
    <MergeVectors name="one" nbInputs="1" input1="1" input2="2"/>
    <MergeVectors name="huge" nbInputs="4000000000" input1="1"/>
  </Node>)",
                       &tree);
  init_root(*s.root);
  auto* one = get<MergeVectors<D>>(*s.root, "one");
  ASSERT_TRUE(one);
  EXPECT_EQ(one->output.get(), (D{1}));
  auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  auto more = test::messages(tree, Severity::warning);
  warnings.insert(warnings.end(), more.begin(), more.end());
  EXPECT_TRUE(test::any_contains(warnings, "attribute 'input2' ignored: nbInputs is 1"));
  auto errors = test::messages(s.root->diagnostics(), Severity::error);
  auto more_e = test::messages(tree, Severity::error);
  errors.insert(errors.end(), more_e.begin(), more_e.end());
  EXPECT_TRUE(test::any_contains(errors, "nbInputs = 4000000000 is more than the 1024 inputs supported"));
  auto* huge = get<MergeVectors<D>>(*s.root, "huge");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->output.get().size(), 1u);
  huge->nb_inputs.set(5000);
  EXPECT_EQ(huge->output.get().size(), 1u);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error),
                                 "nbInputs = 5000 but only 1024 inputs exist"));
}

TEST(MergeMeshes, ShiftsElementIndicesByThePointsBefore) {
  auto s = load(R"(<Node>
    <MergeMeshes name="m" nbMeshes="3"
      position1="0 0 0  1 0 0  0 1 0" triangles1="0 1 2" edges1="0 1"
      position2="5 5 5  6 5 5" edges2="0 1"
      position3="9 9 9  8 9 9  9 8 9  9 9 8" tetrahedra3="0 1 2 3" quads3="3 2 1 0"/>
  </Node>)");
  auto* m = get<MergeMeshes>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->npoints.get(), 9u);
  EXPECT_EQ(m->position.get().data, (D{0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 6, 5, 5, 9, 9, 9, 8, 9, 9, 9, 8, 9, 9, 9, 8}));
  EXPECT_EQ(m->out_edges.get(), (std::vector<Edge>{{0, 1}, {3, 4}}));
  EXPECT_EQ(m->out_triangles.get(), (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(m->out_quads.get(), (std::vector<Quad>{{8, 7, 6, 5}}));
  EXPECT_EQ(m->out_tetrahedra.get(), (std::vector<Tetra>{{5, 6, 7, 8}}));
  EXPECT_TRUE(m->out_hexahedra.get().empty());
  m->positions[0].set(FlatVec{3, {0, 0, 0}});  // mesh 2 now starts at point 1
  EXPECT_EQ(m->out_edges.get(), (std::vector<Edge>{{0, 1}, {1, 2}}));
}

TEST(MergeMeshes, FeedsATopologyAndReportsBadIndices) {
  auto s = test::build(R"(<Node>
    <MergeMeshes name="m" position1="0 0 0  1 0 0" edges1="0 7" position2="2 0 0" triangles2="0 0 0"/>
    <MeshTopology name="t" src="@m"/>
  </Node>)");
  init_root(*s.root);
  auto* m = get<MergeMeshes>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->out_edges.get(), (std::vector<Edge>{{0, 7}}));  // kept, as SOFA
  EXPECT_EQ(m->out_triangles.get(), (std::vector<Triangle>{{2, 2, 2}}));
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning),
                                 "edges1 has index 7, beyond the 2 points of position1"));
}
