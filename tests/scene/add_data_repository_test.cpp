// AddDataRepository: the folder it names (relative to the scene's folder) is
// searched for the files named after it in the scene, as SOFA's DataRepository.
#include <gtest/gtest.h>

#include "scene/builder.h"
#include "test_scene.h"

using namespace sinew;
using sinew::test::TempDir;

namespace {
const char* kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
}

TEST(AddDataRepository, LaterFilesAreFoundInTheAddedFolder) {
  register_all_components();
  TempDir d;
  d.write("meshes/tri.obj", kObj);
  const std::string scene = d.write("scene.scn", R"(<Node>
      <AddDataRepository name="repo" path="./meshes"/>
      <MeshOBJLoader name="l" filename="tri.obj"/>
    </Node>)");
  Diagnostics diag;
  scene::LoadOptions opt;
  opt.use_sofa_data_path = false;
  scene::LoadedScene s = scene::load_scene(scene, opt, diag);
  ASSERT_TRUE(s.root);
  for (const std::string& m : test::messages(s.root->diagnostics(), Severity::error)) ADD_FAILURE() << m;
  init_root(*s.root);
  Component* l = s.root->find_object_named("l");
  ASSERT_TRUE(l);
  EXPECT_EQ(l->find_field("position")->text(), "0 0 0 1 0 0 0 1 0");
  // The path is rewritten absolute, as SOFA does.
  EXPECT_EQ(s.root->find_object_named("repo")->find_field("path")->text(), d.dir() + "/meshes");
}

TEST(AddDataRepository, BeforeItTheFolderIsNotSearched) {
  register_all_components();
  TempDir d;
  d.write("meshes/tri.obj", kObj);
  const std::string scene = d.write("scene.scn", R"(<Node>
      <MeshOBJLoader name="l" filename="tri.obj"/>
      <AddDataRepository path="meshes"/>
      <AddDataRepository path="nowhere"/>
    </Node>)");
  Diagnostics diag;
  scene::LoadOptions opt;
  opt.use_sofa_data_path = false;
  scene::LoadedScene s = scene::load_scene(scene, opt, diag);
  ASSERT_TRUE(s.root);
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "file not found"));
  EXPECT_TRUE(test::any_contains(errors, "nowhere does not exist"));
}
