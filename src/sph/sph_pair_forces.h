// The vector passes of SPHFluidForceField over its pair rows
// (spec/interaction.md §8): the pairs' r², and the pressure and
// artificial-viscosity forces four (AVX2) or eight (AVX-512) pairs at a time;
// the module's SIMD level.
//
// SPHFluidForceField keeps the scalar loops, which cover every option; these
// are the fast paths for the case SOFA's fluid scenes use (viscosityType 0 or
// 2, no colour-field surface tension). Each lane computes exactly the scalar
// expressions (same operations, same order, no FMA) and the lanes are added
// to the forces one after the other in pair order, so the result is the same
// bit for bit (tests/sph/sph_fluid_test.cpp compares every level).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sinew::sph {

struct PairForceInput {
  std::size_t n = 0;                          // particles
  const std::uint32_t* row_start = nullptr;   // n + 1 offsets: row i holds its pairs (j > i)
  const std::uint32_t* neighbour = nullptr;   // j of each pair
  const double* q = nullptr;                  // r/h of each pair
  const double* grad = nullptr;               // the pressure kernel's gradient scalar of each pair
  const double* x = nullptr;                  // positions, 3 per particle (length)
  const double* v = nullptr;                  // velocities, 3 per particle
  const double* rho = nullptr;                // densities
  const double* p_over_rho2 = nullptr;        // p/ρ² per particle
  double m = 0, m2 = 0;                       // particle mass and its square
  double mu = 0, h = 0;                       // viscosity, kernel radius
  double soft = 0, half = 0;                  // SOFA's float constants: 0.01f·h², 0.5f
  bool artificial_viscosity = false;          // viscosityType 2 (else no viscosity term)
};

// The widest vector instructions the SPH module's passes use: what the
// processor runs, at most the ceiling tests and benchmarks set (default: no cap).
enum class SphSimd { scalar = 0, avx2 = 1, avx512 = 2 };
SphSimd sph_simd();
void set_sph_simd_ceiling(SphSimd ceiling);

// r² of every pair of the rows (row i: pairs (i, neighbour[e]) for e in
// [row_start[i], row_start[i + 1])): ((x_j − x_i)² + (y_j − y_i)²) + (z_j − z_i)²,
// the pair search's expression, so the same bits as the search's test saw.
// Four pairs at a time: it writes up to three slots past a row's end, which
// the next rows overwrite, so r2 and neighbour need three slots more than the
// pairs (neighbour's extra slots holding valid point indices). Precondition:
// sph_simd() >= avx2. `points` is scratch (4 doubles per particle).
void pair_squared_distances_avx2(std::size_t n, const std::uint32_t* row_start, const std::uint32_t* neighbour,
                                 const double* x, double* r2, std::vector<double>& points);

// Adds the forces of every pair to f (3 per particle). Preconditions:
// sph_simd() >= avx2, and avx512 for the second. `records` is scratch (8
// doubles per particle). Both give the scalar loop's bits.
void add_pair_forces_avx2(const PairForceInput& in, double* f, std::vector<double>& records);
void add_pair_forces_avx512(const PairForceInput& in, double* f, std::vector<double>& records);

}  // namespace sinew::sph
