// SpatialGrid::find_pairs: the pair search of for_each_pair writing flat
// arrays, with an AVX2 kernel chosen at run time.
//
// Why a second kernel: SPH spends most of its step here, testing about ten
// candidates for each pair it keeps. One candidate at a time, the outcome of
// each test is a branch the processor cannot predict. Four at a time, the
// kept lanes are packed with a permutation table and written unconditionally,
// so the only branches left are loop bounds. Both kernels visit candidates in
// the same order and compute r² with the same operations (no FMA), so the
// output is identical, bit for bit (tested).
#include <immintrin.h>

#include <algorithm>

#include "sph/spatial_grid.h"

namespace sinew::sph {
namespace {

// One visited cell: ranges of candidate entries in visiting order, the first
// starting at the cell's own points (each point p of the cell tests from p + 1).
// Stencil cells next to each other in a block row have adjacent entry ranges;
// those are merged, so 14 ranges usually become 8.
struct PairCellJob {
  std::uint32_t begin[14], end[14];
  int ranges = 0;
  std::uint32_t own_end = 0;  // end of the visited cell's own points
};

struct PairArrays {
  const double *x, *y, *z;
  const std::uint32_t* idx;
};

// Upper bound of the pairs one job can add (every candidate kept).
std::size_t pair_candidates(const PairCellJob& job) {
  const std::size_t n0 = job.own_end - job.begin[0];
  std::size_t all = 0;
  for (int s = 0; s < job.ranges; ++s) all += job.end[s] - job.begin[s];
  return n0 * (n0 - 1) / 2 + n0 * (all - n0);
}

std::size_t pairs_scalar(const PairCellJob& job, const PairArrays& a, double dist2, PairBuffer& out, std::size_t n) {
  std::uint32_t* first = out.first.data();
  std::uint32_t* second = out.second.data();
  double* r2out = out.r2.data();
  for (std::uint32_t p = job.begin[0]; p < job.own_end; ++p) {
    const double x1 = a.x[p], y1 = a.y[p], z1 = a.z[p];
    for (int s = 0; s < job.ranges; ++s) {
      for (std::uint32_t q = s == 0 ? p + 1 : job.begin[s]; q < job.end[s]; ++q) {
        const double dx = a.x[q] - x1, dy = a.y[q] - y1, dz = a.z[q] - z1;
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < dist2) {
          first[n] = a.idx[p];
          second[n] = a.idx[q];
          r2out[n] = r2;
          ++n;
        }
      }
    }
    out.run_end[out.runs++] = static_cast<std::uint32_t>(n);
  }
  return n;
}

// Lanes kept for each 4-bit mask, packed to the front (unused slots repeat lane 0).
struct PairPackTable {
  alignas(32) std::int32_t lanes32[16][4];   // for 4 × 32-bit (point indices)
  alignas(32) std::int32_t lanes64[16][8];   // for 4 × 64-bit (r², as pairs of 32-bit halves)
  PairPackTable() {
    for (int m = 0; m < 16; ++m) {
      int k = 0;
      for (int l = 0; l < 4; ++l)
        if (m & (1 << l)) {
          lanes32[m][k] = l;
          lanes64[m][2 * k] = 2 * l;
          lanes64[m][2 * k + 1] = 2 * l + 1;
          ++k;
        }
      for (; k < 4; ++k) {
        lanes32[m][k] = 0;
        lanes64[m][2 * k] = 0;
        lanes64[m][2 * k + 1] = 1;
      }
    }
  }
};
const PairPackTable kPairPack;

__attribute__((target("avx2,popcnt"))) std::size_t pairs_avx2(const PairCellJob& job, const PairArrays& a, double dist2,
                                                                PairBuffer& out, std::size_t n) {
  std::uint32_t* first = out.first.data();
  std::uint32_t* second = out.second.data();
  double* r2out = out.r2.data();
  const __m256d d2 = _mm256_set1_pd(dist2);
  const __m256i lane = _mm256_set_epi64x(3, 2, 1, 0);
  for (std::uint32_t p = job.begin[0]; p < job.own_end; ++p) {
    const __m256d x1 = _mm256_set1_pd(a.x[p]), y1 = _mm256_set1_pd(a.y[p]), z1 = _mm256_set1_pd(a.z[p]);
    const __m128i i1 = _mm_set1_epi32(static_cast<int>(a.idx[p]));
    for (int s = 0; s < job.ranges; ++s) {
      const std::uint32_t qe = job.end[s];
      for (std::uint32_t q = s == 0 ? p + 1 : job.begin[s]; q < qe; q += 4) {
        const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(a.x + q), x1);
        const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(a.y + q), y1);
        const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(a.z + q), z1);
        // (dx² + dy²) + dz², as the scalar expression associates.
        const __m256d r2 = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                         _mm256_mul_pd(dz, dz));
        const __m256d inside = _mm256_cmp_pd(r2, d2, _CMP_LT_OQ);
        const __m256i valid = _mm256_cmpgt_epi64(_mm256_set1_epi64x(static_cast<long long>(qe - q)), lane);
        const int m = _mm256_movemask_pd(_mm256_and_pd(inside, _mm256_castsi256_pd(valid)));
        const __m256i perm64 = _mm256_load_si256(reinterpret_cast<const __m256i*>(kPairPack.lanes64[m]));
        const __m128i perm32 = _mm_load_si128(reinterpret_cast<const __m128i*>(kPairPack.lanes32[m]));
        _mm256_storeu_pd(r2out + n, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(r2), perm64)));
        const __m128 i2 = _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a.idx + q)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(second + n), _mm_castps_si128(_mm_permutevar_ps(i2, perm32)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(first + n), i1);
        n += static_cast<std::size_t>(_mm_popcnt_u32(static_cast<unsigned>(m)));
      }
    }
    out.run_end[out.runs++] = static_cast<std::uint32_t>(n);
  }
  return n;
}

bool cpu_has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
  return yes;
}

}  // namespace

void SpatialGrid::find_pairs(double dist, PairBuffer& out, bool simd) const {
  const double dist2 = dist * dist;
  const bool wide = simd && cpu_has_avx2();
  const PairArrays arrays{entry_x_.data(), entry_y_.data(), entry_z_.data(), entry_index_.data()};
  const std::uint32_t* start = cell_start_.data();
  std::size_t n = 0;
  // One run per point: every point searches once, from its own cell.
  const std::size_t points = entry_index_.size() >= kPad ? entry_index_.size() - kPad : 0;
  if (out.run_end.size() < points) out.run_end.resize(points);
  out.runs = 0;
  for_each_cell([&](const std::uint32_t* cells) {
    PairCellJob job;
    job.own_end = start[cells[0] + 1];
    for (int s = 0; s < 14; ++s) {
      const std::uint32_t c = cells[s];
      // [a, b) then [b, c) is [a, c): same candidates, same order.
      if (job.ranges > 0 && job.end[job.ranges - 1] == start[c]) {
        job.end[job.ranges - 1] = start[c + 1];
      } else {
        job.begin[job.ranges] = start[c];
        job.end[job.ranges] = start[c + 1];
        ++job.ranges;
      }
    }
    // Room for every candidate plus the lanes a 4-wide store writes past the last pair.
    const std::size_t need = n + pair_candidates(job) + 4;
    if (out.r2.size() < need) {
      const std::size_t grown = std::max(need, 2 * out.r2.size());
      out.first.resize(grown);
      out.second.resize(grown);
      out.r2.resize(grown);
    }
    n = wide ? pairs_avx2(job, arrays, dist2, out, n) : pairs_scalar(job, arrays, dist2, out, n);
  });
  out.size = n;
}

}  // namespace sinew::sph
