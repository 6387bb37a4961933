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
  Field<std::vector<Vec3>> normal{this, "normal", {}, "Normals of the model", "Vector"};
  Field<bool> init_rest_positions{this, "initRestPositions", false,
                                  "True if rest positions must be initialized with initial positions", "Visual"};
  Field<bool> use_normals{this, "useNormals", true, "True if normal smoothing groups should be read from file",
                          "Visual"};
  Field<bool> update_normals{this, "updateNormals", true, "True if normals should be updated at each iteration",
                             "Visual"};
  Field<bool> compute_tangents{this, "computeTangents", false, "True if tangents should be computed at startup",
                               "Visual"};
  Field<bool> update_tangents{this, "updateTangents", true, "True if tangents should be updated at each iteration",
                              "Visual"};
  Field<bool> compute_texture_coordinates{this, "computeTextureCoordinates", false,
                                          "True if texture coordinates should be computed at startup, using UV "
                                          "sphere projection",
                                          "Visual"};
  Field<bool> handle_dynamic_topology{this, "handleDynamicTopology", true,
                                      "True if topological changes should be handled", "Visual"};
  Field<bool> fix_merged_uv_seams{this, "fixMergedUVSeams", true,
                                  "True if UV seams should be handled even when duplicate UVs are merged", "Visual"};
  Field<bool> keep_lines{this, "keepLines", false, "keep and draw lines (false by default)", "Visual"};
  Field<std::vector<Vec3>> vertices{this, "vertices", {},
                                    "vertices of the model (only if vertices have multiple normals/texcoords, "
                                    "otherwise positions are used)",
                                    "Vector"};
  Field<std::vector<Vec2>> texcoords{this, "texcoords", {}, "coordinates of the texture", "Vector"};
  Field<std::vector<Vec3>> tangents{this, "tangents", {}, "tangents for normal mapping", "Vector"};
  Field<std::vector<Vec3>> bitangents{this, "bitangents", {}, "tangents for normal mapping", "Vector"};
  Field<std::vector<Edge>> edges{this, "edges", {}, "edges of the model", "Vector"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the model", "Vector"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the model", "Vector"};
  Field<std::vector<unsigned>> vert_pos_idx{this, "vertPosIdx", {},
                                            "If vertices have multiple normals/texcoords stores vertices position "
                                            "indices",
                                            "Vector"};
  Field<std::vector<unsigned>> vert_norm_idx{this, "vertNormIdx", {},
                                             "If vertices have multiple normals/texcoords stores vertices normal "
                                             "indices",
                                             "Vector"};
  Field<std::string> filename{this, "filename", "", " Path to an ogl model", "Visual"};
  Field<std::string> texturename{this, "texturename", "", "Full path of the texture file", "Visual"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "Initial Translation of the object", "Transformation"};
  Field<Vec3> rotation{this, "rotation", Vec3::Zero(), "Initial Rotation of the object", "Transformation"};
  Field<Vec3> scale3d{this, "scale3d", Vec3::Ones(), "Initial Scale of the object", "Transformation"};
  Field<Vec2> scale_tex{this, "scaleTex", Vec2(1, 1), "Scale of the texture", "Visual"};
  Field<Vec2> translation_tex{this, "translationTex", Vec2(0, 0), "Translation of the texture", "Visual"};
  Field<std::string> material{this, "material", "", "Material", "Visual"};
  Field<bool> put_only_tex_coords{this, "putOnlyTexCoords", false,
                                  "Give Texture Coordinates without the texture binding", "Visual"};
  Field<bool> srgb_texturing{this, "srgbTexturing", false,
                             "When sRGB rendering is enabled, is the texture in sRGB colorspace?", "Visual"};
  Field<std::string> materials{this, "materials", "", "List of materials", "Visual"};
  Field<std::string> groups{this, "groups", "", "Groups of triangles and quads using a given material", "Visual"};
  Link<MeshTopologyBase> topology{this, "topology", "link to the topology container"};
  Field<bool> enable{this, "enable", true, "Display the object or not", "Visualization"};
  // OglModel (OpenGL options, viewer only).
  Field<bool> blend_translucency{this, "blendTranslucency", true, "Blend transparent parts", "Visualization"};
  Field<bool> premultiplied_alpha{this, "premultipliedAlpha", false, "is alpha premultiplied ?", "Visualization"};
  Field<bool> write_z_transparent{this, "writeZTransparent", false, "Write into Z Buffer for Transparent Object",
                                  "Visualization"};
  Field<bool> alpha_blend{this, "alphaBlend", false, "Enable alpha blending", "Visualization"};
  Field<bool> depth_test{this, "depthTest", true, "Enable depth testing", "Visualization"};
  Field<int> cull_face{this, "cullFace", 0, "Face culling (0 = no culling, 1 = cull back faces, 2 = cull front faces)",
                       "Visualization"};
  Field<double> line_width{this, "lineWidth", 1.0, "Line width (set if != 1, only for lines rendering)",
                           "Visualization"};
  Field<double> point_size{this, "pointSize", 1.0, "Point size (set if != 1, only for points rendering)",
                           "Visualization"};
  Field<bool> line_smooth{this, "lineSmooth", false, "Enable smooth line rendering", "Visualization"};
  Field<bool> point_smooth{this, "pointSmooth", false, "Enable smooth point rendering", "Visualization"};
  Field<bool> is_enabled{this, "isEnabled", true, "Activate/deactive the component.", "Visualization"};
  Field<std::string> primitive_type{this, "primitiveType", "DEFAULT",
                                    "Select types of primitives to send (DEFAULT, LINES_ADJACENCY, PATCHES, POINTS)",
                                    "Visualization"};
  Field<std::string> blend_equation{this, "blendEquation", "GL_FUNC_ADD",
                                    "if alpha blending is enabled this specifies how source and destination colors "
                                    "are combined",
                                    "Visualization"};
  Field<std::string> source_factor{this, "sfactor", "GL_SRC_ALPHA",
                                   "if alpha blending is enabled, how the source blending factors are computed",
                                   "Visualization"};
  Field<std::string> dest_factor{this, "dfactor", "GL_ONE_MINUS_SRC_ALPHA",
                                 "if alpha blending is enabled, how the destination blending factors are computed",
                                 "Visualization"};

  // Pseudo-attribute `color` (SOFA's setColor): kept as written.
  const std::string& color() const { return color_; }

  // VisualState
  std::size_t visual_size() const override { return position.value().data.size() / 3; }
  void visual_resize(std::size_t n) override;
  std::vector<double>* visual_vec(int id) override;

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;

 private:
  bool load_file();
  void from_topology();
  std::string color_;
  bool flip_ = false;
};

}  // namespace sinew
