// Mappings (spec/mechanics.md §6) and the visual model OglModel.
//
// Every mapping is checked on real numbers: Jᵀ is the adjoint of J on random
// vectors, apply_j equals central finite differences of apply, apply_djt
// equals finite differences of Jᵀ(x)·f, plus mapping-specific values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "core/matrix_sink.h"
#include "core/mechanical_ops.h"
#include "mapping/linear/barycentric_mapping.h"
#include "mapping/nonlinear/distance_mapping.h"
#include "mapping/nonlinear/rigid_mapping.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "visual/ogl_model.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {

template <class T>
T& find_named(Node& root, std::string_view name) {
  std::vector<T*> all;
  root.collect_down(all);
  for (T* t : all)
    if (t->name.value() == name) return *t;
  throw std::runtime_error("component '" + std::string(name) + "' not found");
}

Mapping& mapping_of(scene::LoadedScene& s, std::string_view name = "map") { return find_named<Mapping>(*s.root, name); }

std::vector<double> random_vec(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = d(gen);
  return v;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// J·u for random u on every input (kDx), returned per output scalar.
std::vector<double> apply_j_of(Mapping& m, const std::vector<std::vector<double>>& u) {
  auto ins = m.inputs();
  for (std::size_t k = 0; k < ins.size(); ++k) ins[k]->write(kDx) = u[k];
  m.apply_j(kDx, kDx);
  return m.output()->write(kDx);
}

// Jᵀ·w, per input.
std::vector<std::vector<double>> apply_jt_of(Mapping& m, const std::vector<double>& w) {
  auto ins = m.inputs();
  for (MechanicalState* s : ins) std::fill(s->write(kForce).begin(), s->write(kForce).end(), 0.0);
  m.output()->write(kForce) = w;
  m.apply_jt(kForce, kForce);
  std::vector<std::vector<double>> out;
  for (MechanicalState* s : ins) out.push_back(s->write(kForce));
  return out;
}

std::vector<std::vector<double>> random_input_derivs(Mapping& m, unsigned seed) {
  std::vector<std::vector<double>> u;
  for (MechanicalState* s : m.inputs()) u.push_back(random_vec(s->size() * s->info().deriv_width, seed++));
  return u;
}

// ⟨J u, w⟩ = ⟨u, Jᵀ w⟩.
void expect_adjoint(Mapping& m, unsigned seed = 1) {
  m.apply(kPosition);
  const auto u = random_input_derivs(m, seed);
  const auto ju = apply_j_of(m, u);
  const auto w = random_vec(ju.size(), seed + 100);
  const auto jtw = apply_jt_of(m, w);
  double rhs = 0;
  for (std::size_t k = 0; k < u.size(); ++k) rhs += dot(u[k], jtw[k]);
  const double lhs = dot(ju, w);
  EXPECT_NEAR(lhs, rhs, 1e-12 * (1 + std::abs(lhs))) << m.class_name();
  EXPECT_GT(std::abs(lhs), 1e-6) << "degenerate test vectors";
  // The assembled Jacobian (when the mapping provides it) gives the same product.
  std::vector<JacobianEntry> entries;
  if (m.jacobian(entries)) {
    std::vector<double> ju2(ju.size(), 0.0);
    for (const JacobianEntry& e : entries) ju2.at(e.row) += e.value * u.at(e.input).at(e.col);
    for (std::size_t i = 0; i < ju.size(); ++i) EXPECT_NEAR(ju2[i], ju[i], 1e-12) << m.class_name() << " row " << i;
  }
}

// x_k ← x0_k + h·u_k on every input (Rigid: exponential map), then apply.
std::vector<double> mapped_at(Mapping& m, const std::vector<std::vector<double>>& x0,
                              const std::vector<std::vector<double>>& u, double h) {
  auto ins = m.inputs();
  for (std::size_t k = 0; k < ins.size(); ++k) {
    ins[k]->write(kPosition) = x0[k];
    ins[k]->write(kDx) = u[k];
    ins[k]->add_deriv_to_coord(kPosition, kPosition, kDx, h);
  }
  m.apply(kPosition);
  return m.output()->write(kPosition);
}

// apply_j = central finite differences of apply (Vec outputs).
void expect_j_is_derivative(Mapping& m, unsigned seed = 7, double tol = 1e-7) {
  auto ins = m.inputs();
  std::vector<std::vector<double>> x0;
  for (MechanicalState* s : ins) x0.push_back(s->write(kPosition));
  const auto u = random_input_derivs(m, seed);
  const double h = 1e-6;
  const auto yp = mapped_at(m, x0, u, h);
  const auto ym = mapped_at(m, x0, u, -h);
  mapped_at(m, x0, u, 0.0);
  const auto ju = apply_j_of(m, u);
  ASSERT_EQ(ju.size(), yp.size());
  for (std::size_t i = 0; i < ju.size(); ++i)
    EXPECT_NEAR((yp[i] - ym[i]) / (2 * h), ju[i], tol * (1 + std::abs(ju[i]))) << m.class_name() << " row " << i;
}

// apply_djt(k = 1) = finite differences of Jᵀ(x)·w along u.
void expect_djt_is_derivative(Mapping& m, const std::vector<double>& w, unsigned seed = 11, double tol = 1e-6) {
  auto ins = m.inputs();
  std::vector<std::vector<double>> x0;
  for (MechanicalState* s : ins) x0.push_back(s->write(kPosition));
  const auto u = random_input_derivs(m, seed);
  const double h = 1e-6;
  mapped_at(m, x0, u, h);
  const auto gp = apply_jt_of(m, w);
  mapped_at(m, x0, u, -h);
  const auto gm = apply_jt_of(m, w);
  mapped_at(m, x0, u, 0.0);
  m.output()->write(kForce) = w;
  for (std::size_t k = 0; k < ins.size(); ++k) {
    ins[k]->write(kDx) = u[k];
    std::fill(ins[k]->write(kDforce).begin(), ins[k]->write(kDforce).end(), 0.0);
  }
  m.apply_djt(kDforce, kDx, 1.0);
  double scale = 0;
  for (std::size_t k = 0; k < ins.size(); ++k) scale = std::max(scale, max_abs(ins[k]->write(kDforce)));
  EXPECT_GT(scale, 1e-6) << "geometric stiffness is zero in this test";
  for (std::size_t k = 0; k < ins.size(); ++k) {
    const auto& df = ins[k]->read(kDforce);
    for (std::size_t i = 0; i < df.size(); ++i)
      EXPECT_NEAR((gp[k][i] - gm[k][i]) / (2 * h), df[i], tol * (1 + scale)) << m.class_name() << " input " << k
                                                                             << " scalar " << i;
  }
}

std::vector<double> pos(scene::LoadedScene& s, std::string_view name) {
  return find_named<MechanicalState>(*s.root, name).write(kPosition);
}

}  // namespace

// ---------------------------------------------------------------- IdentityMapping

TEST(MapIdentity, CopiesPositionsAndVelocitiesAndResizesOutput) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" position="1 2 3 4 5 6" velocity="0.1 0.2 0.3 0.4 0.5 0.6"/>
    <Node name="child">
      <MechanicalObject name="out"/>
      <IdentityMapping name="map" input="@../in" output="@out"/>
    </Node>
  </Node>)");
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(find_named<MechanicalState>(*s.root, "out").write(kVelocity), (std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6}));
  auto& m = mapping_of(s);
  EXPECT_TRUE(m.is_mechanical());
  EXPECT_FALSE(find_named<MechanicalState>(*s.root, "out").independent());
  expect_adjoint(m);
  expect_j_is_derivative(m);
}

TEST(MapIdentity, RigidTemplateDeducedFromStates) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" template="Rigid3d" position="1 2 3 0 0 0.6 0.8  4 5 6 0 0 0 1"/>
    <Node name="child">
      <MechanicalObject name="out" template="Rigid3d"/>
      <IdentityMapping name="map"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_EQ(m.template_name(), "Rigid3d,Rigid3d");
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{1, 2, 3, 0, 0, 0.6, 0.8, 4, 5, 6, 0, 0, 0, 1}));
  expect_adjoint(m);
}

// Rigid3d → Vec3d copies the centres (collision points of rigid bodies).
TEST(MapIdentity, RigidToVec3CopiesCentres) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" template="Rigid3d" position="1 2 3 0 0 0.6 0.8" velocity="0.1 0.2 0.3 1 2 3"/>
    <Node name="child">
      <MechanicalObject name="out"/>
      <IdentityMapping name="map"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_EQ(m.template_name(), "Rigid3d,Vec3d");
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(find_named<MechanicalState>(*s.root, "out").write(kVelocity), (std::vector<double>{0.1, 0.2, 0.3}));
  expect_adjoint(m);
  expect_j_is_derivative(m);
  const auto jt = apply_jt_of(m, {4, 5, 6});
  EXPECT_EQ(jt[0], (std::vector<double>{4, 5, 6, 0, 0, 0}));
}

// ---------------------------------------------------------------- SubsetMapping

TEST(MapSubset, IndicesAndNearestPointSearch) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" position="0 0 0  1 0 0  2 0 0  3 0 0"/>
    <Node name="a">
      <MechanicalObject name="outA"/>
      <SubsetMapping name="map" indices="3 1" handleTopologyChange="false"/>
    </Node>
    <Node name="b">
      <MechanicalObject name="outB" position="2 0 0  0 0 0"/>
      <SubsetMapping name="mapB" handleTopologyChange="false"/>
    </Node>
  </Node>)");
  EXPECT_EQ(pos(s, "outA"), (std::vector<double>{3, 0, 0, 1, 0, 0}));
  EXPECT_EQ(pos(s, "outB"), (std::vector<double>{2, 0, 0, 0, 0, 0}));
  auto& m = mapping_of(s);
  expect_adjoint(m);
  expect_j_is_derivative(m);
  // Jᵀ adds each output force to its source point.
  auto jt = apply_jt_of(m, {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(jt[0], (std::vector<double>{0, 0, 0, 4, 5, 6, 0, 0, 0, 1, 2, 3}));
}

// ---------------------------------------------------------------- BarycentricMapping

// A regular grid mapping reproduces affine deformations exactly, also for
// points outside the grid (nearest cell, extrapolated coordinates).
TEST(MapBarycentric, RegularGridReproducesAffineFieldsAndExtrapolates) {
  auto s = load(R"(<Node gravity="0 0 0">
    <RegularGridTopology name="grid" n="3 3 3" min="0 0 0" max="2 2 2"/>
    <MechanicalObject name="in"/>
    <Node name="child">
      <MechanicalObject name="out" position="0.5 0.25 1.5  1.9 1.1 0.2  2.5 -0.5 1  0 0 0"/>
      <BarycentricMapping name="map" input="@../in" output="@out"/>
    </Node>
  </Node>)");
  auto& m = dynamic_cast<BarycentricMapping&>(mapping_of(s));
  EXPECT_EQ(m.mapper_name(), "RegularGrid");
  // Identity at rest (positions propagated at the end of init).
  const std::vector<double> x0{0.5, 0.25, 1.5, 1.9, 1.1, 0.2, 2.5, -0.5, 1, 0, 0, 0};
  const auto out0 = pos(s, "out");
  for (std::size_t i = 0; i < x0.size(); ++i) EXPECT_NEAR(out0[i], x0[i], 1e-14);
  // Affine map y = A x + b applied to the grid points → same map on the embedded points.
  auto& in = find_named<MechanicalState>(*s.root, "in");
  const Mat3 A = (Mat3() << 1.1, 0.2, -0.3, 0.05, 0.9, 0.1, 0.4, -0.2, 1.3).finished();
  const Vec3 b(0.3, -1, 2);
  auto& xin = in.write(kPosition);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Vec3 p = A * Vec3(xin[3 * i], xin[3 * i + 1], xin[3 * i + 2]) + b;
    for (int c = 0; c < 3; ++c) xin[3 * i + c] = p[c];
  }
  m.apply(kPosition);
  const auto out = pos(s, "out");
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3 e = A * Vec3(x0[3 * i], x0[3 * i + 1], x0[3 * i + 2]) + b;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out[3 * i + c], e[c], 1e-12) << "point " << i;
  }
  expect_adjoint(m);
  expect_j_is_derivative(m);
}

TEST(MapBarycentric, TetrahedralMeshAndSetContainerMappers) {
  const std::string tets = R"(position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1" tetrahedra="0 1 2 3  1 2 3 4")";
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="mesh">
      <MeshTopology name="topo" )" + tets + R"(/>
      <MechanicalObject name="in"/>
      <Node name="child">
        <MechanicalObject name="out" position="0.1 0.2 0.3  0.6 0.6 0.6  2 2 2"/>
        <BarycentricMapping name="map"/>
      </Node>
    </Node>
    <Node name="set">
      <TetrahedronSetTopologyContainer name="topo2" )" + tets + R"(/>
      <MechanicalObject name="in2"/>
      <Node name="child2">
        <MechanicalObject name="out2" position="0.1 0.2 0.3  0.6 0.6 0.6  2 2 2"/>
        <BarycentricMapping name="map2"/>
      </Node>
    </Node>
  </Node>)");
  auto& m = dynamic_cast<BarycentricMapping&>(mapping_of(s));
  auto& m2 = dynamic_cast<BarycentricMapping&>(mapping_of(s, "map2"));
  EXPECT_EQ(m.mapper_name(), "Mesh");
  EXPECT_EQ(m2.mapper_name(), "TetrahedronSet");
  const std::vector<double> x0{0.1, 0.2, 0.3, 0.6, 0.6, 0.6, 2, 2, 2};
  for (const char* name : {"out", "out2"}) {
    const auto out = pos(s, name);
    for (std::size_t i = 0; i < x0.size(); ++i) EXPECT_NEAR(out[i], x0[i], 1e-12) << name << " " << i;
  }
  // Weights of point 0 in tetrahedron 0: (1 − 0.6, 0.1, 0.2, 0.3).
  auto& in = find_named<MechanicalState>(*s.root, "in");
  std::vector<double> ju = apply_j_of(m, {{1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}});
  EXPECT_NEAR(ju[0], 0.4, 1e-14);
  (void)in;
  expect_adjoint(m);
  expect_j_is_derivative(m);
  expect_adjoint(m2);
}

TEST(MapBarycentric, GridWithoutVolumeIsRefused) {
  auto s = test::build(R"(<Node gravity="0 0 0">
    <RegularGridTopology name="grid" n="3 3 1" min="0 0 0" max="2 2 0"/>
    <MechanicalObject name="in"/>
    <Node name="child">
      <MechanicalObject name="out" position="0.5 0.5 0"/>
      <BarycentricMapping name="map"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_EQ(mapping_of(s).state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "no volume"));
}

// ---------------------------------------------------------------- RigidMapping

TEST(MapRigid, LocalCoordinatesPositionsVelocitiesAndGeometricStiffness) {
  // Rigid at (1,2,3), q = (0, 0, 0.6, 0.8): rotation about z with cos = 0.28, sin = 0.96.
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="rigid" template="Rigid3d" position="1 2 3 0 0 0.6 0.8" velocity="0.1 0 0 0 0 2"/>
    <Node name="local">
      <MechanicalObject name="pts" position="1 0 0  0 0 1"/>
      <RigidMapping name="map" geometricStiffness="Exact"/>
    </Node>
    <Node name="global">
      <MechanicalObject name="pts2" position="1 3 3"/>
      <RigidMapping name="map2" globalToLocalCoords="true"/>
    </Node>
  </Node>)");
  const auto p = pos(s, "pts");
  EXPECT_NEAR(p[0], 1.28, 1e-12);
  EXPECT_NEAR(p[1], 2.96, 1e-12);
  EXPECT_NEAR(p[2], 3, 1e-12);
  EXPECT_NEAR(p[3], 1, 1e-12);
  EXPECT_NEAR(p[4], 2, 1e-12);
  EXPECT_NEAR(p[5], 4, 1e-12);
  // v = v_r + ω × r = (0.1,0,0) + (0,0,2) × (0.28,0.96,0) = (−1.82, 0.56, 0).
  const auto v = find_named<MechanicalState>(*s.root, "pts").write(kVelocity);
  EXPECT_NEAR(v[0], -1.82, 1e-12);
  EXPECT_NEAR(v[1], 0.56, 1e-12);
  EXPECT_NEAR(v[2], 0, 1e-12);
  // globalToLocalCoords: the point stays where it was given.
  const auto p2 = pos(s, "pts2");
  EXPECT_NEAR(p2[0], 1, 1e-12);
  EXPECT_NEAR(p2[1], 3, 1e-12);
  EXPECT_NEAR(p2[2], 3, 1e-12);
  auto& m = mapping_of(s);
  expect_adjoint(m);
  expect_j_is_derivative(m);
  expect_djt_is_derivative(m, {0.3, -1.2, 0.7, 2.0, 0.5, -0.4});
}

// Stabilized: K = Σ [f]×·[p]× = Σ (p·fᵀ − (f·p)·I), symmetrised, positive eigenvalues dropped.
TEST(MapRigid, StabilizedGeometricStiffnessIsTheNegativePartOfTheSymmetrisedBlock) {
  auto torque_of = [](const char* points, const std::vector<double>& forces, const char* mode) {
    auto s = load(std::string(R"(<Node gravity="0 0 0">
      <MechanicalObject name="rigid" template="Rigid3d" position="0 0 0 0 0 0 1"/>
      <Node name="local"><MechanicalObject name="pts" position=")") + points +
                  R"("/><RigidMapping name="map" geometricStiffness=")" + mode + R"("/></Node></Node>)");
    auto& m = mapping_of(s);
    auto& rigid = find_named<MechanicalState>(*s.root, "rigid");
    m.output()->write(kForce) = forces;
    std::vector<std::vector<double>> K;  // columns: the torque for δω = e_c, k = 2
    for (int c = 0; c < 3; ++c) {
      std::vector<double> dx(6, 0.0);
      dx[3 + c] = 1;
      rigid.write(kDx) = dx;
      std::fill(rigid.write(kDforce).begin(), rigid.write(kDforce).end(), 0.0);
      m.apply_djt(kDforce, kDx, 2.0);
      const auto& df = rigid.write(kDforce);
      K.push_back({df[3] / 2, df[4] / 2, df[5] / 2});
    }
    // The assembled entries are the same matrix.
    MatrixSink sink;
    EXPECT_TRUE(m.build_geometric_stiffness(sink));
    std::vector<double> dense(36, 0.0);
    for (const auto& e : sink.entries()) dense[e.row * 6 + e.col] += e.value;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(dense[(3 + a) * 6 + 3 + b], K[b][a], 1e-14) << a << b;
    return K;
  };
  // p = (1,0,0), f = (0,3,0); p = (0,2,0), f = (1,0,0): K = [[0,3,0],[2,0,0],[0,0,0]], its
  // symmetric part has eigenvalues ±2.5 and 0; the negative part is −2.5·v·vᵀ, v = (1,−1,0)/√2.
  const auto K = torque_of("1 0 0  0 2 0", {0, 3, 0, 1, 0, 0}, "Stabilized");
  const double want[3][3] = {{-1.25, 1.25, 0}, {1.25, -1.25, 0}, {0, 0, 0}};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(K[b][a], want[a][b], 1e-14) << a << b;
  // Already negative semi-definite (a point pulled outward along its arm): kept as is,
  // p·fᵀ − (f·p)·I = diag(0, −2, −2).
  const auto K2 = torque_of("1 0 0", {2, 0, 0}, "2");
  EXPECT_NEAR(K2[0][0], 0, 1e-14);
  EXPECT_NEAR(K2[1][1], -2, 1e-14);
  EXPECT_NEAR(K2[2][2], -2, 1e-14);
  EXPECT_NEAR(K2[1][0], 0, 1e-14);
}

TEST(MapRigid, Rigid2dIndexFromEndAndPerPointRigids) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="rigid" template="Rigid2d" position="0 0 0  5 0 1.5707963267948966"/>
    <Node name="a">
      <MechanicalObject name="pa" template="Vec2d" position="1 0"/>
      <RigidMapping name="map" index="0" indexFromEnd="true"/>
    </Node>
    <Node name="b">
      <MechanicalObject name="pb" template="Vec2d" position="1 0  1 0"/>
      <RigidMapping name="map2" rigidIndexPerPoint="0 1"/>
    </Node>
  </Node>)");
  const auto pa = pos(s, "pa");
  EXPECT_NEAR(pa[0], 5, 1e-12);
  EXPECT_NEAR(pa[1], 1, 1e-12);
  const auto pb = pos(s, "pb");
  EXPECT_NEAR(pb[0], 1, 1e-12);
  EXPECT_NEAR(pb[1], 0, 1e-12);
  EXPECT_NEAR(pb[2], 5, 1e-12);
  EXPECT_NEAR(pb[3], 1, 1e-12);
  expect_adjoint(mapping_of(s));
  expect_adjoint(mapping_of(s, "map2"));
  expect_j_is_derivative(mapping_of(s, "map2"));
}

// ---------------------------------------------------------------- BeamLinearMapping

TEST(MapBeamLinear, SmoothInterpolationBetweenFrames) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="frames" template="Rigid3d" position="0 0 0 0 0 0 1  2 0 0 0 0 0 1"/>
    <Node name="straight">
      <MechanicalObject name="pts" position="0.5 0.1 0  0 0 0.2  1.25 0 0"/>
      <BeamLinearMapping name="map"/>
    </Node>
  </Node>)");
  // t = 0.5 → h = 0.5; both frames give (1, 0.2, 0).
  const auto p = pos(s, "pts");
  EXPECT_NEAR(p[0], 1, 1e-15);
  EXPECT_NEAR(p[1], 0.2, 1e-15);
  EXPECT_NEAR(p[5], 0.4, 1e-15);
  EXPECT_NEAR(p[6], 2.5, 1e-15);  // extrapolated past the last frame along the last beam
  expect_adjoint(mapping_of(s));
}

TEST(MapBeamLinear, DerivativesOnRotatedFrames) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="frames" template="Rigid3d"
        position="0 0 0 0 0 0.6 0.8  1 1 0 0.28 0 0 0.96  2 1.5 0.5 0 0.6 0 0.8"/>
    <Node name="pts">
      <MechanicalObject name="pts" position="0.3 0.1 -0.2  1.6 -0.1 0.05  1.0 0.2 0.2"/>
      <BeamLinearMapping name="map"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  expect_adjoint(m);
  expect_j_is_derivative(m);
}

// ---------------------------------------------------------------- distance mappings

namespace {
const char* kTriangleEdges = R"(<MeshTopology name="topo" edges="0 1  1 2  2 0  3 1"/>)";
const char* kPoints = R"(position="0 0 0  1.5 0.2 0  0.3 1.1 0.4  2 2 -1")";
}  // namespace

TEST(MapDistance, LengthsRestLengthsAndExactGeometricStiffness) {
  auto s = load(std::string(R"(<Node gravity="0 0 0">)") + kTriangleEdges + R"(
    <MechanicalObject name="in" )" + kPoints + R"(/>
    <Node name="child">
      <MechanicalObject name="out" template="Vec1d"/>
      <DistanceMapping name="map" topology="@../topo" geometricStiffness="Exact" applyRestPosition="true"/>
    </Node>
    <Node name="child2">
      <MechanicalObject name="out2" template="Vec1d"/>
      <DistanceMapping name="map2" topology="@../topo" computeDistance="true"/>
    </Node>
  </Node>)");
  auto& m = dynamic_cast<DistanceMapping&>(mapping_of(s));
  // Rest lengths are the initial lengths: outputs are 0; with computeDistance the lengths themselves.
  const auto out = pos(s, "out");
  ASSERT_EQ(out.size(), 4u);
  for (double d : out) EXPECT_NEAR(d, 0, 1e-15);
  const auto out2 = pos(s, "out2");
  EXPECT_NEAR(out2[0], std::sqrt(1.5 * 1.5 + 0.2 * 0.2), 1e-15);
  EXPECT_NEAR(out2[3], std::sqrt(0.5 * 0.5 + 1.8 * 1.8 + 1.0), 1e-15);
  EXPECT_NEAR(m.rest_lengths.get()[1], std::sqrt(1.2 * 1.2 + 0.9 * 0.9 + 0.16), 1e-15);
  // Stretch the input so that lengths differ from the rest lengths.
  auto& in = find_named<MechanicalState>(*s.root, "in");
  in.write(kPosition)[3] = 1.8;
  expect_adjoint(m);
  expect_j_is_derivative(m);
  expect_djt_is_derivative(m, {0.5, -1.0, 2.0, 0.25});
  // Stabilized keeps only edges in extension (λ < 0); None has no geometric stiffness.
  auto& m2 = mapping_of(s, "map2");
  expect_adjoint(m2);
}

TEST(MapDistance, StabilizedKeepsOnlyTensionAndNoneIsZero) {
  auto s = load(std::string(R"(<Node gravity="0 0 0">)") + kTriangleEdges + R"(
    <MechanicalObject name="in" )" + kPoints + R"(/>
    <Node name="c1"><MechanicalObject name="o1" template="Vec1d"/>
      <DistanceMapping name="stab" topology="@../topo"/></Node>
    <Node name="c2"><MechanicalObject name="o2" template="Vec1d"/>
      <DistanceMapping name="exact" topology="@../topo" geometricStiffness="1"/></Node>
    <Node name="c3"><MechanicalObject name="o3" template="Vec1d"/>
      <DistanceMapping name="none" topology="@../topo" geometricStiffness="None"/></Node>
  </Node>)");
  auto& in = find_named<MechanicalState>(*s.root, "in");
  auto djt = [&](Mapping& m, const std::vector<double>& w) {
    m.apply(kPosition);
    m.output()->write(kForce) = w;
    in.write(kDx) = random_vec(12, 3);
    std::fill(in.write(kDforce).begin(), in.write(kDforce).end(), 0.0);
    m.apply_djt(kDforce, kDx, 1.0);
    return in.write(kDforce);
  };
  // Only edge 1 in tension: Stabilized equals Exact restricted to that edge.
  const auto a = djt(mapping_of(s, "stab"), {0.0, -2.0, 3.0, 0.0});
  const auto b = djt(mapping_of(s, "exact"), {0.0, -2.0, 0.0, 0.0});
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-15);
  EXPECT_GT(max_abs(a), 1e-3);
  EXPECT_EQ(max_abs(djt(mapping_of(s, "none"), {1, -2, 3, 4})), 0.0);
}

TEST(MapSquareDistance, SquaredLengthsAndDerivatives) {
  auto s = load(std::string(R"(<Node gravity="0 0 0">)") + kTriangleEdges + R"(
    <MechanicalObject name="in" )" + kPoints + R"(/>
    <Node name="child">
      <MechanicalObject name="out" template="Vec1d"/>
      <SquareDistanceMapping name="map" topology="@../topo" geometricStiffness="1"/>
    </Node>
  </Node>)");
  const auto out = pos(s, "out");
  EXPECT_NEAR(out[0], 1.5 * 1.5 + 0.2 * 0.2, 1e-15);
  EXPECT_NEAR(out[2], 0.3 * 0.3 + 1.1 * 1.1 + 0.4 * 0.4, 1e-15);
  auto& m = mapping_of(s);
  expect_adjoint(m);
  expect_j_is_derivative(m);
  expect_djt_is_derivative(m, {0.5, -1.0, 2.0, 0.25});
}

TEST(MapDistanceMulti, TwoInputsThroughIndexPairs) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" position="0 0 0  1 0 0"/></Node>
    <Node name="b"><MechanicalObject name="pb" position="3 1 0  4 4 1"/></Node>
    <Node name="link">
      <MechanicalObject name="out" template="Vec1d"/>
      <MeshTopology name="edges" edges="0 1  1 2"/>
      <DistanceMultiMapping name="map" template="Vec3,Vec1" topology="@edges" input="@../a @../b" output="@out"
                            indexPairs="0 1  1 0  1 1" restLengths="1 0.5" geometricStiffness="Exact"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  ASSERT_EQ(m.inputs().size(), 2u);
  const auto out = pos(s, "out");
  EXPECT_NEAR(out[0], std::sqrt(4.0 + 1.0) - 1, 1e-15);
  EXPECT_NEAR(out[1], std::sqrt(1.0 + 9.0 + 1.0) - 0.5, 1e-15);
  expect_adjoint(m);
  expect_j_is_derivative(m);
  expect_djt_is_derivative(m, {-0.7, 1.3});
  // The forces of the mapped node reach both inputs in a force computation.
  MechanicalOps ops(*s.root);
  EXPECT_EQ(ops.mappings().size(), 1u);
}

// ---------------------------------------------------------------- SubsetMultiMapping

TEST(MapSubsetMulti, GathersPointsOfSeveralInputs) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" position="0 0 0  1 0 0  2 0 0"/></Node>
    <Node name="b"><MechanicalObject name="pb" position="3 1 0  4 4 1"/></Node>
    <Node name="all">
      <MechanicalObject name="out"/>
      <SubsetMultiMapping name="map" template="Vec3,Vec3" input="@../a @../b" output="@out"
                          indexPairs="1 1  0 2  0 0  1 1"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  ASSERT_EQ(m.inputs().size(), 2u);
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{4, 4, 1, 2, 0, 0, 0, 0, 0, 4, 4, 1}));
  expect_adjoint(m);
  expect_j_is_derivative(m);
  // Jᵀ sums the two outputs that share a point.
  const auto jt = apply_jt_of(m, {1, 2, 3, 10, 20, 30, 100, 200, 300, 4, 5, 6});
  EXPECT_EQ(jt[1], (std::vector<double>{0, 0, 0, 5, 7, 9}));
  EXPECT_EQ(jt[0], (std::vector<double>{100, 200, 300, 0, 0, 0, 10, 20, 30}));
}

TEST(MapSubsetMulti, RigidToVecTakesTheCentres) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" template="Rigid3" position="1 2 3 0 0 0.6 0.8"/></Node>
    <Node name="b"><MechanicalObject name="pb" template="Rigid3" position="0 0 0 0 0 0 1  5 6 7 0.6 0 0 0.8"/></Node>
    <Node name="all">
      <MechanicalObject name="out"/>
      <SubsetMultiMapping name="map" template="Rigid3,Vec3" input="@../a @../b" output="@out"
                          indexPairs="0 0  1 1"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{1, 2, 3, 5, 6, 7}));
  expect_adjoint(m);
  expect_j_is_derivative(m);
  // Forces reach the translational part only.
  const auto jt = apply_jt_of(m, {1, 2, 3, 4, 5, 6});
  EXPECT_EQ(jt[0], (std::vector<double>{1, 2, 3, 0, 0, 0}));
  EXPECT_EQ(jt[1], (std::vector<double>{0, 0, 0, 0, 0, 0, 4, 5, 6, 0, 0, 0}));
}

TEST(MapSubsetMulti, RigidToRigidCopiesFrames) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" template="Rigid3" position="1 2 3 0 0 0.6 0.8"/></Node>
    <Node name="b"><MechanicalObject name="pb" template="Rigid3" position="5 6 7 0.6 0 0 0.8"/></Node>
    <Node name="all">
      <MechanicalObject name="out" template="Rigid3"/>
      <SubsetMultiMapping name="map" template="Rigid3,Rigid3" input="@../a @../b" output="@out"
                          indexPairs="1 0  0 0"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{5, 6, 7, 0.6, 0, 0, 0.8, 1, 2, 3, 0, 0, 0.6, 0.8}));
  expect_adjoint(m);  // (the output is a frame: apply_j is checked against the identity by the adjoint test)
}

TEST(MapIdentityMulti, ConcatenatesTheInputs) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" position="0 0 0  1 0 0  2 0 0"/></Node>
    <Node name="b"><MechanicalObject name="pb" position="3 1 0  4 4 1"/></Node>
    <Node name="all">
      <MechanicalObject name="out"/>
      <IdentityMultiMapping name="map" input="@../b @../a" output="@out"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_EQ(pos(s, "out"), (std::vector<double>{3, 1, 0, 4, 4, 1, 0, 0, 0, 1, 0, 0, 2, 0, 0}));
  expect_adjoint(m);
  expect_j_is_derivative(m);
}

TEST(MapSubsetMulti, BadIndexPairsAreClearErrors) {
  const char* scene = R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" position="0 0 0  1 0 0"/></Node>
    <Node name="all">
      <MechanicalObject name="out"/>
      <SubsetMultiMapping name="map" input="@../a" output="@out" indexPairs="%s"/>
    </Node>
  </Node>)";
  const std::pair<const char*, const char*> cases[] = {
      {"0 0 1", "must hold (input index, point index) couples"},
      {"0 0  1 0", "names input 1 but there are 1 inputs"},
      {"0 2", "names point 2 of input 0"},
  };
  for (const auto& [pairs, msg] : cases) {
    char buf[1024];
    std::snprintf(buf, sizeof buf, scene, pairs);
    auto s = test::build(buf);
    ASSERT_TRUE(s.root);
    init_root(*s.root);
    EXPECT_EQ(mapping_of(s).state(), ComponentState::invalid) << pairs;
    EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), msg)) << pairs;
  }
}

TEST(MapSubsetMulti, ConstraintRowsGoToTheirInputs) {
  auto s = load(R"(<Node gravity="0 0 0">
    <Node name="a"><MechanicalObject name="pa" position="0 0 0  1 0 0"/></Node>
    <Node name="b"><MechanicalObject name="pb" position="3 1 0  4 4 1"/></Node>
    <Node name="all">
      <MechanicalObject name="out"/>
      <SubsetMultiMapping name="map" input="@../a @../b" output="@out" indexPairs="1 1  0 0"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  std::vector<JacobianEntry> j;
  ASSERT_TRUE(m.jacobian(j));
  ASSERT_EQ(j.size(), 6u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(j[c].input, 1u);
    EXPECT_EQ(j[c].row, static_cast<std::uint32_t>(c));
    EXPECT_EQ(j[c].col, static_cast<std::uint32_t>(3 + c));
    EXPECT_EQ(j[3 + c].input, 0u);
    EXPECT_EQ(j[3 + c].row, static_cast<std::uint32_t>(3 + c));
    EXPECT_EQ(j[3 + c].col, static_cast<std::uint32_t>(c));
    EXPECT_EQ(j[c].value, 1.0);
  }
}

// ---------------------------------------------------------------- framework plumbing

TEST(MapFramework, IsMechanicalAliasAndMapForcesPruning) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" position="0 0 0 1 1 1"/>
    <Node name="child">
      <MechanicalObject name="out"/>
      <IdentityMapping name="map" isMechanical="false"/>
      <UniformMass totalMass="1"/>
    </Node>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_FALSE(m.map_forces.value());
  EXPECT_FALSE(m.map_masses.value());
  EXPECT_TRUE(m.map_constraints.value());
  MechanicalOps ops(*s.root);
  EXPECT_TRUE(ops.mappings().empty());    // no force / dx propagation through it
  EXPECT_TRUE(ops.masses().empty());      // the subtree below is pruned for forces
  EXPECT_EQ(ops.all_states().size(), 1u);
}

TEST(MapFramework, MissingInputIsAClearError) {
  auto s = test::build(R"(<Node gravity="0 0 0">
    <MechanicalObject name="in" position="0 0 0"/>
    <Node name="child">
      <MechanicalObject name="out" template="Vec1d"/>
      <MeshTopology name="t" edges="0 5"/>
      <DistanceMapping name="map" topology="@t"/>
    </Node>
  </Node>)");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  EXPECT_EQ(mapping_of(s).state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "edge 0 uses point 5"));
}

// ---------------------------------------------------------------- OglModel

TEST(MapOglModel, VisualOutputIsNonMechanicalAndFollowsTheSimulation) {
  auto s = load(R"(<Node gravity="0 -10 0" dt="0.1">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="20" tolerance="1e-12" threshold="1e-20"/>
    <MechanicalObject name="in" position="0 0 0  1 0 0"/>
    <UniformMass totalMass="2"/>
    <Node name="visu">
      <OglModel name="visual" color="red" dy="1" scale="2"/>
      <IdentityMapping name="map" input="@.." output="@visual"/>
    </Node>
    <Node name="visu2">
      <VisualModel name="visual2" position="0.5 0 0"/>
      <BarycentricMapping name="bary" input="@.." output="@visual2" input_topology="@../edges"/>
    </Node>
    <MeshTopology name="edges" edges="0 1"/>
  </Node>)");
  auto& m = mapping_of(s);
  EXPECT_FALSE(m.is_mechanical());
  EXPECT_FALSE(m.map_forces.value());
  EXPECT_NE(m.visual_output(), nullptr);
  auto& vis = find_named<OglModel>(*s.root, "visual");
  EXPECT_EQ(vis.color(), "red");
  EXPECT_EQ(vis.position.get().data, (std::vector<double>{0, 0, 0, 1, 0, 0}));
  MechanicalOps ops(*s.root);
  EXPECT_TRUE(ops.mappings().empty());
  EXPECT_EQ(ops.all_states().size(), 1u);
  animate(*s.root, 0.1);
  const auto& x = find_named<MechanicalState>(*s.root, "in").read(kPosition);
  EXPECT_LT(x[1], -1e-3);
  EXPECT_EQ(vis.position.get().data, x);
  auto& vis2 = find_named<OglModel>(*s.root, "visual2");
  EXPECT_NEAR(vis2.position.get().data[1], x[1], 1e-12);
  EXPECT_EQ(vis2.class_name(), "VisualModelImpl");
}

TEST(MapOglModel, TransformPseudoAttributesAndLoaderLink) {
  auto s = load(R"(<Node gravity="0 0 0">
    <MeshTopology name="mesh" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2"/>
    <OglModel name="visual" src="@mesh" dx="1" dy="2" dz="3" scale="2" flip="1"/>
  </Node>)");
  auto& vis = find_named<OglModel>(*s.root, "visual");
  EXPECT_EQ(vis.position.get().data, (std::vector<double>{1, 2, 3, 3, 2, 3, 1, 4, 3}));
  ASSERT_EQ(vis.triangles.get().size(), 1u);
  EXPECT_EQ(vis.triangles.get()[0], (Triangle{0, 2, 1}));
  EXPECT_EQ(vis.translation.get(), Vec3::Zero());
}
