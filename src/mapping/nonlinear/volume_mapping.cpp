#include "mapping/nonlinear/volume_mapping.h"

#include "core/registry.h"
#include "core/value_text.h"
#include "mapping/nonlinear/element_measure_kernels.h"

namespace sinew {

using namespace measure;

bool VolumeMapping::init_mapping() {
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 2);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
              quote_value(geometric_stiffness.get()));
    return false;
  }
  MeshTopologyBase* topo = resolve_topology(*this, topology);
  if (!topo) return false;
  if (topo->tetrahedra().empty()) {
    msg_error("the topology " + topo->describe() + " has no tetrahedra");
    return false;
  }
  if (!topo->hexahedra().empty()) {
    msg_error("the topology " + topo->describe() +
              " has hexahedra, which VolumeMapping does not measure (convert them to tetrahedra)");
    return false;
  }
  tets_ = topo->tetrahedra();
  if (!check_elements(*this, tets_, in_size(), "tetrahedron")) return false;
  sorted_.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const auto order = sorted_order(tets_[t]);
    for (int i = 0; i < 4; ++i) sorted_[t][i] = tets_[t][order[i]];
  }
  grad_.assign(tets_.size() * 12, 0.0);
  verts_.assign(tets_.size() * 12, 0.0);
  resize_output(tets_.size());
  return true;
}

void VolumeMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_coord(x);
  out.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    const Tetra& tet = tets_[t];
    double* p = &verts_[t * 12];
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) p[i * 3 + c] = in[tet[i] * 3 + c];
    double v[3][3];
    for (int i = 0; i < 3; ++i) sub(p + 3 * (i + 1), p, v[i]);
    double c12[3];
    cross(v[1], v[2], c12);
    out[t] = dot(v[0], c12) / 6;
    double c[3][3], g[4][3];
    cross(v[1], v[2], c[0]);
    cross(v[2], v[0], c[1]);
    cross(v[0], v[1], c[2]);
    for (auto& ci : c)
      for (double& s : ci) s /= 6;
    for (int k = 0; k < 3; ++k) {
      g[0][k] = -((c[0][k] + c[1][k]) + c[2][k]);
      g[1][k] = c[0][k];
      g[2][k] = c[1][k];
      g[3][k] = c[2][k];
    }
    for (int i = 0; i < 4; ++i) {
      int local = 0;
      while (tet[local] != sorted_[t][i]) ++local;
      for (int k = 0; k < 3; ++k) grad_[t * 12 + i * 3 + k] = g[local][k];
    }
  }
}

void VolumeMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  std::vector<double>& out = *outp;
  const std::vector<double>& in = in_deriv(v, role);
  out.resize(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    double s = 0;
    for (int i = 0; i < 4; ++i) {
      const double* g = &grad_[t * 12 + i * 3];
      const double* d = &in[sorted_[t][i] * 3];
      for (int c = 0; c < 3; ++c) s += g[c] * d[c];
    }
    out[t] = s;
  }
}

void VolumeMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(tets_.size(), out.size());
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 4; ++i) {
      const double* g = &grad_[t * 12 + i * 3];
      double* r = &in[sorted_[t][i] * 3];
      for (int c = 0; c < 3; ++c) r[c] += g[c] * out[t];
    }
}

void VolumeMapping::second_derivative(const double* x, double h[4][4][9]) {
  const double* v[4] = {x, x + 3, x + 6, x + 9};
  // Block (i, j), i < j, is [v_a − v_b]×/6 with (a, b) the other two vertices in the
  // orientation that makes V = (x1 − x0)·((x2 − x0) × (x3 − x0))/6.
  static constexpr int kPair[4][4][2] = {{{0, 0}, {2, 3}, {3, 1}, {1, 2}},
                                         {{0, 0}, {0, 0}, {0, 3}, {2, 0}},
                                         {{0, 0}, {0, 0}, {0, 0}, {0, 1}},
                                         {{0, 0}, {0, 0}, {0, 0}, {0, 0}}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 9; ++k) h[i][j][k] = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double d[3], m[9];
      sub(v[kPair[i][j][0]], v[kPair[i][j][1]], d);
      cross_matrix(d, m);
      for (int k = 0; k < 9; ++k) h[i][j][k] = m[k] / 6;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) h[j][i][r * 3 + c] = h[i][j][c * 3 + r];
    }
}

void VolumeMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_) return;
  const std::vector<double>& child_force = out_->read(kForce);
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  double h[4][4][9];
  const std::size_t n = std::min(tets_.size(), child_force.size());
  for (std::size_t t = 0; t < n; ++t) {
    const double lambda = child_force[t];
    if (!(lambda < 0 || gs_ == 1)) continue;
    second_derivative(&verts_[t * 12], h);
    const Tetra& tet = tets_[t];
    // The diagonal blocks are zero: SOFA visits the pairs i < j and their transposes.
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        add_scaled_block_product(k, h[i][j], &d[tet[j] * 3], lambda, &f[tet[i] * 3]);
        add_scaled_block_product(k, h[j][i], &d[tet[i] * 3], lambda, &f[tet[j] * 3]);
      }
  }
}

bool VolumeMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t t = 0; t < tets_.size(); ++t)
    for (int i = 0; i < 4; ++i)
      for (std::uint32_t c = 0; c < 3; ++c)
        out.push_back({0, static_cast<std::uint32_t>(t), sorted_[t][i] * 3 + c, grad_[t * 12 + i * 3 + c]});
  return true;
}

bool VolumeMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  const std::vector<double>& child_force = out_->read(kForce);
  const MechanicalState* s = in_[0];
  double h[4][4][9];
  const std::size_t n = std::min(tets_.size(), child_force.size());
  for (std::size_t t = 0; t < n; ++t) {
    const double lambda = child_force[t];
    if (!(lambda < 0 || gs_ == 1)) continue;
    second_derivative(&verts_[t * 12], h);
    const Tetra& tet = tets_[t];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) {
            K.add(s, tet[i] * 3 + r, s, tet[j] * 3 + c, h[i][j][r * 3 + c] * lambda);
            K.add(s, tet[j] * 3 + r, s, tet[i] * 3 + c, h[j][i][r * 3 + c] * lambda);
          }
  }
  return true;
}

void register_volume_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "VolumeMapping";
  info.category = "Mapping/NonLinear";
  info.description = "maps the tetrahedra of a topology to their signed volumes";
  info.templates = {"Vec3d,Vec1d"};
  info.default_template = "Vec3d,Vec1d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<VolumeMapping>(); };
  r.add(std::move(info));
}

}  // namespace sinew
