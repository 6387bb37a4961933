// Removing elements must not stall a step (issue 11): a body of 113,400 tetrahedra
// (30 × 30 × 21 cubes, 6 each; implicit Euler, CG 25, corotational FEM, diagonal mass)
// loses 100 random tetrahedra, and the step that follows — where the FEM and the mass
// catch up — is compared with a plain step.
//
//   BM_FirstRemove100     the first removal on a fresh body (one-time: live arrays made)
//   BM_Step               one step, nothing removed
//   BM_Remove100          the removal alone (events, arrays, cascades, handlers)
//   BM_Remove100ThenStep  the removal and the next step
//
// The removal costs (BM_Remove100ThenStep − BM_Step) must stay below one BM_Step.
#include <benchmark/benchmark.h>

#include <random>

#include "components/register_all.h"
#include "core/simulation.h"
#include "scene/builder.h"
#include "scene/xml_tree.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

namespace {

using namespace sinew;

const char* kBody = R"(<Node gravity="0 0 -9.81" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver rayleighStiffness="0.1" rayleighMass="0.1"/>
  <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-12"/>
  <RegularGridTopology name="grid" n="31 31 22" min="0 0 0" max="3 3 2.1"/>
  <MechanicalObject name="dofs"/>
  <TetrahedronSetTopologyContainer name="volume"/>
  <TetrahedronSetTopologyModifier name="mod"/>
  <Hexa2TetraTopologicalMapping input="@grid" output="@volume"/>
  <DiagonalMass massDensity="1"/>
  <BoxROI name="base" box="-0.1 -0.1 -0.1 3.1 3.1 0.01"/>
  <FixedProjectiveConstraint indices="@base.indices"/>
  <TetrahedralCorotationalFEMForceField youngModulus="1e4" poissonRatio="0.3" method="large"/>
</Node>)";

struct Body {
  scene::LoadedScene scene;
  TetrahedronSetTopologyContainer* volume = nullptr;
  TetrahedronSetTopologyModifier* mod = nullptr;
  std::mt19937 rng{11};

  explicit Body(bool warm = true) {
    register_all_components();
    Diagnostics d;
    scene::ResourcePaths paths;
    auto tree = scene::parse_scene_tree(kBody, "/virtual/bench.scn", paths, scene::is_known_component, d);
    scene = scene::build_scene(*tree, paths);
    init_root(*scene.root);
    volume = dynamic_cast<TetrahedronSetTopologyContainer*>(scene.root->find_object_named("volume"));
    mod = dynamic_cast<TetrahedronSetTopologyModifier*>(scene.root->find_object_named("mod"));
    animate(*scene.root);  // first step: solver and FEM caches built
    // The first removal turns the container's cached neighbourhoods into live arrays (a
    // one-time copy, reported by BM_FirstRemove100 on its own body); later ones edit them.
    if (warm) {
      remove100();
      animate(*scene.root);
    }
  }
  void remove100() {
    std::vector<unsigned> ids;
    const auto n = static_cast<unsigned>(volume->tetrahedra().size());
    for (int i = 0; i < 100; ++i) ids.push_back(std::uniform_int_distribution<unsigned>(0, n - 1)(rng));
    mod->remove_tetrahedra(ids);
  }
};

Body& body() {
  static Body b;
  return b;
}

void BM_Step(benchmark::State& state) {
  Body& b = body();
  for (auto _ : state) animate(*b.scene.root);
  state.counters["tetrahedra"] = static_cast<double>(b.volume->tetrahedra().size());
}

void BM_Remove100(benchmark::State& state) {
  Body& b = body();
  for (auto _ : state) {
    b.remove100();
    state.PauseTiming();
    animate(*b.scene.root);  // catch up outside the measure
    state.ResumeTiming();
  }
  state.counters["tetrahedra"] = static_cast<double>(b.volume->tetrahedra().size());
}

void BM_Remove100ThenStep(benchmark::State& state) {
  Body& b = body();
  for (auto _ : state) {
    b.remove100();
    animate(*b.scene.root);
  }
  state.counters["tetrahedra"] = static_cast<double>(b.volume->tetrahedra().size());
}

void BM_FirstRemove100(benchmark::State& state) {
  for (auto _ : state) {
    state.PauseTiming();
    auto* b = new Body(false);
    state.ResumeTiming();
    b->remove100();
    state.PauseTiming();
    delete b;
    state.ResumeTiming();
  }
}

BENCHMARK(BM_FirstRemove100)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Step)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_Remove100)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_Remove100ThenStep)->Unit(benchmark::kMillisecond)->Iterations(10);
BENCHMARK(BM_Step)->Unit(benchmark::kMillisecond)->Iterations(10);

}  // namespace
