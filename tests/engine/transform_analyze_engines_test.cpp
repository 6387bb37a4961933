// Engine/Transform and Engine/Analyze: the transform-matrix engines,
// DisplacementTransformEngine, DisplacementMatrixEngine, Vertex2Frame,
// SmoothMeshEngine, AverageCoord, HausdorffDistance, on hand-computed cases.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "engine/analyze/average_coord.h"
#include "engine/analyze/hausdorff_distance.h"
#include "engine/transform/displacement_transform_engine.h"
#include "engine/transform/smooth_mesh_engine.h"
#include "engine/transform/transform_matrix_engine.h"
#include "engine/transform/vertex2_frame.h"
#include "math/quat.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using M4 = VecN<16>;
M4 mat(std::initializer_list<double> v) {
  M4 m;
  int i = 0;
  for (double d : v) m[i++] = d;
  return m;
}
void expect_near(const M4& a, const M4& b, double tol) {
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(a[i], b[i], tol) << "entry " << i;
}
}  // namespace

// T = translate(1,2,3); S = T·diag(2,3,4); R = S·Rz(90°); I = S⁻¹ = [R⁻¹, −R⁻¹t].
TEST(TransformMatrixEngines, ComposeAndInvert) {
  auto s = load(R"(<Node>
      <TranslateTransformMatrixEngine name="T" translation="1 2 3"/>
      <ScaleTransformMatrixEngine name="S" inT="@T.outT" scale="2 3 4"/>
      <RotateTransformMatrixEngine name="R" inT="@S.outT" rotation="0 0 90"/>
      <InvertTransformMatrixEngine name="I" inT="@S.outT"/>
    </Node>)");
  auto* t = get<TranslateTransformMatrixEngine>(*s.root, "T");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->out_t.get(), mat({1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1}));
  EXPECT_EQ(get<ScaleTransformMatrixEngine>(*s.root, "S")->out_t.get(),
            mat({2, 0, 0, 1, 0, 3, 0, 2, 0, 0, 4, 3, 0, 0, 0, 1}));
  expect_near(get<RotateTransformMatrixEngine>(*s.root, "R")->out_t.get(),
              mat({0, -2, 0, 1, 3, 0, 0, 2, 0, 0, 4, 3, 0, 0, 0, 1}), 1e-15);
  expect_near(get<InvertTransformMatrixEngine>(*s.root, "I")->out_t.get(),
              mat({0.5, 0, 0, -0.5, 0, 1.0 / 3, 0, -2.0 / 3, 0, 0, 0.25, -0.75, 0, 0, 0, 1}), 1e-15);
}

TEST(TransformMatrixEngines, SingularMatrixWarns) {
  auto s = load(R"(<Node><InvertTransformMatrixEngine name="I" inT="1 0 0 0  0 0 0 0  0 0 1 0  0 0 0 1"/></Node>)");
  auto* i = get<InvertTransformMatrixEngine>(*s.root, "I");
  i->out_t.get();
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "cannot invert"));
}

// Rest frame at (1,0,0); current frame at (1,2,0) turned 90° about z:
// D = H(x)·H(x0)⁻¹ = [Rz | Rz·(−1,0,0) + (1,2,0)] = [Rz | (1,1,0)].
// With scale (2,1,1): D = [Rz·S | Rz·S·(−1,0,0) + (1,2,0)] = [Rz·S | (1,0,0)].
TEST(DisplacementEngines, DisplacementOfARotatedFrame) {
  std::ostringstream os;
  os << std::setprecision(17) << "1 2 0 0 0 " << std::sqrt(0.5) << " " << std::sqrt(0.5);
  const std::string x = os.str();
  auto s = load("<Node><DisplacementTransformEngine name=\"d\" x0=\"1 0 0 0 0 0 1\" x=\"" + x +
                "\"/><DisplacementMatrixEngine name=\"m\" x0=\"1 0 0 0 0 0 1\" x=\"" + x +
                "\" scales=\"2 1 1\"/><DisplacementMatrixEngine name=\"u\" x0=\"1 0 0 0 0 0 1\" x=\"" + x +
                "\"/></Node>");
  auto* d = get<DisplacementTransformEngine>(*s.root, "d");
  ASSERT_TRUE(d);
  ASSERT_EQ(d->displacements.get().size(), 1u);
  expect_near(d->displacements.get()[0], mat({0, -1, 0, 1, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1}), 1e-15);
  auto* m = get<DisplacementMatrixEngine>(*s.root, "m");
  ASSERT_TRUE(m);
  ASSERT_TRUE(m->find_field("displaceMats"));
  expect_near(m->displacements.get()[0], mat({0, -1, 0, 1, 2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}), 1e-15);
  // Scales default to 1 1 1 per frame (written at init): same as the transform engine.
  auto* u = get<DisplacementMatrixEngine>(*s.root, "u");
  EXPECT_EQ(u->scales.get(), (std::vector<Vec3>{Vec3(1, 1, 1)}));
  expect_near(u->displacements.get()[0], d->displacements.get()[0], 1e-15);
}

// Normal (0,0,1): the frame is the identity. Normal (0,1,0) (along y₀): y₀ becomes z,
// x = z × n = (−1,0,0), y = n × x = (0,0,1). Without normals: x points to the next
// vertex (0,1,0), y = (1,0,0) × x = (0,0,1), z = x × y = (1,0,0); the last copies it.
TEST(Vertex2Frame, FramesFromNormalsAndFromNeighbours) {
  auto s = load(R"(<Node>
      <Vertex2Frame name="n" position="1 2 3  4 5 6" normals="0 0 1  0 1 0"/>
      <Vertex2Frame name="v" useNormals="0" position="0 0 0  0 2 0"/>
      <Vertex2Frame name="r" position="0 0 0" normals="0 0 1" rotation="2" rotationAngle="90"/>
    </Node>)");
  auto* n = get<Vertex2Frame>(*s.root, "n");
  ASSERT_TRUE(n);
  const FlatVec& f = n->frames.get();
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(std::vector<double>(f.data.begin(), f.data.begin() + 7), (std::vector<double>{1, 2, 3, 0, 0, 0, 1}));
  auto columns = [](const double* q) { return quat_to_matrix(Quat::from(q)); };
  Mat3 expected;
  expected << -1, 0, 0, 0, 0, 1, 0, 1, 0;  // columns x, y, z
  EXPECT_TRUE(columns(&f.data[10]).isApprox(expected, 1e-15));
  const FlatVec& g = get<Vertex2Frame>(*s.root, "v")->frames.get();
  ASSERT_EQ(g.size(), 2u);
  Mat3 e2;
  e2 << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  EXPECT_TRUE(columns(&g.data[3]).isApprox(e2, 1e-15));
  EXPECT_EQ(std::vector<double>(g.data.begin() + 10, g.data.end()),
            std::vector<double>(g.data.begin() + 3, g.data.begin() + 7));
  // rotationAngle turns the frame about its own z: 90° gives q = (0, 0, sin 45°, cos 45°).
  const FlatVec& r = get<Vertex2Frame>(*s.root, "r")->frames.get();
  EXPECT_NEAR(r.data[5], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(r.data[6], std::sqrt(0.5), 1e-15);
}

// Chain 0-1-2 at x = 0, 1, 5: one iteration gives x = 1, 2.5, 1; two give 2.5, 1, 2.5;
// with input_indices = 1 only the middle point moves.
TEST(SmoothMeshEngine, LaplacianOverTheEdges) {
  auto s = load(R"(<Node><MeshTopology name="t" position="0 0 0  1 0 0  5 0 0" edges="0 1  1 2"/>
      <SmoothMeshEngine name="one" input_position="0 0 0  1 0 0  5 0 0"/>
      <SmoothMeshEngine name="two" nb_iterations="2" input_position="0 0 0  1 0 0  5 0 0"/>
      <SmoothMeshEngine name="mid" input_indices="1" input_position="0 0 0  1 0 0  5 0 0" topology="@t"/>
    </Node>)");
  auto xs = [&](const char* name) {
    std::vector<double> v;
    for (const Vec3& p : get<SmoothMeshEngine>(*s.root, name)->output_position.get()) v.push_back(p[0]);
    return v;
  };
  EXPECT_EQ(xs("one"), (std::vector<double>{1, 2.5, 1}));
  EXPECT_EQ(xs("two"), (std::vector<double>{2.5, 1, 2.5}));
  EXPECT_EQ(xs("mid"), (std::vector<double>{0, 2.5, 5}));
}

// Mean of (0,0,0), (2,0,0), (4,6,0): (2,2,0); of entries 0 and 2: (2,3,0).
// Rigid3d: the quaternions are summed from the identity (SOFA's default Coord), so two
// identity frames average to w = (1 + 1 + 1)/2 = 1.5.
TEST(AverageCoord, MeanOfTheStatesCoordinates) {
  auto s = load(R"(<Node>
      <Node name="v"><MechanicalObject position="0 0 0  2 0 0  4 6 0"/>
        <AverageCoord name="all"/><AverageCoord name="some" indices="0 2"/></Node>
      <Node name="r"><MechanicalObject template="Rigid3" position="0 0 0 0 0 0 1  2 0 0 0 0 0 1"/>
        <AverageCoord name="rigid" template="Rigid3"/></Node>
    </Node>)");
  Node* v = s.root->children()[0];
  EXPECT_EQ(get<AverageCoord>(*v, "all")->average.get().data, (std::vector<double>{2, 2, 0}));
  EXPECT_EQ(get<AverageCoord>(*v, "some")->average.get().data, (std::vector<double>{2, 3, 0}));
  Node* r = s.root->children()[1];
  EXPECT_EQ(get<AverageCoord>(*r, "rigid")->average.get().data, (std::vector<double>{1, 0, 0, 0, 0, 0, 1.5}));
}

TEST(AverageCoord, BadVecIdIsAnError) {
  auto s = test::build(R"(<Node><MechanicalObject position="0 0 0"/><AverageCoord name="a" vecId="7"/></Node>)");
  init_root(*s.root);
  get<AverageCoord>(*s.root, "a")->average.get();
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "vecId 7"));
}

// Cloud 1 = {(0,0,0), (1,0,0)}, cloud 2 = {(0,0,0)}: d12 = 1, d21 = 0, max = 1; in 2D
// {(3,4)} against {(0,0)}: 5.
TEST(HausdorffDistance, DirectedAndSymmetric) {
  auto s = load(R"(<Node><HausdorffDistance name="h" points1="0 0 0  1 0 0" points2="0 0 0"/>
                   <HausdorffDistance name="p" template="Vec2" points1="3 4" points2="0 0"/></Node>)");
  auto* h = get<HausdorffDistance>(*s.root, "h");
  ASSERT_TRUE(h);
  EXPECT_EQ(h->d12.get(), 1.0);
  EXPECT_EQ(h->d21.get(), 0.0);
  EXPECT_EQ(h->max.get(), 1.0);
  EXPECT_EQ(get<HausdorffDistance>(*s.root, "p")->max.get(), 5.0);
}
