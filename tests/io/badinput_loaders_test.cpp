// Bad-input audit, mesh loaders: a missing file and malformed files
// (truncated, garbage numbers, indices beyond the points) for each format.
// Each case: an error naming the loader and the file (with the line for
// text formats), the scene refused, no crash.
#include <gtest/gtest.h>

#include <regex>

#include "badinput_helpers.h"

using namespace sinew;
using namespace sinew::test;

namespace {

struct LoaderCase {
  const char* type;
  const char* ext;
  const char* good;      // a valid file
  const char* garbage;   // a number replaced by garbage
  int garbage_line;      // 1-based line of the garbage
  const char* truncated; // cut in the middle
  const char* bad_index; // an element refers to a point that does not exist ("" when not applicable)
};

std::ostream& operator<<(std::ostream& os, const LoaderCase& c) { return os << c.type; }

const char* kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
const char* kObjGarbage = "v 0 0 0\nv 1 0 0\nv 0 1e+ 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\n";
// Cut inside a face line: a one-vertex face (two vertices would be a valid edge, as in SOFA).
const char* kObjTrunc = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1";
const char* kObjIndex = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 9\n";

const char* kMsh =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 0 0 1 2 3 4\n$EndElements\n";
const char* kMshGarbage =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0.x\n4 0 0 1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 0 0 1 2 3 4\n$EndElements\n";
const char* kMshTrunc = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1";
const char* kMshIndex =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n1\n1 4 2 0 0 1 2 3 9\n$EndElements\n";

const char* kVtk =
    "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
const char* kVtkGarbage =
    "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0 0 0\n1 zz 0\n0 1 0\n0 0 1\n"
    "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
const char* kVtkTrunc =
    "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0 0 0\n1 0 0\n0 1";
const char* kVtkIndex =
    "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "CELLS 1 5\n4 0 1 2 9\nCELL_TYPES 1\n10\n";

const char* kStl =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
const char* kStlGarbage =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 q 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n";
const char* kStlTrunc = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0";

const char* kSph = "sph 1.0\nnums 2\nsphe 1 0 0 0 0.5\nsphe 2 1 0 0 0.5\n";
const char* kSphGarbage = "sph 1.0\nnums 2\nsphe 1 0 0 0 0.5\nsphe 2 1 0 0 0,5\n";
const char* kSphTrunc = "sph 1.0\nnums 2\nsphe 1 0 0 0 0.5\nsphe 2 1 0";

std::string loader_scene(const LoaderCase& c, const std::string& file) {
  const bool sph = std::string(c.type) == "SphereLoader";
  return std::string(R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <EulerImplicitSolver/>
  <CGLinearSolver iterations="20" tolerance="1e-9" threshold="1e-12"/>
  <)") + c.type + R"( name="loader" filename=")" + file + R"("/>
  <MechanicalObject name="dofs" position="@loader.position"/>)" +
         (sph ? "" : "\n  <MeshTopology name=\"topo\" src=\"@loader\"/>") + R"(
  <UniformMass totalMass="1"/>
</Node>)";
}

std::string who(const LoaderCase& c) { return std::string("component 'loader' (") + c.type + ")"; }

class BadInputLoader : public ::testing::TestWithParam<LoaderCase> {
 protected:
  TempDir dir;
  std::string file(const std::string& base) const { return base + "." + GetParam().ext; }
};

}  // namespace

TEST_P(BadInputLoader, GoodFileLoads) {
  const LoaderCase& c = GetParam();
  dir.write(file("good"), c.good);
  const Outcome o = run_xml(dir, loader_scene(c, file("good")), 2);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_TRUE(o.finite);
}

TEST_P(BadInputLoader, MissingFileIsAnErrorWithTheSceneLine) {
  const LoaderCase& c = GetParam();
  const Outcome o = run_xml(dir, loader_scene(c, file("nothere")), 2);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), file("nothere")})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"scene.scn:5:", who(c)})) << o.all();
}

TEST_P(BadInputLoader, GarbageNumberIsAnErrorWithTheFileLine) {
  const LoaderCase& c = GetParam();
  dir.write(file("bad"), c.garbage);
  const Outcome o = run_xml(dir, loader_scene(c, file("bad")), 2);
  EXPECT_FALSE(o.init_ok);
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), file("bad") + ":" + std::to_string(c.garbage_line)})) << o.all();
}

TEST_P(BadInputLoader, TruncatedFileIsAnError) {
  const LoaderCase& c = GetParam();
  dir.write(file("cut"), c.truncated);
  const Outcome o = run_xml(dir, loader_scene(c, file("cut")), 2);
  EXPECT_FALSE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), file("cut")})) << o.all();
}

TEST_P(BadInputLoader, ElementBeyondThePointsIsAnError) {
  const LoaderCase& c = GetParam();
  if (!*c.bad_index) GTEST_SKIP() << "this format has no element indices";
  dir.write(file("idx"), c.bad_index);
  const Outcome o = run_xml(dir, loader_scene(c, file("idx")), 2);
  EXPECT_FALSE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), "9"}) || any_contains_all(o.errors, {who(c), "10"})) << o.all();
}

TEST_P(BadInputLoader, EmptyFileIsNotSilent) {
  const LoaderCase& c = GetParam();
  dir.write(file("empty"), "");
  const Outcome o = run_xml(dir, loader_scene(c, file("empty")), 2);
  // An empty file has no points: either the loader says so or the scene runs empty; never a crash.
  EXPECT_TRUE(o.loaded);
  if (o.init_ok) {
    EXPECT_TRUE(o.finite);
  }
}

TEST_P(BadInputLoader, DirectoryInsteadOfAFileIsAnError) {
  const LoaderCase& c = GetParam();
  dir.write(file("folder") + "/x", "");
  const Outcome o = run_xml(dir, loader_scene(c, file("folder")), 2);
  EXPECT_FALSE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {who(c), file("folder")})) << o.all();
}

INSTANTIATE_TEST_SUITE_P(All, BadInputLoader,
                         ::testing::Values(LoaderCase{"MeshOBJLoader", "obj", kObj, kObjGarbage, 3, kObjTrunc, kObjIndex},
                                           LoaderCase{"MeshGmshLoader", "msh", kMsh, kMshGarbage, 8, kMshTrunc, kMshIndex},
                                           LoaderCase{"MeshVTKLoader", "vtk", kVtk, kVtkGarbage, 7, kVtkTrunc, kVtkIndex},
                                           LoaderCase{"MeshSTLLoader", "stl", kStl, kStlGarbage, 5, kStlTrunc, ""},
                                           LoaderCase{"SphereLoader", "sph", kSph, kSphGarbage, 4, kSphTrunc, ""}),
                         [](const ::testing::TestParamInfo<LoaderCase>& info) { return std::string(info.param.type); });

// Binary STL whose triangle count promises more than the file holds.
TEST(BadInputLoaderBinary, TruncatedBinaryStlIsAnError) {
  TempDir dir;
  std::string bin(80, ' ');
  const std::uint32_t n = 1000;
  bin.append(reinterpret_cast<const char*>(&n), 4);
  bin.append(50, '\0');  // one triangle of 1000
  dir.write("cut.stl", bin);
  const Outcome o = run_xml(dir, R"(<Node name="root" dt="0.01">
  <MeshSTLLoader name="loader" filename="cut.stl"/>
  <MechanicalObject name="dofs" position="@loader.position"/>
</Node>)",
                            1);
  EXPECT_FALSE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"component 'loader' (MeshSTLLoader)", "cut.stl"})) << o.all();
}
