#include "sph/sph_fluid_surface_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "sph/sph_fluid_force_field.h"
#include "visual/ogl_model.h"

namespace sinew {

namespace {
// The seven lattice directions an edge of the Kuhn tetrahedra can take (lower corner → upper).
constexpr int kDirs[7][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
int dir_of(int dx, int dy, int dz) {
  for (int d = 0; d < 7; ++d)
    if (kDirs[d][0] == dx && kDirs[d][1] == dy && kDirs[d][2] == dz) return d;
  return -1;
}
// The six tetrahedra of a unit cube around its diagonal (0,0,0)–(1,1,1): corner bits x=1, y=2, z=4.
constexpr int kTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
// Guard against lattices that would not fit in memory (a diverged particle far away).
constexpr std::size_t kMaxNodes = std::size_t(1) << 22;
}  // namespace

void SPHFluidSurfaceMapping::parse(AttributeMap& attrs, Diagnostics& diag) {
  MappingBase::parse(attrs, diag);
  if (!(step.value() > 0))
    diag.error(where, describe() + ": step must be positive (got " + parse::format_double(step.value()) + ")");
  if (!(radius.value() > 0))
    diag.error(where, describe() + ": radius must be positive (got " + parse::format_double(radius.value()) + ")");
}

bool SPHFluidSurfaceMapping::init_mapping() {
  iso_ = iso_value.get();
  const SPHFluidForceField* sph = in_[0]->node() ? in_[0]->node()->find_local<SPHFluidForceField>() : nullptr;
  if (sph && iso_ == 0.5) {
    // SOFA rescales its default level by the colour-field constant of the SPH force field.
    const double R = radius.get();
    iso_ = iso_ / (315 / (64 * std::numbers::pi * R * R * R) * sph->mass.get());
  }
  if (!dynamic_cast<OglModel*>(vout_) && !out_) {
    msg_error("the output must be a visual model (OglModel) or a Vec3d state");
    return false;
  }
  return true;
}

void SPHFluidSurfaceMapping::sample_field(const std::vector<double>& x) {
  const std::size_t n = x.size() / 3;
  const double h = step.value(), R = radius.value(), R2 = R * R;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[3 * i + d]);
      hi[d] = std::max(hi[d], x[3 * i + d]);
    }
  // Nodes at integer multiples of the step (SOFA's lattice), one node of margin beyond the support.
  int i0[3], cnt[3];
  for (int d = 0; d < 3; ++d) {
    i0[d] = static_cast<int>(std::floor((lo[d] - R) / h)) - 1;
    cnt[d] = static_cast<int>(std::ceil((hi[d] + R) / h)) + 1 - i0[d] + 1;
    origin_[d] = i0[d] * h;
  }
  nx_ = cnt[0];
  ny_ = cnt[1];
  nz_ = cnt[2];
  const std::size_t nodes = std::size_t(nx_) * std::size_t(ny_) * std::size_t(nz_);
  if (nodes > kMaxNodes) {
    if (!warned_size_)
      msg_warning("the particles span " + std::to_string(nodes) + " lattice nodes (more than " +
                  std::to_string(kMaxNodes) + "): no surface while they do");
    warned_size_ = true;
    nx_ = ny_ = nz_ = 0;
    field_.clear();
    return;
  }
  field_.assign(nodes, 0.0);
  const SPHFluidForceField* sph = in_[0]->node() ? in_[0]->node()->find_local<SPHFluidForceField>() : nullptr;
  const std::vector<double>* rho = sph && sph->densities().size() == n ? &sph->densities() : nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = &x[3 * i];
    const double inv_rho = rho ? 1.0 / (*rho)[i] : 1.0;
    int a[3], b[3];
    for (int d = 0; d < 3; ++d) {
      a[d] = std::max(0, static_cast<int>(std::ceil((p[d] - R - origin_[d]) / h)));
      b[d] = std::min(cnt[d] - 1, static_cast<int>(std::floor((p[d] + R - origin_[d]) / h)));
    }
    for (int k = a[2]; k <= b[2]; ++k) {
      const double dz = origin_[2] + k * h - p[2];
      for (int j = a[1]; j <= b[1]; ++j) {
        const double dy = origin_[1] + j * h - p[1];
        double* row = &field_[(std::size_t(k) * ny_ + j) * nx_];
        for (int l = a[0]; l <= b[0]; ++l) {
          const double dx = origin_[0] + l * h - p[0];
          const double r2 = dx * dx + dy * dy + dz * dz;
          if (r2 < R2) {
            const double s = 1 - r2 / R2;
            row[l] += s * s * s * inv_rho;
          }
        }
      }
    }
  }
}

std::uint32_t SPHFluidSurfaceMapping::edge_vertex(std::size_t node_a, int dir, const int (&ca)[3], const int (&cb)[3],
                                                  double va, double vb) {
  std::int32_t& slot = slot_[7 * node_a + static_cast<std::size_t>(dir)];
  if (slot >= 0) return static_cast<std::uint32_t>(slot);
  const double t = (iso_ - va) / (vb - va);
  const double h = step.value();
  for (int d = 0; d < 3; ++d) points_.push_back(origin_[d] + h * (ca[d] + t * (cb[d] - ca[d])));
  slot = static_cast<std::int32_t>(points_.size() / 3 - 1);
  return static_cast<std::uint32_t>(slot);
}

void SPHFluidSurfaceMapping::extract() {
  points_.clear();
  tris_.clear();
  if (nx_ < 2 || ny_ < 2 || nz_ < 2) return;
  slot_.assign(field_.size() * 7, -1);
  auto node_index = [&](int i, int j, int k) { return (std::size_t(k) * ny_ + j) * nx_ + i; };
  for (int k = 0; k + 1 < nz_; ++k)
    for (int j = 0; j + 1 < ny_; ++j)
      for (int i = 0; i + 1 < nx_; ++i) {
        int c[8][3];
        double v[8];
        bool any_in = false, any_out = false;
        for (int b = 0; b < 8; ++b) {
          c[b][0] = i + (b & 1);
          c[b][1] = j + ((b >> 1) & 1);
          c[b][2] = k + ((b >> 2) & 1);
          v[b] = field_[node_index(c[b][0], c[b][1], c[b][2])];
          (v[b] > iso_ ? any_in : any_out) = true;
        }
        if (!any_in || !any_out) continue;
        for (const auto& tet : kTets) {
          int in[4], out[4], ni = 0, no = 0;
          for (int q : tet) (v[q] > iso_ ? in[ni++] : out[no++]) = q;
          if (ni == 0 || no == 0) continue;
          // Vertex on the edge between corner a (inside) and corner b (outside), keyed by its lower end.
          auto cut = [&](int a, int b) {
            int lo = a, hi = b;
            if (c[lo][0] > c[hi][0] || c[lo][1] > c[hi][1] || c[lo][2] > c[hi][2]) std::swap(lo, hi);
            const int d = dir_of(c[hi][0] - c[lo][0], c[hi][1] - c[lo][1], c[hi][2] - c[lo][2]);
            return edge_vertex(node_index(c[lo][0], c[lo][1], c[lo][2]), d, c[lo], c[hi], v[lo], v[hi]);
          };
          // Outward: from the inside corners towards the outside ones.
          double inside[3] = {0, 0, 0}, outside[3] = {0, 0, 0};
          for (int q = 0; q < ni; ++q)
            for (int d = 0; d < 3; ++d) inside[d] += c[in[q]][d] / double(ni);
          for (int q = 0; q < no; ++q)
            for (int d = 0; d < 3; ++d) outside[d] += c[out[q]][d] / double(no);
          auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t e) {
            const double* pa = &points_[3 * a];
            const double* pb = &points_[3 * b];
            const double* pe = &points_[3 * e];
            const double u[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
            const double w[3] = {pe[0] - pa[0], pe[1] - pa[1], pe[2] - pa[2]};
            const double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            const double dot = nrm[0] * (outside[0] - inside[0]) + nrm[1] * (outside[1] - inside[1]) +
                               nrm[2] * (outside[2] - inside[2]);
            if (dot < 0) std::swap(b, e);
            tris_.push_back(a);
            tris_.push_back(b);
            tris_.push_back(e);
          };
          if (ni == 1) {
            emit(cut(in[0], out[0]), cut(in[0], out[1]), cut(in[0], out[2]));
          } else if (ni == 3) {
            emit(cut(in[0], out[0]), cut(in[1], out[0]), cut(in[2], out[0]));
          } else {
            // Two in, two out: the cut is a quad a0-b0, a0-b1, a1-b1, a1-b0 (in that cyclic order).
            const std::uint32_t p0 = cut(in[0], out[0]), p1 = cut(in[0], out[1]), p2 = cut(in[1], out[1]),
                                p3 = cut(in[1], out[0]);
            emit(p0, p1, p2);
            emit(p0, p2, p3);
          }
        }
      }
}

void SPHFluidSurfaceMapping::apply(int x) {
  if (x != kPosition) return;  // rest positions and solver vectors have no surface of their own
  const std::vector<double>& in = in_coord(x);
  if (in.empty()) {
    points_.clear();
    tris_.clear();
  } else {
    sample_field(in);
    extract();
  }
  resize_output(points_.size() / 3);
  if (std::vector<double>* out = out_coord(kPosition)) {
    out->resize(points_.size());
    std::copy(points_.begin(), points_.end(), out->begin());
  }
  if (auto* ogl = dynamic_cast<OglModel*>(vout_)) {
    std::vector<Triangle> t(tris_.size() / 3);
    for (std::size_t f = 0; f < t.size(); ++f) t[f] = Triangle{tris_[3 * f], tris_[3 * f + 1], tris_[3 * f + 2]};
    ogl->triangles.set(std::move(t));
  }
}

void register_sph_fluid_surface_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SPHFluidSurfaceMapping";
  info.category = "SPH";
  info.description = "iso-surface of a particle fluid as a triangle mesh (SofaSphFluid)";
  info.templates = {"Vec3d,Vec3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Vec3d,Vec3d") return nullptr;
    return std::make_unique<SPHFluidSurfaceMapping>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
