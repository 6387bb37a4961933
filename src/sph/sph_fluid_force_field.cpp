#include "sph/sph_fluid_force_field.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "sph/spatial_grid_container.h"
#include "sph/sph_pair_forces.h"
#include "sph/sph_kernels.h"

namespace sinew {

void SPHFluidForceField::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  if (!(radius.value() > 0))
    diag.error(where, describe() + ": radius must be positive (got " + parse::format_double(radius.value()) + ")");
  if (viscosity_type.value() < 0 || viscosity_type.value() > 2)
    diag.error(where, describe() + ": viscosityType must be 0, 1 or 2 (got " +
                          std::to_string(viscosity_type.value()) + ")");
  if (surface_tension_type.value() < 0 || surface_tension_type.value() > 2)
    diag.error(where, describe() + ": surfaceTensionType must be 0, 1 or 2 (got " +
                          std::to_string(surface_tension_type.value()) + ")");
  if (pressure_type.value() < 0 || pressure_type.value() > 1)
    diag.error(where, describe() + ": pressureType must be 0 or 1 (got " + std::to_string(pressure_type.value()) + ")");
}

void SPHFluidForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (mstate->state_type() != StateType::vec3) {
    msg_error("needs a Vec3d state (got " + std::string(mstate->info().name) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (kernel_type.get() != 0 && kernel_type.get() != 1) {
    // SOFA reports it at every step and falls back to the default kernels.
    msg_error("unsupported kernelType " + std::to_string(kernel_type.get()) + ": using the default kernels (0)");
  }
  grid_ = node()->find_up<SpatialGridContainer>();
  if (!grid_) msg_error("no SpatialGridContainer in this node or above: the slow O(n²) neighbour search is used");
  else if (grid_->cell_width.get() < radius.get())
    msg_warning("the SpatialGridContainer's cellWidth " + parse::format_double(grid_->cell_width.get()) +
                " is smaller than the radius " + parse::format_double(radius.get()) + ": neighbours will be missed");
  const std::size_t n = mstate->size();
  density_.assign(n, density.get());
  pressure_.assign(n, 0.0);
}

namespace {

sph::PairKernel pair_kernel(sph::SphSimd level) {
  switch (level) {
    case sph::SphSimd::avx512: return sph::PairKernel::avx512;
    case sph::SphSimd::avx2: return sph::PairKernel::avx2;
    default: return sph::PairKernel::scalar;
  }
}

}  // namespace

void SPHFluidForceField::find_neighbours(const std::vector<double>& x) {
  const std::size_t n = x.size() / 3;
  const double h = radius.value();
  const double h2 = h * h;
  // The grid is looked up again each step (cheap): it may have been removed from the graph.
  grid_ = node()->find_up<SpatialGridContainer>();
  if (grid_ && grid_->state() == ComponentState::valid) {
    grid_->update(x);
    grid_->grid().find_pairs(h, found_, pair_kernel(sph::sph_simd()));
  } else {
    found_.size = 0;
    found_.runs = 0;
    if (found_.run_end.size() < n) {
      found_.run_end.resize(n);
      found_.run_first.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double* xi = &x[3 * i];
      for (std::size_t j = i + 1; j < n; ++j) {
        const double* xj = &x[3 * j];
        const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
        if (dx * dx + dy * dy + dz * dz < h2) {
          if (found_.size == found_.second.size())
            found_.second.resize(std::max<std::size_t>(64, 2 * found_.size));
          found_.second[found_.size++] = static_cast<std::uint32_t>(j);
        }
      }
      found_.run_first[found_.runs] = static_cast<std::uint32_t>(i);
      found_.run_end[found_.runs++] = static_cast<std::uint32_t>(found_.size);
    }
  }
  // SOFA's addNeighbor puts each pair in the row of its lower index, in the
  // order found; a counting sort by row keeps that order within each row.
  //
  // The pairs come in runs that share their first point f, and within a run
  // every other point appears once. So a run's pairs of row f are counted in a
  // register and placed at consecutive slots, and its other pairs each touch a
  // different row: no counter is incremented twice in a row, which would chain
  // each pair's read-modify-write to the previous one through memory.
  const std::size_t np = found_.size;
  const std::size_t runs = found_.runs;
  const std::uint32_t* second = found_.second.data();
  const std::uint32_t* run_first = found_.run_first.data();
  const std::uint32_t* run_end = found_.run_end.data();
  row_start_.assign(n + 1, 0);
  std::uint32_t* count = row_start_.data() + 1;
  for (std::size_t r = 0, k = 0; r < runs; ++r) {
    const std::size_t end = run_end[r];
    const std::uint32_t f = run_first[r];
    std::uint32_t own = 0;
    for (; k < end; ++k) {
      const std::uint32_t s = second[k];
      const std::uint32_t lower = s < f ? 1u : 0u;
      own += 1u - lower;
      count[s] += lower;
    }
    count[f] += own;
  }
  for (std::size_t i = 0; i < n; ++i) row_start_[i + 1] += row_start_[i];
  // kPairPad slots more than pairs: the 4-wide passes over the rows read and
  // write up to three slots past a row's end (see squared_distances).
  nb_j_.resize(np + kPairPad);
  std::fill(nb_j_.begin() + static_cast<std::ptrdiff_t>(np), nb_j_.end(), 0u);
  nb_q_.resize(np + kPairPad);
  // Fill with a cursor per row (row_start_ shifted back afterwards). The
  // other point's slot and the run's own slot are both computed and one is
  // chosen without a branch: whether a pair goes to the other row is not
  // predictable.
  std::uint32_t* cursor = row_start_.data();
  std::uint32_t* nj = nb_j_.data();
  for (std::size_t r = 0, k = 0; r < runs; ++r) {
    const std::size_t end = run_end[r];
    const std::uint32_t f = run_first[r];
    std::uint32_t own = cursor[f];
    for (; k < end; ++k) {
      const std::uint32_t s = second[k];
      const std::uint32_t lower = s < f ? 1u : 0u;
      const std::uint32_t pick = 0u - lower;  // all ones when the pair goes to row s
      const std::uint32_t other = cursor[s];
      cursor[s] = other + lower;
      // Selects written as masks: GCC turns the ternaries back into branches.
      nj[own ^ ((own ^ other) & pick)] = s ^ ((s ^ f) & pick);
      own += 1u - lower;
    }
    cursor[f] = own;
  }
  for (std::size_t i = n; i > 0; --i) row_start_[i] = row_start_[i - 1];
  row_start_[0] = 0;
  squared_distances(x);

  if (debug_grid.value() && grid_) {
    // Brute-force check of the grid's pairs, per particle (SOFA's debugGrid).
    std::size_t missing = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double* xi = &x[3 * i];
      std::size_t count = 0;
      for (std::size_t j = i + 1; j < n; ++j) {
        const double* xj = &x[3 * j];
        const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
        if (dx * dx + dy * dy + dz * dz < h2) ++count;
      }
      if (count != row_start_[i + 1] - row_start_[i]) ++missing;
    }
    if (missing)
      msg_error(std::to_string(missing) + " particles have a different neighbour count on the grid than by brute force");
  }
}

void SPHFluidForceField::squared_distances(const std::vector<double>& x) {
  const std::size_t n = x.size() / 3;
  double* r2 = nb_q_.data();
  if (sph::sph_simd() >= sph::SphSimd::avx2) {
    sph::pair_squared_distances_avx2(n, row_start_.data(), nb_j_.data(), x.data(), r2, records_);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double* xi = &x[3 * i];
    for (std::uint32_t e = row_start_[i]; e < row_start_[i + 1]; ++e) {
      const double* xj = &x[3 * nb_j_[e]];
      const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
      r2[e] = dx * dx + dy * dy + dz * dz;
    }
  }
}

namespace {

// q, m·W(q) and the pressure gradient's scalar of every pair, from r² (stored
// in q). Inlined into both entry points below; the AVX2 one lets the compiler
// use 4-wide vectors (no FMA: the same roundings as the scalar code). The
// kernels come by value: through a reference their constants might alias the
// outputs, and GCC then gives up vectorizing.
template <class Kd, class Kp>
[[gnu::always_inline]] inline void kernel_pass_body(double* __restrict q, double* __restrict w, double* __restrict g,
                                                    std::size_t np, double h2, double m, const Kd kd, const Kp kp) {
  for (std::size_t e = 0; e < np; ++e) {
    const double qe = std::sqrt(q[e] / h2);
    q[e] = qe;
    w[e] = m * kd.W(qe);
    g[e] = kp.grad(qe);
  }
}

template <class Kd, class Kp>
void kernel_pass(double* q, double* w, double* g, std::size_t np, double h2, double m, const Kd kd, const Kp kp) {
  kernel_pass_body(q, w, g, np, h2, m, kd, kp);
}

template <class Kd, class Kp>
__attribute__((target("avx512f,avx512vl,avx512dq,prefer-vector-width=512"))) void kernel_pass_avx512(
    double* q, double* w, double* g, std::size_t np, double h2, double m, const Kd kd, const Kp kp) {
  kernel_pass_body(q, w, g, np, h2, m, kd, kp);
}

template <class Kd, class Kp>
__attribute__((target("avx2"))) void kernel_pass_avx2(double* q, double* w, double* g, std::size_t np, double h2,
                                                      double m, const Kd kd, const Kp kp) {
  kernel_pass_body(q, w, g, np, h2, m, kd, kp);
}

}  // namespace

template <class Kd, class Kp, class Kv, class Kc>
void SPHFluidForceField::compute_force(const std::vector<double>& x, const std::vector<double>& v,
                                       std::vector<double>& f) {
  const double h = radius.value();
  const double h2 = h * h;
  const double m = mass.value();
  const double m2 = m * m;
  const double d0 = density.value();
  const double k = pressure.value();
  const double mu = viscosity.value();
  const int visc_type = mu == 0 ? 0 : viscosity_type.value();
  const double sigma = surface_tension.value();
  const int tension_type = sigma <= 0 ? 0 : surface_tension_type.value();
  const std::size_t n = x.size() / 3;
  const Kd kd(h);
  const Kp kp(h);
  const Kv kv(h);
  const Kc kc(h);
  const std::uint32_t* rs = row_start_.data();
  const std::uint32_t* nj = nb_j_.data();
  const std::size_t np = row_start_[n];

  // Per-pair kernel terms first, in a loop without branches (the compiler
  // vectorizes it): q = √(r²/h²) in place, m·W(q) for the density, ∇W's scalar for the
  // pressure. The same expressions as inline, so the same bits.
  pair_w_.resize(np);
  pair_g_.resize(np);
  const sph::SphSimd simd = sph::sph_simd();
  if (simd == sph::SphSimd::avx512)
    kernel_pass_avx512(nb_q_.data(), pair_w_.data(), pair_g_.data(), np, h2, m, kd, kp);
  else if (simd == sph::SphSimd::avx2)
    kernel_pass_avx2(nb_q_.data(), pair_w_.data(), pair_g_.data(), np, h2, m, kd, kp);
  else
    kernel_pass(nb_q_.data(), pair_w_.data(), pair_g_.data(), np, h2, m, kd, kp);
  const double* nq = nb_q_.data();
  const double* w = pair_w_.data();
  const double* grad = pair_g_.data();

  density_.assign(n, 0.0);
  pressure_.assign(n, 0.0);
  // Density: lower-index contributions arrive first, then the particle's own term, then its row.
  const double self = m * kd.W(0);
  for (std::size_t i = 0; i < n; ++i) {
    double rho = density_[i];
    rho += self;
    for (std::uint32_t e = rs[i]; e < rs[i + 1]; ++e) {
      rho += w[e];
      density_[nj[e]] += w[e];
    }
    density_[i] = rho;
    pressure_[i] = k * (rho - d0);
  }

  if (tension_type == 1) {
    normal_.assign(3 * n, 0.0);
    curvature_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::uint32_t e = rs[i]; e < rs[i + 1]; ++e) {
        const std::uint32_t j = nj[e];
        const double q = nq[e];
        const double s = m / density_[j] - m / density_[i];
        const double g = kc.grad(q);
        for (int c = 0; c < 3; ++c) {
          const double nc = (x[3 * i + c] - x[3 * j + c]) * g * s;
          normal_[3 * i + c] += nc;
          normal_[3 * j + c] -= nc;
        }
        const double cv = kc.lap(q) * s;
        curvature_[i] += cv;
        curvature_[j] -= cv;
      }
  }

  // p/ρ² once per particle: the same operations on the same operands as SOFA's per-pair
  // expression, so the same bits, at a third of the divisions.
  p_over_rho2_.resize(n);
  for (std::size_t i = 0; i < n; ++i) p_over_rho2_[i] = pressure_[i] / (density_[i] * density_[i]);
  const double* a = p_over_rho2_.data();
  const double* rho = density_.data();
  // SOFA's literal constants are floats: 0.01f is not 0.01, 0.5f happens to be 0.5.
  const double soft = static_cast<double>(0.01f) * h2;
  const double half = static_cast<double>(0.5f);
  if (visc_type != 1 && tension_type != 1 && simd >= sph::SphSimd::avx2) {
    sph::PairForceInput in;
    in.n = n;
    in.row_start = rs;
    in.neighbour = nj;
    in.q = nq;
    in.grad = grad;
    in.x = x.data();
    in.v = v.data();
    in.rho = rho;
    in.p_over_rho2 = a;
    in.m = m;
    in.m2 = m2;
    in.mu = mu;
    in.h = h;
    in.soft = soft;
    in.half = half;
    in.artificial_viscosity = visc_type == 2;
    if (simd == sph::SphSimd::avx512)
      sph::add_pair_forces_avx512(in, f.data(), records_);
    else
      sph::add_pair_forces_avx2(in, f.data(), records_);
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double rho_i = rho[i], a_i = a[i];
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double vi0 = v[3 * i], vi1 = v[3 * i + 1], vi2 = v[3 * i + 2];
    // Row i's pairs are the only updates of f_i while the row runs (the others
    // touch j > i), so f_i stays in registers: the same additions in the same order.
    double fi0 = f[3 * i], fi1 = f[3 * i + 1], fi2 = f[3 * i + 2];
    for (std::uint32_t e = rs[i]; e < rs[i + 1]; ++e) {
      const std::uint32_t j = nj[e];
      const double q = nq[e];
      const double rho_j = rho[j];
      const double* xj = &x[3 * j];
      const double* vj = &v[3 * j];
      double* fj = &f[3 * j];
      double pressure_fv = -m2 * (a_i + a[j]);
      if (visc_type == 1) {
        const double s = m2 * mu / (rho_i * rho_j) * kv.lap(q);
        const double fv0 = (vj[0] - vi0) * s, fv1 = (vj[1] - vi1) * s, fv2 = (vj[2] - vi2) * s;
        fi0 += fv0;
        fi1 += fv1;
        fi2 += fv2;
        fj[0] -= fv0;
        fj[1] -= fv1;
        fj[2] -= fv2;
      } else if (visc_type == 2) {
        double vx = (vi0 - vj[0]) * (xi0 - xj[0]);
        vx += (vi1 - vj[1]) * (xi1 - xj[1]);
        vx += (vi2 - vj[2]) * (xi2 - xj[2]);
        // Computed for every pair and selected: a data-dependent branch here is
        // mispredicted half of the time.
        const double art = vx * mu * h * m / ((q * q + soft) * (rho_i + rho_j) * half);
        pressure_fv = vx < 0 ? pressure_fv + art : pressure_fv;
      }
      const double g = grad[e];
      const double fp0 = (xi0 - xj[0]) * g * pressure_fv;
      const double fp1 = (xi1 - xj[1]) * g * pressure_fv;
      const double fp2 = (xi2 - xj[2]) * g * pressure_fv;
      fi0 += fp0;
      fi1 += fp1;
      fi2 += fp2;
      fj[0] -= fp0;
      fj[1] -= fp1;
      fj[2] -= fp2;
    }
    if (tension_type == 1) {
      const double* ni = &normal_[3 * i];
      const double nn = std::sqrt(ni[0] * ni[0] + ni[1] * ni[1] + ni[2] * ni[2]);
      if (nn > 0.000001) {
        const double s = -m * sigma * curvature_[i] / nn;
        fi0 += ni[0] * s;
        fi1 += ni[1] * s;
        fi2 += ni[2] * s;
      }
    }
    f[3 * i] = fi0;
    f[3 * i + 1] = fi1;
    f[3 * i + 2] = fi2;
  }
}

void SPHFluidForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.read(p.x);
  const std::vector<double>& v = s.read(p.v);
  std::vector<double>& f = s.write(p.f);
  find_neighbours(x);
  if (kernel_type.value() == 1)
    compute_force<sph::CubicKernel, sph::CubicKernel, sph::CubicKernel, sph::CubicKernel>(x, v, f);
  else
    compute_force<sph::DensityKernel, sph::PressureKernel, sph::ViscosityKernel, sph::DensityKernel>(x, v, f);
}

void register_sph_fluid_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "SPHFluidForceField";
  info.category = "SPH";
  info.description = "smoothed particle hydrodynamics fluid forces (SofaSphFluid)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<SPHFluidForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
