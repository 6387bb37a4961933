// BeamFEMForceField: no force at rest and under rigid motions, add_dforce is
// the derivative of add_force where the beams are unloaded (the corotational
// K omits the geometric term, as SOFA's), build_stiffness equals add_dforce,
// cantilever deflections match Euler–Bernoulli (and the kernel matches
// Timoshenko when shear areas are given), and bad input is reported.
#include "forcefield/fem/beam_fem_force_field.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/matrix_sink.h"
#include "core/node.h"
#include "core/simulation.h"
#include "math/rigid.h"
#include "state/mechanical_object.h"
#include "topology/mesh_topology.h"

namespace sinew {
namespace {

// A straight beam of `n` elements along x (node frames = identity).
struct BeamFixture {
  std::unique_ptr<Node> root = std::make_unique<Node>("root");
  MechanicalObject* dofs = nullptr;
  BeamFEMForceField* ff = nullptr;

  BeamFixture(int n, double length, double E, double nu, double r, double ri = 0.0,
              StateType type = StateType::rigid3, std::vector<Edge> edges = {}, double spacing_scale = 1.0) {
    if (edges.empty())
      for (int i = 0; i < n; ++i) edges.push_back({static_cast<unsigned>(i), static_cast<unsigned>(i + 1)});
    auto topo = std::make_unique<MeshTopology>();
    topo->name.set("lines");
    topo->edges_f.set(edges);
    root->add_object(std::move(topo));
    auto mo = std::make_unique<MechanicalObject>(type);
    mo->name.set("DOFs");
    FlatVec p;
    p.width = type == StateType::rigid3 ? 7 : 3;
    for (int i = 0; i <= n; ++i) {
      p.data.insert(p.data.end(), {length * i / n * spacing_scale, 0.0, 0.0});
      if (type == StateType::rigid3) p.data.insert(p.data.end(), {0.0, 0.0, 0.0, 1.0});
    }
    mo->position.set(p);
    dofs = static_cast<MechanicalObject*>(root->add_object(std::move(mo)));
    auto f = std::make_unique<BeamFEMForceField>();
    f->name.set("FEM");
    f->young_modulus.set(E);
    f->poisson_ratio.set(nu);
    f->radius.set(r);
    f->radius_inner.set(ri);
    ff = static_cast<BeamFEMForceField*>(root->add_object(std::move(f)));
    init_root(*root);
  }

  std::size_t ndof() const { return dofs->size() * 6; }

  std::vector<double> force(const std::vector<double>& x) {
    dofs->write(kPosition) = x;
    auto& f = dofs->write(kForce);
    f.assign(ndof(), 0.0);
    ff->add_force(MechParams{});
    return f;
  }
  std::vector<double> dforce(const std::vector<double>& dx, double k = 1.0) {
    dofs->write(kDx) = dx;
    auto& df = dofs->write(kDforce);
    df.assign(ndof(), 0.0);
    MechParams p;
    p.k = k;
    ff->add_dforce(p, k);
    return df;
  }
  Eigen::MatrixXd dense_stiffness() {
    MatrixSink sink;
    EXPECT_TRUE(ff->build_stiffness(sink));
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(ndof(), ndof());
    for (const auto& e : sink.entries()) K(e.row, e.col) += e.value;
    return K;
  }
  bool has_error(const std::string& text) const {
    for (const Message& m : root->diagnostics().messages())
      if (m.severity == Severity::error && Diagnostics::format(m).find(text) != std::string::npos) return true;
    return false;
  }
};

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

std::vector<double> wiggle(std::size_t n, unsigned seed) {
  std::vector<double> v(n);
  unsigned s = seed * 2654435761u + 12345u;
  for (auto& x : v) {
    s = s * 1664525u + 1013904223u;
    x = (static_cast<double>(s >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
  }
  return v;
}

// x ⊕ h·d for every node (rigid rule: world-frame rotation vector).
std::vector<double> displaced(const std::vector<double>& x, const std::vector<double>& d, double h) {
  std::vector<double> out(x.size());
  for (std::size_t i = 0; i < x.size() / 7; ++i) rigid3_add_deriv(&x[i * 7], &d[i * 6], h, &out[i * 7]);
  return out;
}

// Rigid motion: rotation vector w about the origin, then translation t.
std::vector<double> rigidly_moved(const std::vector<double>& x, const Eigen::Vector3d& w, const Eigen::Vector3d& t) {
  const Eigen::Quaterniond q =
      w.norm() > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(w.norm(), w.normalized())) : Eigen::Quaterniond::Identity();
  std::vector<double> out(x.size());
  for (std::size_t i = 0; i < x.size() / 7; ++i) {
    const Eigen::Vector3d c = q * Eigen::Vector3d(x[i * 7], x[i * 7 + 1], x[i * 7 + 2]) + t;
    const Eigen::Quaterniond qi(x[i * 7 + 6], x[i * 7 + 3], x[i * 7 + 4], x[i * 7 + 5]);
    const Eigen::Quaterniond r = q * qi;
    out[i * 7] = c[0], out[i * 7 + 1] = c[1], out[i * 7 + 2] = c[2];
    out[i * 7 + 3] = r.x(), out[i * 7 + 4] = r.y(), out[i * 7 + 5] = r.z(), out[i * 7 + 6] = r.w();
  }
  return out;
}

// Central differences of add_force along d compared with add_dforce(d) (K at x, after add_force(x)).
double fd_error(BeamFixture& b, const std::vector<double>& x, const std::vector<double>& d, double h,
                double* scale = nullptr) {
  const std::vector<double> fp = b.force(displaced(x, d, h));
  const std::vector<double> fm = b.force(displaced(x, d, -h));
  b.force(x);  // beam frames at x
  const std::vector<double> df = b.dforce(d);
  double err = 0, s = 0;
  for (std::size_t i = 0; i < df.size(); ++i) {
    err = std::max(err, std::fabs((fp[i] - fm[i]) / (2 * h) - df[i]));
    s = std::max(s, std::fabs(df[i]));
  }
  if (scale) *scale = s;
  return err;
}

// Static solve of K·u = f with node 0 clamped (K assembled at the current frames).
Eigen::VectorXd clamped_solve(BeamFixture& b, const Eigen::VectorXd& f) {
  const Eigen::MatrixXd K = -b.dense_stiffness();  // ∂f/∂x = −K
  const int n = static_cast<int>(b.ndof()) - 6;
  const Eigen::VectorXd u = K.bottomRightCorner(n, n).ldlt().solve(f.tail(n));
  Eigen::VectorXd full = Eigen::VectorXd::Zero(b.ndof());
  full.tail(n) = u;
  return full;
}

constexpr double kE = 2e7, kNu = 0.49, kR = 0.1;

TEST(BeamFEM, ZeroForceAtRest) {
  BeamFixture b(7, 7.0, kE, kNu, kR);
  const std::vector<double> x = b.dofs->write(kPosition);
  EXPECT_EQ(max_abs(b.force(x)), 0.0);
  EXPECT_EQ(b.ff->beams().size(), 7u);
}

TEST(BeamFEM, RigidMotionGivesNoForce) {
  BeamFixture b(5, 3.0, kE, kNu, kR);
  const std::vector<double> x = b.dofs->write(kPosition);
  const double translated = max_abs(b.force(rigidly_moved(x, Eigen::Vector3d::Zero(), {0.3, -1.2, 2.5})));
  EXPECT_LT(translated, 1e-9);
  // Large rotation (about 1.6 rad about a skew axis) plus translation.
  const double rotated = max_abs(b.force(rigidly_moved(x, Eigen::Vector3d(0.7, -1.1, 0.9), {1, 2, 3})));
  std::printf("[beam] max |f| under rigid translation %.3g, under rigid rotation %.3g (EA/L = %.3g)\n", translated,
              rotated, kE * M_PI * kR * kR / 0.6);
  EXPECT_LT(rotated, 1e-6);  // round-off of EA/L ≈ 1e6 times ~1e-15 displacements
}

TEST(BeamFEM, DforceMatchesFiniteDifferencesWhereUnloaded) {
  BeamFixture b(4, 2.0, kE, kNu, kR);
  const std::vector<double> x0 = b.dofs->write(kPosition);
  const std::vector<double> d = wiggle(b.ndof(), 3);
  double scale = 0;
  const double e_rest = fd_error(b, x0, d, 1e-6, &scale);
  std::printf("[beam] FD vs add_dforce at rest: max err %.3g (|df| max %.3g)\n", e_rest, scale);
  EXPECT_LT(e_rest, 1e-6 * scale);
  // Rigidly rotated configuration: still unloaded, so K is the exact tangent.
  const std::vector<double> xr = rigidly_moved(x0, Eigen::Vector3d(0.4, 0.8, -0.5), {0.5, 0, -1});
  const double e_rot = fd_error(b, xr, d, 1e-6, &scale);
  std::printf("[beam] FD vs add_dforce rigidly rotated: max err %.3g (|df| max %.3g)\n", e_rot, scale);
  EXPECT_LT(e_rot, 1e-6 * scale);
}

TEST(BeamFEM, DforceApproximatesDerivativeWhenLoaded) {
  // Loaded beams: SOFA's K leaves out the derivative of the corotated frame,
  // so the gap grows with the deformation (first order in it).
  BeamFixture b(4, 2.0, kE, kNu, kR);
  const std::vector<double> x0 = b.dofs->write(kPosition);
  const std::vector<double> d = wiggle(b.ndof(), 5);
  for (double amp : {1e-4, 1e-3}) {
    const std::vector<double> x = displaced(x0, wiggle(b.ndof(), 9), amp);
    double scale = 0;
    const double e = fd_error(b, x, d, 1e-7, &scale);
    std::printf("[beam] deformation %.0e: FD vs add_dforce relative gap %.3g\n", amp, e / scale);
    EXPECT_LT(e / scale, 20 * amp);
  }
}

TEST(BeamFEM, AssembledStiffnessEqualsMatrixFreeProduct) {
  for (bool sym : {false, true}) {
    BeamFixture b(4, 2.0, kE, kNu, kR, 0.02);
    b.ff->use_symmetric_assembly.set(sym);
    const std::vector<double> x0 = b.dofs->write(kPosition);
    b.force(displaced(x0, wiggle(b.ndof(), 11), 0.2));  // frames of a deformed, rotated state
    const Eigen::MatrixXd K = b.dense_stiffness();
    const std::vector<double> d = wiggle(b.ndof(), 13);
    const std::vector<double> df = b.dforce(d, 0.7);
    const Eigen::VectorXd Kd = 0.7 * K * Eigen::Map<const Eigen::VectorXd>(d.data(), d.size());
    double err = 0;
    for (std::size_t i = 0; i < df.size(); ++i) err = std::max(err, std::fabs(Kd[i] - df[i]));
    std::printf("[beam] assembled vs matrix-free (symmetric=%d): max err %.3g (|df| max %.3g)\n", sym, err,
                max_abs(df));
    EXPECT_LT(err, 1e-9 * max_abs(df));
    EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
  }
}

TEST(BeamFEM, CantileverMatchesEulerBernoulli) {
  // Cubic Hermite beam elements are exact for point loads: tip deflection PL³/(3EI),
  // tip rotation PL²/(2EI), axial PL/(EA), twist TL/(GJ).
  const double L = 2.0, r = 0.05, ri = 0.02, E = 2e9, nu = 0.3, P = 10.0, T = 3.0;
  BeamFixture b(8, L, E, nu, r, ri);
  b.force(b.dofs->write(kPosition));
  const double I = M_PI * (std::pow(r, 4) - std::pow(ri, 4)) / 4, A = M_PI * (r * r - ri * ri);
  const double G = E / (2 * (1 + nu)), J = 2 * I;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(b.ndof());
  const int tip = 8 * 6;
  f[tip + 0] = P, f[tip + 1] = P, f[tip + 2] = P, f[tip + 3] = T;
  const Eigen::VectorXd u = clamped_solve(b, f);
  const double w = P * L * L * L / (3 * E * I), th = P * L * L / (2 * E * I);
  std::printf("[beam] cantilever tip: v %.9g (EB %.9g), w %.9g, θz %.9g (EB %.9g), axial %.9g (%.9g), twist %.9g "
              "(%.9g)\n",
              u[tip + 1], w, u[tip + 2], u[tip + 5], th, u[tip], P * L / (E * A), u[tip + 3], T * L / (G * J));
  EXPECT_NEAR(u[tip + 1], w, 1e-9 * w);
  EXPECT_NEAR(u[tip + 2], w, 1e-9 * w);
  EXPECT_NEAR(u[tip + 5], th, 1e-9 * th);   // bending about z from a load along y
  EXPECT_NEAR(u[tip + 4], -th, 1e-9 * th);  // bending about y from a load along z
  EXPECT_NEAR(u[tip + 0], P * L / (E * A), 1e-9 * P * L / (E * A));
  EXPECT_NEAR(u[tip + 3], T * L / (G * J), 1e-9 * T * L / (G * J));
}

TEST(BeamFEM, NonlinearStaticCantileverSmallLoad) {
  // The corotational force itself (not only K) gives the Euler–Bernoulli tip
  // deflection for a small load: fixed-point iterations x ← x + K⁻¹(f_ext + f(x)).
  const double L = 7.0, P = -2.0;  // the example scene's beam, a small tip load along y
  BeamFixture b(7, L, kE, kNu, kR);
  std::vector<double> x = b.dofs->write(kPosition);
  const int tip = 7;
  for (int it = 0; it < 50; ++it) {
    Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(b.force(x).data(), b.ndof());
    r[tip * 6 + 1] += P;
    const Eigen::VectorXd du = clamped_solve(b, r);
    x = displaced(x, std::vector<double>(du.data(), du.data() + du.size()), 1.0);
    if (du.cwiseAbs().maxCoeff() < 1e-15) break;
  }
  const double I = M_PI * std::pow(kR, 4) / 4, w = P * L * L * L / (3 * kE * I);
  std::printf("[beam] nonlinear static tip deflection %.9g, Euler–Bernoulli %.9g (rel %.2g)\n", x[tip * 7 + 1], w,
              std::fabs(x[tip * 7 + 1] / w - 1));
  EXPECT_NEAR(x[tip * 7 + 1], w, 2e-3 * std::fabs(w));  // geometric non-linearity ~ (w/L)²
}

TEST(BeamFEM, KernelMatchesTimoshenkoWithShearAreas) {
  // SOFA sets no shear area (φ = 0); the kernel still carries the Timoshenko terms:
  // a one-element cantilever deflects PL³/(3EI) + PL/(G·As).
  const double E = 2e7, nu = 0.3, L = 0.5, r = 0.1, P = 1.0;
  beam::BeamSection s = beam::make_section(E, L, nu, r, 0.0);
  s.Asy = s.Asz = 0.9 * s.A;
  const beam::Mat12 k = beam::local_stiffness(s);
  Eigen::Matrix<double, 6, 6> Kbb;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) Kbb(i, j) = k[(6 + i) * 12 + 6 + j];
  Eigen::Matrix<double, 6, 1> f = Eigen::Matrix<double, 6, 1>::Zero();
  f[1] = P;
  const Eigen::Matrix<double, 6, 1> u = Kbb.ldlt().solve(f);
  const double expected = P * L * L * L / (3 * E * s.Iz) + P * L / (s.G * s.Asy);
  const double eb = P * L * L * L / (3 * E * s.Iz);
  std::printf("[beam] Timoshenko tip %.9g (analytic %.9g; Euler–Bernoulli %.9g)\n", u[1], expected, eb);
  EXPECT_NEAR(u[1], expected, 1e-9 * expected);
  EXPECT_NEAR(u[5], P * L * L / (2 * E * s.Iz), 1e-9 * P * L * L / (2 * E * s.Iz));  // rotation unchanged
}

TEST(BeamFEM, BadInputIsReported) {
  {
    BeamFixture b(3, 1.0, kE, kNu, kR, 0.0, StateType::vec3);
    EXPECT_TRUE(b.has_error("Rigid3d"));
  }
  {
    BeamFixture b(3, 1.0, kE, kNu, kR, 0.0, StateType::rigid3, {{0, 1}, {1, 1}});
    EXPECT_TRUE(b.has_error("zero rest length"));
    b.force(b.dofs->write(kPosition));  // no crash, no force
  }
  {
    BeamFixture b(3, 1.0, kE, kNu, -0.1);
    EXPECT_TRUE(b.has_error("cross-section"));
  }
  {
    BeamFixture b(3, 1.0, kE, kNu, 0.1, 0.1);
    EXPECT_TRUE(b.has_error("cross-section"));
  }
  {
    BeamFixture b(3, 1.0, kE, kNu, kR, 0.0, StateType::rigid3, {{0, 1}, {1, 7}});
    EXPECT_TRUE(b.has_error("beyond the state size"));
  }
}

TEST(BeamFEM, NoEdgesIsReported) {
  auto root = std::make_unique<Node>("root");
  root->add_object(std::make_unique<MeshTopology>());
  auto mo = std::make_unique<MechanicalObject>(StateType::rigid3);
  FlatVec p;
  p.width = 7;
  p.data = {0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1};
  mo->position.set(p);
  auto* dofs = static_cast<MechanicalObject*>(root->add_object(std::move(mo)));
  auto* ff = static_cast<BeamFEMForceField*>(root->add_object(std::make_unique<BeamFEMForceField>()));
  init_root(*root);
  bool found = false;
  for (const Message& m : root->diagnostics().messages())
    found |= m.severity == Severity::error && Diagnostics::format(m).find("no edges") != std::string::npos;
  EXPECT_TRUE(found);
  dofs->write(kForce).assign(12, 0.0);
  ff->add_force(MechParams{});
  EXPECT_EQ(max_abs(dofs->write(kForce)), 0.0);
}

}  // namespace
}  // namespace sinew
