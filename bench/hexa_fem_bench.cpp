// Hexahedral FEM kernel on the benchmark beam (39×9×9 cells): force and
// force-differential throughput, the two hot operations of a matrix-free step.
#include <benchmark/benchmark.h>

#include "forcefield/fem/hexa_fem.h"

namespace {

struct Beam {
  std::vector<sinew::Vec3> x0;
  std::vector<std::array<int, 8>> hexa;
  Beam(int nx, int ny, int nz) {
    auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) x0.emplace_back(0.4 * i, 0.4 * j, 0.4 * k);
    for (int k = 0; k + 1 < nz; ++k)
      for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i)
          hexa.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                          id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  }
};

void BM_HexaAddForce(benchmark::State& state) {
  Beam b(40, 10, 10);
  sinew::fem::HexaFEM fem;
  std::vector<double> E(b.hexa.size(), 2000.0), nu(b.hexa.size(), 0.3);
  fem.init(b.x0, b.hexa, E, nu, sinew::fem::HexaMethod::large);
  std::vector<sinew::Vec3> x = b.x0, f(b.x0.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i].y() -= 0.001 * x[i].x() * x[i].x();
  for (auto _ : state) {
    fem.add_force(x, f);
    benchmark::DoNotOptimize(f.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(b.hexa.size()));
}
BENCHMARK(BM_HexaAddForce)->Unit(benchmark::kMicrosecond);

void BM_HexaAddDForce(benchmark::State& state) {
  Beam b(40, 10, 10);
  sinew::fem::HexaFEM fem;
  std::vector<double> E(b.hexa.size(), 2000.0), nu(b.hexa.size(), 0.3);
  fem.init(b.x0, b.hexa, E, nu, sinew::fem::HexaMethod::large);
  std::vector<sinew::Vec3> dx(b.x0.size(), sinew::Vec3(0.1, -0.2, 0.05)), df(b.x0.size());
  for (auto _ : state) {
    fem.add_dforce(dx, df, 0.5);
    benchmark::DoNotOptimize(df.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(b.hexa.size()));
}
BENCHMARK(BM_HexaAddDForce)->Unit(benchmark::kMicrosecond);

}  // namespace
