// SPHFluidSurfaceMapping: the surface of a ball of particles is closed
// (every edge shared by two triangles, Euler characteristic 2), faces
// outward (positive enclosed volume), lies on the requested level of the
// colour field, and encloses the particles.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "core/simulation.h"
#include "sph/sph_fluid_surface_mapping.h"
#include "test_scene.h"
#include "visual/ogl_model.h"

namespace sinew {
namespace {

// Particles of a cubic lattice (spacing 0.25) inside a ball of radius 1 centred at (0.1, 0.2, -0.3).
std::string ball() {
  std::ostringstream o;
  o.precision(17);
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = -4; k <= 4; ++k)
        if (i * i + j * j + k * k <= 16) o << 0.1 + 0.25 * i << ' ' << 0.2 + 0.25 * j << ' ' << -0.3 + 0.25 * k << ' ';
  return o.str();
}

TEST(SPHFluidSurfaceMapping, BallSurfaceIsClosedOutwardAndOnTheLevel) {
  auto s = test::load(
      "<Node dt='0.01' gravity='0 0 0'><DefaultAnimationLoop/><Node name='fluid'>"
      "<MechanicalObject name='dofs' position='" + ball() + "'/>"
      "<Node name='visual'><OglModel name='VModel'/>"
      "<SPHFluidSurfaceMapping name='surface' input='@../dofs' output='@VModel' isoValue='0.2' radius='0.5' "
      "step='0.05'/></Node></Node></Node>");
  ASSERT_TRUE(s.root);
  Node* visual = s.root->find_child_named("fluid")->find_child_named("visual");
  auto* m = test::get<SPHFluidSurfaceMapping>(*visual, "surface");
  auto* ogl = test::get<OglModel>(*visual, "VModel");
  ASSERT_NE(m, nullptr);
  ASSERT_NE(ogl, nullptr);
  m->apply(kPosition);
  const std::vector<double>& p = m->surface_points();
  const std::vector<std::uint32_t>& t = m->surface_triangles();
  ASSERT_GT(t.size(), 300u);
  EXPECT_EQ(ogl->triangles.value().size() * 3, t.size());
  EXPECT_EQ(ogl->visual_size() * 3, p.size());
  // Closed 2-manifold: each undirected edge in exactly two triangles, once in each direction.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t f = 0; f < t.size(); f += 3)
    for (int e = 0; e < 3; ++e) ++directed[{t[f + e], t[f + (e + 1) % 3]}];
  std::size_t edges = 0;
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "open edge";
    if (e.first < e.second) ++edges;
  }
  const long V = static_cast<long>(p.size() / 3), E = static_cast<long>(edges), F = static_cast<long>(t.size() / 3);
  EXPECT_EQ(V - E + F, 2);
  // Outward orientation: the enclosed volume (divergence theorem) is positive, and close to the
  // volume of the level set, a ball a little larger than the particles' (radius 1).
  double vol = 0;
  for (std::size_t f = 0; f < t.size(); f += 3) {
    const double* a = &p[3 * t[f]];
    const double* b = &p[3 * t[f + 1]];
    const double* c = &p[3 * t[f + 2]];
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  EXPECT_GT(vol, 4.0 / 3.0 * std::numbers::pi * 1.0);
  EXPECT_LT(vol, 4.0 / 3.0 * std::numbers::pi * std::pow(1.5, 3));
  // Vertices on the level: recompute the colour field (no SPH force field: densities 1).
  const std::vector<double>& x = s.root->find_child_named("fluid")->mechanical_state->read(kPosition);
  for (std::size_t v = 0; v < p.size() / 3; v += 13) {
    double phi = 0;
    for (std::size_t i = 0; i < x.size() / 3; ++i) {
      double r2 = 0;
      for (int d = 0; d < 3; ++d) r2 += (p[3 * v + d] - x[3 * i + d]) * (p[3 * v + d] - x[3 * i + d]);
      if (r2 < 0.25) phi += std::pow(1 - r2 / 0.25, 3);
    }
    // Linear interpolation along a lattice edge (0.05, diagonals up to 0.087) of a field whose
    // second derivative is O(10) here: h²/8·φ'' stays below 0.01; 0.05 leaves room for the
    // diagonals' longer edges.
    EXPECT_NEAR(phi, 0.2, 0.05) << "vertex " << v;
  }
}

}  // namespace
}  // namespace sinew
