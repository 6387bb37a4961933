// SPH fluid step cost against particle count (issue 17): a block of fluid
// (spacing 0.3, SOFA's SPHFluidForceField.scn parameters: radius 0.745, cubic
// kernel, artificial viscosity, pressure 1000) collapsing in a box of
// PlaneForceFields, symplectic explicit Euler, neighbour grid of cell 0.75.
// The block is first run 20 steps (grid warm, the flow started); each
// iteration is one step.
//
//   BM_SphStep/1000, /10000, /50000   ms per step
//   BM_SphNeighbours/...              the grid update and pair search alone
//                                     (find_pairs, as SPHFluidForceField uses it;
//                                     /simd:0 the scalar kernel, /simd:1 AVX2,
//                                     /simd:2 AVX-512, each when the processor has it)
#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>
#include <string>

#include "components/register_all.h"
#include "core/simulation.h"
#include "scene/builder.h"
#include "scene/xml_tree.h"
#include "sph/spatial_grid.h"

namespace {

using namespace sinew;

std::string block_scene(int n) {
  // nx = nz = side, ny = 2·side: n ≈ 2·side³ particles.
  const int side = static_cast<int>(std::lround(std::cbrt(n / 2.0)));
  const int nx = side, ny = (n + side * side - 1) / (side * side), nz = side;
  const double s = 0.3;
  std::ostringstream o;
  o << "<Node dt='0.005' gravity='0 -10 0'><DefaultAnimationLoop/><Node name='fluid'>"
       "<EulerExplicitSolver symplectic='1'/>"
    << "<RegularGridTopology nx='" << nx << "' ny='" << ny << "' nz='" << nz << "' xmin='0' xmax='" << s * (nx - 1)
    << "' ymin='0' ymax='" << s * (ny - 1) << "' zmin='0' zmax='" << s * (nz - 1) << "'/>"
    << "<MechanicalObject name='dofs'/><UniformMass vertexMass='1'/><SpatialGridContainer cellWidth='0.75'/>"
       "<SPHFluidForceField radius='0.745' density='37' kernelType='1' viscosityType='2' viscosity='10' "
       "pressure='1000'/>"
    << "<PlaneForceField normal='0 1 0' d='-0.2'/><PlaneForceField normal='1 0 0' d='-0.2'/>"
    << "<PlaneForceField normal='-1 0 0' d='" << -(s * nx * 2.5) << "'/>"
    << "<PlaneForceField normal='0 0 1' d='-0.2'/><PlaneForceField normal='0 0 -1' d='" << -(s * nz + 0.2) << "'/>"
    << "</Node></Node>";
  return o.str();
}

scene::LoadedScene load(const std::string& xml) {
  register_all_components();
  Diagnostics d;
  scene::ResourcePaths paths;
  auto tree = scene::parse_scene_tree(xml, "/virtual/bench.scn", paths, scene::is_known_component, d);
  scene::LoadedScene s = scene::build_scene(*tree, paths);
  init_root(*s.root);
  return s;
}

void BM_SphStep(benchmark::State& state) {
  scene::LoadedScene s = load(block_scene(static_cast<int>(state.range(0))));
  for (int k = 0; k < 20; ++k) animate(*s.root);
  for (auto _ : state) animate(*s.root);
  const std::size_t n = s.root->find_child_named("fluid")->mechanical_state->size();
  state.counters["particles"] = static_cast<double>(n);
}
BENCHMARK(BM_SphStep)->Arg(1000)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond);

void BM_SphNeighbours(benchmark::State& state) {
  scene::LoadedScene s = load(block_scene(static_cast<int>(state.range(0))));
  for (int k = 0; k < 20; ++k) animate(*s.root);
  const std::vector<double>& x = s.root->find_child_named("fluid")->mechanical_state->read(kPosition);
  sph::SpatialGrid grid(0.75);
  sph::PairBuffer pairs;
  const auto kernel = static_cast<sph::PairKernel>(state.range(1));
  for (auto _ : state) {
    grid.update(x.data(), x.size() / 3);
    grid.find_pairs(0.745, pairs, kernel);
    benchmark::DoNotOptimize(pairs.size);
  }
  state.counters["pairs"] = static_cast<double>(pairs.size);
}
BENCHMARK(BM_SphNeighbours)
    ->ArgsProduct({{1000, 10000, 50000}, {0, 1, 2}})
    ->ArgNames({"", "simd"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
