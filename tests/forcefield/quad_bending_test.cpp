// QuadBendingFEMForceField (SOFA's "small" quad plate): rest and rigid
// translation give no force, add_dforce is the derivative of add_force
// (K sized from the state's positions, as SOFA does), build_stiffness equals
// add_dforce, a clamped plate under a uniform load sags symmetrically, and
// bad input is reported without crashing.
#include "forcefield/fem/quad_bending_fem_force_field.h"

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
#include "state/mechanical_object.h"
#include "topology/mesh_topology.h"

namespace sinew {
namespace {

// A node holding a mesh topology, a Vec3d state and the force field.
struct Plate {
  std::unique_ptr<Node> root = std::make_unique<Node>("root");
  MechanicalObject* dofs = nullptr;
  QuadBendingFEMForceField* ff = nullptr;
  int n = 0;  // quads per side (grid plates only)

  Plate(const std::vector<Vec3>& points, const std::vector<Quad>& quads, bool with_topology = true,
        double E = 2000, double nu = 0.49, double t = 0.5) {
    if (with_topology) {
      auto topo = std::make_unique<MeshTopology>();
      topo->name.set("topo");
      topo->position.set(points);
      topo->quads_f.set(quads);
      root->add_object(std::move(topo));
    }
    auto mo = std::make_unique<MechanicalObject>(StateType::vec3);
    mo->name.set("dofs");
    if (!with_topology) {
      FlatVec p;
      for (const Vec3& q : points) p.data.insert(p.data.end(), {q[0], q[1], q[2]});
      mo->position.set(p);
    }
    dofs = static_cast<MechanicalObject*>(root->add_object(std::move(mo)));
    auto f = std::make_unique<QuadBendingFEMForceField>();
    f->name.set("FEM");
    f->young_modulus.set({E});
    f->poisson_ratio.set({nu});
    f->thickness.set(t);
    ff = static_cast<QuadBendingFEMForceField*>(root->add_object(std::move(f)));
    init_root(*root);
  }

  std::size_t ndof() const { return dofs->size() * 3; }

  std::vector<double> force(const std::vector<double>& x) {
    dofs->write(kPosition) = x;
    auto& f = dofs->write(kForce);
    std::fill(f.begin(), f.end(), 0.0);
    ff->add_force(MechParams{});
    return f;
  }
  std::vector<double> dforce(const std::vector<double>& dx, double k = 1.0) {
    dofs->write(kDx) = dx;
    auto& df = dofs->write(kDforce);
    std::fill(df.begin(), df.end(), 0.0);
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
  // True when an error of the force field contains `text`.
  bool has_error(const std::string& text) const {
    for (const Message& m : root->diagnostics().messages())
      if (m.severity == Severity::error && Diagnostics::format(m).find(text) != std::string::npos) return true;
    return false;
  }
};

// (n+1)² points on the square [0, size]² at z = 0; quad corners counter-clockwise
// so that q0q1 runs along x and q0q3 along y (the axes SOFA's element assumes).
Plate grid_plate(int n, double size = 1.0) {
  std::vector<Vec3> pts;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pts.emplace_back(size * i / n, size * j / n, 0.0);
  std::vector<Quad> quads;
  auto id = [n](int i, int j) { return static_cast<unsigned>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  Plate p(pts, quads);
  p.n = n;
  return p;
}

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

void expect_near_rel(const std::vector<double>& a, const std::vector<double>& b, double rel, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  const double scale = std::max({max_abs(a), max_abs(b), 1e-300});
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], rel * scale) << what << " entry " << i;
}

TEST(QuadBendingFEM, ZeroForceAtRest) {
  Plate p = grid_plate(3);
  ASSERT_EQ(p.ff->state(), ComponentState::valid);
  EXPECT_EQ(p.ff->elements().size(), 9u);
  const auto f = p.force(p.dofs->write(kRestPosition));
  EXPECT_LT(max_abs(f), 1e-12);
}

TEST(QuadBendingFEM, RigidTranslationGivesNoForce) {
  Plate p = grid_plate(3);
  std::vector<double> x = p.dofs->write(kRestPosition);
  for (std::size_t i = 0; i < x.size(); i += 3) {
    x[i] += 0.7;
    x[i + 1] -= 1.3;
    x[i + 2] += 2.1;
  }
  EXPECT_LT(max_abs(p.force(x)), 1e-9);
  // A deformed state shifted as a whole keeps its forces.
  std::vector<double> y = p.dofs->write(kRestPosition);
  const auto w = wiggle(y.size(), 3);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += 0.01 * w[i];
  const auto fy = p.force(y);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += (i % 3 == 2 ? 5.0 : -2.0);
  expect_near_rel(p.force(y), fy, 1e-9, "translated deformed state");
  EXPECT_GT(max_abs(fy), 1e-3);
}

// At rest the tangent of SOFA's force is exactly −K (K does not move to first order
// when the displacement is zero), so central differences must agree with add_dforce.
TEST(QuadBendingFEM, DforceMatchesFiniteDifferencesAtRest) {
  Plate p = grid_plate(3);
  const std::vector<double> x0 = p.dofs->write(kRestPosition);
  for (unsigned seed : {1u, 2u, 7u}) {
    const auto dx = wiggle(x0.size(), seed);
    const double h = 1e-6;
    std::vector<double> xp = x0, xm = x0;
    for (std::size_t i = 0; i < x0.size(); ++i) {
      xp[i] += h * dx[i];
      xm[i] -= h * dx[i];
    }
    const auto fp = p.force(xp), fm = p.force(xm);
    std::vector<double> fd(x0.size());
    for (std::size_t i = 0; i < fd.size(); ++i) fd[i] = (fp[i] - fm[i]) / (2 * h);
    p.force(x0);  // tangent at x0
    expect_near_rel(p.dforce(dx), fd, 1e-6, "add_dforce vs finite differences");
    // kfactor scales the product.
    const auto d1 = p.dforce(dx, 1.0), d3 = p.dforce(dx, -0.25);
    for (std::size_t i = 0; i < d1.size(); ++i) EXPECT_NEAR(d3[i], -0.25 * d1[i], 1e-12 * max_abs(d1));
  }
}

// Away from rest SOFA sizes K from the state's positions and applies it to the
// displacement of x: with the positions (hence K) held, the force is linear in x
// and add_dforce is its exact derivative. Evaluate x through another vector id.
TEST(QuadBendingFEM, DforceIsDerivativeForHeldShape) {
  Plate p = grid_plate(3);
  std::vector<double> xs = p.dofs->write(kRestPosition);
  const auto w = wiggle(xs.size(), 11);
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] += 0.05 * w[i];
  p.dofs->write(kPosition) = xs;
  auto force_of = [&](const std::vector<double>& x) {
    p.dofs->write(kFreePosition) = x;
    auto& f = p.dofs->write(kForce);
    std::fill(f.begin(), f.end(), 0.0);
    MechParams mp;
    mp.x = kFreePosition;
    p.ff->add_force(mp);
    return f;
  };
  const auto dx = wiggle(xs.size(), 5);
  const double h = 1e-4;
  std::vector<double> xp = xs, xm = xs;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    xp[i] += h * dx[i];
    xm[i] -= h * dx[i];
  }
  const auto fp = force_of(xp), fm = force_of(xm);
  std::vector<double> fd(xs.size());
  for (std::size_t i = 0; i < fd.size(); ++i) fd[i] = (fp[i] - fm[i]) / (2 * h);
  expect_near_rel(p.dforce(dx), fd, 1e-8, "add_dforce vs finite differences, shape held");
}

TEST(QuadBendingFEM, AssembledStiffnessEqualsMatrixFreeProduct) {
  Plate p = grid_plate(3);
  std::vector<double> x = p.dofs->write(kRestPosition);
  const auto w = wiggle(x.size(), 9);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.03 * w[i];
  p.force(x);
  const Eigen::MatrixXd K = p.dense_stiffness();
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
  for (unsigned seed : {2u, 4u}) {
    const auto dx = wiggle(p.ndof(), seed);
    const Eigen::VectorXd Kdx = K * Eigen::Map<const Eigen::VectorXd>(dx.data(), dx.size());
    expect_near_rel(std::vector<double>(Kdx.data(), Kdx.data() + Kdx.size()), p.dforce(dx), 1e-12,
                    "build_stiffness vs add_dforce");
  }
}

// Clamped square plate, uniform load −z on the free points: the static solution
// K·u = f sags everywhere, has the plate's symmetries and its lowest point in
// the middle; nothing moves in the plane.
TEST(QuadBendingFEM, ClampedPlateUnderUniformLoadSagsSymmetrically) {
  const int n = 6;
  Plate p = grid_plate(n);
  const Eigen::MatrixXd K = -p.dense_stiffness();  // build_stiffness gives ∂f/∂x = −K
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  std::vector<int> free_dofs;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i)
      for (int c = 0; c < 3; ++c) free_dofs.push_back(3 * id(i, j) + c);
  const int m = static_cast<int>(free_dofs.size());
  Eigen::MatrixXd Kff(m, m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
  for (int a = 0; a < m; ++a) {
    for (int b = 0; b < m; ++b) Kff(a, b) = K(free_dofs[a], free_dofs[b]);
    if (free_dofs[a] % 3 == 2) f[a] = -1.0;
  }
  const Eigen::VectorXd u = Kff.ldlt().solve(f);
  ASSERT_TRUE(u.allFinite());
  std::vector<double> uz((n + 1) * (n + 1), 0.0);
  for (int a = 0; a < m; ++a) {
    if (free_dofs[a] % 3 == 2) {
      uz[free_dofs[a] / 3] = u[a];
    } else {
      EXPECT_NEAR(u[a], 0.0, 1e-12) << "in-plane motion at dof " << free_dofs[a];
    }
  }
  double lowest = 0;
  for (int j = 1; j < n; ++j)
    for (int i = 1; i < n; ++i) {
      const double w = uz[id(i, j)];
      EXPECT_LT(w, 0.0) << "point (" << i << ", " << j << ")";
      const double tol = 1e-10 * std::fabs(w);
      EXPECT_NEAR(w, uz[id(n - i, j)], tol);
      EXPECT_NEAR(w, uz[id(i, n - j)], tol);
      EXPECT_NEAR(w, uz[id(j, i)], tol);
      lowest = std::min(lowest, w);
    }
  EXPECT_EQ(lowest, uz[id(n / 2, n / 2)]);
  // The static solution balances the load: the force field's own force there is
  // −load (K sized from the rest shape, as the linear solve assumed).
  p.dofs->write(kPosition) = p.dofs->read(kRestPosition);
  std::vector<double>& x = p.dofs->write(kFreePosition);
  x = p.dofs->write(kRestPosition);
  for (int a = 0; a < m; ++a) x[free_dofs[a]] += u[a];
  auto& fx = p.dofs->write(kForce);
  std::fill(fx.begin(), fx.end(), 0.0);
  MechParams mp;
  mp.x = kFreePosition;
  p.ff->add_force(mp);
  for (int a = 0; a < m; ++a) EXPECT_NEAR(fx[free_dofs[a]], -f[a], 1e-9);
}

TEST(QuadBendingFEM, UniformMembraneStretchLeavesInteriorUnloaded) {
  const int n = 4;
  Plate p = grid_plate(n);
  std::vector<double> x = p.dofs->write(kRestPosition);
  for (std::size_t i = 0; i < x.size(); i += 3) x[i] *= 1.01;  // ε_xx = 1 %
  const auto f = p.force(x);
  double sum_x = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int k = j * (n + 1) + i;
      sum_x += f[3 * k];
      if (i > 0 && i < n && j > 0 && j < n) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[3 * k + c], 0.0, 1e-9) << "interior point " << k;
      }
    }
  EXPECT_NEAR(sum_x, 0.0, 1e-9);
  // Stretched along x, the plate pulls its x = 0 edge towards +x and its x = 1 edge towards −x.
  EXPECT_GT(f[0], 0.0);
  EXPECT_LT(f[3 * n], 0.0);
}

TEST(QuadBendingFEM, DegenerateQuadIsReported) {
  // Points 0 and 1 coincide: edge q0q1 has zero length.
  Plate p({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {{0, 1, 2, 3}});
  EXPECT_EQ(p.ff->state(), ComponentState::invalid);
  EXPECT_TRUE(p.has_error("quad 0 is degenerate in its rest shape"));
  EXPECT_LT(max_abs(p.force(p.dofs->write(kRestPosition))), 1e-300);  // no crash, no force
  EXPECT_LT(max_abs(p.dforce(std::vector<double>(p.ndof(), 1.0))), 1e-300);
}

TEST(QuadBendingFEM, QuadCollapsingDuringSimulationStops) {
  Plate p = grid_plate(1);
  ASSERT_EQ(p.ff->state(), ComponentState::valid);
  std::vector<double> x = p.dofs->write(kRestPosition);
  for (int c = 0; c < 3; ++c) x[3 + c] = x[c];  // point 1 onto point 0
  const auto f = p.force(x);
  EXPECT_EQ(p.ff->state(), ComponentState::invalid);
  EXPECT_TRUE(p.has_error("quad 0 is degenerate"));
  for (double v : f) EXPECT_TRUE(std::isfinite(v));
}

TEST(QuadBendingFEM, OutOfRangeIndexIsReported) {
  Plate p({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {{0, 1, 2, 7}}, /*with_topology=*/true);
  EXPECT_EQ(p.ff->state(), ComponentState::invalid);
  EXPECT_TRUE(p.has_error("quad 0 refers to point 7"));
}

TEST(QuadBendingFEM, MissingTopologyIsReported) {
  Plate p({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {{0, 1, 2, 3}}, /*with_topology=*/false);
  EXPECT_EQ(p.ff->state(), ComponentState::invalid);
  EXPECT_TRUE(p.has_error("no topology found"));
  EXPECT_LT(max_abs(p.force(p.dofs->write(kPosition))), 1e-300);
}

}  // namespace
}  // namespace sinew
