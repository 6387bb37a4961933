#include "mapping/nonlinear/area_mapping.h"

#include <cmath>

#include "core/registry.h"
#include "core/value_text.h"
#include "mapping/nonlinear/element_measure_kernels.h"

namespace sinew {

using namespace measure;

bool AreaMapping::init_mapping() {
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 2);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
              quote_value(geometric_stiffness.get()));
    return false;
  }
  MeshTopologyBase* topo = resolve_topology(*this, topology);
  if (!topo) return false;
  if (topo->triangles().empty()) {
    msg_error("the topology " + topo->describe() + " has no triangles");
    return false;
  }
  if (!topo->quads().empty()) {
    msg_error("the topology " + topo->describe() +
              " has quads, which AreaMapping does not measure (convert them to triangles)");
    return false;
  }
  tris_ = topo->triangles();
  if (!check_elements(*this, tris_, in_size(), "triangle")) return false;
  sorted_.resize(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const auto order = sorted_order(tris_[t]);
    for (int i = 0; i < 3; ++i) sorted_[t][i] = tris_[t][order[i]];
  }
  grad_.assign(tris_.size() * 9, 0.0);
  verts_.assign(tris_.size() * 9, 0.0);
  degenerate_.assign(tris_.size(), 0);
  resize_output(tris_.size());
  return true;
}

void AreaMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  out.resize(tris_.size());
  std::size_t degenerate = 0;
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    const Triangle& tri = tris_[t];
    const double* p0 = &in[tri[0] * 3];
    const double* p1 = &in[tri[1] * 3];
    const double* p2 = &in[tri[2] * 3];
    double* v = &verts_[t * 9];
    for (int c = 0; c < 3; ++c) v[c] = p0[c], v[3 + c] = p1[c], v[6 + c] = p2[c];
    double e01[3], e02[3], e12[3], N[3];
    sub(p1, p0, e01);
    sub(p2, p0, e02);
    cross(e01, e02, N);
    const double norm = std::sqrt(dot(N, N));
    out[t] = 0.5 * norm;
    // Gradients in the triangle's own vertex order, then stored in increasing vertex order.
    double g[3][3];
    if (norm > 0) {
      const double k = 1 / (2 * norm);
      sub(p1, p2, e12);
      double c0[3], c1[3], c2[3];
      cross(e12, N, c0);
      cross(e02, N, c1);
      cross(e01, N, c2);
      for (int c = 0; c < 3; ++c) g[0][c] = k * c0[c], g[1][c] = k * c1[c], g[2][c] = -k * c2[c];
      degenerate_[t] = 0;
    } else {
      for (auto& row : g) row[0] = row[1] = row[2] = 0.0;
      degenerate_[t] = 1;
      ++degenerate;
    }
    for (int i = 0; i < 3; ++i) {
      const int local = tri[0] == sorted_[t][i] ? 0 : tri[1] == sorted_[t][i] ? 1 : 2;
      for (int c = 0; c < 3; ++c) grad_[t * 9 + i * 3 + c] = g[local][c];
    }
  }
  if (degenerate && !warned_degenerate_) {
    warned_degenerate_ = true;
    msg_warning(std::to_string(degenerate) +
                " triangle(s) have zero area: no derivative there (zero Jacobian row, no geometric stiffness)");
  }
}

void AreaMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv(v, role);
  out.resize(tris_.size());
  for (std::size_t t = 0; t < tris_.size(); ++t) {
    double s = 0;
    for (int i = 0; i < 3; ++i) {
      const double* g = &grad_[t * 9 + i * 3];
      const double* d = &in[sorted_[t][i] * 3];
      for (int c = 0; c < 3; ++c) s += g[c] * d[c];
    }
    out[t] = s;
  }
}

void AreaMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(tris_.size(), out.size());
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i) {
      const double* g = &grad_[t * 9 + i * 3];
      double* r = &in[sorted_[t][i] * 3];
      for (int c = 0; c < 3; ++c) r[c] += g[c] * out[t];
    }
}

void AreaMapping::second_derivative(const double* v0, const double* v1, const double* v2, double h[3][3][9]) {
  const double* v[3] = {v0, v1, v2};
  double e01[3], e02[3], N[3];
  sub(v1, v0, e01);
  sub(v2, v0, e02);
  cross(e01, e02, N);
  const double n2 = dot(N, N);
  const double ka = 1 / (2 * std::sqrt(std::pow(n2, 3)));
  double nx[9];
  cross_matrix(N, nx);
  // Sign of the [N]× term: the entries of [(1, 1, 1)]×.
  static constexpr double kSkewSign[3][3] = {{0, -1, 1}, {1, 0, -1}, {-1, 1, 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double di[3], dj[3], a[3], b[3];
      sub(v[(i + 1) % 3], v[(i + 2) % 3], di);
      sub(v[(j + 1) % 3], v[(j + 2) % 3], dj);
      cross(N, di, a);
      cross(N, dj, b);
      const double d = dot(di, dj);
      double* e = h[i][j];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) e[r * 3 + c] = -(a[r] * b[c]) + n2 * (d * (r == c ? 1.0 : 0.0) - dj[r] * di[c]);
      if (i != j) {
        const double s = kSkewSign[i][j] * n2;
        for (int k = 0; k < 9; ++k) e[k] += s * nx[k];
      }
      for (int k = 0; k < 9; ++k) e[k] *= ka;
    }
}

void AreaMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  double h[3][3][9];
  const std::size_t n = std::min(tris_.size(), child_force.size());
  for (std::size_t t = 0; t < n; ++t) {
    const double lambda = child_force[t];
    if (!(lambda < 0 || gs_ == 1) || degenerate_[t]) continue;
    const double* v = &verts_[t * 9];
    second_derivative(v, v + 3, v + 6, h);
    const Triangle& tri = tris_[t];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) add_scaled_block_product(k, h[i][j], &d[tri[j] * 3], lambda, &f[tri[i] * 3]);
  }
}

bool AreaMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t t = 0; t < tris_.size(); ++t)
    for (int i = 0; i < 3; ++i)
      for (std::uint32_t c = 0; c < 3; ++c)
        out.push_back({0, static_cast<std::uint32_t>(t), sorted_[t][i] * 3 + c, grad_[t * 9 + i * 3 + c]});
  return true;
}

bool AreaMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  double h[3][3][9];
  const std::size_t n = std::min(tris_.size(), child_force.size());
  for (std::size_t t = 0; t < n; ++t) {
    const double lambda = child_force[t];
    if (!(lambda < 0 || gs_ == 1) || degenerate_[t]) continue;
    const double* v = &verts_[t * 9];
    second_derivative(v, v + 3, v + 6, h);
    const Triangle& tri = tris_[t];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) K.add(s, tri[i] * 3 + r, s, tri[j] * 3 + c, h[i][j][r * 3 + c] * lambda);
  }
  return true;
}

void register_area_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "AreaMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps the triangles of a topology to their areas";
  info.templates = {"Vec3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<AreaMapping>(); };
  r.add(std::move(info));
}

}  // namespace sinew
