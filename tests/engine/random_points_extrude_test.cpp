// SOFA's random generator (math/rand48.h), RandomPointDistributionInSurface and
// ExtrudeSurface (Engine/Generate; ExtrudeSurface.scn uses both).
#include <gtest/gtest.h>

#include <cstdlib>

#include "engine/generate/extrude_surface.h"
#include "engine/generate/random_point_distribution_in_surface.h"
#include "math/rand48.h"
#include "test_scene.h"

namespace sinew {
namespace random_extrude_test {

TEST(Rand48, IsDrand48SeededAsSofaSeedsIt) {
  // SOFA's initSeed is srand48's seeding; randomBase is the state's high 32 bits (mrand48).
  for (long seed : {1L, 12345L, 0x7fffffffL}) {
    Rand48 r(seed);
    srand48(seed);
    for (int i = 0; i < 100; ++i) ASSERT_EQ(r.next(), static_cast<std::uint32_t>(mrand48())) << seed << " " << i;
  }
  Rand48 r(3);
  for (int i = 0; i < 1000; ++i) {
    const double u = r.uniform(-2.0, 5.0);
    ASSERT_GE(u, -2.0);
    ASSERT_LE(u, 5.0);
  }
}

// The cube [0, 2]³, twelve triangles with outward normals (or inward when `inward`).
std::string cube(const std::string& attrs, bool inward = false) {
  std::string tris = "0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7";
  if (inward) tris = "0 1 2  0 2 3  4 6 5  4 7 6  0 5 1  0 4 5  1 6 2  1 5 6  2 7 3  2 6 7  3 4 0  3 7 4";
  return R"(<Node><RandomPointDistributionInSurface name="r" vertices="0 0 0  2 0 0  2 2 0  0 2 0  0 0 2  2 0 2  2 2 2  0 2 2" triangles=")" +
         tris + "\" " + attrs + "/></Node>";
}

TEST(RandomPointDistributionInSurface, PointsAreInsideApartAndSofasDraws) {
  auto s = test::load(cube("randomSeed='7' numberOfInPoints='50' numberOfTests='3' minDistanceBetweenPoints='0.1'"));
  auto* r = test::get<RandomPointDistributionInSurface>(*s.root, "r");
  ASSERT_NE(r, nullptr);
  const FlatVec& in = r->in_points.get();
  ASSERT_EQ(in.size(), 50u);
  for (std::size_t i = 0; i < in.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(in.data[3 * i + c], 0.0);
      EXPECT_LE(in.data[3 * i + c], 2.0);
    }
    for (std::size_t j = 0; j < i; ++j) {
      double d2 = 0;
      for (int c = 0; c < 3; ++c) d2 += (in.data[3 * i + c] - in.data[3 * j + c]) * (in.data[3 * i + c] - in.data[3 * j + c]);
      EXPECT_GE(d2, 0.01) << i << " " << j;
    }
  }
  // The box is the cube, so every draw is inside: draws = inside points + those too close.
  // The first point is SOFA's fourth draw triple (three directions first), scaled to the box.
  Rand48 g(7);
  for (int k = 0; k < 9; ++k) g.next();
  for (int c = 0; c < 3; ++c) EXPECT_EQ(in.data[c], g.uniform(0.0, 2.0)) << c;
  // Same seed, same points; another seed, other points.
  auto s2 = test::load(cube("randomSeed='7' numberOfInPoints='50' numberOfTests='3' minDistanceBetweenPoints='0.1'"));
  EXPECT_EQ(test::get<RandomPointDistributionInSurface>(*s2.root, "r")->in_points.get(), in);
  auto s3 = test::load(cube("randomSeed='8' numberOfInPoints='50' numberOfTests='3'"));
  EXPECT_NE(test::get<RandomPointDistributionInSurface>(*s3.root, "r")->in_points.get(), in);
}

TEST(RandomPointDistributionInSurface, InwardNormalsMeanNothingIsInsideAndTheDrawStops) {
  // Normals decide inside: flipped, no point passes; SOFA stops after n⁴ draws (3⁴ = 81).
  auto s = test::build(cube("randomSeed='5' numberOfInPoints='3' numberOfTests='4'", true));
  init_root(*s.root);
  auto* r = test::get<RandomPointDistributionInSurface>(*s.root, "r");
  EXPECT_EQ(r->number_of_tests.get(), 5u);  // an even count gets one more
  EXPECT_EQ(r->in_points.get().size(), 0u);
  EXPECT_EQ(r->out_points.get().size(), 81u);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "stopped after 81 draws"));
}

TEST(ExtrudeSurface, SquareBecomesSofasShell) {
  auto s = test::load(R"(<Node><ExtrudeSurface name="e" heightFactor="0.5"
      surfaceVertices="0 0 0  1 0 0  1 1 0  0 1 0" triangles="0 1 2  0 2 3" surfaceTriangles="0 1"/></Node>)");
  auto* e = test::get<ExtrudeSurface>(*s.root, "e");
  ASSERT_NE(e, nullptr);
  // Each vertex, then itself lifted along its normal (+z).
  EXPECT_EQ(e->extrusion_vertices.get().data,
            (std::vector<double>{0, 0, 0, 0, 0, 0.5, 1, 0, 0, 1, 0, 0.5, 1, 1, 0, 1, 1, 0.5, 0, 1, 0, 0, 1, 0.5}));
  // Flipped bottoms and tops in patch order, then two side triangles per border edge in
  // sorted edge order ((0,4) is shared: inner).
  const std::vector<Triangle> want = {{0, 4, 2}, {1, 3, 5}, {0, 6, 4}, {1, 5, 7}, {0, 2, 1}, {3, 1, 2},
                                      {0, 6, 1}, {7, 1, 6}, {2, 4, 3}, {5, 3, 4}, {4, 6, 5}, {7, 5, 6}};
  EXPECT_EQ(e->extrusion_triangles.get(), want);
}

TEST(ExtrudeSurface, VertexNormalIsTheNormalisedSumOfUnitNormals) {
  // Two triangles folded at 90° along the x axis (normals +z and +y): the shared vertices
  // move along (0, 1, 1)/√2.
  auto s = test::load(R"(<Node><ExtrudeSurface name="e" heightFactor="2"
      surfaceVertices="0 0 0  1 0 0  1 1 0  0 0 1" triangles="0 1 2  1 0 3" surfaceTriangles="0 1"/></Node>)");
  auto* e = test::get<ExtrudeSurface>(*s.root, "e");
  const std::vector<double>& v = e->extrusion_vertices.get().data;
  ASSERT_EQ(v.size(), 24u);
  const double r = 2 / std::sqrt(2.0);
  EXPECT_NEAR(v[3], 0, 1e-15);
  EXPECT_NEAR(v[4], r, 1e-15);
  EXPECT_NEAR(v[5], r, 1e-15);
  // Vertex 2 belongs to the first triangle only: +z.
  EXPECT_NEAR(v[15], 1, 1e-15);
  EXPECT_NEAR(v[16], 1, 1e-15);
  EXPECT_NEAR(v[17], 2, 1e-15);
}

TEST(ExtrudeSurface, BadIndicesAreReported) {
  auto s = test::build(R"(<Node><ExtrudeSurface name="e" surfaceVertices="0 0 0  1 0 0  1 1 0"
      triangles="0 1 2  0 2 7" surfaceTriangles="0 1 5"/></Node>)");
  init_root(*s.root);
  auto* e = test::get<ExtrudeSurface>(*s.root, "e");
  EXPECT_TRUE(e->extrusion_triangles.get().empty());
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "names"));
}

}  // namespace random_extrude_test
}  // namespace sinew
