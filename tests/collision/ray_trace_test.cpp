// Ray casting (SOFA's TriangleOctree, TriangleOctreeCollisionModel and
// RayTraceNarrowPhase): the ray–triangle test on hand-computed cases, the
// octree's traversal against a loop over every triangle, and the volume
// contacts of a tetrahedron's vertex inside a box, with SOFA's facing rules.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "collision/model/triangle_octree_collision_model.h"
#include "collision/ray_trace_narrow_phase.h"
#include "collision/response/penalty_contact.h"
#include "math/triangle_octree.h"
#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew {
namespace ray_trace_test {

TEST(RayTriangleIntersection, HitsMissesParallelAndBehind) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  double t, u, v;
  ASSERT_TRUE(ray_triangle_intersection(a, b, c, Vec3(0.25, 0.5, 2), Vec3(0, 0, -1), t, u, v));
  EXPECT_DOUBLE_EQ(t, 2.0);
  EXPECT_DOUBLE_EQ(u, 0.25);  // weight of b
  EXPECT_DOUBLE_EQ(v, 0.5);   // weight of c
  // Scaled direction: t scales inversely.
  ASSERT_TRUE(ray_triangle_intersection(a, b, c, Vec3(0.25, 0.5, 2), Vec3(0, 0, -4), t, u, v));
  EXPECT_DOUBLE_EQ(t, 0.5);
  EXPECT_FALSE(ray_triangle_intersection(a, b, c, Vec3(0.8, 0.8, 2), Vec3(0, 0, -1), t, u, v));  // u + v > 1
  EXPECT_FALSE(ray_triangle_intersection(a, b, c, Vec3(0.2, 0.2, 2), Vec3(1, 0, 0), t, u, v));   // parallel
  EXPECT_FALSE(ray_triangle_intersection(a, b, c, Vec3(0.2, 0.2, 2), Vec3(0, 0, 1), t, u, v));   // behind
  // From a point of the triangle itself: t = 0 is not a hit (t must exceed ε).
  EXPECT_FALSE(ray_triangle_intersection(a, b, c, Vec3(0.2, 0.2, 0), Vec3(0, 0, -1), t, u, v));
}

// A closed UV sphere of centre `o` and radius r.
struct Mesh {
  std::vector<Vec3> x;
  std::vector<Triangle> tris;
};
Mesh uv_sphere(const Vec3& o, double r, int rings, int sectors) {
  Mesh m;
  const double pi = std::acos(-1.0);
  m.x.push_back(o + Vec3(0, 0, r));
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const double th = pi * i / rings, ph = 2 * pi * j / sectors;
      m.x.push_back(o + r * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
    }
  m.x.push_back(o + Vec3(0, 0, -r));
  const unsigned south = static_cast<unsigned>(m.x.size() - 1);
  auto ring = [&](int i, int j) { return static_cast<unsigned>(1 + (i - 1) * sectors + (j % sectors)); };
  for (int j = 0; j < sectors; ++j) m.tris.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i < rings - 1; ++i)
    for (int j = 0; j < sectors; ++j) {
      m.tris.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.tris.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < sectors; ++j) m.tris.push_back({ring(rings - 1, j), south, ring(rings - 1, j + 1)});
  return m;
}

// From inside a closed convex surface every ray leaves it once: the octree
// finds the triangle a loop over all triangles finds first, at the same t.
TEST(TriangleOctree, TraceFindsTheNearestTriangleFromInsideAClosedSurface) {
  const Vec3 centre(3, -2, 5);
  const Mesh m = uv_sphere(centre, 2.0, 12, 20);
  TriangleOctree octree;
  octree.build(m.tris, m.x);
  EXPECT_EQ(octree.outside(), 0u);
  EXPECT_GT(octree.node_count(), 8u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> directions = {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(1, 1, 0), Vec3(0, -1, 1)};
  for (int k = 0; k < 400; ++k) directions.emplace_back(u(rng), u(rng), u(rng));
  int traced = 0;
  for (const Vec3& d : directions) {
    const Vec3 origin = centre + 0.5 * Vec3(u(rng), u(rng), u(rng));
    double best = 1e300;
    std::vector<int> best_tris;
    for (std::size_t i = 0; i < m.tris.size(); ++i) {
      double t, uu, vv;
      const Triangle& tr = m.tris[i];
      if (!ray_triangle_intersection(m.x[tr[0]], m.x[tr[1]], m.x[tr[2]], origin, d, t, uu, vv)) continue;
      if (t < best - 1e-12) best_tris.clear();
      if (t <= best + 1e-12) best_tris.push_back(static_cast<int>(i));
      best = std::min(best, t);
    }
    ASSERT_FALSE(best_tris.empty());
    TriangleOctree::TraceResult res;
    const int found = octree.trace(origin, d, res);
    ASSERT_NE(found, -1) << "direction " << d.transpose();
    EXPECT_NE(std::find(best_tris.begin(), best_tris.end(), found), best_tris.end());
    EXPECT_NEAR(res.t, best, 1e-12);
    EXPECT_EQ(res.tid, found);
    // The hit point from (u, v) lies on the ray.
    const Triangle& tr = m.tris[static_cast<std::size_t>(found)];
    const Vec3 q = m.x[tr[0]] * (1 - res.u - res.v) + m.x[tr[1]] * res.u + m.x[tr[2]] * res.v;
    EXPECT_LT((q - (origin + res.t * d)).norm(), 1e-12);
    ++traced;
  }
  EXPECT_EQ(traced, 405);
  // Outward from outside the sphere: nothing.
  TriangleOctree::TraceResult res;
  EXPECT_EQ(octree.trace(centre + Vec3(0, 0, 3), Vec3(0, 0.1, 1), res), -1);
}

TEST(TriangleOctree, LeavesOutTrianglesOutsideItsCubeAndOfNoExtent) {
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {900, 0, 0}, {901, 0, 0}, {900, 1, 0}};
  const std::vector<Triangle> tris = {{0, 1, 2}, {3, 4, 5}, {0, 0, 0}, {0, 1, 9}};
  TriangleOctree octree;
  octree.build(tris, x);
  EXPECT_EQ(octree.outside(), 3u);
  TriangleOctree::TraceResult res;
  EXPECT_EQ(octree.trace(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1), res), 0);
  EXPECT_DOUBLE_EQ(res.t, 1.0);
  EXPECT_EQ(octree.trace(Vec3(900.2, 0.2, 1), Vec3(0, 0, -1), res), -1);
}

std::string text(const std::vector<Vec3>& x) {
  std::ostringstream s;
  s.precision(17);
  for (const Vec3& p : x) s << p[0] << ' ' << p[1] << ' ' << p[2] << ' ';
  return s.str();
}
std::string text(const std::vector<Triangle>& t) {
  std::ostringstream s;
  for (const Triangle& f : t) s << f[0] << ' ' << f[1] << ' ' << f[2] << ' ';
  return s.str();
}

// Regular tetrahedron v0 = (1,1,1), v1 = (1,-1,-1), v2 = (-1,1,-1), v3 = (-1,-1,1),
// outward triangles; `first_around_v0` picks the triangle owning v0 (the first with it).
std::vector<Triangle> tetra_triangles(bool owner_faces_away_from_box) {
  const Triangle opposite_v0{1, 3, 2}, opposite_v1{0, 2, 3}, opposite_v2{0, 3, 1}, opposite_v3{0, 1, 2};
  // Triangle 0 takes no part in the vertex normals (SOFA): keep v0's three faces after it.
  if (owner_faces_away_from_box) return {opposite_v0, opposite_v2, opposite_v1, opposite_v3};
  return {opposite_v0, opposite_v1, opposite_v2, opposite_v3};
}
// Box [lo, hi], 12 outward triangles (faces z0, z1, x0, x1, y0, y1).
std::vector<Vec3> box_points(const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> x;
  for (int k = 0; k < 8; ++k) x.emplace_back(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]);
  return x;
}
const std::vector<Triangle> kBoxTriangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 4, 2}, {2, 4, 6},
                                             {1, 3, 5}, {3, 7, 5}, {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7}};

struct TwoBodies {
  scene::LoadedScene s;
  TriangleOctreeCollisionModel* tetra = nullptr;
  TriangleOctreeCollisionModel* box = nullptr;
  MechanicalObject* mo = nullptr;
};
TwoBodies load_two_bodies(const std::vector<Triangle>& tetra_tris, bool with_pipeline) {
  const std::vector<Vec3> tetra = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const std::string pipeline = with_pipeline ? R"(<CollisionPipeline/><BruteForceBroadPhase/><RayTraceNarrowPhase name="narrow"/>
      <NewProximityIntersection alarmDistance="0.5" contactDistance="0.1"/>
      <CollisionResponse response="PenalityContactForceField"/>)"
                                             : "";
  TwoBodies b;
  b.s = test::load(R"(<Node name="root" dt="0.01" gravity="0 0 0">)" + pipeline + R"(
      <Node name="T"><EulerImplicitSolver/><CGLinearSolver iterations="100" tolerance="1e-12" threshold="1e-14"/>
        <MechanicalObject name="x" position=")" + text(tetra) + R"("/><UniformMass totalMass="1"/>
        <MeshTopology triangles=")" + text(tetra_tris) + R"("/><TriangleOctreeCollisionModel name="m"/></Node>
      <Node name="B"><MechanicalObject position=")" + text(box_points({0.85, 0.75, 0.55}, {3, 3, 3})) + R"("/>
        <MeshTopology triangles=")" + text(kBoxTriangles) + R"("/>
        <TriangleOctreeCollisionModel name="m" simulated="0" moving="0"/></Node>
    </Node>)");
  if (!b.s.root) return b;
  b.tetra = test::get<TriangleOctreeCollisionModel>(*b.s.root->find_child_named("T"), "m");
  b.box = test::get<TriangleOctreeCollisionModel>(*b.s.root->find_child_named("B"), "m");
  b.mo = test::get<MechanicalObject>(*b.s.root->find_child_named("T"), "x");
  return b;
}

// v0 = (1,1,1) is inside the box: the ray along minus its normal (1,1,1)/√3
// meets the box face x = 0.85 at (0.85, 0.85, 0.85), at t = 0.15·√3, before
// leaving the tetrahedron through the face opposite v0.
TEST(RayTraceNarrowPhase, AVertexInsideTheOtherSurfaceGivesOneContact) {
  TwoBodies b = load_two_bodies(tetra_triangles(true), false);
  ASSERT_TRUE(b.tetra && b.box);
  b.tetra->compute_bounding_tree(0);
  b.box->compute_bounding_tree(0);
  const Vec3 n0 = b.tetra->vertex_normals()[0];
  EXPECT_LT((n0 - Vec3(1, 1, 1) / std::sqrt(3.0)).norm(), 1e-15);
  std::vector<DetectionOutput> out;
  RayTraceNarrowPhase::find_pairs_volume(*b.tetra, *b.box, out);
  ASSERT_EQ(out.size(), 1u);
  const DetectionOutput& d = out[0];
  EXPECT_EQ(d.elem1, 1u);  // the triangle owning v0
  EXPECT_EQ(d.elem2, 4u);  // the box triangle (0, 4, 2) of face x = 0.85 holding (y, z) = (0.85, 0.85)
  EXPECT_EQ(d.id, 3);      // triangle 1, first point cast from it
  EXPECT_EQ(d.point1, Vec3(1, 1, 1));
  EXPECT_LT((d.point2 - Vec3(0.85, 0.85, 0.85)).norm(), 1e-14);
  EXPECT_LT((d.normal - n0).norm(), 0.0 + 1e-300);
  EXPECT_NEAR(d.value, -0.15 * std::sqrt(3.0), 1e-14);
  // No vertex of the box is inside the tetrahedron.
  out.clear();
  RayTraceNarrowPhase::find_pairs_volume(*b.box, *b.tetra, out);
  EXPECT_TRUE(out.empty());
}

// SOFA keeps a contact only when the triangle owning the vertex faces the
// triangle hit: owned by the face of normal (-1,1,1)/√3, v0's ray meets the
// face x = 0.85 (normal (-1,0,0)) with a positive cosine and is dropped.
TEST(RayTraceNarrowPhase, ContactIsDroppedWhenTheOwningTriangleDoesNotFaceTheHit) {
  TwoBodies b = load_two_bodies(tetra_triangles(false), false);
  ASSERT_TRUE(b.tetra && b.box);
  b.tetra->compute_bounding_tree(0);
  b.box->compute_bounding_tree(0);
  std::vector<DetectionOutput> out;
  RayTraceNarrowPhase::find_pairs_volume(*b.tetra, *b.box, out);
  EXPECT_TRUE(out.empty());
}

// SOFA's order of updates: the vertex normals of a detection come from the
// triangle normals of the one before, and triangle 0 takes no part in them.
TEST(TriangleOctreeCollisionModel, VertexNormalsLagOneDetectionAndLeaveOutTriangleZero) {
  // Triangle 0 (opposite v1) holds v0: v0's normal sums the two other faces with it.
  TwoBodies b = load_two_bodies({{0, 2, 3}, {1, 3, 2}, {0, 3, 1}, {0, 1, 2}}, false);
  ASSERT_TRUE(b.tetra);
  b.tetra->compute_bounding_tree(0);
  const Vec3 expected = (Vec3(1, -1, 1) + Vec3(1, 1, -1)).normalized();
  EXPECT_LT((b.tetra->vertex_normals()[0] - expected).norm(), 1e-15);
  // Move v0; the normals follow one detection late.
  MechanicalObject* mo = b.mo;
  ASSERT_NE(mo, nullptr);
  mo->write(kPosition)[0] = 2.0;  // v0 = (2, 1, 1)
  b.tetra->compute_bounding_tree(0);
  EXPECT_LT((b.tetra->vertex_normals()[0] - expected).norm(), 1e-15);
  b.tetra->compute_bounding_tree(0);
  EXPECT_GT((b.tetra->vertex_normals()[0] - expected).norm(), 1e-3);
  // The box starts at point 0 and covers triangles 1 …
  EXPECT_EQ(b.tetra->surface_box().max, Vec3(2, 1, 1));
  EXPECT_EQ(b.tetra->surface_box().min, Vec3(-1, -1, -1));
}

// Bad input: a triangle naming a point the state does not have is reported
// by the model and casts no ray (no read past the positions).
TEST(RayTraceNarrowPhase, TriangleBeyondThePointsCastsNothing) {
  std::vector<Triangle> tris = tetra_triangles(true);
  tris.push_back({0, 1, 9});
  TwoBodies b = load_two_bodies(tris, false);
  ASSERT_TRUE(b.tetra && b.box);
  b.tetra->compute_bounding_tree(0);
  b.box->compute_bounding_tree(0);
  std::vector<DetectionOutput> out;
  RayTraceNarrowPhase::find_pairs_volume(*b.tetra, *b.box, out);
  EXPECT_EQ(out.size(), 1u);  // v0's contact, as without the bad triangle
  RayTraceNarrowPhase::find_pairs_volume(*b.box, *b.tetra, out);
  EXPECT_EQ(out.size(), 1u);
}

// End to end: in a pipeline, the tetrahedron's vertex inside the fixed box
// gets a penalty contact pushing it out (along the vertex normal, towards -x -y -z).
TEST(RayTraceNarrowPhase, PipelinePushesThePenetratingVertexOut) {
  TwoBodies b = load_two_bodies(tetra_triangles(true), true);
  ASSERT_TRUE(b.tetra && b.box);
  MechanicalObject* mo = b.mo;
  ASSERT_NE(mo, nullptr);
  animate(*b.s.root);
  auto* narrow = test::get<RayTraceNarrowPhase>(*b.s.root, "narrow");
  ASSERT_NE(narrow, nullptr);
  std::size_t n = 0;
  for (const PairOutputs& p : narrow->outputs()) n += p.outputs.size();
  EXPECT_EQ(n, 1u);
  const auto& v = mo->read(kVelocity);
  for (int c = 0; c < 3; ++c) EXPECT_LT(v[c], 0.0) << c;  // v0 moves out of the box
}

}  // namespace ray_trace_test
}  // namespace sinew
