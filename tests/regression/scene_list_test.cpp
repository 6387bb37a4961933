// `.regression-tests` list parsing (regression-protocol.md §1).
#include "regression/scene_list.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace sinew::regression {
namespace {

namespace fs = std::filesystem;

// A temporary tree: <root>/lists (the list folder), <root>/lists/refs,
// <root>/regression/references/examples, <root>/fallback.
class SceneListTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("sinew_list_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_ / "lists" / "refs");
    fs::create_directories(root_ / "regression" / "references" / "examples");
    fs::create_directories(root_ / "fallback");
  }
  void TearDown() override { fs::remove_all(root_); }
  std::string list_dir() const { return (root_ / "lists").string(); }
  std::string regression_dir() const { return (root_ / "regression").string(); }
  fs::path root_;
};

TEST_F(SceneListTest, ParsesCommentsReferenceLineAndScenes) {
  const std::string text =
      "# comment\n"
      "\n"
      "refs\n"
      "#Demos/skipped.scn 10 1e-4\n"
      "Demos/liver.scn 100 1e-4 1 1\n"
      "  #not_a_comment.scn 5\n"  // not a comment; only 2 tokens
      "A/b.scn\t30  1e-8\r\n"
      "C.scn 7 2.5e-3 0 1 5 extra tokens\n";
  const SceneList list = parse_scene_list(text, list_dir(), {});
  EXPECT_EQ(list.list_dir, list_dir());
  EXPECT_EQ(list.reference_dir, list_dir() + "/refs");
  ASSERT_EQ(list.scenes.size(), 3u);

  const SceneEntry& liver = list.scenes[0];
  EXPECT_EQ(liver.scene, "Demos/liver.scn");
  EXPECT_EQ(liver.steps, 100);
  EXPECT_DOUBLE_EQ(liver.epsilon, 1e-4);
  EXPECT_TRUE(liver.mapped);
  EXPECT_TRUE(liver.last_only);
  EXPECT_EQ(liver.period, 0);
  EXPECT_EQ(liver.line, 5);

  // Tabs and a trailing '\r' separate tokens; missing fields take defaults.
  const SceneEntry& b = list.scenes[1];
  EXPECT_EQ(b.scene, "A/b.scn");
  EXPECT_EQ(b.steps, 30);
  EXPECT_DOUBLE_EQ(b.epsilon, 1e-8);
  EXPECT_FALSE(b.mapped);
  EXPECT_FALSE(b.last_only);
  EXPECT_EQ(b.period, 0);
  EXPECT_EQ(b.line, 7);

  const SceneEntry& c = list.scenes[2];
  EXPECT_FALSE(c.mapped);
  EXPECT_TRUE(c.last_only);
  EXPECT_EQ(c.period, 5);
  EXPECT_DOUBLE_EQ(c.epsilon, 2.5e-3);

  // The indented '#' line has fewer than 3 tokens: reported, not fatal.
  ASSERT_EQ(list.problems.size(), 1u);
  EXPECT_NE(list.problems[0].find("line 6"), std::string::npos) << list.problems[0];

  EXPECT_EQ(reference_base(list, liver), list_dir() + "/refs/Demos/liver.scn.reference");
  EXPECT_EQ(scene_path(list, liver), list_dir() + "/Demos/liver.scn");
}

TEST_F(SceneListTest, SubstitutesRegressionDir) {
  ListEnvironment env;
  env.regression_dir = regression_dir();
  const SceneList list =
      parse_scene_list("$REGRESSION_DIR/references/examples\nx.scn 5 1e-4\n", list_dir(), env);
  EXPECT_EQ(list.reference_dir, regression_dir() + "/references/examples");
  ASSERT_EQ(list.scenes.size(), 1u);
  EXPECT_EQ(reference_base(list, list.scenes[0]),
            regression_dir() + "/references/examples/x.scn.reference");
  EXPECT_TRUE(list.problems.empty());
}

TEST_F(SceneListTest, FallsBackToReferencesDirThenIgnoresList) {
  ListEnvironment env;  // REGRESSION_DIR unset: the first candidate cannot exist
  env.references_dir = "../fallback";
  const std::string text = "$REGRESSION_DIR/references/examples\nx.scn 5 1e-4\n";
  const SceneList with_fallback = parse_scene_list(text, list_dir(), env);
  EXPECT_EQ(with_fallback.reference_dir, list_dir() + "/../fallback");
  EXPECT_EQ(with_fallback.scenes.size(), 1u);

  env.references_dir = "nowhere";
  const SceneList ignored = parse_scene_list(text, list_dir(), env);
  EXPECT_TRUE(ignored.scenes.empty());
  EXPECT_FALSE(ignored.problems.empty());
  // A relative folder that does not exist ignores the list the same way.
  const SceneList missing = parse_scene_list("no_refs\nx.scn 5 1e-4\n", list_dir(), {});
  EXPECT_TRUE(missing.scenes.empty());
  EXPECT_FALSE(missing.problems.empty());
}

TEST_F(SceneListTest, NumberConversionsFollowStoiAndStod) {
  const SceneList list = parse_scene_list(
      "refs\n"
      "a.scn 100steps 1e-4x 2\n"  // leading integer / leading float; mapped 2 is true
      "b.scn many 1e-4\n"         // no leading integer: reported, ignored
      "c.scn 10 1e-4 0 0 -3\n",
      list_dir(), {});
  ASSERT_EQ(list.scenes.size(), 2u);
  EXPECT_EQ(list.scenes[0].steps, 100);
  EXPECT_DOUBLE_EQ(list.scenes[0].epsilon, 1e-4);
  EXPECT_TRUE(list.scenes[0].mapped);
  EXPECT_EQ(list.scenes[1].scene, "c.scn");
  EXPECT_EQ(list.scenes[1].period, -3);
  ASSERT_EQ(list.problems.size(), 1u);
  EXPECT_NE(list.problems[0].find("line 3"), std::string::npos);
}

TEST_F(SceneListTest, ReadsFromFileRelativeToItsFolder) {
  std::ofstream(root_ / "lists" / "My.regression-tests") << "#x\nrefs\ns.scn 3 0.1 1\n";
  std::string error;
  const auto list = read_scene_list((root_ / "lists" / "My.regression-tests").string(), {}, &error);
  ASSERT_TRUE(list.has_value()) << error;
  EXPECT_EQ(list->reference_dir, list_dir() + "/refs");
  ASSERT_EQ(list->scenes.size(), 1u);
  EXPECT_EQ(list->scenes[0].line, 3);
  EXPECT_FALSE(read_scene_list((root_ / "missing").string(), {}, &error).has_value());
}

}  // namespace
}  // namespace sinew::regression
