// MeshTetraStuffing (SOFA's isosurface stuffing) on a cube [−0.6, 0.6]³ with cell
// size 0.5 and the box [−1, 1]³: grid 1 has its points at multiples of 0.5 and
// grid 2 at odd multiples of 0.25, none on the cube's faces, so every point is
// clearly inside or outside. Without snapping and splitting, SOFA keeps every
// BCC tetrahedron with an inside vertex; the test enumerates the lattice on
// its own and compares, then checks the volumes of the split mesh.
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <set>

#include "engine/generate/mesh_tetra_stuffing.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
const char* kCube =
    "inputPoints=\"-0.6 -0.6 -0.6  0.6 -0.6 -0.6  -0.6 0.6 -0.6  0.6 0.6 -0.6  -0.6 -0.6 0.6  0.6 -0.6 0.6  "
    "-0.6 0.6 0.6  0.6 0.6 0.6\" inputTriangles=\"0 2 3  0 3 1  4 5 7  4 7 6  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  "
    "0 6 2  1 3 7  1 7 5\" vbbox=\"-1 -1 -1 1 1 1\" size=\"0.5\"";

double volume6(const std::vector<Vec3>& x, const Tetra& t) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]);
}
bool inside(const Vec3& p) { return std::fabs(p[0]) < 0.6 && std::fabs(p[1]) < 0.6 && std::fabs(p[2]) < 0.6; }
// A tetrahedron as the sorted list of its vertices' coordinates (in units of 0.25).
using Key = std::array<std::array<int, 3>, 4>;
Key key(const std::array<Vec3, 4>& v) {
  Key k;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) k[i][c] = static_cast<int>(std::lround(v[i][c] * 4));
  std::sort(k.begin(), k.end());
  return k;
}
}  // namespace

TEST(MeshTetraStuffing, KeepsTheLatticeTetrahedraWithAnInsideVertex) {
  auto s = load(std::string("<Node><MeshTetraStuffing name=\"m\" ") + kCube + "/></Node>");
  auto* m = get<MeshTetraStuffing>(*s.root, "m");
  ASSERT_TRUE(m);
  const std::vector<Vec3>& x = m->output_points.get();
  const std::vector<Tetra>& t = m->output_tetrahedra.get();
  // Grid 1: p0 = 0, c0 = −(1/0.5 + 2) = −4 … 4: 9 points per axis at k/2; grid 2 at k/2 − 1/4, 10 per axis.
  // Each pair of neighbouring grid-1 points (p, p − e) and the 4 grid-2 points around their edge
  // make 4 tetrahedra of volume 0.5³/12.
  std::set<Key> expected;
  for (int a = 0; a < 3; ++a)
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j)
        for (int k = -4; k <= 4; ++k) {
          Vec3 p(i * 0.5, j * 0.5, k * 0.5);
          if (p[a] <= -2.0 + 1e-9) continue;
          Vec3 q = p;
          q[a] -= 0.5;
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          Vec3 h[4];
          const double sb[4] = {-1, 1, 1, -1}, sc[4] = {-1, -1, 1, 1};
          for (int r = 0; r < 4; ++r) {
            h[r] = p;
            h[r][a] -= 0.25;
            h[r][b] += 0.25 * sb[r];
            h[r][c] += 0.25 * sc[r];
          }
          for (int r = 0; r < 4; ++r) {
            const std::array<Vec3, 4> tet{p, q, h[r], h[(r + 1) % 4]};
            bool any = false;
            for (const Vec3& v : tet) any = any || inside(v);
            if (any) expected.insert(key(tet));
          }
        }
  std::set<Key> got;
  for (const Tetra& e : t) {
    EXPECT_NEAR(volume6(x, e), 0.125 / 2, 1e-12);  // positive, 6·0.5³/12
    got.insert(key({x[e[0]], x[e[1]], x[e[2]], x[e[3]]}));
  }
  EXPECT_EQ(got.size(), t.size());  // no tetrahedron twice
  EXPECT_EQ(got, expected);
  // Every point is used.
  std::set<unsigned> used;
  for (const Tetra& e : t) used.insert(e.begin(), e.end());
  EXPECT_EQ(used.size(), x.size());
}

// Splitting cuts the tetrahedra at the surface: the mesh lies inside the cube (1.2³ = 1.728)
// and holds the inner lattice [−0.5, 0.5]³ (volume 1); with this coarse grid the cuts round
// off the cube's edges and corners (1.481 here).
TEST(MeshTetraStuffing, SplitAndSnapApproachTheVolume) {
  auto s = load(std::string("<Node><MeshTetraStuffing name=\"m\" splitTetras=\"1\" snapPoints=\"1\" ") + kCube +
                "/></Node>");
  auto* m = get<MeshTetraStuffing>(*s.root, "m");
  ASSERT_TRUE(m);
  const std::vector<Vec3>& x = m->output_points.get();
  double v = 0;
  for (const Tetra& e : m->output_tetrahedra.get()) {
    EXPECT_GE(volume6(x, e), 0.0);
    v += volume6(x, e) / 6;
  }
  for (const Vec3& p : x)
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::fabs(p[c]), 0.6 + 1e-12);
  EXPECT_GT(v, 1.4);
  EXPECT_LE(v, 1.728 + 1e-9);
}

TEST(MeshTetraStuffing, EmptyInputIsAnError) {
  auto s = test::build(R"(<Node><MeshTetraStuffing name="m"/></Node>)");
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "empty input mesh"));
}
