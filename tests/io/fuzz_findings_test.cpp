// Findings of the mesh-reader fuzz targets (fuzz/RESULTS.md), one test each: the
// readers refuse what used to come through as garbage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "io/mesh_readers.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::test;

namespace {

// A binary STL of one facet with the given normal and vertices.
std::string binary_stl(const float normal[3], const float v[9]) {
  std::string s(80, ' ');
  const std::uint32_t count = 1;
  s.append(reinterpret_cast<const char*>(&count), 4);
  s.append(reinterpret_cast<const char*>(normal), 12);
  s.append(reinterpret_cast<const char*>(v), 36);
  s.append(2, '\0');
  return s;
}

}  // namespace

// fuzz_mesh_stl: a binary STL facet whose normal is NaN (raw float bits 0xffffffff) gave a
// mesh with a NaN normal; the facet's normal and vertices must be finite.
TEST(MeshReaderFuzzFindings, BinaryStlWithNonFiniteNormalOrVertexIsRefused) {
  TempDir dir;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float good_n[3] = {0, 0, 1};
  const float bad_n[3] = {0, nan, 1};
  const float good_v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const float bad_v[9] = {0, 0, 0, 1, inf, 0, 0, 1, 0};
  std::string error;
  ASSERT_TRUE(io::read_stl(dir.write("good.stl", binary_stl(good_n, good_v)), &error)) << error;
  EXPECT_FALSE(io::read_stl(dir.write("n.stl", binary_stl(bad_n, good_v)), &error));
  EXPECT_NE(error.find("non-finite normal"), std::string::npos) << error;
  EXPECT_FALSE(io::read_stl(dir.write("v.stl", binary_stl(good_n, bad_v)), &error));
  EXPECT_NE(error.find("non-finite coordinate"), std::string::npos) << error;
}

// The text formats: "nan", "inf" or an overflowing number as a coordinate is a parse
// error at its line (std::from_chars accepts the first two, SOFA's stream read does not).
TEST(MeshReaderFuzzFindings, NonFiniteCoordinateInTextIsAnErrorAtItsLine) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(io::read_obj(dir.write("a.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"), &error));
  EXPECT_NE(error.find("a.obj:2"), std::string::npos) << error;
  EXPECT_FALSE(io::read_off(dir.write("b.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n"), &error));
  EXPECT_NE(error.find("b.off:"), std::string::npos) << error;
  EXPECT_FALSE(io::read_gmsh(dir.write("c.msh", "$NOD\n3\n1 0 0 0\n2 1e999 0 0\n3 0 1 0\n$ENDNOD\n$ELM\n1\n"
                                                "1 2 1 1 3 1 2 3\n$ENDELM\n"),
                             &error));
  EXPECT_NE(error.find("c.msh:"), std::string::npos) << error;
  const std::string vtk =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 -inf 0\n"
      "POLYGONS 1 4\n3 0 1 2\n";
  EXPECT_FALSE(io::read_vtk(dir.write("d.vtk", vtk), &error));
  EXPECT_FALSE(error.empty());
}
