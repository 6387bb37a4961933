// WriteTopology, ReadTopology and CompareTopology: the file written while a topology changes
// (exact text, SOFA's schedule and its quirks), read back into outputs, compared with the live
// topology (zero on a round trip, SOFA's counts on a doctored file), and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <fstream>
#include <sstream>

#include "core/node.h"
#include "core/simulation.h"
#include "exporter/playback/compare_topology.h"
#include "exporter/playback/read_topology.h"
#include "exporter/playback/write_topology.h"
#include "regression/gzip_text.h"
#include "regression/topology_file.h"
#include "test_paths.h"
#include "runner/session.h"
#include "test_scene.h"

namespace sinew {
namespace {

using test::TempDir;

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Outcome {
  std::unique_ptr<runner::Session> session;
  std::vector<std::string> errors, warnings;
};

// Loads `xml`, runs `steps` steps; the session stays open (close() flushes exportAtEnd only).
Outcome run(const TempDir& dir, const std::string& xml, int steps) {
  Outcome r;
  r.session = std::make_unique<runner::Session>(dir.write("scene.scn", xml), runner::SessionOptions{});
  for (int i = 0; i < steps && r.session->ok(); ++i) r.session->step();
  r.errors = test::messages(r.session->diagnostics(), Severity::error);
  r.warnings = test::messages(r.session->diagnostics(), Severity::warning);
  return r;
}

// Three tetrahedra in a row; the change processor removes tetrahedron 0 at t = 0.25 and again
// at t = 0.5 (dt = 0.25, exact in binary: the clock reads 0, 0.25, 0.5, ...). `tail` is put
// after the processor, so that it sees each step's change.
std::string changing_scene(const std::string& dir, const std::string& tail) {
  std::ofstream(dir + "/changes.txt") << "T= 0.25\n  REMOVE= 1\n0\nT= 0.5\n  REMOVE= 1\n0\n";
  return R"(<Node name="root" dt="0.25" gravity="0 0 0">
  <DefaultAnimationLoop/>
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1  2 1 1"/>
  <TetrahedronSetTopologyContainer name="topo" tetrahedra="0 1 2 3  1 2 3 4  2 3 4 5"/>
  <TetrahedronSetTopologyModifier/>
  <TopologicalChangeProcessor filename=")" + dir + R"(/changes.txt"/>
  )" + tail + R"(
</Node>)";
}

TEST(WriteTopology, WritesEveryStepWhileTheTopologyChanges) {
  TempDir dir;
  const std::string file = dir.dir() + "/topo.txt";
  Outcome r = run(dir, changing_scene(dir.dir(), R"(<WriteTopology name="w" filename=")" + file + R"("/>)"), 4);
  ASSERT_TRUE(r.errors.empty()) << ::testing::PrintToString(r.errors);
  auto* w = test::get<WriteTopology>(r.session->root(), "w");
  EXPECT_EQ(w->exports(), 4);
  const std::string text = slurp(file);
  auto blocks = regression::parse_topology_text(text);
  ASSERT_EQ(blocks.size(), 4u) << text;
  const long long tetras[4] = {3, 2, 1, 1};
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(blocks[k].time, 0.25 * k);
    EXPECT_EQ(blocks[k].counts[3], tetras[k]) << "block " << k;
    EXPECT_EQ(blocks[k].counts[2], 0);  // quads
    EXPECT_EQ(blocks[k].counts[4], 0);  // hexahedra
    // The tetrahedra's triangles and edges are written too (built on demand, as SOFA's getters).
    EXPECT_GT(blocks[k].counts[0], 0);
    EXPECT_GT(blocks[k].counts[1], 0);
  }
  // SOFA's layout: two spaces before each header, its count, the indices on the next line
  // (an empty line for none), the time with 6 significant digits.
  EXPECT_EQ(text.rfind("T= 0\n  Edges= ", 0), 0u) << text;
  EXPECT_NE(text.find("\n  Quads= 0\n\n  Tetrahedra= 3\n0 1 2 3 1 2 3 4 2 3 4 5\n  Hexahedra= 0\n\nT= 0.25\n"),
            std::string::npos)
      << text;
  // The removal moves the last tetrahedron into the freed slot and the last point (5) into the
  // freed point 0 (SOFA's swap-with-last).
  EXPECT_NE(text.find("\n  Tetrahedra= 2\n2 3 4 0 1 2 3 4\n"), std::string::npos) << text;
}

TEST(WriteTopology, ListedTimesThenPeriod) {
  TempDir dir;
  const std::string a = dir.dir() + "/a.txt.gz", b = dir.dir() + "/b.txt", c = dir.dir() + "/c.txt";
  Outcome r = run(dir, changing_scene(dir.dir(), R"(<WriteTopology filename=")" + a + R"(" time="0.25 0.75" period="0.5"/>
  <WriteTopology filename=")" + b + R"(" time="0.5"/>
  <WriteTopology filename=")" + c + R"(" writeContainers="0" time="1"/>)"),
              8);
  ASSERT_TRUE(r.errors.empty()) << ::testing::PrintToString(r.errors);
  auto times = [](const std::string& path) {
    auto blocks = regression::read_topology_file(path);
    std::vector<double> t;
    if (blocks)
      for (const auto& blk : *blocks) t.push_back(blk.time);
    return t;
  };
  // Steps begin at 0, 0.25, ..., 1.75: 0.25 and 0.75 from the list, then every 0.5.
  EXPECT_EQ(times(a), (std::vector<double>{0.25, 0.75, 1.25, 1.75}));
  // Times listed and no period: once the list is done, every step (SOFA's period 0).
  EXPECT_EQ(times(b), (std::vector<double>{0.5, 0.75, 1, 1.25, 1.5, 1.75}));
  // Without containers, the time lines alone.
  EXPECT_EQ(slurp(c), "T= 1\nT= 1.25\nT= 1.5\nT= 1.75\n");
}

TEST(CompareTopology, RoundTripIsExactAndDoctoredFilesCountLikeSofa) {
  TempDir dir;
  const std::string file = dir.dir() + "/ref.txt";
  run(dir, changing_scene(dir.dir(), R"(<WriteTopology filename=")" + file + R"("/>)"), 4);
  const std::string ref = slurp(file);
  ASSERT_FALSE(ref.empty());

  TempDir dir2;
  Outcome same = run(dir2, changing_scene(dir2.dir(), R"(<CompareTopology name="cmp" filename=")" + file + R"("/>)"), 4);
  ASSERT_TRUE(same.errors.empty()) << ::testing::PrintToString(same.errors);
  auto* cmp = test::get<CompareTopology>(same.session->root(), "cmp");
  EXPECT_EQ(cmp->compared_blocks(), 4);
  EXPECT_EQ(cmp->total_error(), 0);

  // One index changed in the block at 0.25, one tetrahedron dropped from the count at 0.5.
  std::string doctored = ref;
  const std::size_t at = doctored.find("Tetrahedra= 2\n2 3 4 0");
  ASSERT_NE(at, std::string::npos);
  doctored.replace(at + std::string("Tetrahedra= 2\n").size(), 1, "9");
  const std::size_t one = doctored.find("Tetrahedra= 1\n");
  ASSERT_NE(one, std::string::npos);
  doctored.replace(one, std::string("Tetrahedra= 1").size(), "Tetrahedra= 4");
  TempDir dir3;
  const std::string bad = dir3.write("bad.txt", doctored);
  Outcome diff = run(dir3, changing_scene(dir3.dir(), R"(<CompareTopology name="cmp" filename=")" + bad + R"("/>)"), 4);
  cmp = test::get<CompareTopology>(diff.session->root(), "cmp");
  // 0.25: one differing tetrahedron; 0.5: counts 4 against 1 add 3.
  EXPECT_EQ(cmp->errors()[3], 1 + 3);
  EXPECT_EQ(cmp->total_error(), 4);
  EXPECT_EQ(cmp->errors()[0] + cmp->errors()[1], 0);
}

TEST(ReadTopology, OutputsTheDueBlockWithShiftAndLoop) {
  for (const bool loop : {false, true}) {
    TempDir dir;
    const std::string file = dir.write("t.txt",
                                       "T= 0\n  Triangles= 1\n0 1 2\nT= 0.25\n  Triangles= 2\n0 1 2 1 2 3\n"
                                       "T= 0.5\n  Triangles= 1\n1 2 3\n  Edges= 1\n4 5\n");
    const std::string xml = R"(<Node name="root" dt="0.25">
  <DefaultAnimationLoop/>
  <MechanicalObject position="0 0 0  1 0 0  0 1 0  1 1 0  2 0 0  2 1 0"/>
  <MeshTopology triangles="0 1 2"/>
  <ReadTopology name="r" filename=")" + file + R"(" shift="0.25" loop=")" + (loop ? "1" : "0") + R"("/>
</Node>)";
    Outcome r = run(dir, xml, 0);
    ASSERT_TRUE(r.errors.empty()) << ::testing::PrintToString(r.errors);
    auto* rt = test::get<ReadTopology>(r.session->root(), "r");
    r.session->step();  // t + shift = 0.25: blocks 0 and 0.25 are due, the last one is read
    EXPECT_EQ(rt->triangles.get(), (std::vector<Triangle>{{0, 1, 2}, {1, 2, 3}}));
    EXPECT_TRUE(rt->edges.get().empty());
    r.session->step();  // 0.5; with loop the file starts again at once (0 + 0.5)
    if (loop) {
      EXPECT_EQ(rt->triangles.get(), (std::vector<Triangle>{{0, 1, 2}}));
      EXPECT_TRUE(rt->edges.get().empty());
    } else {
      EXPECT_EQ(rt->triangles.get(), (std::vector<Triangle>{{1, 2, 3}}));
      EXPECT_EQ(rt->edges.get(), (std::vector<Edge>{{4, 5}}));
    }
    r.session->step();  // 0.75: nothing new without loop (the outputs stay)
    EXPECT_EQ(rt->triangles.get().size(), loop ? 2u : 1u);
    EXPECT_EQ(rt->blocks_read(), loop ? 3 : 2);
    // The lists are replaced, never appended to (SOFA's grow at every block).
    EXPECT_LE(rt->triangles.get().size(), 2u);
  }
}

TEST(PlaybackTopology, BadInputIsReported) {
  TempDir dir;
  // No topology anywhere.
  Outcome none = run(dir, R"(<Node name="root"><DefaultAnimationLoop/><MechanicalObject position="0 0 0"/>
  <WriteTopology filename=")" + dir.dir() + R"(/x.txt"/></Node>)",
                 1);
  EXPECT_TRUE(test::any_contains(none.errors, "no mesh topology")) << ::testing::PrintToString(none.errors);
  // Missing file.
  Outcome missing = run(dir, R"(<Node name="root"><DefaultAnimationLoop/><MeshTopology triangles="0 1 2"/>
  <ReadTopology filename=")" + dir.dir() + R"(/absent.txt"/></Node>)",
                    1);
  EXPECT_TRUE(test::any_contains(missing.errors, "absent.txt")) << ::testing::PrintToString(missing.errors);
  // Hostile counts and indices: a count far beyond the line, negative indices.
  const std::string hostile =
      dir.write("h.txt", "T= 0\n  Triangles= 999999999999\n0 1 2\n  Edges= 2\n0 -1 3 4\n");
  Outcome h = run(dir, R"(<Node name="root"><DefaultAnimationLoop/><MeshTopology triangles="0 1 2"/>
  <ReadTopology name="r" filename=")" + hostile + R"("/>
  <CompareTopology name="c" filename=")" + hostile + R"("/></Node>)",
              1);
  ASSERT_TRUE(h.errors.empty()) << ::testing::PrintToString(h.errors);
  EXPECT_TRUE(test::any_contains(h.warnings, "fewer valid indices")) << ::testing::PrintToString(h.warnings);
  auto* rt = test::get<ReadTopology>(h.session->root(), "r");
  EXPECT_EQ(rt->triangles.get(), (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_TRUE(rt->edges.get().empty());
  auto* c = test::get<CompareTopology>(h.session->root(), "c");
  // Triangles: 999999999999 against 1; edges: 2 against the 3 the triangle has.
  EXPECT_EQ(c->errors()[1], 999999999998LL);
  EXPECT_EQ(c->errors()[0], 1);
}

// SOFA's own regression writes its topology references with WriteTopology. Added to the
// tetrahedral node of RemovingTetra2TriangleProcess.scn (tetrahedra removed over 30 steps),
// Sinew's WriteTopology writes SOFA's reference byte for byte, and CompareTopology finds no
// difference with it.
TEST(PlaybackTopology, WritesSofasReferenceOfATopologyChangingScene) {
  namespace fs = std::filesystem;
  const fs::path data(SINEW_DATA_DIR);
  const fs::path scene = data / "examples/Component/Topology/Container/Dynamic/RemovingTetra2TriangleProcess.scn";
  const fs::path reference = data /
      "references/examples/Component/Topology/Container/Dynamic/"
      "RemovingTetra2TriangleProcess.scn.reference_0_Tetra_topo_topology.txt.gz";
  if (!fs::exists(scene) || !fs::exists(reference))
    GTEST_SKIP() << "SOFA data not found: " << scene << " (set SINEW_DATA_DIR)";
  TempDir dir;
  runner::SessionOptions opts;
  opts.data_paths = {(data / "share").string(), (data / "examples").string()};
  runner::Session session(scene.string(), opts);
  ASSERT_TRUE(session.ok()) << ::testing::PrintToString(test::messages(session.diagnostics(), Severity::error));
  Node* tt = session.root().find_child_named("TT");
  ASSERT_NE(tt, nullptr);
  auto writer = std::make_unique<WriteTopology>();
  writer->filename.set(dir.dir() + "/written.txt");
  auto* w = static_cast<WriteTopology*>(tt->add_object(std::move(writer)));
  auto compare = std::make_unique<CompareTopology>();
  compare->filename.set(reference.string());
  auto* c = static_cast<CompareTopology*>(tt->add_object(std::move(compare)));
  ASSERT_TRUE(init_added(session.root()));  // as components added between steps
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  EXPECT_EQ(w->exports(), 30);
  // SOFA's reader skips the blocks printed just above the clock (0.07, 0.1, ...): 30 blocks,
  // fewer compared, each without a difference.
  EXPECT_GE(c->compared_blocks(), 20);
  EXPECT_EQ(c->total_error(), 0);
  const auto want = regression::read_text_file(reference.string());
  ASSERT_TRUE(want.has_value());
  EXPECT_EQ(slurp(dir.dir() + "/written.txt"), *want);
  // The tetrahedra do change over the run: the comparison is not between constants.
  const auto blocks = regression::parse_topology_text(*want);
  ASSERT_EQ(blocks.size(), 30u);
  EXPECT_GT(blocks.front().counts[3], blocks.back().counts[3]);
}

}  // namespace
}  // namespace sinew
