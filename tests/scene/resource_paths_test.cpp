#include "scene/resource_paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include "test_paths.h"

namespace fs = std::filesystem;
using sinew::scene::ResourcePaths;

namespace {

// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "sinew_paths_XXXXXX").string();
    path_ = fs::path(mkdtemp(pattern.data()));
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  // Creates `rel` (and its folders) with some content; returns its absolute path.
  std::string touch(const std::string& rel) const {
    const fs::path p = path_ / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << "x";
    return p.string();
  }

 private:
  fs::path path_;
};

}  // namespace

TEST(ResourcePaths, AbsoluteNameIsUsedAsIsWhenItExists) {
  TempDir t;
  const std::string file = t.touch("a/mesh.obj");
  ResourcePaths paths;
  EXPECT_EQ(paths.resolve(file, "/nonexistent"), file);
  EXPECT_EQ(paths.resolve((t.path() / "a/missing.obj").string(), t.path().string()), std::nullopt);
}

TEST(ResourcePaths, BaseDirComesBeforeDataFolders) {
  TempDir t;
  const std::string local = t.touch("scene/mesh/m.obj");
  const std::string shared = t.touch("share/mesh/m.obj");
  ResourcePaths paths;
  paths.add((t.path() / "share").string());
  EXPECT_EQ(paths.resolve("mesh/m.obj", (t.path() / "scene").string()), local);
  // Without a local copy the data folder is used.
  EXPECT_EQ(paths.resolve("mesh/m.obj", (t.path() / "elsewhere").string()), shared);
  // An empty base folder skips step 2.
  EXPECT_EQ(paths.resolve("mesh/m.obj", ""), shared);
}

TEST(ResourcePaths, DataFoldersAreSearchedInOrder) {
  TempDir t;
  const std::string first = t.touch("one/x.txt");
  const std::string second = t.touch("two/x.txt");
  const std::string only_second = t.touch("two/y.txt");
  ResourcePaths paths;
  paths.add((t.path() / "one").string());
  paths.add((t.path() / "two").string());
  EXPECT_EQ(paths.resolve("x.txt", ""), first);
  EXPECT_EQ(paths.resolve("y.txt", ""), only_second);
  EXPECT_EQ(paths.resolve("z.txt", ""), std::nullopt);
  EXPECT_EQ(paths.resolve("", t.path().string()), std::nullopt);
  (void)second;
}

TEST(ResourcePaths, ResultIsNormalised) {
  TempDir t;
  const std::string file = t.touch("examples/Component/FEMBAR-common.xml");
  ResourcePaths paths;
  const auto got = paths.resolve("../FEMBAR-common.xml", (t.path() / "examples/Component/Iterative").string());
  // The folder "Iterative" does not exist, so "Iterative/.." cannot be followed on
  // disk; SOFA's textual join would still not find it. Resolve from an existing one.
  EXPECT_EQ(got, std::nullopt);
  fs::create_directories(t.path() / "examples/Component/Iterative");
  EXPECT_EQ(paths.resolve("../FEMBAR-common.xml", (t.path() / "examples/Component/Iterative").string()), file);
  EXPECT_EQ(paths.resolve("./Component/../Component/FEMBAR-common.xml", (t.path() / "examples").string()), file);
}

TEST(ResourcePaths, AddNormalisesAndSkipsDuplicatesAndEmpty) {
  TempDir t;
  ResourcePaths paths;
  paths.add((t.path() / "share/").string());
  paths.add((t.path() / "share").string());
  paths.add((t.path() / "x/../examples").string());
  paths.add("");
  ASSERT_EQ(paths.dirs().size(), 2u);
  EXPECT_EQ(paths.dirs()[0], (t.path() / "share").string());
  EXPECT_EQ(paths.dirs()[1], (t.path() / "examples").string());
}

TEST(ResourcePaths, AddFromEnvSplitsOnColons) {
  TempDir t;
  const std::string a = (t.path() / "a").string();
  const std::string b = (t.path() / "b").string();
  const std::string value = a + "::" + b + ":";
  const char* old = std::getenv("SOFA_DATA_PATH");
  const std::string saved = old ? old : "";
  setenv("SOFA_DATA_PATH", value.c_str(), 1);
  ResourcePaths paths;
  paths.add("/first");
  paths.add_from_env();
  if (old) {
    setenv("SOFA_DATA_PATH", saved.c_str(), 1);
  } else {
    unsetenv("SOFA_DATA_PATH");
  }
  ASSERT_EQ(paths.dirs().size(), 3u);
  EXPECT_EQ(paths.dirs()[0], "/first");
  EXPECT_EQ(paths.dirs()[1], a);
  EXPECT_EQ(paths.dirs()[2], b);
}

TEST(ResourcePaths, AddFromEnvWithoutVariableAddsNothing) {
  const char* old = std::getenv("SOFA_DATA_PATH");
  const std::string saved = old ? old : "";
  unsetenv("SOFA_DATA_PATH");
  ResourcePaths paths;
  paths.add_from_env();
  if (old) setenv("SOFA_DATA_PATH", saved.c_str(), 1);
  EXPECT_TRUE(paths.dirs().empty());
}

// regression-protocol §8 examples, on the real data.
TEST(ResourcePathsData, SofaExamplesResolveAsDocumented) {
  const fs::path data = SINEW_DATA_DIR;
  if (!fs::exists(data / "examples")) GTEST_SKIP() << "SOFA data not found at " << data << " (SINEW_DATA_DIR)";
  ResourcePaths paths;
  paths.add((data / "share").string());
  paths.add((data / "examples").string());
  const std::string demos = (data / "examples/Demos").string();
  EXPECT_EQ(paths.resolve("mesh/liver.msh", demos), (data / "share/mesh/liver.msh").lexically_normal().string());
  const std::string dynamic = (data / "examples/Component/Topology/Container/Dynamic").string();
  EXPECT_EQ(paths.resolve("RemovingTrianglesProcess.txt", dynamic),
            (data / "examples/Component/Topology/Container/Dynamic/RemovingTrianglesProcess.txt")
                .lexically_normal()
                .string());
  EXPECT_EQ(paths.resolve("Objects/TorusFEM.xml", demos),
            (data / "examples/Objects/TorusFEM.xml").lexically_normal().string());
  EXPECT_EQ(paths.resolve("mesh/does_not_exist.msh", demos), std::nullopt);
}
