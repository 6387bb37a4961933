// SOFA's viewer-side components (shaders, textures, render passes, clip
// plane, bounding box, meshes and point clouds): Data names, defaults,
// aliases, validation messages, file checks.
#include <gtest/gtest.h>

#include <filesystem>

#include "badinput_helpers.h"
#include "test_scene.h"
#include "visual/clip_plane.h"
#include "visual/color.h"
#include "visual/drawing/visual_bounding_box.h"
#include "visual/ogl_model.h"
#include "visual/shader/ogl_shader.h"
#include "visual/shader/post_process_manager.h"

namespace sinew::test {
namespace {

Component* only(Node& root, std::string_view name) { return dynamic_cast<Component*>(root.find_object_named(name)); }

std::string text_of(Component* c, const char* field) {
  BaseField* f = c ? c->find_field(field) : nullptr;
  return f ? f->text() : "<missing field>";
}

TEST(ViewerComponents, ShaderDefaultsAndAliases) {
  auto s = load(R"(<Node name="root">
      <OglShader name="s" tessellationLevel="6"/>
      <OglShadowShader name="shadow"/>
      <OglShaderDefineMacro name="m" value="2"/>
      <OglShaderDefineMacro name="m2" id="USE_TEXTURE" indexShader="1"/>
    </Node>)");
  ASSERT_TRUE(s.root);
  Component* sh = only(*s.root, "s");
  EXPECT_EQ(text_of(sh, "fileVertexShaders"), "shaders/toonShading.vert");
  EXPECT_EQ(text_of(sh, "fileFragmentShaders"), "shaders/toonShading.frag");
  EXPECT_EQ(text_of(sh, "fileGeometryShaders"), "");
  EXPECT_EQ(text_of(sh, "geometryVerticesOut"), "-1");
  EXPECT_EQ(text_of(sh, "turnOn"), "1");
  EXPECT_EQ(text_of(sh, "passive"), "0");
  EXPECT_EQ(text_of(sh, "clampVertexColor"), "1");
  EXPECT_EQ(text_of(sh, "tessellationOuterLevel"), "6");
  EXPECT_EQ(text_of(sh, "tessellationInnerLevel"), "6");
  Component* shadow = only(*s.root, "shadow");
  EXPECT_EQ(text_of(shadow, "fileVertexShaders"),
            "shaders/hardShadows/shadowMapping.vert shaders/hardShadows/shadowMapping.vert");
  // A macro without id takes its name (SOFA's OglShaderElement::init).
  EXPECT_EQ(text_of(only(*s.root, "m"), "id"), "m");
  EXPECT_EQ(text_of(only(*s.root, "m"), "value"), "2");
  EXPECT_EQ(text_of(only(*s.root, "m2"), "id"), "USE_TEXTURE");
  EXPECT_EQ(text_of(only(*s.root, "m2"), "indexShader"), "1");
}

TEST(ViewerComponents, ShaderFilesResolvedOrWarned) {
  TempDir dir;
  dir.write("shaders/a.vert", "void main() {}\n");
  const Outcome o = run_xml(dir, R"(<Node name="root">
      <OglShader name="s" fileVertexShaders="['shaders/a.vert']" fileFragmentShaders="['shaders/missing.frag']"/>
    </Node>)", 1);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"OglShader", "fileFragmentShaders", "shaders/missing.frag", "not found"}))
      << o.all();
  EXPECT_FALSE(any_contains_all(o.warnings, {"a.vert"})) << o.all();
}

TEST(ViewerComponents, VariablesParseTheirTypes) {
  auto s = load(R"(<Node name="root">
      <OglShader/>
      <OglFloatVariable name="f" value="0.25"/>
      <OglIntVariable name="i" values="3"/>
      <OglFloat4Variable name="f4" value="1 2 3 4"/>
      <OglMatrix4VectorVariable name="m" value="1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1" transpose="1"/>
      <OglInt4Attribute name="ia" value="0 1 2 3 4 5 6 7"/>
      <OglFloat4Attribute name="fa" value="1 0 0 0 0.5 0.5 0 0"/>
    </Node>)");
  ASSERT_TRUE(s.root);
  EXPECT_EQ(text_of(only(*s.root, "f"), "value"), "0.25");
  EXPECT_EQ(text_of(only(*s.root, "i"), "value"), "3");  // `values` is an alias
  EXPECT_EQ(text_of(only(*s.root, "f4"), "value"), "1 2 3 4");
  EXPECT_EQ(text_of(only(*s.root, "m"), "transpose"), "1");
  EXPECT_EQ(text_of(only(*s.root, "ia"), "handleDynamicTopology"), "1");
  EXPECT_EQ(text_of(only(*s.root, "fa"), "value"), "1 0 0 0 0.5 0.5 0 0");
}

TEST(ViewerComponents, BadShaderValuesAreLoadErrors) {
  TempDir dir;
  Outcome o = run_xml(dir, R"(<Node name="root"><OglInt4Attribute value="0 1 2"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"OglInt4Attribute", "value", "multiple of 4"})) << o.all();
  o = run_xml(dir, R"(<Node name="root"><OglMatrix4VectorVariable value="1 2 3"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"OglMatrix4VectorVariable", "multiple of 16"})) << o.all();
  // An unreadable number is Sinew's generic warning (SOFA warns and keeps the default).
  o = run_xml(dir, R"(<Node name="root"><OglFloatVariable value="abc"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.warnings, {"OglFloatVariable", "value", "abc"})) << o.all();
}

TEST(ViewerComponents, TextureDefaultsAndMissingFile) {
  TempDir dir;
  dir.write("tex/a.png", "not checked here");
  const Outcome o = run_xml(dir, R"(<Node name="root">
      <OglTexture name="t" textureFilename="tex/a.png"/>
      <OglTexture name="u" filename="tex/none.png"/>
      <OglTexture2D name="v" texture2DFilename="tex/a.png"/>
    </Node>)", 1);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"OglTexture", "filename", "tex/none.png", "not found"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.warnings, {"OglTexture2D is deprecated"})) << o.all();
  auto s = load(R"(<Node name="root"><OglTexture name="t"/></Node>)");
  Component* t = only(*s.root, "t");
  EXPECT_EQ(text_of(t, "textureUnit"), "1");
  EXPECT_EQ(text_of(t, "repeat"), "0");
  EXPECT_EQ(text_of(t, "linearInterpolation"), "1");
  EXPECT_EQ(text_of(t, "minLod"), "-1000");
  EXPECT_EQ(text_of(t, "maxLod"), "1000");
  EXPECT_EQ(text_of(t, "proceduralTextureNbBits"), "1");
}

TEST(ViewerComponents, RenderPasses) {
  auto s = load(R"(<Node name="root">
      <PostProcessManager name="p" zFar="1000"/>
      <OrderIndependentTransparencyManager name="o"/>
      <OglViewport name="v" screenPosition="300 0" screenSize="400 400" cameraRigid="-1 2.7 13 0 0 0 1"/>
    </Node>)");
  ASSERT_TRUE(s.root);
  EXPECT_EQ(text_of(only(*s.root, "p"), "zNear"), "1");
  EXPECT_EQ(text_of(only(*s.root, "p"), "zFar"), "1000");
  EXPECT_EQ(text_of(only(*s.root, "o"), "depthScale"), "0.01");
  Component* v = only(*s.root, "v");
  EXPECT_EQ(text_of(v, "screenSize"), "400 400");
  EXPECT_EQ(text_of(v, "cameraRigid"), "-1 2.7 13 0 0 0 1");
  EXPECT_EQ(text_of(v, "fovy"), "60");
  EXPECT_EQ(text_of(v, "useFBO"), "1");
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root"><OglViewport screenSize="-1 4" fovy="200"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"OglViewport", "screenSize"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"OglViewport", "fovy"})) << o.all();
  // PostProcessManager draws with the OglShader of its node or above; without one, no pass.
  const Outcome lone = run_xml(dir, R"(<Node name="root"><PostProcessManager/></Node>)", 1);
  EXPECT_TRUE(lone.init_ok) << lone.all();
  EXPECT_TRUE(any_contains_all(lone.warnings, {"PostProcessManager", "no OglShader", "no post-process"})) << lone.all();
  auto with = load(R"(<Node name="root"><OglShader name="sh" passive="1"/><Node name="c"><PostProcessManager name="p"/></Node></Node>)");
  ASSERT_TRUE(with.root);
  const auto* p = get<PostProcessManager>(*with.root->children().front(), "p");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->shader(), get<OglShader>(*with.root, "sh"));
}

TEST(ViewerComponents, ClipPlaneHalfSpace) {
  auto s = load(R"(<Node name="root"><ClipPlane name="c" position="1 0 0" normal="0 0 2"/></Node>)");
  auto* c = get<ClipPlane>(*s.root, "c");
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->clips(Vec3(0, 0, 0.1)));
  EXPECT_FALSE(c->clips(Vec3(5, 5, -0.1)));
  c->active.set(false);
  EXPECT_FALSE(c->clips(Vec3(0, 0, 0.1)));
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root"><ClipPlane id="-1"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"ClipPlane", "id cannot be negative"})) << o.all();
}

TEST(ViewerComponents, BoundingBoxFollowsTheModel) {
  auto s = load(R"(<Node name="root">
      <OglModel name="VisualModel" position="0 0 0  2 -1 0  1 3 5" triangles="0 1 2"/>
      <VisualBoundingBox name="b" color="green" thickness="20" bbox="@VisualModel.bbox"/>
    </Node>)");
  auto* b = get<VisualBoundingBox>(*s.root, "b");
  ASSERT_TRUE(b);
  auto box = b->box();
  ASSERT_TRUE(box);
  EXPECT_EQ(box->first, Vec3(0, -1, 0));
  EXPECT_EQ(box->second, Vec3(2, 3, 5));
  EXPECT_EQ(text_of(b, "thickness"), "20");
  auto d = load(R"(<Node name="root"><VisualBoundingBox name="b"/></Node>)");
  EXPECT_EQ(text_of(only(*d.root, "b"), "color"), "yellow");
  EXPECT_FALSE(get<VisualBoundingBox>(*d.root, "b")->box());
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root"><VisualBoundingBox color="nocolour" bbox="1 2 3"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualBoundingBox", "color", "nocolour", "not a colour"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualBoundingBox", "bbox needs 6 numbers"})) << o.all();
}

TEST(ViewerComponents, MeshPointCloudCylinder) {
  TempDir dir;
  Outcome o = run_xml(dir, R"(<Node name="root">
      <RegularGridTopology name="grid" n="2 2 2" min="0 0 0" max="1 1 1"/>
      <MechanicalObject name="state"/>
      <VisualMesh position="@state.position" topology="@grid" elementSpace="0.2" colorMap="Blue to Red"/>
      <VisualPointCloud position="@state.position" drawMode="Sphere" sphereRadius="0.1" color="lime"/>
      <CylinderVisualModel position="0 0 0  10 0 0" edges="0 1" color="yellow"/>
    </Node>)", 2);
  EXPECT_TRUE(o.init_ok) << o.all();
  EXPECT_EQ(o.steps, 2);
  o = run_xml(dir, R"(<Node name="root">
      <VisualMesh elementSpace="2" colorMap="Purple haze"/>
      <VisualPointCloud drawMode="Frame"/>
      <VisualPointCloud template="Rigid3" drawMode="Cube"/>
      <CylinderVisualModel position="0 0 0" edges="0 1" radius="0"/>
    </Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualMesh", "elementSpace"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualMesh", "colorMap", "Purple haze"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualPointCloud", "Frame", "Point or Sphere"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualPointCloud", "Cube", "Point, Sphere or Frame"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"CylinderVisualModel", "radius must be positive"})) << o.all();
  // No topology at all: SOFA's VisualMesh is invalid.
  o = run_xml(dir, R"(<Node name="root"><VisualMesh/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"VisualMesh", "no topology"})) << o.all();
}

TEST(ViewerComponents, ColorText) {
  EXPECT_EQ(*parse_rgba("lime"), (Rgba{0.5f, 1, 0, 1}));
  EXPECT_EQ(*parse_rgba("#ff000080"), (Rgba{1, 0, 0, 128 / 255.f}));
  EXPECT_EQ(*parse_rgba("0.1 0.2 0.3"), (Rgba{0.1f, 0.2f, 0.3f, 1}));
  EXPECT_FALSE(parse_rgba("nocolour"));
}

TEST(ViewerComponents, ShaderVisualModelIsAnOglModel) {
  auto s = load(R"(<Node name="root"><OglShaderVisualModel name="m" position="0 0 0 1 0 0 0 1 0" triangles="0 1 2"/></Node>)");
  auto* m = get<OglModel>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->bbox.get(), (std::vector<double>{0, 0, 0, 1, 1, 0}));
}

TEST(ViewerComponents, MergeVisualModelsConcatenates) {
  auto s = load(R"(<Node name="root">
      <OglModel name="a" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2" texcoords="0 0 1 0 0 1"/>
      <OglModel name="b" position="0 0 1  1 0 1  1 1 1  0 1 1" quads="0 1 2 3" triangles="0 1 2"/>
      <OglModel name="c" position="9 9 9" />
      <MergeVisualModels name="m" nb="2" input1="@a" input2="@b"/>
    </Node>)");
  auto* m = get<OglModel>(*s.root, "m");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->visual_size(), 7u);
  EXPECT_EQ(m->triangles.get(), (std::vector<Triangle>{{0, 1, 2}, {3, 4, 5}}));
  EXPECT_EQ(m->quads.get(), (std::vector<Quad>{{3, 4, 5, 6}}));
  EXPECT_EQ(m->texcoords.get().size(), 3u);
  EXPECT_EQ(m->bbox.get(), (std::vector<double>{0, 0, 0, 1, 1, 1}));
  // The merged positions follow the inputs after a step.
  get<OglModel>(*s.root, "b")->position.edit().data[0] = -2.0;
  Event e;
  e.kind = Event::Kind::animate_end;
  m->handle_event(e);
  EXPECT_EQ(m->position.get().data[9], -2.0);
  EXPECT_EQ(m->bbox.get()[0], -2.0);
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root"><MergeVisualModels nb="1" input1="@nothing"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"MergeVisualModels", "input1", "@nothing"})) << o.all();
}

TEST(ViewerComponents, PointSplatModelData) {
  auto s = load(R"(<Node name="root"><PointSplatModel name="p" radius="0.25" alpha="0.1" color="cyan"/></Node>)");
  Component* p = only(*s.root, "p");
  EXPECT_EQ(text_of(p, "radius"), "0.25");
  EXPECT_EQ(text_of(p, "textureSize"), "32");
  EXPECT_EQ(text_of(p, "alpha"), "0.1");
  TempDir dir;
  const Outcome o = run_xml(dir, R"(<Node name="root"><PointSplatModel alpha="2" pointData="3 300"/></Node>)", 1);
  EXPECT_TRUE(any_contains_all(o.errors, {"PointSplatModel", "alpha"})) << o.all();
  EXPECT_TRUE(any_contains_all(o.errors, {"PointSplatModel", "pointData", "300"})) << o.all();
}

}  // namespace
}  // namespace sinew::test
