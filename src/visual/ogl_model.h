// OglModel (and VisualModelImpl, alias VisualModel): a visual model without
// any OpenGL. It holds the points of a surface (positions, normals,
// triangles, quads, texture coordinates, material strings, colour) that a
// mapping (IdentityMapping, BarycentricMapping, RigidMapping, ...) may write
// after each step. It is a VisualState, not a MechanicalState: mechanical
// operations never touch it, and a mapping towards it is non-mechanical
// (framework.md trap T1), so it costs one apply per step.
//
// Initial geometry (VisualModelImpl::init): `filename` (OBJ), else the
// fields (src="@loader", position="@x.position", ...), else the node's mesh
// topology (its points, or its state's positions, and its triangles/quads).
// Then scale3d, rotation (degrees), translation are applied once; the
// pseudo-attributes dx/dy/dz, rx/ry/rz, scale/sx/sy/sz, su/sv, du/dv, color,
// normals, castshadow and flip are accepted as in SOFA.
#pragma once

#include "core/roles.h"

namespace sinew {

class OglModel : public VisualState {
 public:
  OglModel();

  Field<FlatVec> position;
  Field<FlatVec> rest_position;
  Field<std::vector<Vec3>> normal{this, "normal", {}, "vertex normals", "Vector"};
  Field<bool> init_rest_positions{this, "initRestPositions", false,
                                  "copy the initial positions into the rest positions", "Visual"};
  Field<bool> use_normals{this, "useNormals", true, "read the smoothing groups of the file", "Visual"};
  Field<bool> update_normals{this, "updateNormals", true, "recompute the normals every step", "Visual"};
  Field<bool> compute_tangents{this, "computeTangents", false, "compute tangents at init", "Visual"};
  Field<bool> update_tangents{this, "updateTangents", true, "recompute the tangents every step", "Visual"};
  Field<bool> compute_texture_coordinates{this, "computeTextureCoordinates", false,
                                          "generate texture coordinates at init by spherical projection", "Visual"};
  Field<bool> handle_dynamic_topology{this, "handleDynamicTopology", true, "follow topology changes", "Visual"};
  Field<bool> fix_merged_uv_seams{this, "fixMergedUVSeams", true,
                                  "keep UV seams when merging duplicated texture coordinates", "Visual"};
  Field<bool> keep_lines{this, "keepLines", false, "keep the line elements and draw them", "Visual"};
  Field<std::vector<Vec3>> vertices{
      this, "vertices", {}, "render vertices (when they differ from positions because of seams)", "Vector"};
  Field<std::vector<Vec2>> texcoords{this, "texcoords", {}, "texture coordinates per vertex", "Vector"};
  Field<std::vector<Vec3>> tangents{this, "tangents", {}, "tangent vectors (normal mapping)", "Vector"};
  Field<std::vector<Vec3>> bitangents{this, "bitangents", {}, "bitangent vectors (normal mapping)", "Vector"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "edges drawn", "Vector"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles drawn", "Vector"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads drawn", "Vector"};
  Field<std::vector<unsigned>> vert_pos_idx{this, "vertPosIdx", {}, "position index of each render vertex", "Vector"};
  Field<std::vector<unsigned>> vert_norm_idx{this, "vertNormIdx", {}, "normal index of each render vertex", "Vector"};
  Field<std::string> filename{this, "filename", "", "mesh file", "Visual"};
  Field<std::string> texturename{this, "texturename", "", "texture image file", "Visual"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied at load", "Transformation", "length"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "rotation applied at load (Euler angles, degrees)",
                       "Transformation", "degrees"};
  Field<Vec3> scale3d{this, "scale3d", Vec3::Ones(), "scale applied at load", "Transformation"};
  Field<Vec2> scale_tex{this, "scaleTex", Vec2(1, 1), "texture coordinate scale", "Visual"};
  Field<Vec2> translation_tex{this, "translationTex", Vec2(0, 0), "texture coordinate offset", "Visual"};
  Field<std::string> material{this, "material", "", "default material", "Visual"};
  Field<bool> put_only_tex_coords{this, "putOnlyTexCoords", false, "send texture coordinates without binding a texture",
                                  "Visual"};
  Field<bool> srgb_texturing{this, "srgbTexturing", false, "texture is in sRGB colour space", "Visual"};
  Field<std::string> materials{this, "materials", "", "materials of the model", "Visual"};
  Field<std::string> groups{this, "groups", "", "face groups, one per material", "Visual"};
  Link<MeshTopologyBase> topology{this, "topology", "topology used by this component (default: the node's)"};
  Field<bool> enable{this, "enable", true, "draw this model", "Visualization"};
  // OglModel (OpenGL options, viewer only).
  Field<bool> blend_translucency{this, "blendTranslucency", true, "blend translucent faces", "Visualization"};
  Field<bool> premultiplied_alpha{this, "premultipliedAlpha", false, "colours use premultiplied alpha",
                                  "Visualization"};
  Field<bool> write_z_transparent{this, "writeZTransparent", false, "write depth for translucent faces",
                                  "Visualization"};
  Field<bool> alpha_blend{this, "alphaBlend", false, "alpha blending", "Visualization"};
  Field<bool> depth_test{this, "depthTest", true, "depth test", "Visualization"};
  Field<int> cull_face{this, "cullFace", 0, "culling: 0 none, 1 back faces, 2 front faces", "Visualization"};
  Field<double> line_width{this, "lineWidth", 1.0, "line width in pixels", "Visualization"};
  Field<double> point_size{this, "pointSize", 1.0, "point size in pixels", "Visualization"};
  Field<bool> line_smooth{this, "lineSmooth", false, "antialiased lines", "Visualization"};
  Field<bool> point_smooth{this, "pointSmooth", false, "antialiased points", "Visualization"};
  Field<bool> is_enabled{this, "isEnabled", true, "enable this component", "Visualization"};
  Field<std::string> primitive_type{this, "primitiveType", "DEFAULT",
                                    "primitive type sent to the GPU (DEFAULT, LINES_ADJACENCY, PATCHES, POINTS)",
                                    "Visualization"};
  Field<std::string> blend_equation{this, "blendEquation", "GL_FUNC_ADD", "blend equation", "Visualization"};
  Field<std::string> source_factor{this, "sfactor", "GL_SRC_ALPHA", "source blend factor", "Visualization"};
  Field<std::string> dest_factor{this, "dfactor", "GL_ONE_MINUS_SRC_ALPHA", "destination blend factor",
                                 "Visualization"};

  // Axis-aligned box of the positions (min x y z, max x y z), computed at init and
  // after each step, as SOFA's computeBBox: VisualBoundingBox links to it.
  Field<std::vector<double>> bbox{this, "bbox", {}, "bounding box of the positions: min x y z, max x y z",
                                  "Visualization"};
  void update_bbox();

  // The alpha blending options as indices in SOFA's lists: blendEquation GL_FUNC_ADD,
  // GL_FUNC_SUBTRACT, GL_MIN, GL_MAX; sfactor and dfactor GL_ZERO, GL_ONE, GL_SRC_ALPHA,
  // GL_ONE_MINUS_SRC_ALPHA. A value outside its list keeps the default (warned at init).
  int blend_equation_index() const;
  int source_factor_index() const;
  int dest_factor_index() const;
  // primitiveType's index in SOFA's list DEFAULT, LINES_ADJACENCY, PATCHES, POINTS (another
  // value: DEFAULT, warned at init).
  int primitive_index() const;

  // Pseudo-attribute `color` (SOFA's setColor): kept as written.
  const std::string& color() const { return color_; }

  // VisualState
  std::size_t visual_size() const override { return position.value().data.size() / 3; }
  void visual_resize(std::size_t n) override;
  std::vector<double>* visual_vec(int id) override;

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  // Events: the box follows the positions after each step; and handleDynamicTopology (SOFA's updateVisual: the mesh is recomputed when the topology's
  // revision moved): after each step, a model whose elements come from a changing topology
  // takes its triangles and quads again.
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  void follow_topology();

 private:
  bool load_file();
  void from_topology();
  void take_elements(const MeshTopologyBase& t);
  std::string color_;
  bool flip_ = false;
  bool follows_topology_ = false;  // elements taken from a topology (handleDynamicTopology)
  std::uint64_t tri_version_ = 0, quad_version_ = 0;
};

}  // namespace sinew
