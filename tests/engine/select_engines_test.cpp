// Engine/Select: MeshROI, MeshBoundaryROI, NearestPointROI, ProximityROI,
// MeshSubsetEngine, MeshSplittingEngine, MeshSampler, ValuesFromPositions,
// on inputs whose outputs are computed by hand in the comments.
#include <gtest/gtest.h>

#include "engine/select/mesh_boundary_roi.h"
#include "engine/select/mesh_roi.h"
#include "engine/select/mesh_sampler.h"
#include "engine/select/mesh_splitting_engine.h"
#include "engine/select/mesh_subset_engine.h"
#include "engine/select/nearest_point_roi.h"
#include "engine/select/proximity_roi.h"
#include "engine/select/values_from_positions.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using Idx = std::vector<unsigned>;
using D = std::vector<double>;
const char* kCubePoints = "0 0 0  1 0 0  0 1 0  1 1 0  0 0 1  1 0 1  0 1 1  1 1 1";
const char* kCubeTriangles = "0 2 3  0 3 1  4 5 7  4 7 6  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  0 6 2  1 3 7  1 7 5";
const char* kOpenCubeTriangles = "0 2 3  0 3 1  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  0 6 2  1 3 7  1 7 5";
}  // namespace

// Points against the unit cube: (0.3,0.6,0.45) casts its ray towards the nearer
// corner (0,0,0) − 100 and leaves through face x = 0 once (inside); (0.8,0.1,0.3)
// leaves through y = 0 once (inside); (2,0.5,0.5) is outside the box.
// Non-strict by default: the edge 0-1 has one vertex out, its centre (1.15,0.55,0.475)
// is outside; the edge 0-2 has both vertices in.
TEST(MeshROI, PointsInsideAClosedMesh) {
  auto s = load(std::string("<Node><MeshROI name=\"r\" position=\"0.3 0.6 0.45  2 0.5 0.5  0.8 0.1 0.3\" "
                            "edges=\"0 1  0 2\" ROIposition=\"") +
                kCubePoints + "\" ROItriangles=\"" + kCubeTriangles + "\"/></Node>");
  auto* r = get<MeshROI>(*s.root, "r");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->indices.get(), (Idx{0, 2}));
  EXPECT_EQ(r->indices_out.get(), (Idx{1}));
  EXPECT_EQ(r->edge_indices.get(), (Idx{1}));
  EXPECT_EQ(r->box.get(), (VecN<6>() << 0, 0, 0, 1, 1, 1).finished());
  EXPECT_FALSE(r->strict.get());
  // computeMeshROI = false: every point is in.
  auto s2 = load(std::string("<Node><MeshROI name=\"r\" computeMeshROI=\"0\" position=\"0.3 0.6 0.45  2 0.5 0.5\" "
                             "ROIposition=\"") +
                 kCubePoints + "\" ROItriangles=\"" + kCubeTriangles + "\"/></Node>");
  EXPECT_EQ(get<MeshROI>(*s2.root, "r")->indices.get(), (Idx{0, 1}));
}

// The open cube's border is the square 4 5 7 6 (sorted); with inputROI, only the
// triangles of the bottom face (vertices 0..3) count: its border is 0 1 2 3.
TEST(MeshBoundaryROI, BorderOfAnOpenCube) {
  auto s = load(std::string("<Node><MeshBoundaryROI name=\"b\" triangles=\"") + kOpenCubeTriangles +
                "\"/><MeshBoundaryROI name=\"c\" triangles=\"" + kOpenCubeTriangles +
                "\" inputROI=\"0 1 2 3\"/><MeshBoundaryROI name=\"d\" triangles=\"" + kCubeTriangles + "\"/></Node>");
  EXPECT_EQ(get<MeshBoundaryROI>(*s.root, "b")->indices.get(), (Idx{4, 5, 6, 7}));
  EXPECT_EQ(get<MeshBoundaryROI>(*s.root, "c")->indices.get(), (Idx{0, 1, 2, 3}));
  EXPECT_TRUE(get<MeshBoundaryROI>(*s.root, "d")->indices.get().empty());
}

// The node's topology supplies the quads when none are given (a square of two quads: border = all 6 points).
TEST(MeshBoundaryROI, TakesTheNodesTopology) {
  auto s = load(R"(<Node><MeshTopology position="0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0" quads="0 1 4 3  1 2 5 4"/>
                   <MeshBoundaryROI name="b"/></Node>)");
  EXPECT_EQ(get<MeshBoundaryROI>(*s.root, "b")->indices.get(), (Idx{0, 1, 2, 3, 4, 5}));
}

// object2's point 0 (1.05,0,0) is 0.05 from object1's point 1; its point 2
// (0,0,0.01) is 0.01 from point 0; its point 1 is 3 away from everything (beyond radius 0.1).
TEST(NearestPointROI, PairsWithinTheRadius) {
  auto s = load(R"(<Node>
      <Node name="A"><MechanicalObject name="mo" position="0 0 0  1 0 0  2 0 0"/></Node>
      <Node name="B"><MechanicalObject name="mo" position="1.05 0 0  5 0 0  0 0 0.01"/></Node>
      <NearestPointROI name="np" object1="@A/mo" object2="@B/mo" radius="0.1"/>
      <NearestPointROI name="sub" object1="@A/mo" object2="@B/mo" radius="100" inputIndices1="2" inputIndices2="2 0"/>
    </Node>)");
  auto* np = get<NearestPointROI>(*s.root, "np");
  ASSERT_TRUE(np);
  EXPECT_EQ(np->indices1.get(), (Idx{1, 0}));
  EXPECT_EQ(np->indices2.get(), (Idx{0, 2}));
  EXPECT_EQ(np->edges.get(), (std::vector<Edge>{{0, 1}, {4, 5}}));
  EXPECT_EQ(np->index_pairs.get(), (Idx{0, 1, 1, 0, 0, 0, 1, 2}));
  ASSERT_EQ(np->distances.get().size(), 2u);
  EXPECT_NEAR(np->distances.get()[0], 0.05, 1e-12);
  EXPECT_NEAR(np->distances.get()[1], 0.01, 1e-15);
  // Restricted to object1's point 2: both listed points of object2 pair with it, in inputIndices2's order.
  auto* sub = get<NearestPointROI>(*s.root, "sub");
  EXPECT_EQ(sub->indices1.get(), (Idx{2, 2}));
  EXPECT_EQ(sub->indices2.get(), (Idx{2, 0}));
}

// SOFA checks the radius in reinit (an error, the engine stops); init only warns.
TEST(NearestPointROI, RadiusMustBePositive) {
  auto s = test::build(R"(<Node><MechanicalObject position="0 0 0"/><NearestPointROI name="n" radius="0"/></Node>)");
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "radius is not positive"));
  auto* n = get<NearestPointROI>(*s.root, "n");
  n->reinit();
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "radius must be positive"));
  EXPECT_EQ(n->state(), ComponentState::invalid);
}

// Points at x = 0..5, sphere of radius 3.5 at the origin, N = 2: the heap keeps the two
// nearest (0, 1) and lists them in heap order (1, 0); 2 and 3 are inside but not kept.
TEST(ProximityROI, KeepsTheNNearest) {
  auto s = load(R"(<Node><ProximityROI name="p" centers="0 0 0" radii="3.5" N="2"
                   position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0  5 0 0"/></Node>)");
  auto* p = get<ProximityROI>(*s.root, "p");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->indices.get(), (Idx{1, 0}));
  EXPECT_EQ(p->distance.get(), (D{1, 0}));
  EXPECT_EQ(p->indices_out.get(), (Idx{2, 3, 4, 5}));
  EXPECT_EQ(p->points_in_roi.get().size(), 2u);
}

// Distances 3, 2, 1, 0 in turn with N = 2: each nearer point evicts the farthest kept
// one, and SOFA's indicesOut records the index then on top of the heap (1, then 2),
// not the evicted one (0, then 1): kept [2, 3], out [1, 2].
TEST(ProximityROI, SofasEvictionQuirk) {
  auto s = load(R"(<Node><ProximityROI name="p" centers="0 0 0" radii="5" N="2"
                   position="3 0 0  2 0 0  1 0 0  0 0 0"/></Node>)");
  auto* p = get<ProximityROI>(*s.root, "p");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->indices.get(), (Idx{2, 3}));
  EXPECT_EQ(p->distance.get(), (D{1, 0}));
  EXPECT_EQ(p->indices_out.get(), (Idx{1, 2}));
}

// Missing radii repeat the last one (written back); N = 0 is an error when read.
// Heap order: the farther point (1, at 0.5 from its centre) on top.
TEST(ProximityROI, RadiiAndN) {
  auto s = test::build(R"(<Node><ProximityROI name="p" centers="0 0 0  10 0 0" radii="1" N="3"
                   position="0 0 0  10.5 0 0"/><ProximityROI name="z" centers="0 0 0" radii="1"
                   position="0 0 0"/></Node>)");
  init_root(*s.root);
  auto* p = get<ProximityROI>(*s.root, "p");
  EXPECT_EQ(p->indices.get(), (Idx{1, 0}));
  EXPECT_EQ(p->radii.get(), (D{1, 1}));
  get<ProximityROI>(*s.root, "z")->indices.get();
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "'N' must be greater"));
}

// Subset {2, 0, 3} of a square (0 1 2, 0 2 3): vertex i of the subset is input
// vertex indices[i]; only triangle 0 2 3 survives, renumbered 1 0 2.
TEST(MeshSubsetEngine, RenumbersTheKeptElements) {
  auto s = load(R"(<Node><MeshSubsetEngine name="m" inputPosition="0 0 0  1 0 0  1 1 0  0 1 0"
                   inputTriangles="0 1 2  0 2 3" inputEdges="2 3  0 1" indices="2 0 3"/></Node>)");
  auto* m = get<MeshSubsetEngine>(*s.root, "m");
  ASSERT_TRUE(m);
  ASSERT_EQ(m->position.get().size(), 3u);
  EXPECT_TRUE(m->position.get()[0].isApprox(Vec3(1, 1, 0)));
  EXPECT_EQ(m->triangles.get(), (std::vector<Triangle>{{1, 0, 2}}));
  EXPECT_EQ(m->edges.get(), (std::vector<Edge>{{0, 2}}));
}

// Two selections on 4 points: part 1 = vertex 1, part 2 = triangle 0 (0 1 2) minus
// vertex 1 (taken by part 1), part 3 = the rest.
TEST(MeshSplittingEngine, ThreeParts) {
  auto s = load(R"(<Node><MeshSplittingEngine name="m" nbInputs="2" position="0 0 0  1 0 0  2 0 0  3 0 0"
                   triangles="0 1 2" indices1="1" triangleIndices2="0"/></Node>)");
  auto* m = get<MeshSplittingEngine>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->index_pairs.get(), (Idx{1, 0, 0, 0, 1, 1, 2, 0}));
  ASSERT_EQ(m->position.size(), 3u);
  EXPECT_EQ(m->position[0].get(), (std::vector<Vec3>{Vec3(1, 0, 0)}));
  EXPECT_EQ(m->position[1].get(), (std::vector<Vec3>{Vec3(0, 0, 0), Vec3(2, 0, 0)}));
  EXPECT_EQ(m->position[2].get(), (std::vector<Vec3>{Vec3(3, 0, 0)}));
}

// Five points on a line x = 0..4, two samples. Farthest point sampling: 0 then 4.
// Voronoi regions {0,1,2} (2 ties, the first sample wins) and {3,4}; centroids 1 and
// 3.5; Lloyd moves sample 0 to vertex 1, sample 1 stays (3 and 4 are equally near
// 3.5, the first found is kept); the next iteration changes nothing.
TEST(MeshSampler, FarthestPointsThenLloyd) {
  auto s = load(R"(<Node>
      <MeshSampler name="e" number="2" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0"/>
      <MeshSampler name="g" number="2" position="0 0 0  1 0 0  2 0 0  3 0 0  4 0 0" edges="0 1  1 2  2 3  3 4"/>
      <MeshSampler name="z" number="0" maxIter="0" position="0 0 0  1 0 0"/>
    </Node>)");
  auto* e = get<MeshSampler>(*s.root, "e");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->output_indices.get(), (Idx{1, 4}));
  EXPECT_EQ(e->output_position.get(), (std::vector<Vec3>{Vec3(1, 0, 0), Vec3(4, 0, 0)}));
  EXPECT_EQ(get<MeshSampler>(*s.root, "g")->output_indices.get(), (Idx{1, 4}));
  // SOFA always seeds with vertex 0.
  EXPECT_EQ(get<MeshSampler>(*s.root, "z")->output_indices.get(), (Idx{0}));
}

// Scalar field with the root's box x ∈ [0, 10] and values 0, 10 along x: a point at
// x = 2.5 gets 2.5, x = 10 the last value, x = −1 the first; the edge 0-1 (centre 6.25) 6.25.
TEST(ValuesFromPositions, ScalarAndVectorFields) {
  auto s = load(R"(<Node bbox="0 0 0 10 10 10">
      <ValuesFromPositions name="v" inputValues="0 10" direction="1 0 0"
                           position="2.5 0 0  10 0 0  -1 0 0" edges="0 1"/>
      <ValuesFromPositions name="w" fieldType="Vector" direction="1 1 0" position="2.5 0 0  10 0 0" edges="0 1"/>
    </Node>)");
  auto* v = get<ValuesFromPositions>(*s.root, "v");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->values.get(), (D{2.5, 10, 0}));
  EXPECT_EQ(v->edge_values.get(), (D{6.25}));
  auto* w = get<ValuesFromPositions>(*s.root, "w");
  EXPECT_EQ(w->point_vectors.get(), (std::vector<Vec3>{Vec3(1, 1, 0), Vec3(1, 1, 0)}));
  EXPECT_EQ(w->edge_vectors.get(), (std::vector<Vec3>{Vec3(1, 1, 0)}));
}
