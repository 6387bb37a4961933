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
  std::uint32_t* second = out.second.data();
  for (std::uint32_t p = job.begin[0]; p < job.own_end; ++p) {
    const double x1 = a.x[p], y1 = a.y[p], z1 = a.z[p];
    for (int s = 0; s < job.ranges; ++s) {
      for (std::uint32_t q = s == 0 ? p + 1 : job.begin[s]; q < job.end[s]; ++q) {
        const double dx = a.x[q] - x1, dy = a.y[q] - y1, dz = a.z[q] - z1;
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < dist2) second[n++] = a.idx[q];
      }
    }
    out.run_first[out.runs] = a.idx[p];
    out.run_end[out.runs++] = static_cast<std::uint32_t>(n);
  }
  return n;
}

// Lanes kept for each 4-bit mask, packed to the front (unused slots repeat lane 0).
struct PairPackTable {
  alignas(32) std::int32_t lanes32[16][4];
  PairPackTable() {
    for (int m = 0; m < 16; ++m) {
      int k = 0;
      for (int l = 0; l < 4; ++l)
        if (m & (1 << l)) lanes32[m][k++] = l;
      for (; k < 4; ++k) lanes32[m][k] = 0;
    }
  }
};
const PairPackTable kPairPack;

__attribute__((target("avx2,popcnt"))) std::size_t pairs_avx2(const PairCellJob& job, const PairArrays& a, double dist2,
                                                                PairBuffer& out, std::size_t n) {
  std::uint32_t* second = out.second.data();
  const __m256d d2 = _mm256_set1_pd(dist2);
  const __m256i lane = _mm256_set_epi64x(3, 2, 1, 0);
  for (std::uint32_t p = job.begin[0]; p < job.own_end; ++p) {
    const __m256d x1 = _mm256_set1_pd(a.x[p]), y1 = _mm256_set1_pd(a.y[p]), z1 = _mm256_set1_pd(a.z[p]);
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
        const __m128i perm32 = _mm_load_si128(reinterpret_cast<const __m128i*>(kPairPack.lanes32[m]));
        const __m128 i2 = _mm_castsi128_ps(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a.idx + q)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(second + n), _mm_castps_si128(_mm_permutevar_ps(i2, perm32)));
        n += static_cast<std::size_t>(_mm_popcnt_u32(static_cast<unsigned>(m)));
      }
    }
    out.run_first[out.runs] = a.idx[p];
    out.run_end[out.runs++] = static_cast<std::uint32_t>(n);
  }
  return n;
}

// Eight candidates at a time, over the cell's candidates copied one range
// after the other: each point then tests one contiguous list (the cell's own
// points after it, then the stencil) with a single partial vector at its end,
// where the 4-wide kernel has one per range (about eight). The kept lanes'
// indices are packed by a compress; r² is the same expression.
__attribute__((target("avx512f,avx512vl,popcnt"))) std::size_t pairs_avx512(const PairCellJob& job,
                                                                              const PairArrays& a, double dist2,
                                                                              PairBuffer& out, std::size_t n) {
  std::size_t m = 0;
  for (int s = 0; s < job.ranges; ++s) m += job.end[s] - job.begin[s];
  if (out.cand_x.size() < m + 8) {
    const std::size_t grown = std::max(m + 8, 2 * out.cand_x.size());
    out.cand_x.resize(grown);
    out.cand_y.resize(grown);
    out.cand_z.resize(grown);
    out.cand_index.resize(grown);
  }
  double* cx = out.cand_x.data();
  double* cy = out.cand_y.data();
  double* cz = out.cand_z.data();
  std::uint32_t* ci = out.cand_index.data();
  // Copied eight at a time: a copy may run up to seven entries past its range
  // (the grid's arrays have kPad spare entries); the next range overwrites them.
  for (int s = 0, k = 0; s < job.ranges; ++s) {
    const std::uint32_t b = job.begin[s], len = job.end[s] - b;
    for (std::uint32_t t = 0; t < len; t += 8) {
      _mm512_storeu_pd(cx + k + t, _mm512_loadu_pd(a.x + b + t));
      _mm512_storeu_pd(cy + k + t, _mm512_loadu_pd(a.y + b + t));
      _mm512_storeu_pd(cz + k + t, _mm512_loadu_pd(a.z + b + t));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(ci + k + t),
                          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.idx + b + t)));
    }
    k += static_cast<int>(len);
  }
  std::uint32_t* second = out.second.data();
  const __m512d d2 = _mm512_set1_pd(dist2);
  // The cell's own points come first in the list (range 0 starts with them).
  const std::size_t own = job.own_end - job.begin[0];
  for (std::size_t k = 0; k < own; ++k) {
    const __m512d x1 = _mm512_set1_pd(cx[k]), y1 = _mm512_set1_pd(cy[k]), z1 = _mm512_set1_pd(cz[k]);
    for (std::size_t t = k + 1; t < m; t += 8) {
      const std::size_t left = m - t;
      const __mmask8 valid = left >= 8 ? static_cast<__mmask8>(0xff) : static_cast<__mmask8>((1u << left) - 1u);
      const __m512d dx = _mm512_sub_pd(_mm512_loadu_pd(cx + t), x1);
      const __m512d dy = _mm512_sub_pd(_mm512_loadu_pd(cy + t), y1);
      const __m512d dz = _mm512_sub_pd(_mm512_loadu_pd(cz + t), z1);
      // (dx² + dy²) + dz², as the scalar expression associates.
      const __m512d r2 =
          _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
      const __mmask8 kept = _mm512_mask_cmp_pd_mask(valid, r2, d2, _CMP_LT_OQ);
      const __m256i i2 = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ci + t));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(second + n), _mm256_maskz_compress_epi32(kept, i2));
      n += static_cast<std::size_t>(_mm_popcnt_u32(kept));
    }
    out.run_first[out.runs] = ci[k];
    out.run_end[out.runs++] = static_cast<std::uint32_t>(n);
  }
  return n;
}

bool cpu_has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
  return yes;
}

bool cpu_has_avx512() {
  static const bool yes =
      __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("popcnt");
  return yes;
}

}  // namespace

void SpatialGrid::find_pairs(double dist, PairBuffer& out, PairKernel kernel) const {
  const double dist2 = dist * dist;
  if (kernel == PairKernel::best) kernel = PairKernel::avx512;
  if (kernel == PairKernel::avx512 && !cpu_has_avx512()) kernel = PairKernel::avx2;
  if (kernel == PairKernel::avx2 && !cpu_has_avx2()) kernel = PairKernel::scalar;
  const PairArrays arrays{entry_x_.data(), entry_y_.data(), entry_z_.data(), entry_index_.data()};
  const std::uint32_t* start = cell_start_.data();
  std::size_t n = 0;
  // One run per point: every point searches once, from its own cell.
  const std::size_t points = entry_index_.size() >= kPad ? entry_index_.size() - kPad : 0;
  if (out.run_end.size() < points) {
    out.run_end.resize(points);
    out.run_first.resize(points);
  }
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
    // Room for every candidate plus the lanes an 8-wide store writes past the last pair.
    const std::size_t need = n + pair_candidates(job) + 8;
    if (out.second.size() < need) out.second.resize(std::max(need, 2 * out.second.size()));
    switch (kernel) {
      case PairKernel::avx512: n = pairs_avx512(job, arrays, dist2, out, n); break;
      case PairKernel::avx2: n = pairs_avx2(job, arrays, dist2, out, n); break;
      default: n = pairs_scalar(job, arrays, dist2, out, n); break;
    }
  });
  out.size = n;
}

}  // namespace sinew::sph
