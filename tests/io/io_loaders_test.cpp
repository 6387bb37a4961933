// Mesh readers and loader components (spec/mechanics.md §7.1–7.6, §0.2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "test_scene.h"
#include "io/grid_mesh_creator.h"
#include "io/mesh_gmsh_loader.h"
#include "io/mesh_obj_loader.h"
#include "io/mesh_readers.h"
#include "io/mesh_stl_loader.h"
#include "io/mesh_vtk_loader.h"
#include "io/sphere_loader.h"
#include "io/string_mesh_creator.h"
#include "state/mechanical_object.h"
#include "topology/mesh_topology.h"
#include "test_paths.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;
using sinew::test::TempDir;

namespace {

using Tris = std::vector<Triangle>;
using Edges = std::vector<Edge>;

const char* kObj = R"(# test
mtllib none.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
vt 0 0
vt 1 0
vn 0 0 1
vn 0 0 -1
g first
f 1/1/1 2/2/1 3//1
f 1 2 3 4
f -5 -4 -3 -2 -1
l 4 2
)";

const char* kTetV1 = R"($NOD
5
10 0 0 0
20 1 0 0
30 0 1 0
40 0 0 1
50 1 1 1
$ENDNOD
$ELM
2
1 4 1 1 4 10 20 30 40
2 15 1 1 1 50
$ENDELM
)";

}  // namespace

// ---------------------------------------------------------------- OBJ

// §7.2: faces 1-based (negative = relative), 4 → quad, more → fan (n0, n_{j−1}, n_j), `l` → sorted edge.
TEST(IoObj, FacesSplitIntoTrianglesQuadsAndEdges) {
  TempDir t;
  std::string err;
  auto m = io::read_obj(t.write("a.obj", kObj), &err);
  ASSERT_TRUE(m) << err;
  ASSERT_EQ(m->positions.size(), 5u);
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  EXPECT_EQ(m->quads, (std::vector<Quad>{{0, 1, 2, 3}}));
  EXPECT_EQ(m->edges, (Edges{{1, 3}}));
  // Normals accumulated per vertex from the face items and normalised; vertices without any stay 0.
  ASSERT_EQ(m->normals.size(), 5u);
  EXPECT_EQ(m->normals[0], Vec3(0, 0, 1));
  EXPECT_EQ(m->normals[4], Vec3(0, 0, 0));
  ASSERT_EQ(m->texcoords.size(), 5u);
  EXPECT_EQ(m->texcoords[1], Vec2(1, 0));
  EXPECT_EQ(m->face_texcoords[0], (std::vector<int>{0, 1, -1}));
  // One group per face type, named by the last `g`.
  ASSERT_EQ(m->triangles_groups.size(), 1u);
  EXPECT_EQ(m->triangles_groups[0].group_name, "first");
  EXPECT_EQ(m->triangles_groups[0].nbp, 2);
}

// MeshOBJLoader::readMTL: each material in sofa::type::Material's text, from SOFA's defaults;
// defaultMaterial is the first material a usemtl names (not the first of the file).
TEST(IoObj, MtlMaterialsAndTheDefaultMaterial) {
  TempDir t;
  t.write("m.mtl", "# comment\nnewmtl a\nKd 0 1 0\nnewmtl b\nNs 96\nKa 0 0 0\nKd 0.5 0.25 1\nKs 0.1 0.2 0.3\n"
                   "Ni 1.45\nd 0.5\nillum 2\n");
  std::string err;
  auto m = io::read_obj(t.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl b\nf 1 2 3\n"), &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->materials, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(m->material_texts.size(), 2u);
  EXPECT_EQ(m->material_texts[0],
            "a Diffuse 1 0 1 0 1 Ambient 1 0.2 0.2 0.2 1 Specular 0 1 1 1 1 Emissive 0 0 0 0 0 Shininess 0 45");
  EXPECT_EQ(m->default_material,
            "b Diffuse 1 0.5 0.25 1 0.5 Ambient 1 0 0 0 1 Specular 1 0.1 0.2 0.3 1 Emissive 0 0 0 0 0 Shininess 1 96");
}

TEST(IoObj, TriangulateAndFlipNormals) {
  TempDir t;
  io::ReadOptions o;
  o.triangulate = true;
  o.flip_normals = true;
  auto m = io::read_obj(t.write("a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"), nullptr, o);
  ASSERT_TRUE(m);
  EXPECT_TRUE(m->quads.empty());
  EXPECT_EQ(m->triangles, (Tris{{2, 1, 0}, {3, 2, 0}}));
}

// handleSeams: one vertex per distinct (texcoord, normal) pair of a position, ordered by the pair.
TEST(IoObj, HandleSeamsDuplicatesVertices) {
  TempDir t;
  io::ReadOptions o;
  o.handle_seams = true;
  auto m = io::read_obj(
      t.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/1 2/1\n"), nullptr, o);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->positions.size(), 4u);  // position 0 appears with two texcoords
  EXPECT_EQ(m->vert_pos_idx, (std::vector<unsigned>{0, 0, 1, 2}));
  EXPECT_EQ(m->triangles, (Tris{{0, 2, 3}, {1, 3, 2}}));
  EXPECT_EQ(m->texcoords[1], Vec2(1, 1));
}

TEST(IoObj, BadIndexIsAnErrorWithLine) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_obj(t.write("a.obj", "v 0 0 0\nf 1 2 x\n"), &err));
  EXPECT_NE(err.find(":2:"), std::string::npos) << err;
  EXPECT_FALSE(io::read_obj(t.write("b.obj", "v 0 0 0\nf 1 2 3\n"), &err));
  EXPECT_NE(err.find("uses vertex 2"), std::string::npos) << err;
  EXPECT_FALSE(io::read_obj(t.dir() + "/missing.obj", &err));
  EXPECT_NE(err.find("cannot open"), std::string::npos) << err;
}

// SOFA reads v, vn and vt into one vector shared by all three and never reset: values missing at
// the end of a line keep those of the previous v/vn/vt line (zeros before the first).
TEST(IoObj, MissingValuesKeepThePreviousLines) {
  TempDir t;
  std::string err;
  auto m = io::read_obj(t.write("carry.obj", "v 0\n"
                                             "v 1 2 3\n"
                                             "v 4\n"
                                             "vn 0 0 1\n"
                                             "v 5 6\n"
                                             "vt 0.5\n"
                                             "vt 0.25 0.75 9\n"
                                             "v\n"
                                             "vn 7\r\n"),
                        &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions_definition,
            (std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {4, 2, 3}, {5, 6, 1}, {0.25, 0.75, 1}}));
  EXPECT_EQ(m->normals_definition, (std::vector<Vec3>{{0, 0, 1}, {7, 0.75, 1}}));
  EXPECT_EQ(m->texcoords_definition, (std::vector<Vec2>{{0.5, 6}, {0.25, 0.75}}));
  EXPECT_EQ(m->positions, m->positions_definition);
}

// A value that is there but is not a number stays an error, with the line.
TEST(IoObj, UnparsableCoordinateIsAnErrorWithLine) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_obj(t.write("a.obj", "v 0 0 0\nv 1 abc 2\n"), &err));
  EXPECT_NE(err.find("a.obj:2: bad coordinate in 'v 1 abc 2'"), std::string::npos) << err;
  EXPECT_FALSE(io::read_obj(t.write("b.obj", "vt 0.5 x\n"), &err));
  EXPECT_NE(err.find("b.obj:1: bad texture coordinate"), std::string::npos) << err;
  EXPECT_FALSE(io::read_obj(t.write("c.obj", "vn 1 1e+\n"), &err));
  EXPECT_NE(err.find("c.obj:1: bad coordinate"), std::string::npos) << err;
}

// ---------------------------------------------------------------- Gmsh

// v1: node ids mapped to their ordinal; type 15 (point) ignored.
TEST(IoGmsh, Version1RenumbersNodes) {
  TempDir t;
  std::string err;
  auto m = io::read_gmsh(t.write("a.msh", kTetV1), &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions.size(), 5u);
  EXPECT_EQ(m->tetrahedra, (std::vector<Tetra>{{0, 1, 2, 3}}));
  EXPECT_TRUE(m->triangles.empty());
}

TEST(IoGmsh, Version2AndVersion4) {
  TempDir t;
  std::string err;
  auto v2 = io::read_gmsh(t.write("b.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
0
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 0 1 0
7 0 0 1
$EndNodes
$Elements
2
1 2 2 0 1 1 2 3
2 3 2 0 1 1 2 3 7
$EndElements
)"),
                          &err);
  ASSERT_TRUE(v2) << err;
  EXPECT_EQ(v2->triangles, (Tris{{0, 1, 2}}));
  EXPECT_EQ(v2->quads, (std::vector<Quad>{{0, 1, 2, 3}}));
  auto v4 = io::read_gmsh(t.write("c.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
2 4 1 4
0 1 0 1
1
0 0 0
3 1 0 3
2
3
4
1 0 0
0 1 0
0 0 2
$EndNodes
$Elements
1 1 1 1
3 1 4 1
1 1 2 3 4
$EndElements
)"),
                          &err);
  ASSERT_TRUE(v4) << err;
  ASSERT_EQ(v4->positions.size(), 4u);
  EXPECT_EQ(v4->positions[3], Vec3(0, 0, 2));
  EXPECT_EQ(v4->tetrahedra, (std::vector<Tetra>{{0, 1, 2, 3}}));
}

// Quadratic tetrahedron (type 11): corner nodes kept, corner-pair edges (sorted) with their mid-node.
TEST(IoGmsh, QuadraticTetrahedron) {
  TempDir t;
  std::string err;
  auto m = io::read_gmsh(t.write("q.msh", R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
10
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
5 0.5 0 0
6 0.5 0.5 0
7 0 0.5 0
8 0 0 0.5
9 0 0.5 0.5
10 0.5 0 0.5
$EndNodes
$Elements
1
1 11 2 0 1 1 2 3 4 5 6 7 8 9 10
$EndElements
)"),
                         &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->tetrahedra, (std::vector<Tetra>{{0, 1, 2, 3}}));
  EXPECT_EQ(m->edges, (Edges{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}}));
  ASSERT_EQ(m->high_order_edge_positions.size(), 6u);
  EXPECT_EQ(m->high_order_edge_positions[4], (io::HighOrderEdgePosition{8, 4, 1, 1}));
}

// §7.1 createSubelements on a hexahedron: 6 quads (0,3,2,1),(4,5,6,7),... then their edges.
TEST(IoLoader, HexahedronSubelements) {
  io::MeshData m;
  for (int k = 0; k < 8; ++k) m.positions.emplace_back(k & 1, (k >> 1) & 1, k >> 2);
  m.hexahedra.push_back({0, 1, 3, 2, 4, 5, 7, 6});
  m.quads.push_back({4, 5, 7, 6});  // already present (same vertex set as the second face)
  io::FinishOptions o;
  o.create_subelements = true;
  io::finish_mesh(m, o);
  ASSERT_EQ(m.quads.size(), 6u);
  EXPECT_EQ(m.quads[0], (Quad{4, 5, 7, 6}));
  EXPECT_EQ(m.quads[1], (Quad{0, 2, 3, 1}));
  EXPECT_EQ(m.quads[5], (Quad{2, 0, 4, 6}));
  EXPECT_EQ(m.edges.size(), 12u);
  EXPECT_EQ(m.edges[0], (Edge{5, 7}));
}

TEST(IoGmsh, MalformedFileReportsTheLine) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_gmsh(t.write("a.msh", "$NOD\n2\n1 0 0 0\n2 1 x 0\n$ENDNOD\n"), &err));
  EXPECT_NE(err.find("a.msh:4:"), std::string::npos) << err;
  EXPECT_FALSE(io::read_gmsh(t.write("b.msh", "hello\n"), &err));
  EXPECT_NE(err.find("not a Gmsh file"), std::string::npos) << err;
  EXPECT_FALSE(io::read_gmsh(t.write("c.msh", "$NOD\n1\n1 0 0 0\n$ENDNOD\n$ELM\n1\n1 4 1 1 4 1 2 3 4\n$ENDELM\n"), &err));
  EXPECT_NE(err.find("unknown node"), std::string::npos) << err;
}

// Trap 2: MeshGmshLoader creates triangles (t0,t2,t1),(t0,t1,t3),(t0,t3,t2),(t1,t2,t3) then their edges.
TEST(IoGmsh, LoaderCreatesSubelementsByDefault) {
  TempDir t;
  const std::string f = t.write("a.msh", kTetV1);
  auto s = load("<Node><MeshGmshLoader name='l' filename='" + f + "'/>"
                "<MeshGmshLoader name='n' createSubelements='0' filename='" + f + "'/></Node>");
  auto* l = get<MeshGmshLoader>(*s.root, "l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->triangles.get(), (Tris{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
  EXPECT_EQ(l->edges.get(), (Edges{{2, 1}, {1, 0}, {0, 2}, {1, 3}, {3, 0}, {3, 2}}));
  EXPECT_EQ(l->normals.get().size(), 5u);
  auto* n = get<MeshGmshLoader>(*s.root, "n");
  EXPECT_TRUE(n->triangles.get().empty());
  EXPECT_TRUE(n->edges.get().empty());
}

// ---------------------------------------------------------------- VTK

TEST(IoVtk, LegacyAsciiCellTypes) {
  TempDir t;
  std::string err;
  auto m = io::read_vtk(t.write("a.vtk", R"(# vtk DataFile Version 2.0
title
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 8 float
0 0 0 1 0 0 1 1 0 0 1 0
0 0 1 1 0 1 1 1 1 0 1 1.1
CELLS 5 28
4 0 1 2 4
8 0 1 3 2 4 5 7 6
4 0 1 3 2
2 6 7
5 0 1 2 3 4
CELL_TYPES 5
10
11
8
3
7
POINT_DATA 8
SCALARS temp float 1
LOOKUP_TABLE default
1 2 3 4 5 6 7 8
)"),
                        &err);
  ASSERT_TRUE(m) << err;
  ASSERT_EQ(m->positions.size(), 8u);
  EXPECT_EQ(m->positions[7][2], static_cast<double>(1.1f));  // float data stay float-rounded
  EXPECT_EQ(m->tetrahedra, (std::vector<Tetra>{{0, 1, 2, 4}}));
  EXPECT_EQ(m->hexahedra, (std::vector<Hexa>{{0, 1, 2, 3, 4, 5, 6, 7}}));  // voxel reordered
  EXPECT_EQ(m->quads, (std::vector<Quad>{{0, 1, 2, 3}}));                  // pixel reordered
  EXPECT_EQ(m->edges, (Edges{{6, 7}}));
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  ASSERT_EQ(m->point_data.size(), 1u);
  EXPECT_EQ(m->point_data[0].values[7], 8.0);
}

namespace {
void put_be32(std::string& s, uint32_t v) {
  for (int k = 3; k >= 0; --k) s += static_cast<char>((v >> (8 * k)) & 0xFF);
}
void put_be_double(std::string& s, double d) {
  uint64_t u;
  std::memcpy(&u, &d, 8);
  for (int k = 7; k >= 0; --k) s += static_cast<char>((u >> (8 * k)) & 0xFF);
}
std::string base64(const std::string& in) {
  const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8) |
                       static_cast<unsigned char>(in[i + 2]);
    out += a[(v >> 18) & 63], out += a[(v >> 12) & 63], out += a[(v >> 6) & 63], out += a[v & 63];
  }
  if (i < in.size()) {
    unsigned v = static_cast<unsigned char>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<unsigned char>(in[i + 1]) << 8;
    out += a[(v >> 18) & 63], out += a[(v >> 12) & 63];
    out += i + 1 < in.size() ? a[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}
}  // namespace

TEST(IoVtk, LegacyBinaryIsBigEndian) {
  TempDir t;
  std::string f = "# vtk DataFile Version 3.0\nbin\nBINARY\nDATASET POLYDATA\nPOINTS 3 double\n";
  for (double d : {0.0, 0.0, 0.0, 2.5, 0.0, 0.0, 0.0, -1.0, 0.0}) put_be_double(f, d);
  f += "\nPOLYGONS 1 4\n";
  for (uint32_t v : {3u, 0u, 1u, 2u}) put_be32(f, v);
  f += "\n";
  std::string err;
  auto m = io::read_vtk(t.write("b.vtk", f), &err);
  ASSERT_TRUE(m) << err;
  ASSERT_EQ(m->positions.size(), 3u);
  EXPECT_EQ(m->positions[1], Vec3(2.5, 0, 0));
  EXPECT_EQ(m->positions[2], Vec3(0, -1, 0));
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}}));
}

// SOFA reads natively and swaps only when the first polygon size looks byte-swapped: little-endian files load too.
TEST(IoVtk, LegacyBinaryLittleEndianIsDetected) {
  TempDir t;
  std::string f = "# vtk DataFile Version 3.0\nbin\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n";
  for (float x : {0.f, 0.f, 0.f, 0.5f, 0.f, 0.f, 0.f, 3.f, 0.f}) f.append(reinterpret_cast<const char*>(&x), 4);
  f += "\nPOLYGONS 1 4\n";
  for (uint32_t v : {3u, 2u, 1u, 0u}) f.append(reinterpret_cast<const char*>(&v), 4);
  f += "\n";
  std::string err;
  auto m = io::read_vtk(t.write("le.vtk", f), &err);
  ASSERT_TRUE(m) << err;
  ASSERT_EQ(m->positions.size(), 3u);
  EXPECT_EQ(m->positions[2], Vec3(0, 3, 0));
  EXPECT_EQ(m->triangles, (Tris{{2, 1, 0}}));
}

TEST(IoVtk, XmlAsciiAndBase64) {
  TempDir t;
  std::string raw;
  auto le32 = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) raw += static_cast<char>((v >> (8 * k)) & 0xFF);
  };
  le32(16);
  for (uint32_t v : {0u, 1u, 2u, 3u}) le32(v);
  const std::string conn = base64(raw);
  std::string err;
  auto m = io::read_vtk(t.write("c.vtu", R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="4" NumberOfCells="1">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="binary">)" + conn + R"(</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">10</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)"),
                        &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions.size(), 4u);
  EXPECT_EQ(m->tetrahedra, (std::vector<Tetra>{{0, 1, 2, 3}}));
}

// PolyData: Polys by size (3 → triangle, 4 → quad, more → polyline); ASCII points are kept as doubles.
TEST(IoVtk, XmlPolyData) {
  TempDir t;
  std::string err;
  auto m = io::read_vtk(t.write("p.vtp", R"(<VTKFile type="PolyData" version="0.1">
  <PolyData><Piece NumberOfPoints="5" NumberOfPolys="3">
    <Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 1 1 0 0 1 0 0.1 0.5 0</DataArray></Points>
    <Polys>
      <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2  0 1 2 3  0 1 2 3 4</DataArray>
      <DataArray type="Int32" Name="offsets" format="ascii">3 7 12</DataArray>
    </Polys>
  </Piece></PolyData>
</VTKFile>)"),
                        &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions[4][0], 0.1);
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}}));
  EXPECT_EQ(m->quads, (std::vector<Quad>{{0, 1, 2, 3}}));
  ASSERT_EQ(m->polylines.size(), 1u);
  EXPECT_EQ(m->polylines[0].size(), 5u);
}

namespace {
// The bytes of `v` in the given byte order.
template <class T>
std::string bytes_of(T v, bool big_endian) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &v, sizeof(T));
  if (big_endian) std::reverse(s.begin(), s.end());
  return s;
}

// One "binary" DataArray body: base64 of (byte count, values), the count as UInt32 or UInt64. VTK
// may encode the count and the values as one base64 block or as two; `split` picks the second form.
template <class T>
std::string vtk_binary(const std::vector<T>& values, bool big_endian, bool header64, bool split) {
  std::string data;
  for (T v : values) data += bytes_of(v, big_endian);
  const std::string header = header64 ? bytes_of<uint64_t>(data.size(), big_endian)
                                      : bytes_of<uint32_t>(static_cast<uint32_t>(data.size()), big_endian);
  return split ? base64(header) + base64(data) : base64(header + data);
}

// Two tetrahedra and one triangle on 5 points, every array binary. Int is the connectivity and
// offsets type (Int32 or Int64); the point data are Float32 to swap 4-byte floats too.
template <class Int>
std::string binary_vtu(bool big_endian, bool header64, bool split) {
  const std::vector<double> points{0, 0, 0, 1.5, 0, 0, 0, -2.25, 0, 0, 0, 3.125, 1e-3, 7, -0.1};
  const std::vector<Int> conn{0, 1, 2, 3, 1, 2, 3, 4, 4, 0, 1};
  const std::vector<Int> offsets{4, 8, 11};
  const std::vector<uint8_t> types{10, 10, 5};
  const std::vector<float> temperature{0.5f, -1.0f, 2.75f, 1e-6f, 300.0f};
  const char* int_type = sizeof(Int) == 8 ? "Int64" : "Int32";
  return std::string(R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order=")") +
         (big_endian ? "BigEndian" : "LittleEndian") + R"(" header_type=")" + (header64 ? "UInt64" : "UInt32") +
         R"(">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="3">
      <PointData>
        <DataArray type="Float32" Name="temperature" format="binary">)" +
         vtk_binary(temperature, big_endian, header64, split) + R"(</DataArray>
      </PointData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="binary">
          )" + vtk_binary(points, big_endian, header64, split) + R"(
        </DataArray>
      </Points>
      <Cells>
        <DataArray type=")" + int_type + R"(" Name="connectivity" format="binary">)" +
         vtk_binary(conn, big_endian, header64, split) + R"(</DataArray>
        <DataArray type=")" + int_type + R"(" Name="offsets" format="binary">)" +
         vtk_binary(offsets, big_endian, header64, split) + R"(</DataArray>
        <DataArray type="UInt8" Name="types" format="binary">)" +
         vtk_binary(types, big_endian, header64, split) + R"(</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";
}

void expect_binary_vtu_mesh(const io::MeshData& m) {
  EXPECT_EQ(m.positions, (std::vector<Vec3>{{0, 0, 0}, {1.5, 0, 0}, {0, -2.25, 0}, {0, 0, 3.125}, {1e-3, 7, -0.1}}));
  EXPECT_EQ(m.tetrahedra, (std::vector<Tetra>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  EXPECT_EQ(m.triangles, (Tris{{4, 0, 1}}));
  ASSERT_EQ(m.point_data.size(), 1u);
  EXPECT_EQ(m.point_data[0].name, "temperature");
  EXPECT_EQ(m.point_data[0].values,
            (std::vector<double>{0.5, -1.0, 2.75, static_cast<double>(1e-6f), 300.0}));
}
}  // namespace

// byte_order says how binary values are stored; ASCII arrays read the same either way.
TEST(IoVtk, XmlBigEndianAsciiArrays) {
  TempDir t;
  auto vtu = [](const char* order) {
    return std::string(R"(<VTKFile type="UnstructuredGrid" version="0.1" byte_order=")") + order + R"(">
  <UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">
    <Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">
      0.25 -1.5 3   1 0 0   0 1 0   0 0 1
    </DataArray></Points>
    <Cells>
      <DataArray type="Int32" Name="connectivity" format="ascii">3 2 1 0</DataArray>
      <DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
      <DataArray type="UInt8" Name="types" format="ascii">10</DataArray>
    </Cells>
  </Piece></UnstructuredGrid>
</VTKFile>
)";
  };
  std::string err;
  auto big = io::read_vtk(t.write("big.vtu", vtu("BigEndian")), &err);
  ASSERT_TRUE(big) << err;
  auto little = io::read_vtk(t.write("little.vtu", vtu("LittleEndian")), &err);
  ASSERT_TRUE(little) << err;
  EXPECT_EQ(big->positions, (std::vector<Vec3>{{0.25, -1.5, 3}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
  EXPECT_EQ(big->tetrahedra, (std::vector<Tetra>{{3, 2, 1, 0}}));
  EXPECT_EQ(big->positions, little->positions);
  EXPECT_EQ(big->tetrahedra, little->tetrahedra);
  EXPECT_FALSE(io::read_vtk(t.write("odd.vtu", vtu("MiddleEndian")), &err));
  EXPECT_NE(err.find("unknown byte_order 'MiddleEndian'"), std::string::npos) << err;
}

// A compressor applies to binary arrays only: a file naming one with ASCII arrays (SOFA's
// share/mesh/skull.vtp) reads as any other; a compressed binary array is refused by name.
TEST(IoVtk, XmlCompressorWithAsciiArraysReads) {
  TempDir t;
  auto vtp = [](const char* points_array) {
    return std::string(R"(<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian" compressor="vtkZLibDataCompressor">
  <PolyData><Piece NumberOfPoints="3" NumberOfPolys="1">
    <Points>)") + points_array + R"(</Points>
    <Polys>
      <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2</DataArray>
      <DataArray type="Int32" Name="offsets" format="ascii">3</DataArray>
    </Polys>
  </Piece></PolyData>
</VTKFile>
)";
  };
  std::string err;
  auto m = io::read_vtk(
      t.write("ascii.vtp", vtp(R"(<DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 2 0</DataArray>)")),
      &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}}));
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}}));
  EXPECT_FALSE(io::read_vtk(
      t.write("zlib.vtp", vtp(R"(<DataArray type="Float32" NumberOfComponents="3" format="binary">AQAAAA==</DataArray>)")),
      &err));
  EXPECT_NE(err.find("compressed binary DataArrays are not supported"), std::string::npos) << err;
}

// Big-endian base64 arrays are byte-swapped, their byte-count header too (UInt32 or UInt64), and
// give the mesh of the little-endian file.
TEST(IoVtk, XmlBigEndianBinaryArrays) {
  TempDir t;
  struct Case {
    const char* name;
    std::string big, little;
  };
  const Case cases[] = {
      {"int32_header32", binary_vtu<int32_t>(true, false, false), binary_vtu<int32_t>(false, false, false)},
      {"int64_header32", binary_vtu<int64_t>(true, false, true), binary_vtu<int64_t>(false, false, true)},
      {"int32_header64", binary_vtu<int32_t>(true, true, true), binary_vtu<int32_t>(false, true, true)},
      {"int64_header64", binary_vtu<int64_t>(true, true, false), binary_vtu<int64_t>(false, true, false)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    std::string err;
    auto big = io::read_vtk(t.write(std::string(c.name) + "_be.vtu", c.big), &err);
    ASSERT_TRUE(big) << err;
    auto little = io::read_vtk(t.write(std::string(c.name) + "_le.vtu", c.little), &err);
    ASSERT_TRUE(little) << err;
    expect_binary_vtu_mesh(*big);
    expect_binary_vtu_mesh(*little);
  }
}

// Raw appended data (<AppendedData>) is not read: a clear error, not a wrong mesh.
TEST(IoVtk, XmlAppendedDataIsAnError) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_vtk(t.write("app.vtu", R"(<VTKFile type="UnstructuredGrid" version="0.1" byte_order="BigEndian">
  <UnstructuredGrid><Piece NumberOfPoints="1" NumberOfCells="0">
    <Points><DataArray type="Float32" NumberOfComponents="3" format="appended" offset="0"/></Points>
  </Piece></UnstructuredGrid>
  <AppendedData encoding="raw">_abcdefghijkl</AppendedData>
</VTKFile>
)"),
                            &err));
  EXPECT_NE(err.find("app.vtu: Points: DataArray format 'appended' is not supported (ascii or binary)"),
            std::string::npos)
      << err;
  // Raw bytes that are not XML text ('<', '&', NUL): the file does not parse, the message says why.
  std::string raw = R"(<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
  <UnstructuredGrid><Piece NumberOfPoints="1" NumberOfCells="0">
    <Points><DataArray type="Float32" NumberOfComponents="3" format="appended" offset="0"/></Points>
  </Piece></UnstructuredGrid>
  <AppendedData encoding="raw">_)";
  raw += std::string("\x0c\0\0\0<&\0\x3f\0\0\x80\x3f\0\0\0\x40", 16);
  raw += "\n  </AppendedData>\n</VTKFile>\n";
  EXPECT_FALSE(io::read_vtk(t.write("raw.vtu", raw), &err));
  EXPECT_NE(err.find("raw.vtu: appended data (<AppendedData>) is not supported"), std::string::npos) << err;
}

// Malformed XML is an error with the line tinyxml2 stopped at.
TEST(IoVtk, XmlSyntaxErrorHasTheLine) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_vtk(t.write("bad.vtu", "<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid>\n"
                                               "<Piece></Peice>\n</UnstructuredGrid>\n</VTKFile>\n"),
                            &err));
  EXPECT_NE(err.find("bad.vtu:3: XML error: XML_ERROR_MISMATCHED_ELEMENT"), std::string::npos) << err;
}

TEST(IoVtk, BadCellIndexIsAnError) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_vtk(t.write("a.vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                                             "POINTS 2 float\n0 0 0 1 1 1\nCELLS 1 3\n2 0 5\nCELL_TYPES 1\n3\n"),
                            &err));
  EXPECT_NE(err.find("uses point 5"), std::string::npos) << err;
}

// Absurd counts in a small file give an error, not an allocation failure.
TEST(IoRobustness, HugeCountsAreRejected) {
  TempDir t;
  std::string err;
  EXPECT_FALSE(io::read_vtk(t.write("h.vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET POLYDATA\n"
                                             "POINTS 1000000000000 float\n0 0 0\n"),
                            &err));
  EXPECT_NE(err.find("unexpected end of data"), std::string::npos) << err;
  EXPECT_FALSE(io::read_gmsh(t.write("h.msh", "$NOD\n999999999999\n1 0 0 0\n"), &err));
  EXPECT_FALSE(io::read_gmsh(t.write("h4.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 99999999999 1 2\n"
                                              "2 1 0 99999999999\n1\n"),
                             &err));
  EXPECT_NE(err.find("truncated"), std::string::npos) << err;
  EXPECT_FALSE(io::read_vtk(t.write("n.vtk", "# vtk DataFile Version 2.0\nt\nASCII\nDATASET POLYDATA\n"
                                             "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n-7 0 1 2\n"),
                            &err));
  EXPECT_NE(err.find("negative size"), std::string::npos) << err;
}

// ---------------------------------------------------------------- STL

TEST(IoStl, AsciiAndBinaryMergeDuplicates) {
  TempDir t;
  std::string err;
  auto a = io::read_stl(t.write("a.stl", R"(solid x
facet normal 0 0 1
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 1 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex 1 0 0
  vertex 1 1 0
  vertex 0 1 0
 endloop
endfacet
endsolid x
)"),
                        &err);
  ASSERT_TRUE(a) << err;
  EXPECT_EQ(a->positions.size(), 4u);
  EXPECT_EQ(a->triangles, (Tris{{0, 1, 2}, {1, 3, 2}}));

  std::string b(80, ' ');
  auto le32 = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) b += static_cast<char>((v >> (8 * k)) & 0xFF);
  };
  auto f32 = [&](float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    le32(u);
  };
  le32(2);
  for (int tri = 0; tri < 2; ++tri) {
    for (float f : {0.f, 0.f, 1.f}) f32(f);
    const float v[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 0, 0}};  // second is degenerate
    for (float f : v[tri]) f32(f);
    b += std::string(2, '\0');
  }
  auto bin = io::read_stl(t.write("b.stl", b), &err);
  ASSERT_TRUE(bin) << err;
  EXPECT_EQ(bin->positions.size(), 3u);
  EXPECT_EQ(bin->triangles, (Tris{{0, 1, 2}}));  // degenerate facet dropped
  EXPECT_EQ(bin->normals.size(), 2u);
  EXPECT_FALSE(io::read_stl(t.write("c.stl", std::string(90, 'x')), &err));
  EXPECT_NE(err.find("not a binary STL"), std::string::npos) << err;
}

// ---------------------------------------------------------------- OFF

// 3 → triangle, 4 → quad, other sizes skipped without counting; '#' lines skipped.
TEST(IoOff, TrianglesQuadsAndSkippedPolygons) {
  TempDir t;
  std::string err;
  auto m = io::read_off(t.write("a.off", "OFF\n# c\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n"
                                         "3 0 1 2\n5 0 1 2 3 4\n4 0 1 2 3\n3 1 4 2\n"),
                        &err);
  ASSERT_TRUE(m) << err;
  EXPECT_EQ(m->positions.size(), 5u);
  EXPECT_EQ(m->triangles, (Tris{{0, 1, 2}, {1, 4, 2}}));
  EXPECT_EQ(m->quads, (std::vector<Quad>{{0, 1, 2, 3}}));
  EXPECT_FALSE(io::read_off(t.write("b.off", "OFF\n2 1 0\n0 0 0\n1 0 0\n3 0 1 7\n"), &err));
  EXPECT_NE(err.find("b.off:5:"), std::string::npos) << err;
  EXPECT_FALSE(io::read_off(t.write("c.off", "FOO\n"), &err));
}

// GridMeshCreator: x = i·1/(n−1); pattern 2 (default) gives two triangles per cell, edges sorted and unique.
TEST(IoLoader, GridMeshCreator) {
  auto s = load("<Node><GridMeshCreator name='g' resolution='3 2'/><GridMeshCreator name='q' trianglePattern='0'/></Node>");
  auto* g = get<GridMeshCreator>(*s.root, "g");
  ASSERT_TRUE(g);
  ASSERT_EQ(g->position.get().size(), 6u);
  EXPECT_EQ(g->position.get()[4], Vec3(0.5, 1, 0));
  EXPECT_EQ(g->triangles.get(), (Tris{{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}}));
  EXPECT_EQ(g->edges.get(), (Edges{{0, 1}, {1, 2}, {1, 4}, {2, 5}, {3, 0}, {4, 0}, {4, 3}, {5, 1}, {5, 4}}));
  auto* q = get<GridMeshCreator>(*s.root, "q");
  EXPECT_EQ(q->quads.get(), (std::vector<Quad>{{0, 1, 3, 2}}));
  EXPECT_EQ(q->edges.get().size(), 4u);
}

// ---------------------------------------------------------------- SphereLoader

TEST(IoSph, CentresTransformedRadiiNot) {
  TempDir t;
  const std::string f = t.write("a.sph", "sph 1.0\n# comment\nnums 2\nsphe 1 1 2 3 0.5\nsphe 2 0 0 0 2\n");
  auto m = io::read_sph(f, nullptr);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->radii, (std::vector<double>{0.5, 2}));
  auto s = load("<Node><SphereLoader name='s' filename='" + f + "' scale='2 2 2' translation='1 0 0'/></Node>");
  auto* l = get<SphereLoader>(*s.root, "s");
  ASSERT_TRUE(l);
  ASSERT_EQ(l->position.get().size(), 2u);
  EXPECT_EQ(l->position.get()[0], Vec3(3, 4, 6));
  EXPECT_EQ(l->list_radius.get(), (std::vector<double>{0.5, 2}));
}

// ---------------------------------------------------------------- MeshLoader behaviour

// §7.6: x = i·1.0/(N−1) evaluated left to right.
TEST(IoLoader, StringMeshCreator) {
  auto s = load("<Node><StringMeshCreator name='s' resolution='4'/></Node>");
  auto* c = get<StringMeshCreator>(*s.root, "s");
  ASSERT_TRUE(c);
  ASSERT_EQ(c->position.get().size(), 4u);
  EXPECT_EQ(c->position.get()[1][0], 1.0 / 3);
  EXPECT_EQ(c->position.get()[3][0], 1.0);
  EXPECT_EQ(c->edges.get(), (Edges{{0, 1}, {1, 2}, {2, 3}}));
}

// §7.1: p' = T + R·(S ⊙ p), R = Rz·Ry·Rx from degrees; `scale` (float) multiplies scale3d.
TEST(IoLoader, TransformsInSofaOrder) {
  TempDir t;
  const std::string f = t.write("a.obj", "v 1 0 0\nv 0 2 0\nf 1 2 1\n");
  auto s = load("<Node><MeshOBJLoader name='l' filename='" + f +
                "' scale='2' scale3d='1 1 3' rotation='0 0 90' translation='10 0 0'/></Node>");
  auto* l = get<MeshOBJLoader>(*s.root, "l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->scale3d.get(), Vec3(2, 2, 6));
  const auto& p = l->position.get();
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0][0], 10, 1e-12);
  EXPECT_NEAR(p[0][1], 2, 1e-12);
  EXPECT_NEAR(p[1][0], 6, 1e-12);
  EXPECT_NEAR(p[1][1], 0, 1e-12);
  // Rotation about x then z: (0,1,0) → x 90° → (0,0,1) → z 90° stays.
  auto s2 = load("<Node><MeshOBJLoader name='l' filename='" + f + "' rotation='90 0 90'/></Node>");
  const auto& q = get<MeshOBJLoader>(*s2.root, "l")->position.get();
  EXPECT_NEAR(q[1][2], 2, 1e-12);
  EXPECT_NEAR(q[0][1], 1, 1e-12);
  // A transformation matrix replaces translation/rotation/scale.
  auto s3 = load("<Node><MeshOBJLoader name='l' filename='" + f +
                 "' translation='5 5 5' transformation='1 0 0 1  0 1 0 0  0 0 1 0  0 0 0 1'/></Node>");
  EXPECT_EQ(get<MeshOBJLoader>(*s3.root, "l")->position.get()[0], Vec3(2, 0, 0));
}

TEST(IoLoader, OnlyAttachedPointsRenumbers) {
  TempDir t;
  const std::string f = t.write("a.obj", "v 0 0 0\nv 9 9 9\nv 1 0 0\nv 0 1 0\nf 1 3 4\n");
  auto s = load("<Node><MeshOBJLoader name='l' onlyAttachedPoints='1' filename='" + f + "'/></Node>");
  auto* l = get<MeshOBJLoader>(*s.root, "l");
  ASSERT_EQ(l->position.get().size(), 3u);
  EXPECT_EQ(l->position.get()[1], Vec3(1, 0, 0));
  EXPECT_EQ(l->triangles.get(), (Tris{{0, 1, 2}}));
}

// §0.2: src= links every autolinkable field; transforms are not propagated.
TEST(IoLoader, SrcLinksPositionsButNotTransforms) {
  TempDir t;
  const std::string f = t.write("a.obj", "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  auto s = load("<Node><MeshOBJLoader name='l' translation='1 0 0' filename='" + f + "'/>"
                "<MeshTopology name='topo' src='@l'/><MechanicalObject name='mo' src='@l'/></Node>");
  auto* mo = get<MechanicalObject>(*s.root, "mo");
  ASSERT_TRUE(mo);
  ASSERT_EQ(mo->size(), 3u);
  EXPECT_EQ(mo->position.get().data, (std::vector<double>{2, 0, 0, 1, 1, 0, 1, 0, 1}));
  EXPECT_EQ(mo->translation.get(), Vec3::Zero());
  auto* topo = get<MeshContainer>(*s.root, "topo");
  ASSERT_TRUE(topo);
  EXPECT_EQ(topo->triangles(), (Tris{{0, 1, 2}}));
}

// A state declared before its loader, linked with position="@l.position", still gets the data.
TEST(IoLoader, LinkToALoaderDeclaredLater) {
  TempDir t;
  const std::string f = t.write("a.obj", "v 1 2 3\nv 4 5 6\n");
  auto s = load("<Node><MechanicalObject name='mo' position='@l.position'/>"
                "<MeshOBJLoader name='l' filename='" + f + "'/></Node>");
  auto* mo = get<MechanicalObject>(*s.root, "mo");
  ASSERT_EQ(mo->size(), 2u);
  EXPECT_EQ(mo->position.get().data[5], 6.0);
}

TEST(IoLoader, MissingOrBrokenFileIsReported) {
  TempDir t;
  auto s = test::build("<Node><MeshGmshLoader name='l' filename='" + t.write("bad.msh", "garbage\n") + "'/></Node>");
  init_root(*s.root);
  auto* l = get<MeshGmshLoader>(*s.root, "l");
  EXPECT_EQ(l->state(), ComponentState::invalid);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "bad.msh:1:"));
  auto s2 = test::build("<Node><MeshOBJLoader name='l' filename='" + t.dir() + "/nothere.obj'/></Node>");
  EXPECT_TRUE(test::any_contains(test::messages(s2.root->diagnostics(), Severity::error), "nothere.obj"));
  auto s3 = test::build("<Node><MeshOBJLoader name='l'/></Node>");
  init_root(*s3.root);
  EXPECT_TRUE(test::any_contains(test::messages(s3.root->diagnostics(), Severity::error), "no file name"));
}

// ---------------------------------------------------------------- SOFA's meshes

namespace {
std::string data_dir() { return SINEW_DATA_DIR; }
std::string resolve(const std::string& rel) {
  for (const char* sub : {"/share/", "/examples/"}) {
    const std::string p = data_dir() + sub + rel;
    if (std::filesystem::exists(p)) return p;
  }
  return {};
}
}  // namespace

// Every mesh file named by a scene loads, and a few have the counts read independently from the files.
TEST(IoData, EveryMeshReferencedByTheScenesLoads) {
  if (!std::filesystem::exists(data_dir() + "/examples")) GTEST_SKIP() << "SOFA data folder absent: " << data_dir();
  std::set<std::string> files;
  const std::regex attr(R"re((?:filename|fileMesh|fileTopology)\s*=\s*"([^"]+\.(?:obj|msh|vtk|vtu|stl|sph)))re",
                        std::regex::icase);
  for (const auto& e : std::filesystem::recursive_directory_iterator(data_dir() + "/examples")) {
    if (!e.is_regular_file()) continue;
    const auto ext = e.path().extension().string();
    if (ext != ".scn" && ext != ".xml") continue;
    std::ifstream in(e.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), attr); it != std::sregex_iterator(); ++it)
      files.insert((*it)[1].str());
  }
  ASSERT_GT(files.size(), 20u);
  int loaded = 0;
  for (const auto& rel : files) {
    const std::string path = resolve(rel);
    if (path.empty()) continue;  // files missing from the data set are reported by the scene checks
    std::string err;
    auto m = io::read_mesh(path, &err);
    EXPECT_TRUE(m) << rel << ": " << err;
    if (m) {
      ++loaded;
      EXPECT_FALSE(m->positions.empty()) << rel;
    }
  }
  EXPECT_GT(loaded, 30);

  auto m = io::read_mesh(resolve("mesh/liver.msh"), nullptr);  // $NOD 181, 596 elements of type 4
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 181u);
  EXPECT_EQ(m->tetrahedra.size(), 596u);
  m = io::read_mesh(resolve("mesh/torus.obj"), nullptr);  // 800 v, 861 vt, 1600 triangular faces
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 800u);
  EXPECT_EQ(m->texcoords_definition.size(), 861u);
  EXPECT_EQ(m->triangles.size(), 1600u);
  m = io::read_mesh(resolve("mesh/dragon.obj"), nullptr);  // 1190 v, 2564 triangular faces (CRLF lines)
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 1190u);
  EXPECT_EQ(m->triangles.size(), 2564u);
  EXPECT_TRUE(m->quads.empty());
  m = io::read_mesh(resolve("mesh/SofaScene/A.vtk"), nullptr);  // 413 points; 1942 lines, 2645 triangles, 1116 tets
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 413u);
  EXPECT_EQ(m->edges.size(), 1942u);
  EXPECT_EQ(m->triangles.size(), 2645u);
  EXPECT_EQ(m->tetrahedra.size(), 1116u);
  m = io::read_mesh(resolve("mesh/test_quad.vtk"), nullptr);  // 312 points, 288 quads
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 312u);
  EXPECT_EQ(m->quads.size(), 288u);
  m = io::read_mesh(resolve("mesh/liver.sph"), nullptr);  // 34 "sphe" lines
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 34u);
  m = io::read_mesh(resolve("mesh/raptorTetra_8418.vtu"), nullptr);  // BigEndian, ASCII: 2996 points, 8418 tets
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 2996u);
  EXPECT_EQ(m->positions[0], Vec3(-1.55191, 0.180325, -0.22213));
  EXPECT_EQ(m->tetrahedra.size(), 8418u);
  m = io::read_mesh(resolve("mesh/raptorTemperature.obj"), nullptr);  // 2996 "v 0" lines
  ASSERT_TRUE(m);
  ASSERT_EQ(m->positions.size(), 2996u);
  EXPECT_EQ(m->positions[2995], Vec3(0, 0, 0));
  m = io::read_mesh(resolve("mesh/cubeDof.msh"), nullptr);  // v2, 27 nodes numbered from 0, no element
  ASSERT_TRUE(m);
  EXPECT_EQ(m->positions.size(), 27u);
  EXPECT_TRUE(m->tetrahedra.empty());
}
