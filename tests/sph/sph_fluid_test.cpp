// SPHFluidForceField on small scenes: a block of fluid at rest has the
// lattice density the kernel predicts, and no net force inside; the SPH
// forces are pairwise, so a dam break conserves momentum up to gravity and
// walls and keeps its particles (mass); grid and brute force give the same
// neighbour rows; the SIMD paths give the scalar paths' states bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/roles.h"
#include "core/simulation.h"
#include "sph/sph_fluid_force_field.h"
#include "sph/spatial_grid_container.h"
#include "sph/sph_kernels.h"
#include "sph/sph_pair_forces.h"
#include "test_scene.h"

namespace sinew {
namespace {

// An nx×ny×nz lattice of spacing s starting at the origin, as a position list.
std::string lattice(int nx, int ny, int nz, double s, double x0 = 0, double y0 = 0, double z0 = 0) {
  std::ostringstream o;
  o.precision(17);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) o << x0 + i * s << ' ' << y0 + j * s << ' ' << z0 + k * s << ' ';
  return o.str();
}

std::string fluid_scene(const std::string& positions, const std::string& sph, const std::string& extra,
                        const std::string& gravity = "0 0 0", bool grid = true) {
  return "<Node dt='0.005' gravity='" + gravity + "'><DefaultAnimationLoop/>"
         "<Node name='fluid'><EulerExplicitSolver symplectic='1'/>"
         "<MechanicalObject name='dofs' position='" + positions + "'/>"
         "<UniformMass name='mass' vertexMass='1'/>" +
         (grid ? std::string("<SpatialGridContainer cellWidth='0.75'/>") : std::string()) +
         "<SPHFluidForceField name='sph' " + sph + "/>" + extra + "</Node></Node>";
}

std::vector<double> force_of(ForceField& ff, MechanicalState& s) {
  std::vector<double>& f = s.write(kForce);
  std::fill(f.begin(), f.end(), 0.0);
  MechParams p;
  ff.add_force(p);
  return s.read(kForce);
}

TEST(SPHFluidForceField, BlockAtRestHasTheLatticeDensity) {
  // 17³ particles of mass m at spacing s = 0.3 with h = 0.745 (about 2.5 s): an interior particle's
  // summed density is the lattice sum of the kernel, which approximates the continuum density m/s³
  // (unit kernel integral) with the discretisation error of a smooth kernel, well below 1%.
  const double s = 0.3, h = 0.745, m = 1.0;
  const int n = 17;
  auto scene = test::load(fluid_scene(lattice(n, n, n, s), "radius='0.745' mass='1' density='37' kernelType='1' "
                                                           "viscosityType='2' viscosity='10' pressure='1000'",
                                      ""));
  ASSERT_TRUE(scene.root);
  Node* fluid = scene.root->find_child_named("fluid");
  auto* sph = test::get<SPHFluidForceField>(*fluid, "sph");
  ASSERT_NE(sph, nullptr);
  const std::vector<double> f = force_of(*sph, *fluid->mechanical_state);
  const int c = n / 2;
  const std::size_t centre = static_cast<std::size_t>((c * n + c) * n + c);
  const double rho = sph->densities()[centre];
  // Independent lattice sum with the kernel.
  const sph::CubicKernel k(h);
  double sum = 0;
  const int reach = static_cast<int>(std::ceil(h / s));
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j)
      for (int l = -reach; l <= reach; ++l) {
        const double r = s * std::sqrt(double(i * i + j * j + l * l));
        if (r < h) sum += m * k.W(r / h);
      }
  EXPECT_NEAR(rho, sum, 1e-12 * sum);
  const double continuum = m / (s * s * s);
  EXPECT_NEAR(rho / continuum, 1.0, 0.01) << "rho " << rho << " vs m/s³ " << continuum;
  // Every interior particle (beyond one radius from the faces) has that density; beyond two
  // radii its neighbours have it too, and the symmetric pressure forces cancel.
  const double fscale = 1000 * std::abs(rho - 37) * rho;  // pressure-force scale
  for (int z = reach; z < n - reach; ++z)
    for (int y = reach; y < n - reach; ++y)
      for (int x = reach; x < n - reach; ++x) {
        const std::size_t i = static_cast<std::size_t>((z * n + y) * n + x);
        EXPECT_NEAR(sph->densities()[i], rho, 1e-12 * rho);
        const bool deep = std::min({x, y, z}) >= 2 * reach && std::max({x, y, z}) < n - 2 * reach;
        if (deep) {
          for (int d = 0; d < 3; ++d) EXPECT_NEAR(f[3 * i + d], 0.0, 1e-12 * fscale);
        }
      }
  // Surface particles see fewer neighbours: lower density.
  EXPECT_LT(sph->densities()[0], 0.5 * rho);
}

TEST(SPHFluidForceField, ColumnAtRestKeepsItsDensity) {
  // A column 4×12×4 at the lattice density, resting on a floor in a box, viscous; after it
  // settles, the interior density stays within the compression a weakly compressible fluid
  // allows under its own weight: ρ g H / k relative (k = pressure stiffness).
  const double s = 0.3;
  const std::string walls =
      "<PlaneForceField normal='0 1 0' d='-0.15' stiffness='5000' damping='50'/>"
      "<PlaneForceField normal='1 0 0' d='-0.15' stiffness='5000' damping='50'/>"
      "<PlaneForceField normal='-1 0 0' d='-1.05' stiffness='5000' damping='50'/>"
      "<PlaneForceField normal='0 0 1' d='-0.15' stiffness='5000' damping='50'/>"
      "<PlaneForceField normal='0 0 -1' d='-1.05' stiffness='5000' damping='50'/>";
  auto scene = test::load(fluid_scene(lattice(4, 12, 4, s),
                                      "radius='0.745' mass='1' density='26' kernelType='1' viscosityType='2' "
                                      "viscosity='10' pressure='2000'",
                                      walls, "0 -10 0"));
  ASSERT_TRUE(scene.root);
  Node* fluid = scene.root->find_child_named("fluid");
  auto* sph = test::get<SPHFluidForceField>(*fluid, "sph");
  for (int step = 0; step < 400; ++step) animate(*scene.root);
  // Bottom-centre particles of the settled column (layer y ≈ 1 s, not touching walls in x, z).
  const std::vector<double>& x = fluid->mechanical_state->read(kPosition);
  const std::vector<double>& v = fluid->mechanical_state->read(kVelocity);
  double vmax = 0;
  for (double c : v) vmax = std::max(vmax, std::abs(c));
  double rho_max = 0;
  for (std::size_t i = 0; i < sph->densities().size(); ++i) rho_max = std::max(rho_max, sph->densities()[i]);
  // Hydrostatics of a weakly compressible fluid: k dρ/dy = −ρ g, so the bottom is denser than
  // the top by exp(gH/k) − 1 ≈ 2% (H ≈ 3.6); with the kernel's deficiency at the free surface and
  // the start from a lattice at ρ0 = 26 (below the lattice's 37) the densest particle stays within
  // 60% of ρ0, the column stands in the box and has come to rest (|v| < 2).
  EXPECT_LT(rho_max, 26 * 1.6);
  EXPECT_GT(rho_max, 26 * 0.8);
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    EXPECT_GT(x[3 * i + 1], -0.5);
    EXPECT_LT(x[3 * i + 1], 4.0);
  }
  EXPECT_LT(vmax, 2.0);
}

TEST(SPHFluidForceField, ForcesArePairwiseSoMomentumFollowsGravityOnly) {
  // A dam break without walls (free fall of a block that also spreads): the SPH forces cancel in
  // pairs, so the total momentum is exactly N m g t up to rounding, and the particle count and
  // mass never change.
  auto scene = test::load(fluid_scene(lattice(6, 10, 6, 0.3),
                                      "radius='0.745' mass='1' density='15' kernelType='1' viscosityType='2' "
                                      "viscosity='10' pressure='1000'",
                                      "", "0 -10 0"));
  ASSERT_TRUE(scene.root);
  Node* fluid = scene.root->find_child_named("fluid");
  MechanicalState& s = *fluid->mechanical_state;
  const std::size_t n = s.size();
  const double dt = 0.005;
  for (int step = 1; step <= 100; ++step) {
    animate(*scene.root);
    const std::vector<double>& v = s.read(kVelocity);
    double p[3] = {0, 0, 0}, scale = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        p[d] += v[3 * i + d];
        scale += std::abs(v[3 * i + d]);
      }
    ASSERT_EQ(s.size(), n);
    EXPECT_NEAR(p[0], 0.0, 1e-12 * scale);
    EXPECT_NEAR(p[1], -10.0 * dt * step * static_cast<double>(n), 1e-11 * scale);
    EXPECT_NEAR(p[2], 0.0, 1e-12 * scale);
  }
  // The block did spread (the forces were not all zero): its x extent grew.
  const std::vector<double>& x = s.read(kPosition);
  double xmin = 1e9, xmax = -1e9;
  for (std::size_t i = 0; i < n; ++i) {
    xmin = std::min(xmin, x[3 * i]);
    xmax = std::max(xmax, x[3 * i]);
  }
  EXPECT_GT(xmax - xmin, 1.5 + 0.05);
}

TEST(SPHFluidForceField, DamBreakInABoxConservesMassAndSphMomentum) {
  // Dam break: a block in the corner of a box collapses. Particles stay (count × mass constant),
  // and at every step the SPH part of the force sums to zero: the momentum changes only through
  // gravity and the walls.
  const std::string walls =
      "<PlaneForceField normal='0 1 0' d='-0.2'/><PlaneForceField normal='1 0 0' d='-0.2'/>"
      "<PlaneForceField normal='-1 0 0' d='-4'/><PlaneForceField normal='0 0 1' d='-0.2'/>"
      "<PlaneForceField normal='0 0 -1' d='-1.5'/>";
  auto scene = test::load(fluid_scene(lattice(5, 10, 5, 0.3),
                                      "radius='0.745' mass='1' density='15' kernelType='1' viscosityType='2' "
                                      "viscosity='10' pressure='1000'",
                                      walls, "0 -10 0"));
  ASSERT_TRUE(scene.root);
  Node* fluid = scene.root->find_child_named("fluid");
  MechanicalState& s = *fluid->mechanical_state;
  auto* sph = test::get<SPHFluidForceField>(*fluid, "sph");
  auto* mass = dynamic_cast<Mass*>(fluid->mass);
  ASSERT_NE(mass, nullptr);
  const std::size_t n = s.size();
  const double total = mass->total();
  EXPECT_DOUBLE_EQ(total, static_cast<double>(n) * 1.0);
  double xfront = 0;
  for (int step = 0; step < 150; ++step) {
    animate(*scene.root);
    ASSERT_EQ(s.size(), n);
    EXPECT_EQ(mass->total(), total);
    const std::vector<double> f = force_of(*sph, s);
    double sum[3] = {0, 0, 0}, scale = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        sum[d] += f[3 * i + d];
        scale += std::abs(f[3 * i + d]);
      }
    for (double c : sum) EXPECT_NEAR(c, 0.0, 1e-12 * scale);
  }
  const std::vector<double>& x = s.read(kPosition);
  for (std::size_t i = 0; i < n; ++i) xfront = std::max(xfront, x[3 * i]);
  EXPECT_GT(xfront, 1.2 + 0.5);  // the front ran along the floor
}

TEST(SPHFluidForceField, GridAndBruteForceGiveTheSameRows) {
  const std::string pos = lattice(7, 9, 5, 0.27, -0.8, -1.1, 0.3);
  const char* params = "radius='0.745' density='15' kernelType='0' viscosityType='1' viscosity='0.5' "
                       "pressure='100' surfaceTension='2'";
  auto with = test::load(fluid_scene(pos, params, "", "0 -10 0", true));
  auto without = test::load(fluid_scene(pos, params, "", "0 -10 0", false));
  ASSERT_TRUE(with.root && without.root);
  for (int k = 0; k < 20; ++k) {
    animate(*with.root);
    animate(*without.root);
  }
  auto* a = test::get<SPHFluidForceField>(*with.root->find_child_named("fluid"), "sph");
  auto* b = test::get<SPHFluidForceField>(*without.root->find_child_named("fluid"), "sph");
  ASSERT_EQ(a->row_start(), b->row_start());
  EXPECT_GT(a->pair_count(), 100u);
  // Same pairs in each row (the order inside a row may differ).
  for (std::size_t i = 0; i + 1 < a->row_start().size(); ++i) {
    std::vector<std::uint32_t> ra(a->neighbours().begin() + a->row_start()[i],
                                  a->neighbours().begin() + a->row_start()[i + 1]);
    std::vector<std::uint32_t> rb(b->neighbours().begin() + b->row_start()[i],
                                  b->neighbours().begin() + b->row_start()[i + 1]);
    std::sort(ra.begin(), ra.end());
    std::sort(rb.begin(), rb.end());
    ASSERT_EQ(ra, rb) << "row " << i;
  }
}

// The rows in their exact order: each pair the grid finds goes to the row of its
// lower index, rows keep the order found (SOFA's addNeighbor), and q = √(r²/h²)
// to the bit. The reference is a plain stable sort of for_each_pair's pairs.
TEST(SPHFluidForceField, RowsKeepTheGridsOrderOfDiscovery) {
  const std::string pos = lattice(9, 12, 6, 0.26, -0.9, -1.3, 0.2);
  const char* params = "radius='0.745' density='15' kernelType='1' viscosityType='2' viscosity='10' pressure='1000'";
  auto scene = test::load(fluid_scene(pos, params, "<PlaneForceField normal='0 1 0' d='-1'/>", "0 -10 0", true));
  ASSERT_TRUE(scene.root);
  Node& fluid = *scene.root->find_child_named("fluid");
  auto* sph = test::get<SPHFluidForceField>(fluid, "sph");
  for (int k = 0; k < 30; ++k) animate(*scene.root);  // let particles change cells
  MechanicalState& s = *fluid.mechanical_state;
  force_of(*sph, s);
  const std::vector<double>& x = s.read(kPosition);
  const std::size_t n = x.size() / 3;
  // The container's own grid: its block order depends on its hash map's history.
  auto* container = fluid.find_local<SpatialGridContainer>();
  ASSERT_NE(container, nullptr);
  std::vector<std::vector<std::pair<std::uint32_t, double>>> rows(n);
  container->grid().for_each_pair(0.745, [&](std::uint32_t a, std::uint32_t b, double r2) {
    rows[std::min(a, b)].emplace_back(std::max(a, b), std::sqrt(r2 / (0.745 * 0.745)));
  });
  ASSERT_EQ(sph->row_start().size(), n + 1);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t b = sph->row_start()[i], e = sph->row_start()[i + 1];
    ASSERT_EQ(e - b, rows[i].size()) << "row " << i;
    for (std::uint32_t k = b; k < e; ++k) {
      ASSERT_EQ(sph->neighbours()[k], rows[i][k - b].first) << "row " << i << " slot " << k - b;
      ASSERT_EQ(sph->neighbour_q()[k], rows[i][k - b].second) << "row " << i << " slot " << k - b;
    }
    pairs += rows[i].size();
  }
  EXPECT_GT(pairs, 1000u);
}

// The vector passes (AVX2, and AVX-512 where the processor has them) against
// the scalar code, over 60 steps of a splashing block, for the options each
// path covers: every bit of every position and velocity must agree.
TEST(SPHFluidForceField, SimdPathsGiveTheScalarStatesBitForBit) {
  sph::set_sph_simd_ceiling(sph::SphSimd::avx512);
  const sph::SphSimd widest = sph::sph_simd();
  if (widest == sph::SphSimd::scalar) GTEST_SKIP() << "no AVX2 on this processor: only the scalar path runs";
  const std::string pos = lattice(6, 11, 5, 0.3, -0.7, 0.05, -0.4);
  const char* walls = "<PlaneForceField normal='0 1 0' d='0'/><PlaneForceField normal='1 0 0' d='-1'/>"
                      "<PlaneForceField normal='-1 0 0' d='-2'/>";
  for (const char* params : {"radius='0.745' density='15' kernelType='1' viscosityType='2' viscosity='10' "
                             "pressure='1000' surfaceTension='-1000'",
                             "radius='0.745' density='15' kernelType='0' viscosityType='0' pressure='300'",
                             "radius='0.6' density='20' kernelType='0' viscosityType='2' viscosity='3' pressure='500'"}) {
    std::vector<double> states[3];
    for (sph::SphSimd level : {sph::SphSimd::scalar, sph::SphSimd::avx2, sph::SphSimd::avx512}) {
      if (level > widest) continue;
      sph::set_sph_simd_ceiling(level);
      auto scene = test::load(fluid_scene(pos, params, walls, "0 -10 0"));
      ASSERT_TRUE(scene.root);
      for (int k = 0; k < 60; ++k) animate(*scene.root);
      MechanicalState& s = *scene.root->find_child_named("fluid")->mechanical_state;
      std::vector<double>& state = states[static_cast<int>(level)];
      state = s.read(kPosition);
      state.insert(state.end(), s.read(kVelocity).begin(), s.read(kVelocity).end());
    }
    sph::set_sph_simd_ceiling(sph::SphSimd::avx512);
    for (int level = 1; level <= static_cast<int>(widest); ++level) {
      ASSERT_EQ(states[0].size(), states[level].size());
      std::size_t differ = 0;
      for (std::size_t k = 0; k < states[0].size(); ++k) differ += states[0][k] != states[level][k] ? 1 : 0;
      EXPECT_EQ(differ, 0u) << params << " (level " << level << ")";
    }
    // The fluid moved (the comparison is not between two resting blocks).
    const std::vector<double> start = test::load(fluid_scene(pos, params, walls, "0 -10 0"))
                                          .root->find_child_named("fluid")->mechanical_state->read(kPosition);
    double moved = 0;
    for (std::size_t k = 0; k < start.size(); ++k) moved = std::max(moved, std::abs(states[0][k] - start[k]));
    EXPECT_GT(moved, 0.05) << params;
  }
}

TEST(SPHFluidForceField, BadParametersAreReported) {
  Diagnostics d;
  auto s = test::build(fluid_scene(lattice(2, 2, 2, 0.3), "radius='-1' viscosityType='5'", ""), &d);
  ASSERT_TRUE(s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "radius must be positive"));
  EXPECT_TRUE(test::any_contains(errors, "viscosityType must be 0, 1 or 2"));
}

}  // namespace
}  // namespace sinew
