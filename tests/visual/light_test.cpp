// Lights: SOFA's Data and defaults, lights attaching to the LightManager above them in init
// order (at most eight), what the renderer receives (world positions and directions, spot
// look-at, OpenGL's refusal of out-of-range cut-offs and exponents), and bad input.
#include <gtest/gtest.h>

#include <string>

#include "test_scene.h"
#include "visual/shader/light.h"

namespace sinew {
namespace {

TEST(Lights, DefaultsAsSofa) {
  auto s = test::load(R"(<Node name="root"><LightManager name="lm"/>
    <DirectionalLight name="d"/><PositionalLight name="p"/><SpotLight name="s"/></Node>)");
  auto* lm = test::get<LightManager>(*s.root, "lm");
  auto* p = test::get<PositionalLight>(*s.root, "p");
  auto* sp = test::get<SpotLight>(*s.root, "s");
  ASSERT_TRUE(lm && p && sp);
  EXPECT_EQ(lm->ambient.get(), "0 0 0 0");
  EXPECT_FALSE(lm->shadows.get());
  EXPECT_EQ(p->position.get(), Vec3(-0.7, 0.3, 0.0));
  EXPECT_EQ(p->attenuation.get(), 0.0);
  EXPECT_EQ(sp->cutoff.get(), 30.0);
  EXPECT_EQ(sp->exponent.get(), 1.0);
  EXPECT_EQ(test::get<DirectionalLight>(*s.root, "d")->direction.get(), Vec3(0, 0, -1));
  EXPECT_TRUE(p->shadows_enabled.get());
  EXPECT_EQ(p->texture_unit.get(), 1u);
  // The three attached in init order.
  ASSERT_EQ(lm->lights().size(), 3u);
  EXPECT_EQ(lm->lights()[1], p);
  const LightSource d = lm->lights()[0]->source();
  EXPECT_EQ(d.position[3], 0.0);  // a direction
  EXPECT_EQ(d.position[2], -1.0);
  EXPECT_EQ(d.cutoff, 180.f);
  const LightSource ps = p->source();
  EXPECT_EQ(ps.position[3], 1.0);
  EXPECT_EQ(ps.cutoff, 180.f);  // a point light has no cone
  const LightSource ss = sp->source();
  EXPECT_EQ(ss.cutoff, 30.f);
  EXPECT_EQ(ss.spot_direction[2], -1.0);
}

TEST(Lights, SpotLookAtColourAndOpenGLRanges) {
  auto s = test::load(R"(<Node name="root"><LightManager/>
    <SpotLight name="a" position="1 2 3" direction="1 2 0" lookat="1" color="0 1 0"/>
    <SpotLight name="b" cutoff="120" exponent="1000"/></Node>)");
  const LightSource a = test::get<SpotLight>(*s.root, "a")->source();
  // Looking at (1, 2, 0) from (1, 2, 3): straight down.
  EXPECT_NEAR(a.spot_direction[0], 0, 1e-15);
  EXPECT_NEAR(a.spot_direction[2], -1, 1e-15);
  EXPECT_EQ(a.color[0], 0.f);
  EXPECT_EQ(a.color[1], 1.f);
  // OpenGL ignores a cut-off of 120° and an exponent of 1000: its defaults (no cone, 0) stay,
  // with a warning naming them.
  const LightSource b = test::get<SpotLight>(*s.root, "b")->source();
  EXPECT_EQ(b.cutoff, 180.f);
  EXPECT_EQ(b.exponent, 0.f);
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "cutoff 120")) << ::testing::PrintToString(warnings);
  EXPECT_TRUE(test::any_contains(warnings, "exponent 1000"));
}

TEST(Lights, AtMostEightAttachedAndOnlyBelowTheirManager) {
  std::string lights;
  for (int i = 0; i < 10; ++i) lights += "<DirectionalLight name=\"l" + std::to_string(i) + "\"/>";
  auto s = test::load("<Node name=\"root\"><Node name=\"lit\"><LightManager name=\"lm\"/>" + lights +
                      "</Node><Node name=\"other\"><PositionalLight name=\"far\"/></Node></Node>");
  auto* lm = test::get<LightManager>(*s.root->find_child_named("lit"), "lm");
  ASSERT_TRUE(lm);
  EXPECT_EQ(lm->lights().size(), 8u);
  const auto warnings = test::messages(s.root->diagnostics(), Severity::warning);
  EXPECT_TRUE(test::any_contains(warnings, "maximum of 8 lights"));
  EXPECT_TRUE(test::any_contains(warnings, "no LightManager in this node or above"));
}

TEST(Lights, BadColourAndUnknownAttributeAreErrors) {
  auto s = test::build(R"(<Node name="root"><LightManager ambient="nocolour"/><SpotLight colr="1 0 0"/></Node>)");
  const auto errors = test::messages(s.root->diagnostics(), Severity::error);
  EXPECT_TRUE(test::any_contains(errors, "ambient")) << ::testing::PrintToString(errors);
  EXPECT_TRUE(test::any_contains(test::messages(s.root->diagnostics(), Severity::warning), "colr") ||
              test::any_contains(errors, "colr"));
}

}  // namespace
}  // namespace sinew
