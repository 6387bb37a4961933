// MeshTrianLoader (.trian, trian2), GIDMeshLoader (GiD .gidmsh), VoxelGridLoader
// (raw 8-bit voxels): small files written here and their hand-read contents.
#include <gtest/gtest.h>

#include <fstream>

#include "io/gid_mesh_loader.h"
#include "io/mesh_trian_loader.h"
#include "io/voxel_grid_loader.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::get;
using sinew::test::load;
using sinew::test::TempDir;

namespace {
using Idx = std::vector<unsigned>;
}

// Two triangles sharing the edge 0-2. Triangle 0 (0 1 2) has neighbours (1, −1, −1):
// border edges opposite vertices 1 and 2, i.e. (2,0) and (0,1); triangle 1 (0 2 3)
// has (−1, −1, 0)... its border edges (2,3) and (3,0).
TEST(MeshTrianLoader, TrianWithNeighbours) {
  TempDir d;
  const std::string f = d.write("sq.trian", "4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2\n0 1 2 1 -1 -1\n0 2 3 -1 -1 0\n");
  auto s = load("<Node><MeshTrianLoader name=\"l\" filename=\"" + f + "\"/></Node>");
  auto* l = get<MeshTrianLoader>(*s.root, "l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->position.get().size(), 4u);
  EXPECT_EQ(l->triangles.get(), (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(l->neighbor_table.get(), (std::vector<int>{1, -1, -1, -1, -1, 0}));
  EXPECT_EQ(l->edges_on_border.get(), (std::vector<Edge>{{2, 0}, {0, 1}, {2, 3}, {3, 0}}));
  EXPECT_EQ(l->triangles_on_border.get(), (Idx{0, 1}));
}

TEST(MeshTrianLoader, Trian2AndErrors) {
  TempDir d;
  std::string head;
  for (int i = 0; i < 13; ++i) head += "material line\n";
  const std::string f = d.write("t.trian2", head + "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nNormals 1\n0 0 1\n"
                                                   "Triangles 1\n0 1 2\n");
  auto s = load("<Node><MeshTrianLoader name=\"l\" trian2=\"1\" filename=\"" + f + "\"/></Node>");
  auto* l = get<MeshTrianLoader>(*s.root, "l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->triangles.get(), (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(l->position.get()[1], Vec3(1, 0, 0));
  const std::string bad = d.write("b.trian", "3\n0 0 0\n1 0 0\n0 1 0\n1\n0 1 7 -1 -1 -1\n");
  auto s2 = test::build("<Node><MeshTrianLoader name=\"l\" filename=\"" + bad + "\"/></Node>");
  init_root(*s2.root);
  EXPECT_TRUE(test::any_contains(test::messages(s2.root->diagnostics(), Severity::error), "has vertex 7"));
}

// GiD: 1-based node ids, keywords in any case.
TEST(GIDMeshLoader, TetrahedraAndQuadraticNodes) {
  TempDir d;
  const std::string f = d.write("a.gidmsh", "MESH dimension 3 ElemType Tetrahedra Nnode 4\nCoordinates\n"
                                            "  1 0 0 0\n  2 1 0 0\n  3 0 1 0\n  4 0 0 1\n  5 1 1 1\nEnd Coordinates\n"
                                            "\nElements\n 1 1 2 3 4\n 2 2 3 4 5\nEnd elements\n");
  auto s = load("<Node><GIDMeshLoader name=\"l\" filename=\"" + f + "\"/></Node>");
  auto* l = get<GIDMeshLoader>(*s.root, "l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->position.get().size(), 5u);
  EXPECT_EQ(l->position.get()[4], Vec3(1, 1, 1));
  EXPECT_EQ(l->tetrahedra.get(), (std::vector<Tetra>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  // 2D triangles with 6 nodes: the first three are kept (a warning).
  const std::string g = d.write("b.gidmsh", "MESH dimension 2 ElemType Triangle Nnode 6\nCoordinates\n1 0 0\n2 2 0\n"
                                            "3 0 2\n4 1 0\n5 1 1\n6 0 1\nEnd Coordinates\nElements\n1 1 2 3 4 5 6\n"
                                            "End Elements\n");
  auto s2 = load("<Node><GIDMeshLoader name=\"l\" filename=\"" + g + "\"/></Node>");
  auto* l2 = get<GIDMeshLoader>(*s2.root, "l");
  EXPECT_EQ(l2->triangles.get(), (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(l2->position.get()[2], Vec3(0, 2, 0));
  EXPECT_TRUE(test::any_contains(test::messages(s2.root->diagnostics(), Severity::warning), "first 3 nodes"));
  // Prisms are refused, as SOFA does.
  const std::string p = d.write("c.gidmsh", "MESH dimension 3 ElemType Prism Nnode 6\n");
  auto s3 = test::build("<Node><GIDMeshLoader name=\"l\" filename=\"" + p + "\"/></Node>");
  init_root(*s3.root);
  EXPECT_TRUE(test::any_contains(test::messages(s3.root->diagnostics(), Severity::error), "Prism is not supported"));
}

// A 2×2×1 image after a 1-byte header, values 0 5 5 0, background 0: voxels 1 (i=1, j=0)
// and 2 (i=0, j=1) are active. Their corners, numbered z, then y, then x fastest: layer
// k=0 holds (1,0) (2,0) (0,1) (1,1) (2,1) (0,2) (1,2) → 0..6, layer k=1 → 7..13.
// Voxel 1's hexahedron: corners q = (x,y,z bits) → 0 1 3 4 7 8 10 11, SOFA's order 0 1 4 3 7 8 11 10.
TEST(VoxelGridLoader, HexahedraOfTheActiveVoxels) {
  TempDir d;
  const std::string f = (std::filesystem::path(d.dir()) / "v.raw").string();
  {
    std::ofstream o(f, std::ios::binary);
    const unsigned char bytes[5] = {9, 0, 5, 5, 0};
    o.write(reinterpret_cast<const char*>(bytes), 5);
  }
  auto s = load("<Node><VoxelGridLoader name=\"g\" filename=\"" + f +
                "\" resolution=\"2 2 1\" header=\"1\" bgValue=\"0\" voxelSize=\"0.5 0.5 2\"/>"
                "<VoxelGridLoader name=\"p\" filename=\"" + f +
                "\" resolution=\"2 2 1\" header=\"1\" dataValue=\"5\" generateHexa=\"0\"/></Node>");
  auto* g = get<VoxelGridLoader>(*s.root, "g");
  ASSERT_TRUE(g);
  const std::vector<Vec3>& x = g->position.get();
  ASSERT_EQ(x.size(), 14u);
  EXPECT_EQ(x[0], Vec3(0.5, 0, 0));
  EXPECT_EQ(x[6], Vec3(0.5, 1, 0));
  EXPECT_EQ(x[13], Vec3(0.5, 1, 2));
  ASSERT_EQ(g->hexahedra.get().size(), 2u);
  EXPECT_EQ(g->hexahedra.get()[0], (Hexa{0, 1, 4, 3, 7, 8, 11, 10}));
  EXPECT_EQ(g->hexahedra.get()[1], (Hexa{2, 3, 6, 5, 9, 10, 13, 12}));
  EXPECT_EQ(g->idx_in_regular_grid.get(), (Idx{1, 2}));
  // The ROI was clamped to the image at init.
  EXPECT_EQ(g->roi.get(), (std::vector<int>{0, 0, 0, 1, 1, 0}));
  auto* p = get<VoxelGridLoader>(*s.root, "p");
  EXPECT_EQ(p->position.get(), (std::vector<Vec3>{Vec3(1, 0, 0), Vec3(0, 1, 0)}));
  EXPECT_TRUE(p->hexahedra.get().empty());
}

TEST(VoxelGridLoader, ShortFileIsAnError) {
  TempDir d;
  const std::string f = d.write("s.raw", "ab");
  auto s = test::build("<Node><VoxelGridLoader name=\"g\" filename=\"" + f + "\" resolution=\"2 2 2\"/></Node>");
  init_root(*s.root);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::error), "fewer than the header"));
}
