#include "forcefield/fem/triangular_fem_force_field_optim.h"

#include <cmath>
#include <limits>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"
#include "core/value_text.h"

namespace sinew {

namespace {
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
// SOFA's Vec::normalize: divide by the norm when it exceeds machine epsilon.
inline void normalize(Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  if (n > std::numeric_limits<double>::epsilon())
    for (int c = 0; c < 3; ++c) v[c] /= n;
}
// Frame rows: e0 along ab, e1 = (ab × ac) × ab, both normalised.
inline void frame(const Vec3& ab, const Vec3& ac, Vec3& e0, Vec3& e1) {
  e0 = ab;
  const Vec3 n = cross(ab, ac);
  e1 = cross(n, ab);
  normalize(e0);
  normalize(e1);
}
inline Vec3 load(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }
inline Vec3 diff(const double* x, unsigned i, unsigned j) {
  return Vec3(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]);
}
}  // namespace

void TriangularFEMForceFieldOptim::parse(AttributeMap& attrs, Diagnostics& diag) {
  if (const std::string* m = attrs.peek("method"); m && !m->empty() && *m != "large")
    diag.warning(where, describe() + ": method " + quote_value(*m) +
                            " was requested but only the \"large\" method is implemented; ignoring");
  ForceField::parse(attrs, diag);
}

void TriangularFEMForceFieldOptim::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) {
    msg_warning("no triangles found in the topology " + topology->describe());
    if (!topology->quads().empty()) msg_warning("the topology only contains quads; this force field needs triangles");
  }
  if (!rebuild()) set_state(ComponentState::invalid);
}

void TriangularFEMForceFieldOptim::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool TriangularFEMForceFieldOptim::rebuild() {
  const auto& tris = topology->triangles();
  const std::size_t nt = tris.size();
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  const std::size_t np = mstate->size();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const std::vector<double>& x = mstate->read(kPosition);
  const auto& ey = young_modulus.get();
  const auto& pr = poisson_ratio.get();
  if (ey.empty()) msg_warning("'youngModulus' is empty: using 5000");
  if (pr.empty()) msg_warning("'poissonRatio' is empty: using 0.45");
  for (std::size_t i = 0; i < ey.size(); ++i)
    if (ey[i] < 0)
      msg_warning("youngModulus of element " + std::to_string(i) + " is " + parse::format_double(ey[i]) +
                  ": negative, replaced by 5000");
    else if (ey[i] == 0)
      msg_warning("youngModulus of element " + std::to_string(i) + " is 0: the element has no stiffness");
  for (std::size_t i = 0; i < pr.size(); ++i)
    if (pr[i] < 0 || pr[i] >= 0.5)
      msg_warning("poissonRatio of element " + std::to_string(i) + " is " + parse::format_double(pr[i]) +
                  ": outside [0, 0.5[, replaced by 0.45");
  const bool scaled = rest_scale.is_set();
  const double rs = rest_scale.get();
  info_.assign(nt, TriangleInfo{});
  tstate_.assign(nt, TriangleState{});
  for (std::size_t i = 0; i < nt; ++i) {
    const Triangle& t = tris[i];
    if (!triangle_in_state(*this, i, t, np)) return false;
    TriangleInfo& ti = info_[i];
    ti.a = t[0];
    ti.b = t[1];
    ti.c = t[2];
    double E = ey.empty() ? 5000.0 : (i < ey.size() ? ey[i] : ey[0]);
    double nu = pr.empty() ? 0.45 : (i < pr.size() ? pr[i] : pr[0]);
    if (E < 0) E = 5000.0;
    if (nu < 0 || nu >= 0.5) nu = 0.45;
    ti.mu = E / (1 + nu);
    ti.gamma = (E * nu) / (1 - nu * nu);
    Vec3 ab = diff(x0.data(), t[1], t[0]);
    Vec3 ac = diff(x0.data(), t[2], t[0]);
    if (scaled) {
      ab *= rs;
      ac *= rs;
    }
    Vec3 e0, e1;
    frame(ab, ac, e0, e1);
    ti.bx = dot(e0, ab);
    ti.cx = dot(e0, ac);
    ti.cy = dot(e1, ac);
    ti.ss_factor = 0.5 / (ti.bx * ti.cy);
    if (!std::isfinite(ti.ss_factor)) {
      msg_error("triangle " + std::to_string(i) + " has a zero rest area");
      return false;
    }
    frame(diff(x.data(), t[1], t[0]), diff(x.data(), t[2], t[0]), tstate_[i].e0, tstate_[i].e1);
  }
  return true;
}

void TriangularFEMForceFieldOptim::add_force(const MechParams& p) {
  if (topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ && !rebuild()) {
    set_state(ComponentState::invalid);
    info_.clear();
    tstate_.clear();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  const std::size_t nt = info_.size();
  for (std::size_t i = 0; i < nt; ++i) {
    const TriangleInfo& ti = info_[i];
    TriangleState& ts = tstate_[i];
    const Vec3 a = load(x, ti.a);
    const Vec3 ab(x[3 * ti.b] - a[0], x[3 * ti.b + 1] - a[1], x[3 * ti.b + 2] - a[2]);
    const Vec3 ac(x[3 * ti.c] - a[0], x[3 * ti.c + 1] - a[1], x[3 * ti.c + 2] - a[2]);
    frame(ab, ac, ts.e0, ts.e1);
    const double dbx = ti.bx - dot(ts.e0, ab);
    const double dcx = ti.cx - dot(ts.e0, ac);
    const double dcy = ti.cy - dot(ts.e1, ac);
    const double s0 = ti.cy * dbx, s1 = ti.bx * dcy, s2 = ti.bx * dcx - ti.cx * dbx;
    const double gxy = ti.gamma * (s0 + s1);
    Vec3 st(ti.mu * s0 + gxy, ti.mu * s1 + gxy, 0.5 * ti.mu * s2);
    for (int c = 0; c < 3; ++c) st[c] *= ti.ss_factor;
    const double b0 = ti.cy * st[0] - ti.cx * st[2], b1 = ti.cy * st[2] - ti.cx * st[1];
    const double c0 = ti.bx * st[2], c1 = ti.bx * st[1];
    for (int c = 0; c < 3; ++c) {
      const double fb = ts.e0[c] * b0 + ts.e1[c] * b1;
      const double fc = ts.e0[c] * c0 + ts.e1[c] * c1;
      const double fa = -fb - fc;
      f[3 * ti.a + c] += fa;
      f[3 * ti.b + c] += fb;
      f[3 * ti.c + c] += fc;
    }
    ts.stress = st;
  }
}

void TriangularFEMForceFieldOptim::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  const std::size_t nt = info_.size();
  for (std::size_t i = 0; i < nt; ++i) {
    const TriangleInfo& ti = info_[i];
    const TriangleState& ts = tstate_[i];
    const Vec3 da = load(dx, ti.a);
    const Vec3 dab(dx[3 * ti.b] - da[0], dx[3 * ti.b + 1] - da[1], dx[3 * ti.b + 2] - da[2]);
    const Vec3 dac(dx[3 * ti.c] - da[0], dx[3 * ti.c + 1] - da[1], dx[3 * ti.c + 2] - da[2]);
    const double dbx = dot(ts.e0, dab), dby = dot(ts.e1, dab);
    const double dcx = dot(ts.e0, dac), dcy = dot(ts.e1, dac);
    const double s0 = ti.cy * dbx;
    const double s1 = ti.bx * dcy - ti.cx * dby;
    const double s2 = ti.bx * dcx - ti.cx * dbx + ti.cy * dby;
    const double gxy = ti.gamma * (s0 + s1);
    Vec3 st(ti.mu * s0 + gxy, ti.mu * s1 + gxy, 0.5 * ti.mu * s2);
    const double sk = ti.ss_factor * kfactor;
    for (int c = 0; c < 3; ++c) st[c] *= sk;
    const double b0 = ti.cy * st[0] - ti.cx * st[2], b1 = ti.cy * st[2] - ti.cx * st[1];
    const double c0 = ti.bx * st[2], c1 = ti.bx * st[1];
    for (int c = 0; c < 3; ++c) {
      const double dfb = ts.e0[c] * b0 + ts.e1[c] * b1;
      const double dfc = ts.e0[c] * c0 + ts.e1[c] * c1;
      const double dfa = -dfb - dfc;
      df[3 * ti.a + c] -= dfa;
      df[3 * ti.b + c] -= dfb;
      df[3 * ti.c + c] -= dfc;
    }
  }
}

bool TriangularFEMForceFieldOptim::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  using M2 = Eigen::Matrix2d;
  for (std::size_t i = 0; i < info_.size(); ++i) {
    const TriangleInfo& ti = info_[i];
    const TriangleState& ts = tstate_[i];
    const double factor = -ti.ss_factor;
    const double fG = factor * ti.gamma, fGM = factor * (ti.gamma + ti.mu), fM2 = factor * ti.mu / 2;
    double KJt[3][4] = {{fGM * ti.cy, fG * (-ti.cx), 0, fG * ti.bx},
                        {fG * ti.cy, fGM * (-ti.cx), 0, fGM * ti.bx},
                        {fM2 * (-ti.cx), fM2 * ti.cy, fM2 * ti.bx, 0}};
    M2 K11, K12, K22;
    K11(0, 0) = ti.cy * KJt[0][0] - ti.cx * KJt[2][0];
    K11(0, 1) = ti.cy * KJt[0][1] - ti.cx * KJt[2][1];
    K11(1, 0) = K11(0, 1);
    K11(1, 1) = ti.cy * KJt[2][1] - ti.cx * KJt[1][1];
    K12(0, 0) = -ti.cx * KJt[2][2];
    K12(0, 1) = ti.cy * KJt[0][3];
    K12(1, 0) = ti.cy * KJt[2][2];
    K12(1, 1) = -ti.cx * KJt[1][3];
    K22(0, 0) = ti.bx * KJt[2][2];
    K22(0, 1) = 0;
    K22(1, 0) = 0;
    K22(1, 1) = ti.bx * KJt[1][3];
    const M2 K00 = K11 + K12 + K22 + K12.transpose();
    const M2 K01 = -K11 - K12.transpose();
    const M2 K02 = -K12 - K22;
    Eigen::Matrix<double, 2, 3> F;
    F.row(0) = ts.e0.transpose();
    F.row(1) = ts.e1.transpose();
    auto global = [&](const M2& k) -> Mat3 {
      const Eigen::Matrix<double, 2, 3> kf = k * F;
      Mat3 out;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out(r, c) = F(0, r) * kf(0, c) + F(1, r) * kf(1, c);
      return out;
    };
    const std::size_t a = 3 * ti.a, b = 3 * ti.b, c = 3 * ti.c;
    K.add_block(s, a, s, a, global(K00));
    const Mat3 M01 = global(K01);
    K.add_block(s, a, s, b, M01);
    K.add_block(s, b, s, a, M01.transpose());
    const Mat3 M02 = global(K02);
    K.add_block(s, a, s, c, M02);
    K.add_block(s, c, s, a, M02.transpose());
    K.add_block(s, b, s, b, global(K11));
    const Mat3 M12 = global(K12);
    K.add_block(s, b, s, c, M12);
    K.add_block(s, c, s, b, M12.transpose());
    K.add_block(s, c, s, c, global(K22));
  }
  return true;
}

void register_triangular_fem_force_field_optim(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularFEMForceFieldOptim";
  info.category = "ForceField/FEM";
  info.description = "corotational plane-stress triangles (optimised, rest shape in a 2D frame)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularFEMForceFieldOptim>();
  r.add(std::move(info));
}

}  // namespace sinew
