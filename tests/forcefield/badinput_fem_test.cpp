// Bad-input audit, FEM force fields: inverted and flat elements, zero or
// negative Young's modulus, Poisson's ratio >= 0.5, element indices beyond the
// state. Every case must give a message naming the component and the element
// (or the value), and never a crash or NaNs without an error.
#include <gtest/gtest.h>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

enum class Elem { tetra, hexa, triangle };

struct FemCase {
  const char* type;
  const char* tmpl;  // "" for the default template
  Elem elem;
  bool any_orientation = false;  // both vertex orders are valid (no inverted element)
};

std::ostream& operator<<(std::ostream& os, const FemCase& c) { return os << c.type << "<" << c.tmpl << ">"; }

// Points and elements: element 0 is always good; `bad` (if not empty) is element 1.
struct Mesh {
  std::string points, good, inverted, flat, attr, fixed;
};

Mesh mesh_for(Elem e) {
  switch (e) {
    case Elem::tetra:
      return {"0 0 0  1 0 0  0 1 0  0 0 1  1 1 0  1 1 1", "0 1 2 3", "1 2 4 5", "1 2 4 0", "tetrahedra", "0 2 3"};
    case Elem::hexa:
      return {"0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1 "
              "2 0 0  3 0 0  3 1 0  2 1 0  2 0 1  3 0 1  3 1 1  2 1 1 "
              "2 0 0  3 0 0  3 1 0  2 1 0",
              "0 1 2 3 4 5 6 7", "12 13 14 15 8 9 10 11", "8 9 10 11 16 17 18 19", "hexahedra", "0 1 2 3"};
    case Elem::triangle:
      return {"0 0 0  1 0 0  0 1 0  2 0 0", "0 1 2", "", "0 1 3", "triangles", "0 1"};
  }
  return {};
}

std::string fem_scene(const FemCase& c, const std::string& elements, const std::string& material,
                      const std::string& points_override = "") {
  const Mesh m = mesh_for(c.elem);
  const std::string tmpl = *c.tmpl ? std::string(" template=\"") + c.tmpl + "\"" : "";
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="50" tolerance="1e-9" threshold="1e-12"/>
  <MechanicalObject name="dofs" position=")" +
         (points_override.empty() ? m.points : points_override) + R"("/>
  <MeshTopology name="topo" )" +
         m.attr + "=\"" + elements + R"("/>
  <UniformMass totalMass="1"/>
  <FixedProjectiveConstraint indices=")" +
         m.fixed + R"("/>
  <)" + c.type + tmpl +
         R"( name="fem" )" + material + R"(/>
</Node>)";
}

std::string who(const FemCase& c) { return std::string("component 'fem' (") + c.type + ")"; }

class BadInputFem : public ::testing::TestWithParam<FemCase> {
 protected:
  TempDir dir;
};

const char* kMaterial = R"(youngModulus="1000" poissonRatio="0.3")";

}  // namespace

TEST_P(BadInputFem, GoodMeshRunsWithoutMessages) {
  const FemCase c = GetParam();
  const Outcome o = run_xml(dir, fem_scene(c, mesh_for(c.elem).good, kMaterial), 5);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 5);
  EXPECT_TRUE(o.finite);
}

TEST_P(BadInputFem, InvertedElementIsReportedWithItsIndex) {
  const FemCase c = GetParam();
  const Mesh m = mesh_for(c.elem);
  if (m.inverted.empty()) GTEST_SKIP() << "no orientation for triangles in 3D";
  if (c.any_orientation) GTEST_SKIP() << "shape vectors divide by the signed volume: either order is valid";
  const Outcome o = run_xml(dir, fem_scene(c, m.good + "  " + m.inverted, kMaterial), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {who(c), "element 1"})) << o.all();
  EXPECT_FALSE(any_contains_all(o.problems(), {who(c), "element 0"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, FlatElementIsAnErrorNamingTheElement) {
  const FemCase c = GetParam();
  const Mesh m = mesh_for(c.elem);
  const Outcome o = run_xml(dir, fem_scene(c, m.good + "  " + m.flat, kMaterial), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), "1"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), "degenerate"}) || any_contains_all(o.errors, {who(c), "zero"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, ElementIndexBeyondTheStateIsAnError) {
  const FemCase c = GetParam();
  const Mesh m = mesh_for(c.elem);
  // The good element again, with its last index replaced by 99 (the state has fewer points).
  std::string bad = m.good.substr(0, m.good.rfind(' ')) + " 99";
  const Outcome o = run_xml(dir, fem_scene(c, m.good + "  " + bad, kMaterial), 5);
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), "99"}) || any_contains_all(o.errors, {who(c), "element 1"}) ||
              any_contains_all(o.errors, {who(c), "triangle 1"}))
      << o.all();
  EXPECT_FALSE(o.init_ok);
}

TEST_P(BadInputFem, ZeroYoungModulusIsReported) {
  const FemCase c = GetParam();
  const Outcome o = run_xml(dir, fem_scene(c, mesh_for(c.elem).good, R"(youngModulus="0" poissonRatio="0.3")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {who(c), "youngModulus", "0"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, NegativeYoungModulusIsReported) {
  const FemCase c = GetParam();
  const Outcome o =
      run_xml(dir, fem_scene(c, mesh_for(c.elem).good, R"(youngModulus="-1000" poissonRatio="0.3")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {who(c), "youngModulus", "-1000"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, PoissonRatioOfOneHalfIsReported) {
  const FemCase c = GetParam();
  const Outcome o = run_xml(dir, fem_scene(c, mesh_for(c.elem).good, R"(youngModulus="1000" poissonRatio="0.5")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {who(c), "poissonRatio", "0.5"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, PoissonRatioAboveOneHalfIsReported) {
  const FemCase c = GetParam();
  const Outcome o = run_xml(dir, fem_scene(c, mesh_for(c.elem).good, R"(youngModulus="1000" poissonRatio="0.7")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {who(c), "poissonRatio", "0.7"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, UnparsableYoungModulusIsReported) {
  const FemCase c = GetParam();
  const Outcome o =
      run_xml(dir, fem_scene(c, mesh_for(c.elem).good, R"(youngModulus="1e3x" poissonRatio="0.3")"), 5);
  EXPECT_TRUE(any_contains_all(o.problems(), {"fem", "youngModulus", "1e3x"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.problems(), {"scene.scn:"})) << o.all();
  expect_no_silent_garbage(o);
}

TEST_P(BadInputFem, NonFinitePositionIsNotSilent) {
  const FemCase c = GetParam();
  const Mesh m = mesh_for(c.elem);
  std::string pts = m.points;
  pts.replace(pts.find("1 0 0"), 5, "nan 0 0");  // point 1, in element 0
  const Outcome o = run_xml(dir, fem_scene(c, m.good, kMaterial, pts), 5);
  EXPECT_FALSE(o.errors.empty()) << "a NaN rest position must be an error:\n" << o.all();
  expect_no_silent_garbage(o);
}

INSTANTIATE_TEST_SUITE_P(
    All, BadInputFem,
    ::testing::Values(FemCase{"TetrahedronFEMForceField", "", Elem::tetra},
                      FemCase{"TetrahedralCorotationalFEMForceField", "", Elem::tetra},
                      FemCase{"FastTetrahedralCorotationalForceField", "", Elem::tetra, true},
                      FemCase{"LinearSmallStrainFEMForceField", "Vec3d,Tetrahedron", Elem::tetra},
                      FemCase{"CorotationalFEMForceField", "Vec3d,Tetrahedron", Elem::tetra},
                      FemCase{"HexahedronFEMForceField", "", Elem::hexa},
                      FemCase{"LinearSmallStrainFEMForceField", "Vec3d,Hexahedron", Elem::hexa},
                      FemCase{"CorotationalFEMForceField", "Vec3d,Hexahedron", Elem::hexa},
                      FemCase{"TriangularFEMForceField", "", Elem::triangle},
                      FemCase{"TriangularFEMForceFieldOptim", "", Elem::triangle},
                      FemCase{"TriangleFEMForceField", "", Elem::triangle}),
    [](const ::testing::TestParamInfo<FemCase>& info) {
      std::string n = info.param.type;
      if (std::string(info.param.tmpl).find("Hexa") != std::string::npos) n += "Hexa";
      if (std::string(info.param.tmpl).find("Tetra") != std::string::npos) n += "Tetra";
      return n;
    });
