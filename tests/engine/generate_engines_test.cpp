// Engine/Generate: GenerateCylinder, GenerateGrid, GenerateRigidMass, Spiral,
// MeshClosingEngine, VolumeFromTriangles, VolumeFromVolumetricElements, on
// inputs whose outputs are computed by hand in the comments.
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>

#include "engine/generate/generate_cylinder.h"
#include "engine/generate/generate_grid.h"
#include "engine/generate/generate_rigid_mass.h"
#include "engine/generate/mesh_barycentric_mapper_engine.h"
#include "engine/generate/mesh_closing_engine.h"
#include "engine/generate/spiral.h"
#include "engine/generate/volume_from_triangles.h"
#include "engine/generate/volume_from_volumetric_elements.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;

namespace {
using Tris = std::vector<Triangle>;
using Tets = std::vector<Tetra>;

// Unit cube [0,1]³, vertex index x + 2y + 4z, 12 outward triangles (two per face: −z, +z, −y, +y, −x, +x).
const char* kCubePoints = "0 0 0  1 0 0  0 1 0  1 1 0  0 0 1  1 0 1  0 1 1  1 1 1";
const char* kCubeTriangles = "0 2 3  0 3 1  4 5 7  4 7 6  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  0 6 2  1 3 7  1 7 5";
// The same without the +z face (triangles 2 and 3).
const char* kOpenCubeTriangles = "0 2 3  0 3 1  0 1 5  0 5 4  2 6 7  2 7 3  0 4 6  0 6 2  1 3 7  1 7 5";

double signed_volume(const std::vector<Vec3>& x, const Tetra& t) {
  return (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]) / 6.0;
}
std::string cube_scene_attrs() {
  return std::string("position=\"") + kCubePoints + "\" triangles=\"" + kCubeTriangles + "\"";
}
}  // namespace

// Four points per ring, one ring, two levels: level 0 is 0 (axis), 1..4 (ring at
// θ = 0, 90°, 180°, 270°), level 1 is 5..9. One prism per ring sector (3
// tetrahedra): 12 tetrahedra filling the square prism of area 2 and height 2.
TEST(GenerateCylinder, PointsAndTetrahedraOfOneRing) {
  auto s = load(R"(<Node><GenerateCylinder name="c" radius="1" height="2" resCircumferential="4" resRadial="1"
                   resHeight="2"/></Node>)");
  auto* c = get<GenerateCylinder>(*s.root, "c");
  ASSERT_TRUE(c);
  const std::vector<Vec3>& x = c->tetra_positions.get();
  ASSERT_EQ(x.size(), 10u);
  EXPECT_TRUE(x[0].isApprox(Vec3(0, 0, 0)));
  EXPECT_NEAR((x[2] - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((x[8] - Vec3(-1, 0, 2)).norm(), 0.0, 1e-15);
  const Tets& t = c->tetrahedra.get();
  ASSERT_EQ(t.size(), 12u);
  // First sector (k = 1, previous k = 4): prism 5 9 6 over 0 4 1.
  EXPECT_EQ(t[0], (Tetra{9, 5, 6, 0}));
  EXPECT_EQ(t[1], (Tetra{9, 6, 4, 0}));
  EXPECT_EQ(t[2], (Tetra{0, 4, 1, 6}));
  double v = 0;
  for (const Tetra& e : t) {
    EXPECT_GT(signed_volume(x, e), 0.0);
    v += signed_volume(x, e);
  }
  EXPECT_NEAR(v, 4.0, 1e-12);
  // Open surface: the wall's 8 points and 2 triangles per quad.
  EXPECT_EQ(c->triangle_positions.get().size(), 8u);
  ASSERT_EQ(c->triangles.get().size(), 8u);
  EXPECT_EQ(c->triangles.get()[0], (Triangle{4, 0, 1}));
  EXPECT_EQ(c->triangles.get()[1], (Triangle{4, 1, 5}));
  // Also readable under SOFA's aliases.
  EXPECT_TRUE(c->find_field("output_position") != nullptr);
}

// Closed surface, two rings: 4·(2 + 2·1) + 2 = 18 points and
// 2·4·1 + 2·4 + 4·1·4 = 32 triangles; 3·4 + 6·1·4 = 36 tetrahedra of total volume 2·2 = 4.
TEST(GenerateCylinder, ClosedSurfaceAndRings) {
  auto s = load(R"(<Node><GenerateCylinder name="c" radius="1" height="2" resCircumferential="4" resRadial="2"
                   resHeight="2" openSurface="0" origin="1 2 3"/></Node>)");
  auto* c = get<GenerateCylinder>(*s.root, "c");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->triangle_positions.get().size(), 18u);
  EXPECT_EQ(c->triangles.get().size(), 32u);
  const std::vector<Vec3>& x = c->tetra_positions.get();
  EXPECT_TRUE(x[0].isApprox(Vec3(1, 2, 3)));
  double v = 0;
  for (const Tetra& e : c->tetrahedra.get()) v += signed_volume(x, e);
  EXPECT_EQ(c->tetrahedra.get().size(), 36u);
  EXPECT_NEAR(v, 4.0, 1e-12);
  // The caps face outwards: the first bottom triangle's normal points to −z.
  const std::vector<Vec3>& y = c->triangle_positions.get();
  const Triangle& b = c->triangles.get()[8];
  EXPECT_LT((y[b[1]] - y[b[0]]).cross(y[b[2]] - y[b[0]])[2], 0.0);
}

TEST(GenerateCylinder, BezierDegreesAreRefused) {
  auto s = test::build(R"(<Node><GenerateCylinder name="c" BezierTetrahedronDegree="2"/></Node>)");
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "not supported"));
}

// 2×1×1 cells over [0,2]×[0,1]×[0,1]: 3·2·2 points, x fastest; the first hexahedron
// is 0 1 4 3 6 7 10 9 and its six tetrahedra follow SOFA's split.
TEST(GenerateGrid, HexahedraAndTetrahedra) {
  auto s = load(R"(<Node><GenerateGrid name="g" max="2 1 1" resolution="2 1 1"/></Node>)");
  auto* g = get<GenerateGrid>(*s.root, "g");
  ASSERT_TRUE(g);
  const FlatVec& x = g->output_position.get();
  ASSERT_EQ(x.size(), 12u);
  EXPECT_EQ(std::vector<double>(x.data.begin() + 3, x.data.begin() + 6), (std::vector<double>{1, 0, 0}));
  EXPECT_EQ(std::vector<double>(x.data.begin() + 33, x.data.end()), (std::vector<double>{2, 1, 1}));
  ASSERT_EQ(g->hexahedra.get().size(), 2u);
  EXPECT_EQ(g->hexahedra.get()[0], (Hexa{0, 1, 4, 3, 6, 7, 10, 9}));
  const Tets& t = g->tetrahedra.get();
  ASSERT_EQ(t.size(), 12u);
  EXPECT_EQ(t[0], (Tetra{0, 7, 1, 10}));
  EXPECT_EQ(t[5], (Tetra{9, 7, 6, 0}));
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < x.size(); ++i) p.emplace_back(x.data[3 * i], x.data[3 * i + 1], x.data[3 * i + 2]);
  double v = 0;
  for (const Tetra& e : t) v += std::fabs(signed_volume(p, e));
  EXPECT_NEAR(v, 2.0, 1e-14);
  EXPECT_TRUE(g->quads.get().empty());
}

// resolution z = 0: a flat grid of quads, each cut into (q0 q1 q3) and (q3 q1 q2); Vec2d keeps x and y.
TEST(GenerateGrid, FlatGridVec2) {
  auto s = load(R"(<Node><GenerateGrid name="g" template="Vec2" min="1 1 0" max="3 2 0" resolution="2 1 0"/></Node>)");
  auto* g = get<GenerateGrid>(*s.root, "g");
  ASSERT_TRUE(g);
  EXPECT_EQ(g->output_position.get().width, 2);
  EXPECT_EQ(g->output_position.get().data, (std::vector<double>{1, 1, 2, 1, 3, 1, 1, 2, 2, 2, 3, 2}));
  EXPECT_EQ(g->quads.get(), (std::vector<Quad>{{0, 1, 4, 3}, {1, 2, 5, 4}}));
  EXPECT_EQ(g->triangles.get(), (Tris{{0, 1, 3}, {3, 1, 4}, {1, 2, 4}, {4, 2, 5}}));
  EXPECT_TRUE(g->hexahedra.get().empty());
}

// Unit cube moved by (1,2,3), density 2: volume 1, mass 2, centre (1.5,2.5,3.5);
// inertia per unit mass about the centre: (1² + 1²)/12 = 1/6 on the diagonal, 0 elsewhere.
TEST(GenerateRigidMass, UnitCube) {
  std::string pts;
  {
    const double p[24] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i)
      pts += std::to_string(p[3 * i] + 1) + " " + std::to_string(p[3 * i + 1] + 2) + " " +
             std::to_string(p[3 * i + 2] + 3) + "  ";
  }
  auto s = load("<Node><GenerateRigidMass name=\"m\" density=\"2\" position=\"" + pts + "\" triangles=\"" +
                kCubeTriangles + "\"/></Node>");
  auto* m = get<GenerateRigidMass>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->volume.get(), 1.0, 1e-13);
  EXPECT_NEAR(m->mass.get(), 2.0, 1e-13);
  EXPECT_TRUE(m->mass_center.get().isApprox(Vec3(1.5, 2.5, 3.5), 1e-13));
  EXPECT_TRUE(m->center_to_origin.get().isApprox(Vec3(-1.5, -2.5, -3.5), 1e-13));
  const Mat3 I = m->inertia_matrix.get();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(I(i, j), i == j ? 1.0 / 6 : 0.0, 1e-12) << i << j;
  const std::vector<double>& rm = m->rigid_mass.get();
  ASSERT_EQ(rm.size(), 11u);
  EXPECT_NEAR(rm[0], 2.0, 1e-13);
  EXPECT_NEAR(rm[1], 1.0, 1e-13);
  EXPECT_NEAR(rm[2], 1.0 / 6, 1e-12);
}

// The same cube described with quads gives the same integrals.
TEST(GenerateRigidMass, QuadsAreFanned) {
  auto s = load(std::string("<Node><GenerateRigidMass name=\"m\" density=\"1\" position=\"") + kCubePoints +
                "\" quads=\"0 2 3 1  4 5 7 6  0 1 5 4  2 6 7 3  0 4 6 2  1 3 7 5\"/></Node>");
  auto* m = get<GenerateRigidMass>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->volume.get(), 1.0, 1e-13);
  EXPECT_TRUE(m->mass_center.get().isApprox(Vec3(0.5, 0.5, 0.5), 1e-13));
}

// x is the arc length along r = A·t: the point at arc length 1 lies at angle t with
// A/2 (t√(1+t²) + asinh t) = 1 and radius A·t (t found here by bisection).
// At x = 0 the normal (0,1,0) is capped to y = 0.8f, x = −√(1 − 0.8f²).
TEST(Spiral, RollsTheStrip) {
  auto s = load(R"(<Node><Spiral name="s" rest_position="1 0 0  0 1 5"/></Node>)");
  auto* sp = get<Spiral>(*s.root, "s");
  ASSERT_TRUE(sp);
  const std::vector<Vec3>& x = sp->position.get();
  ASSERT_EQ(x.size(), 2u);
  const double A = 0.2;
  double lo = 0, hi = 20;
  for (int i = 0; i < 200; ++i) {
    const double m = (lo + hi) / 2;
    (A / 2 * (m * std::sqrt(1 + m * m) + std::asinh(m)) < 1 ? lo : hi) = m;
  }
  const double t = lo;
  EXPECT_NEAR(x[0][0], A * t * std::cos(t), 1e-12);
  EXPECT_NEAR(x[0][1], A * t * std::sin(t), 1e-12);
  EXPECT_EQ(x[0][2], 0.0);
  const double ny = static_cast<double>(0.8f);
  EXPECT_DOUBLE_EQ(x[1][0], -std::sqrt(1 - ny * ny));
  EXPECT_DOUBLE_EQ(x[1][1], ny);
  EXPECT_EQ(x[1][2], 5.0);
}

// Open cube (no +z face): the hole 4-6-7-5 is closed by a fan around its centroid (0.5,0.5,1), vertex 8.
TEST(MeshClosingEngine, ClosesTheHoleOfAnOpenCube) {
  auto s = load(std::string("<Node><MeshClosingEngine name=\"c\" inputPosition=\"") + kCubePoints +
                "\" inputTriangles=\"" + kOpenCubeTriangles + "\"/></Node>");
  auto* c = get<MeshClosingEngine>(*s.root, "c");
  ASSERT_TRUE(c);
  ASSERT_EQ(c->position.get().size(), 9u);
  EXPECT_TRUE(c->position.get()[8].isApprox(Vec3(0.5, 0.5, 1)));
  const Tris& t = c->triangles.get();
  ASSERT_EQ(t.size(), 14u);
  EXPECT_EQ(Tris(t.begin() + 10, t.end()), (Tris{{8, 4, 5}, {8, 6, 4}, {8, 7, 6}, {8, 5, 7}}));
  EXPECT_EQ(c->indices.get(), (std::vector<std::vector<unsigned>>{{4, 6, 7, 5, 8}}));
  EXPECT_EQ(c->closing_position.get().size(), 5u);
  EXPECT_EQ(c->closing_triangles.get(), (Tris{{4, 0, 3}, {4, 1, 0}, {4, 2, 1}, {4, 3, 2}}));
  // Closed and outward: the enclosed volume is the cube's.
  std::vector<double> flat;
  for (const Vec3& p : c->position.get()) flat.insert(flat.end(), {p[0], p[1], p[2]});
  EXPECT_NEAR(enclosed_volume(flat, 3, t, {}), 1.0, 1e-14);
  // A closed mesh is left as it is.
  auto s2 = load(std::string("<Node><MeshClosingEngine name=\"c\" inputPosition=\"") + kCubePoints +
                 "\" inputTriangles=\"" + kCubeTriangles + "\"/></Node>");
  auto* c2 = get<MeshClosingEngine>(*s2.root, "c");
  EXPECT_EQ(c2->triangles.get().size(), 12u);
  EXPECT_TRUE(c2->closing_position.get().empty());
}

// Volume of the unit cube from the node's state and topology; moving the state changes
// it only with update="1" (SOFA recomputes only then).
TEST(VolumeFromTriangles, CubeFromTheNodesStateAndTopology) {
  auto s = load("<Node><MeshTopology " + cube_scene_attrs() + "/><MechanicalObject name=\"mo\" position=\"" +
                kCubePoints + "\"/><VolumeFromTriangles name=\"v\"/><VolumeFromTriangles name=\"u\" update=\"1\"/>"
                "</Node>");
  auto* v = get<VolumeFromTriangles>(*s.root, "v");
  auto* u = get<VolumeFromTriangles>(*s.root, "u");
  ASSERT_TRUE(v && u);
  EXPECT_NEAR(v->volume.get(), 1.0, 1e-15);
  EXPECT_NEAR(u->volume.get(), 1.0, 1e-15);
  auto* mo = s.root->find_object_named("mo");
  ASSERT_TRUE(mo);
  // Stretch along x by 2.
  std::string doubled;
  const double p[24] = {0, 0, 0, 2, 0, 0, 0, 1, 0, 2, 1, 0, 0, 0, 1, 2, 0, 1, 0, 1, 1, 2, 1, 1};
  for (double d : p) doubled += std::to_string(d) + " ";
  mo->find_field("position")->read(doubled);
  EXPECT_NEAR(v->volume.get(), 1.0, 1e-15);
  EXPECT_NEAR(u->volume.get(), 2.0, 1e-14);
}

// One unit right tetrahedron (1/6) and one 2×1×1 hexahedron (2).
TEST(VolumeFromVolumetricElements, TetrahedraAndHexahedra) {
  auto s = load(R"(<Node><VolumeFromVolumetricElements name="v"
      position="0 0 0  1 0 0  0 1 0  0 0 1  2 0 0  2 1 0  0 1 1  1 0 1  2 0 1  2 1 1  1 1 0  1 1 1"
      tetras="0 1 2 3" hexas="0 4 5 2 3 8 9 6"/></Node>)");
  auto* v = get<VolumeFromVolumetricElements>(*s.root, "v");
  ASSERT_TRUE(v);
  EXPECT_NEAR(v->volume.get(), 2.0 + 1.0 / 6, 1e-14);
  std::array<Vec3, 8> h;
  const double c[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  for (int i = 0; i < 8; ++i) h[i] = Vec3(c[3 * i], c[3 * i + 1], c[3 * i + 2]) * 3;
  EXPECT_NEAR(hexa_volume(h), 27.0, 1e-12);
}

TEST(VolumeFromVolumetricElements, BadIndexIsAnError) {
  auto s = test::build(R"(<Node><VolumeFromVolumetricElements name="v" position="0 0 0" tetras="0 1 2 3"/></Node>)");
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "beyond the 1 positions"));
}

// One unit tetrahedron: a point's barycentric coordinates are its coordinates; a point
// outside every element goes to the nearest centre's element. The interpolation weights
// use SOFA's first weight 1 − (b0 − b1 − b2): 1 − (0.1 − 0.2 − 0.3) = 1.4.
TEST(MeshBarycentricMapperEngine, TetrahedronCoordinates) {
  auto s = load(R"(<Node><MeshTopology name="t" position="0 0 0  1 0 0  0 1 0  0 0 1" tetrahedra="0 1 2 3"/>
      <MeshBarycentricMapperEngine name="m" topology="@t" inputPositions="0 0 0  1 0 0  0 1 0  0 0 1"
          mappedPointPositions="0.1 0.2 0.3  2 0 0" computeLinearInterpolation="1"/></Node>)");
  auto* m = get<MeshBarycentricMapperEngine>(*s.root, "m");
  ASSERT_TRUE(m);
  const std::vector<Vec3>& b = m->barycentric_positions.get();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_TRUE(b[0].isApprox(Vec3(0.1, 0.2, 0.3), 1e-15));
  EXPECT_TRUE(b[1].isApprox(Vec3(2, 0, 0), 1e-15));
  EXPECT_EQ(m->table_elements.get(), (std::vector<unsigned>{0, 0}));
  EXPECT_EQ(m->interpolation_indices.get()[0], (std::vector<unsigned>{0, 1, 2, 3}));
  ASSERT_EQ(m->interpolation_values.get().size(), 8u);
  EXPECT_NEAR(m->interpolation_values.get()[0], 1.4, 1e-15);
  EXPECT_NEAR(m->interpolation_values.get()[3], 0.3, 1e-15);
}

// Triangles only: the third coordinate (off-plane) is dropped.
TEST(MeshBarycentricMapperEngine, TriangleCoordinates) {
  auto s = load(R"(<Node><MeshTopology name="t" position="0 0 0  2 0 0  0 2 0" triangles="0 1 2"/>
      <MeshBarycentricMapperEngine name="m" inputPositions="0 0 0  2 0 0  0 2 0"
          mappedPointPositions="0.5 1 0"/></Node>)");
  auto* m = get<MeshBarycentricMapperEngine>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->barycentric_positions.get()[0].isApprox(Vec3(0.25, 0.5, 0), 1e-15));
}
