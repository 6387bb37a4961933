// SOFA's example scenes whose only unknown components were viewer-side ones
// (shaders, textures, render passes, clip plane, bounding box, visual meshes
// and point clouds): each loads without error and runs 10 steps, as
// `sinew run SCENE -n 10 --data-path share examples` does. Skipped when the
// SOFA data are absent (SINEW_DATA_DIR).
#include <gtest/gtest.h>

#include <filesystem>

#include "badinput_helpers.h"
#include "test_paths.h"

namespace sinew::test {
namespace {

namespace fs = std::filesystem;

fs::path data_dir() {
  if (const char* env = std::getenv("SINEW_DATA_DIR")) return fs::path(env).lexically_normal();
  return fs::path(SINEW_DATA_DIR).lexically_normal();
}

class SofaVisualScene : public ::testing::TestWithParam<const char*> {};

TEST_P(SofaVisualScene, LoadsAndRuns) {
  const fs::path scene = data_dir() / "examples" / GetParam();
  if (!fs::exists(scene)) GTEST_SKIP() << "SOFA data not found: " << scene << " (set SINEW_DATA_DIR)";
  runner::SessionOptions opts;
  opts.data_paths = {(data_dir() / "share").string(), (data_dir() / "examples").string()};
  runner::Session session(scene.string(), opts);
  ASSERT_TRUE(session.ok()) << [&] {
    std::string s;
    for (const auto& e : messages(session.diagnostics(), Severity::error)) s += e + "\n";
    return s;
  }();
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(session.step()) << "step " << i;
  EXPECT_EQ(session.steps_done(), 10);
  EXPECT_TRUE(all_finite(session.root()));
}

INSTANTIATE_TEST_SUITE_P(
    Examples, SofaVisualScene,
    ::testing::Values("Component/Visual/VisualPointCloud.scn", "Component/Visual/CylinderVisualModel.scn",
                      "Component/Visual/OglShadowShader_SpotLight.scn",
                      "Component/Visual/OglShadowShader_SpotLight2.scn",
                      "Component/Visual/OglShadowShader_Directional.scn", "Component/Visual/OglViewport.scn",
                      "Component/Visual/OrderIndependentTransparency.scn", "Component/Visual/ClipPlane.scn",
                      "Component/Visual/OglShader.scn", "Component/Visual/VisualBoundingBox.scn",
                      "Component/Visual/VisualMesh.scn", "Component/Visual/MergeVisualModels.scn",
                      "Component/Visual/PointSplatModel.scn", "Component/Visual/PostProcessManager_DepthOfField.scn",
                      "Tutorials/StepByStep/Visual/3_Visual.scn",
                      "Tutorials/StepByStep/Visual/4_Visual.scn", "Tutorials/StepByStep/Visual/5_Visual.scn",
                      "Tutorials/StepByStep/Visual/6_Visual.scn", "Demos/skybox.scn",
                      "Demos/MeshInducedAnisotropy.scn"),
    [](const ::testing::TestParamInfo<const char*>& info) {
      std::string n = info.param;
      for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return n;
    });

}  // namespace
}  // namespace sinew::test
