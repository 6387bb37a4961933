// What a picture shows, gathered from the scene graph as flat float arrays
// ready to upload: one batch per drawn component.
//
// - Visual models (VisualStyle showVisualModels, on by default): each OglModel's
//   vertices, SOFA's normals (VisualModelImpl::computeNormals: unnormalised face
//   normals summed per vertex — per vertNormIdx group across OBJ seams —, quads per
//   corner, then normalised), its triangles and
//   its quads split in two, the material's colour; a ClipPlane of the model's node or
//   an ancestor (the nearest active one) removes the half-space its normal points to.
//   Translucent models (diffuse alpha < 1) are drawn after the opaque batches, in graph
//   order, as SOFA's transparent pass.
// - Lights: a scene with a LightManager is lit by its lights (fixed-function OpenGL's model),
//   otherwise by a headlight.
// - Force fields (showForceFields): the volume elements of a node's topology under a
//   force field, drawn as SOFA's FEM force fields do (tetrahedra shrunk towards their
//   centre with four blues, hexahedra shrunk with six face colours), flat shaded.
// - Behaviour models (showBehaviorModels): the points of unmapped states with
//   showObject (as SOFA's MechanicalObject); when nothing else is drawn, the points of
//   every unmapped state under the flag, so such a scene still shows its bodies.
//
// gather() reuses the batches' storage: once the sizes are stable (no topology change),
// a frame allocates nothing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/roles.h"
#include "render/material.h"
#include "visual/shader/light.h"
#include "visual/shader/shader_element.h"

namespace sinew {
class Node;
}

namespace sinew::render {

// An OglFluidModel's Data as its surface's passes use them (render/fluid_surface.h).
struct FluidLook {
  float radius = 1.f, thickness = 0.01f;
  float blur_radius = 10.f, blur_scale = 0.1f, blur_falloff = 1.f;
  Rgba color{0, 0, 1, 1};
  unsigned debug = 9;  // debugFBO
};

struct Batch {
  enum class Kind { triangles, points, lines };
  Kind kind = Kind::triangles;
  const Component* source = nullptr;
  std::vector<float> positions;  // x y z per vertex
  std::vector<float> normals;    // x y z per vertex (triangles)
  std::vector<float> colors;     // r g b a per vertex; empty: shading.diffuse for all
  std::vector<unsigned> indices;  // triangles; empty: vertices taken three by three (two by two for lines)
  // A textured visual model: u v per vertex and the image file (OglModel texturename, resolved);
  // the renderer loads each file once. Empty: no texture.
  std::vector<float> texcoords;
  std::string texture;
  Shading shading{};
  float color_ambient = 0.f;  // ambient term proportional to the vertex colour (SOFA's draw tool)
  float point_size = 1.f;
  // Width in pixels of lines and of wireframe edges (SOFA's glLineWidth / drawLines size).
  float line_width = 1.f;
  bool wireframe = false;  // showWireframe: triangles drawn as their edges
  bool lit = true;         // triangles shaded by the headlight; false: their colour as is
  // A visual model whose material is translucent (diffuse used, alpha < 1): drawn after every
  // opaque batch, blended by SOFA's two passes unless `blend` is off (blendTranslucency),
  // writing depth only with `write_depth` (writeZTransparent); `premultiplied`: the colour
  // already holds its alpha (premultipliedAlpha).
  bool translucent = false, blend = true, write_depth = false, premultiplied = false;
  // OglModel's own GL state (internalDraw): `alpha_blend` draws it blended by
  // blend_equation (0 add, 1 subtract, 2 min, 3 max) with source_factor and dest_factor
  // (0 zero, 1 one, 2 source alpha, 3 one minus source alpha), without writing depth;
  // `depth_test` off draws it over everything; `cull` 1 drops back faces, 2 front faces.
  bool alpha_blend = false, depth_test = true;
  int blend_equation = 0, source_factor = 2, dest_factor = 3, cull = 0;
  // Points drawn as camera-facing discs of `splat_radius` (world units; 0: plain points of
  // point_size pixels): `soft` discs fade as cos(π/2·r/R)·splat_alpha and are blended "over",
  // back to front, in the translucent pass (PointSplatModel). `fluid`: the particles of an
  // OglFluidModel, drawn as the screen-space surface `fluid` describes (render/fluid_surface.h).
  enum class Splat { none, soft, fluid };
  Splat splat = Splat::none;
  float splat_radius = 0.f, splat_alpha = 1.f;
  FluidLook fluid;
  // ClipPlanes over the model (visual models only), by OpenGL id: a vertex p is kept where
  // clip[k]·(p, 1) >= 0 for every k (gl_ClipDistance[k]); (0, 0, 0, 1) keeps everything.
  static constexpr int kClipPlanes = 8;  // GL_MAX_CLIP_DISTANCES is at least 8
  std::array<std::array<float, 4>, kClipPlanes> clip = no_clip();
  static std::array<std::array<float, 4>, kClipPlanes> no_clip() {
    std::array<std::array<float, 4>, kClipPlanes> c{};
    for (auto& p : c) p = {0.f, 0.f, 0.f, 1.f};
    return c;
  }
  // A visual model under an OglShadowShader (its node or an ancestor): shaded as SOFA's
  // shadow-mapping shaders do (Lighting::shadows adds the lights' shadow maps).
  bool shadow_shader = false;
  // OglModel's primitiveType, for the stages of its shader: DEFAULT triangles (quads split);
  // PATCHES its triangles as patches of 3 and its quads as patches of 4 (a tessellation
  // shader's input); LINES_ADJACENCY its quads as lines with adjacency (its triangles stay
  // triangles, as SOFA warns); POINTS every vertex as a point of point_size pixels (with or
  // without a shader). indices[0, 3·triangle_count) are the model's own triangles;
  // quad_indices, four per quad, are filled for PATCHES and LINES_ADJACENCY.
  enum class Primitive { triangles, lines_adjacency, patches, points };
  Primitive primitive = Primitive::triangles;
  std::size_t triangle_count = 0;
  std::vector<unsigned> quad_indices;
  // A visual model under an OglShader: the index of its program in DrawList::shaders (-1:
  // none), and the shader's per-vertex attributes (one item of `width` floats per vertex).
  int shader = -1;
  struct Attribute {
    std::string name;
    int width = 1;
    std::vector<float> values;
  };
  std::vector<Attribute> attributes;
  // The texts `shading` was parsed from (a model's material and colour, a box's colour), so
  // that it is parsed again only when they change. Texts rather than field versions: a
  // component of another scene can take a freed component's address with the same version.
  std::string material_text, color_text;
  bool shading_parsed = false;
  std::size_t vertex_count() const { return positions.size() / 3; }
};

// The scene's lights: those of its first LightManager (graph order), when it has one; else the
// viewer's headlight is used.
struct Lighting {
  bool from_scene = false;
  bool shadows = false, soft_shadows = false;  // the LightManager's shadows and softShadows
  Rgba ambient{0, 0, 0, 0};  // LightManager's ambient (GL_LIGHT_MODEL_AMBIENT)
  std::vector<LightSource> lights;
};

// OglSceneFrame: the axes in a corner (style 0 arrows, 1 cylinders, 2 cube and cones;
// corner 0 bottom-left, 1 bottom-right, 2 top-right, 3 top-left).
struct SceneFrame {
  bool on = false;
  int style = 1, corner = 1, size = 150;
};

// A text to draw (render/draw_text.h): its form, where, how big, its colour.
struct Text {
  enum class Kind { world, indices, overlay };
  Kind kind = Kind::world;
  const Component* source = nullptr;
  std::string text;            // world, overlay
  Vec3 anchor = Vec3::Zero();  // world: top-left corner; overlay: pixels (x right, y down) from the top-left
  std::vector<float> points;   // indices: x y z per point, labelled 0, 1, ...
  float size = 1.f;            // world: glyph height (world units); indices: 30·size px high; overlay: fontsize
  Rgba color{1, 1, 1, 1};
  bool depth_test = false;
};

// OglViewport: the scene drawn again from a fixed camera in a rectangle of the picture.
struct ExtraViewport {
  int x = 0, y = 0;                         // screenPosition: pixels from the left and the bottom (< 0: from the right / top)
  int width = 0, height = 0;                // screenSize
  Vec3 position = Vec3::Zero();             // camera position
  VecN<4> orientation = VecN<4>(0, 0, 0, 1);  // rotation world → camera (SOFA's use of it)
  double z_near = 0, z_far = 0, fovy = 60;  // 0: near and far fitted to the scene
  bool swap = false;                        // swapMainView
};

// OrderIndependentTransparencyManager in the root node: the translucent visual models
// (triangle batches) are drawn by weighted blended order-independent transparency.
struct Oit {
  bool on = false;
  float depth_scale = 0.01f;  // of the blending weights (1/length)
};

// PostProcessManager in the root node with an OglShader: the scene is drawn off screen through
// a 60° perspective of aspect 1 between z_near and z_far, then the picture is covered by a quad
// drawn by list.shaders[shader] reading that picture's colour and depth (render/gl_renderer.h).
struct PostProcess {
  bool on = false;
  int shader = -1;
  float z_near = 1.f, z_far = 100.f;
};

// An OglShader the visual models under it are drawn with (render/scene_shader.h): its GLSL
// files (the version in use; tessellation and geometry stages optional), and the #defines, uniforms and textures of its elements.
struct SceneShader {
  const Component* source = nullptr;
  std::string vertex_file, fragment_file;
  std::string tess_control_file, tess_eval_file, geometry_file;  // empty: no such stage
  std::vector<std::pair<std::string, std::string>> defines;
  struct Input {
    std::string name;
    ShaderInput value;
  };
  std::vector<Input> uniforms, textures;
};

struct DrawList {
  std::vector<Batch> batches;
  std::vector<SceneShader> shaders;  // shaders[0, shaders_used) are this frame's, by first use in graph order
  std::size_t shaders_used = 0;
  std::vector<ExtraViewport> viewports;  // OglViewports shown, in graph order
  std::vector<Text> texts;  // texts[0, texts_used) are this frame's, drawn over the models
  std::size_t texts_used = 0;
  // Rectangles over the picture before its overlay texts (OglColorMap's legend bar): pixels
  // x0 y0 x1 y1 (y down from the top) then r g b a, 8 floats each.
  std::vector<float> overlay_rects;
  Lighting lighting;
  // BackgroundSetting's image (a readable file), drawn tiled under the scene; empty: none.
  std::string background_image;
  Oit oit;
  PostProcess post;
  SceneFrame frame;
  std::size_t used = 0;  // batches[0, used) are this frame's
  // Bounding box of what is drawn (valid when has_bounds).
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  bool has_bounds = false;
};

void gather(Node& root, DrawList& out);

// SOFA's VisualModelImpl::computeNormals for vertices `x` (xyz floats) into `n`; with
// `norm_idx` (vertNormIdx, one per vertex), vertices of the same index share their normal.
void compute_normals(const std::vector<float>& x, const std::vector<Triangle>& triangles,
                     const std::vector<Quad>& quads, std::vector<float>& n,
                     const std::vector<unsigned>* norm_idx = nullptr);

}  // namespace sinew::render
