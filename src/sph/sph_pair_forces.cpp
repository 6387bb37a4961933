#include "sph/sph_pair_forces.h"

#include <immintrin.h>

#include <algorithm>
#include <atomic>

namespace sinew::sph {
namespace {

std::atomic<int> g_sph_simd_ceiling{static_cast<int>(SphSimd::avx512)};

SphSimd cpu_simd() {
  static const SphSimd level = [] {
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("popcnt"))
      return SphSimd::avx512;
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt")) return SphSimd::avx2;
    return SphSimd::scalar;
  }();
  return level;
}

// Transposes the 4×4 block of doubles r0..r3 (one particle record half each)
// into c0..c3 (one field for the four particles each).
__attribute__((target("avx2"))) inline void transpose4(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d& c0,
                                                        __m256d& c1, __m256d& c2, __m256d& c3) {
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  c0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  c1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  c2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  c3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}

}  // namespace

SphSimd sph_simd() {
  return static_cast<SphSimd>(std::min(static_cast<int>(cpu_simd()), g_sph_simd_ceiling.load(std::memory_order_relaxed)));
}
void set_sph_simd_ceiling(SphSimd ceiling) { g_sph_simd_ceiling.store(static_cast<int>(ceiling), std::memory_order_relaxed); }

namespace {

// Transposes the 8×8 block of doubles r0..r7 (one particle record each) into
// c[0..7] (one field for the eight particles each). The masked forms with a
// full mask give the plain instructions; GCC 12's plain intrinsics pass an
// undefined vector that -Wmaybe-uninitialized reports.
__attribute__((target("avx512f"))) inline __m512d lo2(__m512d a, __m512d b) {
  return _mm512_mask_unpacklo_pd(a, 0xff, a, b);
}
__attribute__((target("avx512f"))) inline __m512d hi2(__m512d a, __m512d b) {
  return _mm512_mask_unpackhi_pd(a, 0xff, a, b);
}
// 128-bit lanes 0 and 2 (0x88) or 1 and 3 (0xdd) of a, then of b.
__attribute__((target("avx512f"))) inline __m512d even4(__m512d a, __m512d b) {
  return _mm512_mask_shuffle_f64x2(a, 0xff, a, b, 0x88);
}
__attribute__((target("avx512f"))) inline __m512d odd4(__m512d a, __m512d b) {
  return _mm512_mask_shuffle_f64x2(a, 0xff, a, b, 0xdd);
}

__attribute__((target("avx512f"))) inline void transpose8(const __m512d r[8], __m512d c[8]) {
  const __m512d t0 = lo2(r[0], r[1]), t1 = hi2(r[0], r[1]);
  const __m512d t2 = lo2(r[2], r[3]), t3 = hi2(r[2], r[3]);
  const __m512d t4 = lo2(r[4], r[5]), t5 = hi2(r[4], r[5]);
  const __m512d t6 = lo2(r[6], r[7]), t7 = hi2(r[6], r[7]);
  const __m512d u0 = even4(t0, t2), u1 = odd4(t0, t2), u2 = even4(t1, t3), u3 = odd4(t1, t3);
  const __m512d v0 = even4(t4, t6), v1 = odd4(t4, t6), v2 = even4(t5, t7), v3 = odd4(t5, t7);
  c[0] = even4(u0, v0);
  c[4] = odd4(u0, v0);
  c[2] = even4(u1, v1);
  c[6] = odd4(u1, v1);
  c[1] = even4(u2, v2);
  c[5] = odd4(u2, v2);
  c[3] = even4(u3, v3);
  c[7] = odd4(u3, v3);
}

// One 64-byte record per particle, (x, ρ, v, p/ρ²), 64-byte aligned inside `records`.
double* fill_records(const PairForceInput& in, std::vector<double>& records) {
  const std::size_t n = in.n;
  records.resize(8 * n + 8);
  double* rec = records.data();
  if (reinterpret_cast<std::uintptr_t>(rec) % 64 != 0) rec += (64 - reinterpret_cast<std::uintptr_t>(rec) % 64) / 8;
  for (std::size_t i = 0; i < n; ++i) {
    double* r = rec + 8 * i;
    r[0] = in.x[3 * i];
    r[1] = in.x[3 * i + 1];
    r[2] = in.x[3 * i + 2];
    r[3] = in.rho[i];
    r[4] = in.v[3 * i];
    r[5] = in.v[3 * i + 1];
    r[6] = in.v[3 * i + 2];
    r[7] = in.p_over_rho2[i];
  }
  return rec;
}

}  // namespace

__attribute__((target("avx512f,avx512vl,avx512dq"))) void add_pair_forces_avx512(const PairForceInput& in, double* f,
                                                                                  std::vector<double>& records) {
  const std::size_t n = in.n;
  const double* rec = fill_records(in, records);
  const __m512d minus_m2 = _mm512_set1_pd(-in.m2);
  const __m512d mu = _mm512_set1_pd(in.mu), h = _mm512_set1_pd(in.h), m = _mm512_set1_pd(in.m);
  const __m512d soft = _mm512_set1_pd(in.soft), half = _mm512_set1_pd(in.half);
  const __m512d zero = _mm512_setzero_pd();
  alignas(64) double fp[3][8];
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t e_end = in.row_start[i + 1];
    std::uint32_t e = in.row_start[i];
    if (e == e_end) continue;
    const double* ri = rec + 8 * i;
    const __m512d xi0 = _mm512_set1_pd(ri[0]), xi1 = _mm512_set1_pd(ri[1]), xi2 = _mm512_set1_pd(ri[2]);
    const __m512d rho_i = _mm512_set1_pd(ri[3]);
    const __m512d vi0 = _mm512_set1_pd(ri[4]), vi1 = _mm512_set1_pd(ri[5]), vi2 = _mm512_set1_pd(ri[6]);
    const __m512d a_i = _mm512_set1_pd(ri[7]);
    // As in the AVX2 loop: f_i in registers, lanes added in pair order.
    double fi0 = f[3 * i], fi1 = f[3 * i + 1], fi2 = f[3 * i + 2];
    for (; e < e_end; e += 8) {
      const std::uint32_t count = e_end - e < 8 ? e_end - e : 8;
      const __mmask8 live = static_cast<__mmask8>((1u << count) - 1u);
      // Lanes past the row's end repeat its last neighbour and load zeros for
      // q and g; they are computed and dropped.
      std::uint32_t j[8];
      __m512d r[8], c[8];
      for (std::uint32_t k = 0; k < 8; ++k) {
        j[k] = in.neighbour[e + (k < count ? k : count - 1)];
        r[k] = _mm512_load_pd(rec + 8 * j[k]);
      }
      transpose8(r, c);
      const __m512d q = _mm512_maskz_loadu_pd(live, in.q + e);
      const __m512d g = _mm512_maskz_loadu_pd(live, in.grad + e);
      // -m²·(p_i/ρ_i² + p_j/ρ_j²)
      __m512d pressure_fv = _mm512_mul_pd(minus_m2, _mm512_add_pd(a_i, c[7]));
      const __m512d dx0 = _mm512_sub_pd(xi0, c[0]), dx1 = _mm512_sub_pd(xi1, c[1]), dx2 = _mm512_sub_pd(xi2, c[2]);
      if (in.artificial_viscosity) {
        __m512d vx = _mm512_mul_pd(_mm512_sub_pd(vi0, c[4]), dx0);
        vx = _mm512_add_pd(vx, _mm512_mul_pd(_mm512_sub_pd(vi1, c[5]), dx1));
        vx = _mm512_add_pd(vx, _mm512_mul_pd(_mm512_sub_pd(vi2, c[6]), dx2));
        // vx·μ·h·m / ((q² + 0.01f·h²)·(ρ_i + ρ_j)·0.5f), kept where v·x < 0.
        const __m512d num = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(vx, mu), h), m);
        const __m512d den =
            _mm512_mul_pd(_mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(q, q), soft), _mm512_add_pd(rho_i, c[3])), half);
        const __m512d with_art = _mm512_add_pd(pressure_fv, _mm512_div_pd(num, den));
        pressure_fv = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(vx, zero, _CMP_LT_OQ), pressure_fv, with_art);
      }
      // (x_i − x_j)·g·pressure_fv
      _mm512_store_pd(fp[0], _mm512_mul_pd(_mm512_mul_pd(dx0, g), pressure_fv));
      _mm512_store_pd(fp[1], _mm512_mul_pd(_mm512_mul_pd(dx1, g), pressure_fv));
      _mm512_store_pd(fp[2], _mm512_mul_pd(_mm512_mul_pd(dx2, g), pressure_fv));
      for (std::uint32_t k = 0; k < count; ++k) {
        fi0 += fp[0][k];
        fi1 += fp[1][k];
        fi2 += fp[2][k];
        double* fj = f + 3 * j[k];
        fj[0] -= fp[0][k];
        fj[1] -= fp[1][k];
        fj[2] -= fp[2][k];
      }
    }
    f[3 * i] = fi0;
    f[3 * i + 1] = fi1;
    f[3 * i + 2] = fi2;
  }
}

__attribute__((target("avx2"))) void pair_squared_distances_avx2(std::size_t n, const std::uint32_t* row_start,
                                                                  const std::uint32_t* neighbour, const double* x,
                                                                  double* r2, std::vector<double>& points) {
  // (x, y, z, 0) per particle: four of them load as four vectors and transpose
  // into the three coordinates of four neighbours.
  points.resize(4 * n + 4);
  double* pts = points.data();
  if (reinterpret_cast<std::uintptr_t>(pts) % 32 != 0) pts += (32 - reinterpret_cast<std::uintptr_t>(pts) % 32) / 8;
  for (std::size_t i = 0; i < n; ++i) {
    pts[4 * i] = x[3 * i];
    pts[4 * i + 1] = x[3 * i + 1];
    pts[4 * i + 2] = x[3 * i + 2];
    pts[4 * i + 3] = 0.0;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t e_end = row_start[i + 1];
    std::uint32_t e = row_start[i];
    if (e == e_end) continue;
    const __m256d xi0 = _mm256_set1_pd(pts[4 * i]), xi1 = _mm256_set1_pd(pts[4 * i + 1]);
    const __m256d xi2 = _mm256_set1_pd(pts[4 * i + 2]);
    for (; e < e_end; e += 4) {
      __m256d xj0, xj1, xj2, unused;
      transpose4(_mm256_load_pd(pts + 4 * neighbour[e]), _mm256_load_pd(pts + 4 * neighbour[e + 1]),
                 _mm256_load_pd(pts + 4 * neighbour[e + 2]), _mm256_load_pd(pts + 4 * neighbour[e + 3]), xj0, xj1,
                 xj2, unused);
      const __m256d dx = _mm256_sub_pd(xj0, xi0), dy = _mm256_sub_pd(xj1, xi1), dz = _mm256_sub_pd(xj2, xi2);
      // (dx² + dy²) + dz², as the search associates it.
      _mm256_storeu_pd(r2 + e, _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                             _mm256_mul_pd(dz, dz)));
    }
  }
}

__attribute__((target("avx2"))) void add_pair_forces_avx2(const PairForceInput& in, double* f,
                                                           std::vector<double>& records) {
  const std::size_t n = in.n;
  // The four records of a chunk of pairs load as eight vectors and transpose into eight fields.
  const double* rec = fill_records(in, records);
  const __m256d minus_m2 = _mm256_set1_pd(-in.m2);
  const __m256d mu = _mm256_set1_pd(in.mu), h = _mm256_set1_pd(in.h), m = _mm256_set1_pd(in.m);
  const __m256d soft = _mm256_set1_pd(in.soft), half = _mm256_set1_pd(in.half);
  const __m256d zero = _mm256_setzero_pd();
  alignas(32) double fp[3][4];
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t e_end = in.row_start[i + 1];
    std::uint32_t e = in.row_start[i];
    if (e == e_end) continue;
    const double* ri = rec + 8 * i;
    const __m256d xi0 = _mm256_set1_pd(ri[0]), xi1 = _mm256_set1_pd(ri[1]), xi2 = _mm256_set1_pd(ri[2]);
    const __m256d rho_i = _mm256_set1_pd(ri[3]);
    const __m256d vi0 = _mm256_set1_pd(ri[4]), vi1 = _mm256_set1_pd(ri[5]), vi2 = _mm256_set1_pd(ri[6]);
    const __m256d a_i = _mm256_set1_pd(ri[7]);
    // Row i's pairs are the only updates of f_i while the row runs (the others
    // touch j > i): f_i stays in registers, lanes added in pair order.
    double fi0 = f[3 * i], fi1 = f[3 * i + 1], fi2 = f[3 * i + 2];
    for (; e < e_end; e += 4) {
      const std::uint32_t count = e_end - e < 4 ? e_end - e : 4;
      // Lanes past the row's end repeat its last pair; they are computed and dropped.
      std::uint32_t j[4];
      for (std::uint32_t k = 0; k < 4; ++k) j[k] = in.neighbour[e + (k < count ? k : count - 1)];
      __m256d xj0, xj1, xj2, rho_j, vj0, vj1, vj2, a_j;
      transpose4(_mm256_load_pd(rec + 8 * j[0]), _mm256_load_pd(rec + 8 * j[1]), _mm256_load_pd(rec + 8 * j[2]),
                 _mm256_load_pd(rec + 8 * j[3]), xj0, xj1, xj2, rho_j);
      transpose4(_mm256_load_pd(rec + 8 * j[0] + 4), _mm256_load_pd(rec + 8 * j[1] + 4),
                 _mm256_load_pd(rec + 8 * j[2] + 4), _mm256_load_pd(rec + 8 * j[3] + 4), vj0, vj1, vj2, a_j);
      __m256d q, g;
      if (count == 4) {
        q = _mm256_loadu_pd(in.q + e);
        g = _mm256_loadu_pd(in.grad + e);
      } else {
        alignas(32) double qs[4], gs[4];
        for (std::uint32_t k = 0; k < 4; ++k) {
          qs[k] = in.q[e + (k < count ? k : count - 1)];
          gs[k] = in.grad[e + (k < count ? k : count - 1)];
        }
        q = _mm256_load_pd(qs);
        g = _mm256_load_pd(gs);
      }
      // -m²·(p_i/ρ_i² + p_j/ρ_j²)
      __m256d pressure_fv = _mm256_mul_pd(minus_m2, _mm256_add_pd(a_i, a_j));
      const __m256d dx0 = _mm256_sub_pd(xi0, xj0), dx1 = _mm256_sub_pd(xi1, xj1), dx2 = _mm256_sub_pd(xi2, xj2);
      if (in.artificial_viscosity) {
        __m256d vx = _mm256_mul_pd(_mm256_sub_pd(vi0, vj0), dx0);
        vx = _mm256_add_pd(vx, _mm256_mul_pd(_mm256_sub_pd(vi1, vj1), dx1));
        vx = _mm256_add_pd(vx, _mm256_mul_pd(_mm256_sub_pd(vi2, vj2), dx2));
        // vx·μ·h·m / ((q² + 0.01f·h²)·(ρ_i + ρ_j)·0.5f), kept where v·x < 0.
        const __m256d num = _mm256_mul_pd(_mm256_mul_pd(_mm256_mul_pd(vx, mu), h), m);
        const __m256d den =
            _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(q, q), soft), _mm256_add_pd(rho_i, rho_j)), half);
        const __m256d with_art = _mm256_add_pd(pressure_fv, _mm256_div_pd(num, den));
        pressure_fv = _mm256_blendv_pd(pressure_fv, with_art, _mm256_cmp_pd(vx, zero, _CMP_LT_OQ));
      }
      // (x_i − x_j)·g·pressure_fv
      _mm256_store_pd(fp[0], _mm256_mul_pd(_mm256_mul_pd(dx0, g), pressure_fv));
      _mm256_store_pd(fp[1], _mm256_mul_pd(_mm256_mul_pd(dx1, g), pressure_fv));
      _mm256_store_pd(fp[2], _mm256_mul_pd(_mm256_mul_pd(dx2, g), pressure_fv));
      for (std::uint32_t k = 0; k < count; ++k) {
        fi0 += fp[0][k];
        fi1 += fp[1][k];
        fi2 += fp[2][k];
        double* fj = f + 3 * j[k];
        fj[0] -= fp[0][k];
        fj[1] -= fp[1][k];
        fj[2] -= fp[2][k];
      }
    }
    f[3 * i] = fi0;
    f[3 * i + 1] = fi1;
    f[3 * i + 2] = fi2;
  }
}

}  // namespace sinew::sph
