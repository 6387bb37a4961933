// Exporters and state playback: exact file contents for small meshes, numbering, the .pvd
// series, SOFA's event timing (exportAtBegin, every n steps, exportAtEnd at close), bad
// input, and a WriteState → ReadState round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/node.h"
#include "exporter/playback/compare_state.h"
#include "exporter/playback/read_state.h"
#include "exporter/playback/write_state.h"
#include "exporter/vtk_exporter.h"
#include "regression/state_file.h"
#include "runner/session.h"
#include "test_scene.h"

namespace sinew {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A tetrahedron with one face, no solver: the points stay where they are.
std::string tetra_scene(const std::string& exporter) {
  return R"(<Node name="root" dt="0.01" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <MechanicalObject name="mecha" position="0 0 0  1 0 0  0 2 0  0 0 3"/>
  <MeshTopology name="topo" edges="0 1" triangles="0 1 2" tetrahedra="0 1 2 3"/>
  )" + exporter + R"(
</Node>)";
}

struct RunResult {
  std::unique_ptr<runner::Session> session;
  std::vector<std::string> errors, warnings;
};

RunResult run(const TempDir& dir, const std::string& xml, long steps, bool close = true, bool expect_ok = true) {
  RunResult r;
  r.session = std::make_unique<runner::Session>(dir.write("scene.scn", xml), runner::SessionOptions{});
  if (expect_ok) {
    EXPECT_TRUE(r.session->ok()) << ::testing::PrintToString(
        test::messages(r.session->diagnostics(), Severity::error));
  }
  for (long i = 0; i < steps && r.session->ok(); ++i) r.session->step();
  if (close) r.session->close();
  r.errors = test::messages(r.session->diagnostics(), Severity::error);
  r.warnings = test::messages(r.session->diagnostics(), Severity::warning);
  return r;
}

TEST(VTKExporter, XmlFileContentNumberingAndPvdSeries) {
  TempDir dir;
  const std::string base = dir.dir() + "/out";
  RunResult r = run(dir,
              tetra_scene(R"(<VTKExporter name="exp" filename=")" + base +
                          R"(" edges="0" triangles="1" tetras="1" pointsDataFields="mecha.position"
                   exportAtBegin="1" exportEveryNumberOfSteps="2"/>)"),
              5);
  EXPECT_TRUE(r.errors.empty()) << ::testing::PrintToString(r.errors);
  // At begin (k = 0), then after steps 2 and 4; step 5 is not a multiple of 2.
  EXPECT_TRUE(fs::exists(base + "0.vtu"));
  EXPECT_TRUE(fs::exists(base + "1.vtu"));
  EXPECT_TRUE(fs::exists(base + "2.vtu"));
  EXPECT_FALSE(fs::exists(base + "3.vtu"));
  const std::string expected =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n"
      "      <PointData>\n"
      "        <DataArray type=\"Float64\" Name=\"position\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      "          0 0 0\n          1 0 0\n          0 2 0\n          0 0 3\n"
      "        </DataArray>\n"
      "      </PointData>\n"
      "      <Points>\n"
      "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"
      "          0 0 0\n          1 0 0\n          0 2 0\n          0 0 3\n"
      "        </DataArray>\n"
      "      </Points>\n"
      "      <Cells>\n"
      "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n"
      "          0 1 2\n          0 1 2 3\n"
      "        </DataArray>\n"
      "        <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n"
      "          3\n          7\n"
      "        </DataArray>\n"
      "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"
      "          5\n          10\n"
      "        </DataArray>\n"
      "      </Cells>\n"
      "    </Piece>\n"
      "  </UnstructuredGrid>\n"
      "</VTKFile>\n";
  EXPECT_EQ(slurp(base + "0.vtu"), expected);
  EXPECT_EQ(slurp(base + "2.vtu"), expected);  // nothing moves
  const std::string pvd = slurp(base + ".pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"out0.vtu\"/>"), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.02\" group=\"\" part=\"0\" file=\"out1.vtu\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.040000000000000001\" group=\"\" part=\"0\" file=\"out2.vtu\""), std::string::npos)
      << pvd;
  auto* exp = test::get<VTKExporter>(r.session->root(), "exp");
  ASSERT_NE(exp, nullptr);
  EXPECT_EQ(exp->files_written(), 3);
}

TEST(VTKExporter, LegacyFormatOverwriteAndExportAtEnd) {
  TempDir dir;
  const std::string base = dir.dir() + "/legacy.vtk";
  run(dir, tetra_scene(R"(<VTKExporter filename=")" + base + R"(" XMLformat="0" exportAtEnd="1"/>)"), 3);
  // Only the close wrote (exportAtEnd): SOFA's legacy name <base>_<k>.vtk; edges on by default.
  EXPECT_EQ(slurp(dir.dir() + "/legacy_0.vtk"),
            "# vtk DataFile Version 3.0\nExported VTK file\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 4 double\n0 0 0\n1 0 0\n0 2 0\n0 0 3\n"
            "CELLS 1 3\n2 0 1\nCELL_TYPES 1\n3\n");
  EXPECT_FALSE(fs::exists(dir.dir() + "/legacy_1.vtk"));

  TempDir dir2;
  const std::string over = dir2.dir() + "/same";
  run(dir2, tetra_scene(R"(<VTKExporter filename=")" + over + R"(" overwrite="1" exportEveryNumberOfSteps="1"/>)"), 3);
  EXPECT_TRUE(fs::exists(over + ".vtu"));
  EXPECT_FALSE(fs::exists(over + "0.vtu"));
  // One file, one entry in the collection: the last export's time.
  const std::string pvd = slurp(over + ".pvd");
  EXPECT_EQ(pvd.find("file=\"same.vtu\""), pvd.rfind("file=\"same.vtu\""));
}

TEST(VTKExporter, BadInputIsReportedNamingTheField) {
  TempDir dir;
  RunResult r = run(dir,
              tetra_scene(R"(<VTKExporter filename=")" + dir.dir() +
                          R"(/bad" pointsDataFields="nosuch.position mecha.nodata junk" exportAtBegin="1"/>)"),
              1, true, false);
  EXPECT_TRUE(test::any_contains(r.errors, "pointsDataFields: no object 'nosuch'"));
  EXPECT_TRUE(test::any_contains(r.errors, "object 'mecha' has no data 'nodata'"));
  EXPECT_TRUE(test::any_contains(r.errors, "'junk' is not [Name=][@]object.data"));
  // Errors at init: the scene is refused, as every scene with an error.
  EXPECT_FALSE(r.session->ok());

  TempDir dir2;
  // A folder that cannot be created: an error naming the component and its field, no crash.
  RunResult r2 = run(dir2, tetra_scene(R"(<VTKExporter name="vtk" filename="/proc/no/such/out" exportAtBegin="1"/>)"), 1, true, false);
  EXPECT_TRUE(test::any_contains(r2.errors, "filename: cannot create the folder")) << ::testing::PrintToString(r2.errors);
  EXPECT_TRUE(test::any_contains(r2.errors, "vtk"));
}

TEST(MeshExporter, GmshObjVtkContentAndNumbering) {
  TempDir dir;
  const std::string base = dir.dir() + "/mesh";
  run(dir,
      tetra_scene(R"(<MeshExporter filename=")" + base + R"(" format="gmsh" exportEveryNumberOfSteps="2"/>
        <MeshExporter filename=")" + base + R"(_o" format="obj" edges="0" tetras="0" exportAtBegin="1"/>
        <MeshExporter filename=")" + base + R"(_v" format="vtk" edges="0" triangles="0" exportAtBegin="1"/>)"),
      4);
  EXPECT_FALSE(fs::exists(base + "00000.gmsh"));
  EXPECT_TRUE(fs::exists(base + "00002.gmsh"));
  EXPECT_EQ(slurp(base + "00001.gmsh"),
            "$MeshFormat\n2.1 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 2 0\n4 0 0 3\n$EndNodes\n"
            "$Elements\n3\n1 1 0 1 2\n2 2 0 1 2 3\n3 4 0 1 2 3 4\n$EndElements\n");
  EXPECT_EQ(slurp(base + "_o.obj"),
            "#Export in obj format from SOFA\n#\no " + base + "_o\n\n#Points (total = 4 pts)\n"
            "v 0 0 0\nv 1 0 0\nv 0 2 0\nv 0 0 3\n\nf 1 2 3\n");
  EXPECT_EQ(slurp(base + "_v.vtk"),
            "# vtk DataFile Version 3.0\nSOFA Exported Mesh file\nASCII\nDATASET UNSTRUCTURED_GRID\n"
            "POINTS 4 double\n0 0 0\n1 0 0\n0 2 0\n0 0 3\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n");
}

TEST(STLExporter, BinaryAndAscii) {
  TempDir dir;
  run(dir, tetra_scene(R"(<STLExporter filename=")" + dir.dir() + R"(/b" exportAtBegin="1" position="@mecha.position" triangles="@topo.triangles"/>
        <STLExporter filename=")" + dir.dir() + R"(/a" binaryformat="0" exportAtBegin="1"
                       position="@mecha.position" triangle="@topo.triangles"/>)"),
      0);
  const std::string bin = slurp(dir.dir() + "/b.stl");
  ASSERT_EQ(bin.size(), 84u + 50u);  // header, count, one facet
  std::uint32_t n = 0;
  std::memcpy(&n, bin.data() + 80, 4);
  EXPECT_EQ(n, 1u);
  float v[12];
  std::memcpy(v, bin.data() + 84, sizeof v);
  EXPECT_EQ(v[2], 1.f);  // normal of (0 0 0)(1 0 0)(0 2 0): +z
  EXPECT_EQ(v[6], 1.f);  // second vertex x
  EXPECT_EQ(v[10], 2.f);  // third vertex y
  EXPECT_EQ(slurp(dir.dir() + "/a.stl"),
            "solid Exported from Sofa\nfacet normal 0 0 1\nouter loop\nvertex 0.000000 0.000000 0.000000\n"
            "vertex 1.000000 0.000000 0.000000\nvertex 0.000000 2.000000 0.000000\nendloop\nendfacet\n"
            "endsolid Exported from Sofa\n");
}

// Blender point cache: header, then the points from the last to the first (position,
// velocity); hair adds the rest position and one root point per strand.
TEST(BlenderExporter, PointCacheSoftBodyAndHair) {
  TempDir dir;
  auto scene = [](const std::string& folder, const std::string& attrs) {
    return R"(<Node name="root" dt="0.01" gravity="0 0 0"><DefaultAnimationLoop/>
      <MechanicalObject name="m" position="0 0 0  1 0 0  1 2 0  1 2 3" velocity="1 2 3  4 5 6  7 8 9  0 0 1"/>
      <BlenderExporter filename=")" + folder + R"(/c" exportAtBegin="1" )" + attrs + "/></Node>";
  };
  run(dir, scene(dir.dir(), ""), 0);
  std::string b = slurp(dir.dir() + "/c_00.bphys");
  ASSERT_EQ(b.size(), 20u + 4u * 24u);
  EXPECT_EQ(b.substr(0, 8), "BPHYSICS");
  std::uint32_t head[3];
  std::memcpy(head, b.data() + 8, 12);
  EXPECT_EQ(head[0], 0u);
  EXPECT_EQ(head[1], 4u);
  EXPECT_EQ(head[2], 6u);
  float rec[6];
  std::memcpy(rec, b.data() + 20, 24);  // the last point first
  EXPECT_EQ(rec[2], 3.f);
  EXPECT_EQ(rec[5], 1.f);
  std::memcpy(rec, b.data() + 20 + 3 * 24, 24);  // point 0 last
  EXPECT_EQ(rec[0], 0.f);
  EXPECT_EQ(rec[3], 1.f);
  EXPECT_EQ(rec[4], 2.f);

  TempDir dir2;
  run(dir2, scene(dir2.dir(), R"(simulationType="3" nbPtsByHair="2")"), 0);
  b = slurp(dir2.dir() + "/c_00.bphys");
  // Two strands of two points: 4 + 2 root points of 36 bytes; type written as cloth (2), flags 22.
  ASSERT_EQ(b.size(), 20u + 6u * 36u);
  std::memcpy(head, b.data() + 8, 12);
  EXPECT_EQ(head[0], 2u);
  EXPECT_EQ(head[1], 6u);
  EXPECT_EQ(head[2], 22u);
  // Order: point 3, then root of strand (2, 3) = p2 + unit(p3 − p2) = (1 2 1), then point 2, ...
  float r[9];
  std::memcpy(r, b.data() + 20 + 36, 36);
  EXPECT_EQ(r[0], 1.f);
  EXPECT_EQ(r[1], 2.f);
  EXPECT_EQ(r[2], 1.f);
  EXPECT_EQ(r[6], 1.f);  // its "rest" is the root point again
  // The hair info frame of init.
  const std::string info = slurp(dir2.dir() + "/c");
  ASSERT_EQ(info.size(), 32u);
  EXPECT_EQ(info.substr(0, 8), "BPHYSICS");
}

TEST(VisualModelOBJExporter, GroupsMaterialsAndIndexOffsets) {
  TempDir dir;
  const std::string xml = R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <VisualModelOBJExporter filename=")" + dir.dir() + R"(/scene" exportAtBegin="1"/>
  <OglModel name="a" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2" normal="0 0 1  0 0 1  0 0 1"
            material="m Diffuse 1 1 0 0 1 Ambient 1 0.2 0 0 1 Specular 0 1 1 1 1 Emissive 0 0 0 0 0 Shininess 0 45"/>
  <Node name="child">
    <OglModel name="b" position="0 0 1  1 0 1  0 1 1" triangles="0 2 1"/>
  </Node>
</Node>)";
  run(dir, xml, 0);
  const std::string obj = slurp(dir.dir() + "/scene.obj");
  EXPECT_EQ(obj.rfind("mtllib scene.mtl\ng 1_a\nusemtl mat1\nv 0.000000 0.000000 0.000000\n", 0), 0u) << obj;
  EXPECT_NE(obj.find("f 1//1 2//2 3//3\n"), std::string::npos) << obj;
  // The second model's indices continue after the first's 3 vertices and 3 normals.
  EXPECT_NE(obj.find("g 2_b\nusemtl mat2\n"), std::string::npos) << obj;
  EXPECT_NE(obj.find("v 0.000000 0.000000 1.000000\n"), std::string::npos);
  EXPECT_NE(obj.find("f 4//4 6//6 5//5\n"), std::string::npos) << obj;
  const std::string mtl = slurp(dir.dir() + "/scene.mtl");
  EXPECT_NE(mtl.find("newmtl mat1\nillum 4\nKa 0.2 0 0\nKd 1 0 0\nTf 1.00 1.00 1.00\nNi 1.00\n"), std::string::npos)
      << mtl;
  EXPECT_NE(mtl.find("newmtl mat2\n"), std::string::npos);
}

// A body falling under gravity: the state changes at every step.
std::string falling(const std::string& extra) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <Node name="body">
    <EulerImplicitSolver rayleighStiffness="0" rayleighMass="0"/>
    <CGLinearSolver iterations="50" tolerance="1e-12" threshold="1e-15"/>
    <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0" velocity="0.1 0 0  0 0.3 0  0 0 0.7"/>
    <UniformMass totalMass="1"/>
    )" + extra + R"(
  </Node>
</Node>)";
}

std::string replay(const std::string& file) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <DefaultAnimationLoop/>
  <Node name="body">
    <MechanicalObject name="dofs" position="9 9 9  9 9 9  9 9 9"/>
    <ReadState name="reader" filename=")" + file + R"("/>
  </Node>
</Node>)";
}

void round_trip(const std::string& name) {
  TempDir dir;
  const std::string file = dir.dir() + "/" + name;
  RunResult w = run(dir, falling(R"(<WriteState filename=")" + file + R"(" writeV="1"/>)"), 0, false);
  Node* body = w.session->root().find_child_named("body");
  std::vector<std::vector<double>> x{body->get_mechanical_state()->read(kPosition)};
  std::vector<std::vector<double>> v{body->get_mechanical_state()->read(kVelocity)};
  for (int i = 0; i < 8; ++i) {
    w.session->step();
    x.push_back(body->get_mechanical_state()->read(kPosition));
    v.push_back(body->get_mechanical_state()->read(kVelocity));
  }
  w.session.reset();  // closes the file
  // Neither time nor period given: a block at the start of every step (8), times 0 .. 0.07.
  auto blocks = regression::read_state_file(file);
  ASSERT_TRUE(blocks);
  ASSERT_EQ(blocks->size(), 8u);
  EXPECT_NEAR(blocks->back().time, 0.07, 1e-12);

  TempDir dir2;
  RunResult rd = run(dir2, replay(file), 0, false);
  Node* rb = rd.session->root().find_child_named("body");
  MechanicalState* s = rb->get_mechanical_state();
  // At init (bwd_init) the block T= 0 is read; at the start of step k, the block of t_k.
  // Step k starts at t_(k-1): after it the reader holds the writer's state after k-1 steps.
  for (int k = 0; k <= 8; ++k) {
    if (k > 0) rd.session->step();
    const std::size_t j = k > 0 ? static_cast<std::size_t>(k - 1) : 0u;
    const std::vector<double>& got = s->read(kPosition);
    const std::vector<double>& gotv = s->read(kVelocity);
    ASSERT_EQ(got.size(), x[j].size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(got[i], x[j][i], 1e-12) << "step " << k << " scalar " << i;
      EXPECT_NEAR(gotv[i], v[j][i], 1e-12) << "step " << k << " scalar " << i;
    }
  }
  // Positions did move: the comparison above is not between constants.
  EXPECT_GT(std::abs(x[7][1] - x[0][1]), 1e-3);
}

TEST(WriteStateReadState, RoundTripPlainAndGzip) {
  round_trip("state.txt");
  round_trip("state.txt.gz");
}

TEST(WriteState, StartTimeAndPeriod) {
  TempDir dir;
  const std::string file = dir.dir() + "/p.txt";
  run(dir, falling(R"(<WriteState filename=")" + file + R"(" time="0.02" period="0.03" writeX0="1" writeF="1"/>)"),
      10);
  const std::string text = slurp(file);
  auto blocks = regression::parse_state_text(text);
  // Steps start at t = 0, 0.01, ..., 0.09: written at 0.02, then 0.05 and 0.08.
  ASSERT_EQ(blocks.size(), 3u) << text;
  EXPECT_NEAR(blocks[0].time, 0.02, 1e-12);
  EXPECT_NEAR(blocks[1].time, 0.05, 1e-12);
  EXPECT_NEAR(blocks[2].time, 0.08, 1e-12);
  EXPECT_NE(text.find("\n  X0= 0 0 0 1 0 0 0 1 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n  F= "), std::string::npos);
}

TEST(ReadState, ShiftScaleTranslationAndLoop) {
  for (const bool loop : {false, true}) {
    TempDir dir;
    const std::string file = dir.write("s.txt", "T= 0\n  X= 1 0 0\nT= 0.01\n  X= 2 0 0\nT= 0.02\n  X= 3 0 0\n");
    const std::string xml = R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <MechanicalObject name="dofs" position="0 0 0"/>
  <ReadState filename=")" + file + R"(" shift="0.01" scalePos="2" translation="0 0 5" loop=")" +
                            (loop ? "1" : "0") + R"("/>
</Node>)";
    RunResult r = run(dir, xml, 0, false);
    MechanicalState* s = r.session->root().get_mechanical_state();
    // Init: t + shift = 0.01, the second block, scaled then translated.
    EXPECT_EQ(s->read(kPosition), (std::vector<double>{4, 0, 5}));
    r.session->step();  // begins at t = 0 (+ shift 0.01): nothing new
    EXPECT_EQ(s->read(kPosition), (std::vector<double>{4, 0, 5}));
    r.session->step();  // 0.02: the last block; with loop the file restarts at once, its T= 0
                        // moved to 0.02 (SOFA's reader shifts by the last time read)
    EXPECT_EQ(s->read(kPosition), (std::vector<double>{loop ? 2.0 : 6.0, 0, 5}));
    r.session->step();  // 0.03
    EXPECT_EQ(s->read(kPosition), (std::vector<double>{loop ? 4.0 : 6.0, 0, 5}));
  }
}

TEST(CompareState, SumsSofasMeanAbsoluteDifferencePerPoint) {
  TempDir dir;
  const std::string file = dir.write("ref.txt", "T= 0\n  X= 1 2 3 4 5 7\nT= 0.01\n  X= 1 2 3 4 5 6\n");
  const std::string xml = R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <MechanicalObject name="dofs" position="1 2 3  4 5 6"/>
  <CompareState name="cmp" filename=")" + file + R"("/>
</Node>)";
  RunResult r = run(dir, xml, 2, false);
  auto* c = test::get<CompareState>(r.session->root(), "cmp");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->compared_blocks(), 2);
  // First block: one scalar off by 1 among 6 → e = 1/6, per point (2 points) 1/12; second: 0.
  EXPECT_NEAR(c->total_error(), 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(c->error_by_dof(), 1.0 / 12.0, 1e-15);
  // The state is compared, never replayed.
  EXPECT_EQ(r.session->root().get_mechanical_state()->read(kPosition), (std::vector<double>{1, 2, 3, 4, 5, 6}));
}

// CompareState with loop: a two-block file (0, 0.01) compared over five steps: blocks 0 and
// 0.01, then the file again from 0.01 (its T= 0 shifted to 0.01 replaces the last block at once,
// as SOFA's reader), 0.02, ... Every comparison counts: five compared blocks, each off by 1 in
// one scalar of six (e = 1/6, per point 1/12).
TEST(CompareState, LoopComparesTheFileAgain) {
  TempDir dir;
  const std::string file = dir.write("ref.txt", "T= 0\n  X= 1 2 3 4 5 7\nT= 0.01\n  X= 1 2 3 4 5 7\n");
  for (const bool loop : {false, true}) {
    const std::string xml = R"(<Node name="root" dt="0.01">
  <DefaultAnimationLoop/>
  <MechanicalObject name="dofs" position="1 2 3  4 5 6"/>
  <CompareState name="cmp" filename=")" + file + R"(" loop=")" + (loop ? "1" : "0") + R"("/>
</Node>)";
    RunResult r = run(dir, xml, 5, false);
    auto* c = test::get<CompareState>(r.session->root(), "cmp");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->compared_blocks(), loop ? 5 : 2) << "loop " << loop;
    EXPECT_NEAR(c->error_by_dof(), (loop ? 5 : 2) / 12.0, 1e-12);
    EXPECT_TRUE(r.warnings.empty()) << ::testing::PrintToString(r.warnings);
  }
}

}  // namespace
}  // namespace sinew
