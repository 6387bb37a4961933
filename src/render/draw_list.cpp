#include "render/draw_list.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/node.h"
#include "math/quat.h"
#include "render/draw_collision.h"
#include "render/draw_shapes.h"
#include "render/draw_text.h"
#include "render/draw_visual.h"
#include "visual/background_setting.h"
#include "visual/clip_plane.h"
#include "visual/color.h"
#include "visual/drawing/ogl_scene_frame.h"
#include "visual/ogl_model.h"
#include "visual/rendering2d/ogl_viewport.h"
#include "visual/shader/ogl_shader.h"
#include "visual/shader/order_independent_transparency.h"
#include "visual/shader/post_process_manager.h"
#include "visual/visual_style.h"

namespace sinew::render {

// The ClipPlane applying to a node's models for each OpenGL plane id (nullptr: none).
using ClipSet = std::array<const ClipPlane*, Batch::kClipPlanes>;

// The next batch of the list, reused when the same component drew it last frame.
Batch& next_batch(DrawList& list, const Component* source, Batch::Kind kind) {
  if (list.used == list.batches.size()) list.batches.emplace_back();
  Batch& b = list.batches[list.used++];
  if (b.source != source || b.kind != kind) {
    b.positions.clear(), b.normals.clear(), b.colors.clear(), b.indices.clear(), b.texcoords.clear();
    b.texture.clear();
    b.shading_parsed = false;
    b.translucent = false;
  }
  b.source = source;
  b.kind = kind;
  b.color_ambient = 0.f;
  b.point_size = 1.f;
  b.line_width = 1.f;
  b.wireframe = false;
  b.lit = true;
  b.splat = Batch::Splat::none;
  b.primitive = Batch::Primitive::triangles;
  b.clip = Batch::no_clip();
  b.alpha_blend = false;
  b.depth_test = true;
  b.cull = 0;
  return b;
}

void include_point(DrawList& list, const Vec3& p) {
  if (!p.allFinite()) return;
  if (!list.has_bounds) {
    list.min = list.max = p;
    list.has_bounds = true;
  } else {
    list.min = list.min.cwiseMin(p);
    list.max = list.max.cwiseMax(p);
  }
}

void grow_bounds(DrawList& list, const std::vector<float>& x) {
  for (std::size_t i = 0; i + 2 < x.size(); i += 3) include_point(list, Vec3(x[i], x[i + 1], x[i + 2]));
}

// A node's `bbox` given as min then max (SOFA's Node::bboxIsFixed: set in the scene file).
bool fixed_box(const Node& node, Vec3& min, Vec3& max) {
  const std::vector<double>& b = node.bbox.get();
  if (b.size() != 6 || !(b[0] <= b[3] && b[1] <= b[4] && b[2] <= b[5])) return false;
  min = Vec3(b[0], b[1], b[2]), max = Vec3(b[3], b[4], b[5]);
  return min.allFinite() && max.allFinite();
}

// A state whose points are drawn only when nothing else is (see gather); `boxed`: under a node
// with a fixed bbox, so its points do not grow the scene's box.
struct Deferred {
  const MechanicalState* state = nullptr;
  bool boxed = false;
};

// Positions of a state as floats (the first three coordinates of each DoF).
bool state_positions(const MechanicalState& s, std::vector<float>& out) {
  const int w = s.info().coord_width, dim = std::min(3, s.info().spatial_dim);
  if (w <= 0 || dim <= 0) return false;
  const std::vector<double>& x = s.read(kPosition);
  const std::size_t n = s.size();
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) out[i * 3 + c] = c < dim ? static_cast<float>(x[i * w + c]) : 0.f;
  return true;
}

namespace {

// Vertices drawn by a visual model (VisualModelImpl::getVertices): its `vertices` when it has
// some, refreshed from the positions through vertPosIdx (computePositions), else its positions.
// A loader's handleSeams output already has one position per render vertex: drawn as is.
void model_vertices(const OglModel& m, std::vector<float>& out) {
  const std::vector<double>& x = m.position.get().data;
  const std::vector<Vec3>& v2 = m.vertices.get();
  if (v2.empty()) {
    out.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = static_cast<float>(x[i]);
    return;
  }
  const std::vector<unsigned>& idx = m.vert_pos_idx.get();
  out.resize(v2.size() * 3);
  for (std::size_t v = 0; v < v2.size(); ++v) {
    const bool mapped = v < idx.size() && idx[v] * 3 + 2 < x.size();
    for (int c = 0; c < 3; ++c) out[v * 3 + c] = static_cast<float>(mapped ? x[idx[v] * 3 + c] : v2[v][c]);
  }
}

// The nearest shader of a node or above, as SOFA's getShader: an OglShadowShader (shaded by
// render/shadow_maps.h) or an active OglShader, run as written (render/scene_shader.h).
// A passive or turned-off shader leaves its models to the fixed-function look, as in SOFA.
struct ShaderContext {
  bool shadow = false;
  const OglShader* scene = nullptr;
};

// The elements of `shader` (its node's OglShaderElements of the version in use) into the
// list's shaders, once per frame; its index there, or -1 when it cannot run here (no vertex
// or fragment file). The list's entries are reused from frame to frame (their strings and
// vectors keep their storage), so a stable scene allocates nothing here.
int scene_shader_index(DrawList& list, const OglShader& shader) {
  for (std::size_t i = 0; i < list.shaders_used; ++i)
    if (list.shaders[i].source == &shader) return list.shaders[i].vertex_file.empty() ? -1 : static_cast<int>(i);
  if (list.shaders_used == list.shaders.size()) list.shaders.emplace_back();
  SceneShader& s = list.shaders[list.shaders_used++];
  s.source = &shader;
  s.vertex_file = shader.file_of(shader.vertex);
  s.fragment_file = shader.file_of(shader.fragment);
  s.tess_control_file = shader.file_of(shader.tess_control);
  s.tess_eval_file = shader.file_of(shader.tess_eval);
  s.geometry_file = shader.file_of(shader.geometry);
  std::size_t defines = 0, uniforms = 0, textures = 0;
  if (s.vertex_file.empty() || s.fragment_file.empty()) {
    s.vertex_file.clear();
  } else {
    thread_local ShaderInput in;
    const unsigned version = shader.index_active_shader.get();
    auto slot = [](std::vector<SceneShader::Input>& v, std::size_t& n) -> SceneShader::Input& {
      if (n == v.size()) v.emplace_back();
      return v[n++];
    };
    for (const auto& o : shader.node()->objects()) {
      const auto* e = dynamic_cast<const ShaderElement*>(o.get());
      if (!e || e->index_shader.get() != version || e->state() == ComponentState::invalid) continue;
      e->input(in);
      const std::string& id = e->id.get();
      switch (in.kind) {
        case ShaderInput::Kind::macro:
          if (defines == s.defines.size()) s.defines.emplace_back();
          s.defines[defines].first = id;
          s.defines[defines++].second = in.text;
          break;
        case ShaderInput::Kind::int_uniform:
        case ShaderInput::Kind::float_uniform:
        case ShaderInput::Kind::matrix_uniform: {
          SceneShader::Input& u = slot(s.uniforms, uniforms);
          u.name = id;
          u.value = in;  // copy-assignment: the slot's storage is reused
          break;
        }
        case ShaderInput::Kind::texture: {
          SceneShader::Input& t = slot(s.textures, textures);
          t.name = id;
          t.value = in;
          break;
        }
        default: break;
      }
    }
  }
  s.defines.resize(defines);
  s.uniforms.resize(uniforms);
  s.textures.resize(textures);
  return s.vertex_file.empty() ? -1 : static_cast<int>(list.shaders_used - 1);
}

// The per-vertex attributes of `shader` for a model of `n` vertices in `node`: those of the
// shader's node and of the model's, with one item per vertex (others would be read past
// their end). The batch's attribute slots keep their storage.
void add_attributes(Batch& b, const OglShader& shader, const Node& node, std::size_t n) {
  thread_local ShaderInput in;
  std::size_t used = 0;
  const unsigned version = shader.index_active_shader.get();
  const Node* nodes[2] = {shader.node(), &node};
  for (int k = 0; k < (nodes[0] == nodes[1] ? 1 : 2); ++k)
    for (const auto& o : nodes[k]->objects()) {
      const auto* e = dynamic_cast<const ShaderElement*>(o.get());
      if (!e || e->index_shader.get() != version || e->state() == ComponentState::invalid) continue;
      e->input(in);
      if (in.kind != ShaderInput::Kind::attribute || in.values.size() != n * static_cast<std::size_t>(in.width))
        continue;
      if (used == b.attributes.size()) b.attributes.emplace_back();
      Batch::Attribute& a = b.attributes[used++];
      a.name = e->id.get();
      a.width = in.width;
      a.values = in.values;
    }
  b.attributes.resize(used);
}

void add_visual_model(DrawList& list, const OglModel& m, bool wireframe, const ClipSet& clip,
                      const ShaderContext& shader) {
  if (!m.enable.get() || !m.is_enabled.get() || m.state() != ComponentState::valid) return;
  const auto& tris = m.triangles.get();
  const auto& quads = m.quads.get();
  if (tris.empty() && quads.empty()) return;
  Batch& b = next_batch(list, &m, Batch::Kind::triangles);
  b.wireframe = wireframe;
  b.line_width = static_cast<float>(m.line_width.get());  // SOFA's glLineWidth(lineWidth) around the draw
  b.shadow_shader = shader.shadow;
  b.shader = -1;
  for (int k = 0; k < Batch::kClipPlanes; ++k)
    if (const ClipPlane* c = clip[static_cast<std::size_t>(k)]) {
      // kept: (p - position)·normal <= 0, i.e. -normal·p + normal·position >= 0
      const Vec3 n = c->normal.get(), at = c->position.get();
      b.clip[static_cast<std::size_t>(k)] = {static_cast<float>(-n[0]), static_cast<float>(-n[1]),
                                             static_cast<float>(-n[2]), static_cast<float>(n.dot(at))};
    }
  model_vertices(m, b.positions);
  const std::size_t n = b.vertex_count();
  const auto& given = m.normal.get();
  if (!m.update_normals.get() && given.size() == n) {
    b.normals.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) b.normals[i * 3 + c] = static_cast<float>(given[i][c]);
  } else {
    const auto& norm_idx = m.vert_norm_idx.get();
    compute_normals(b.positions, tris, quads, b.normals, norm_idx.size() == n ? &norm_idx : nullptr);
  }
  b.colors.clear();
  // The texture, when every render vertex has its coordinates (without them SOFA would sample
  // one texel); a file that cannot be read is drawn untextured by the renderer.
  const auto& uv = m.texcoords.get();
  const std::string& tex = m.texturename.get();
  if (!tex.empty() && uv.size() == n) {
    b.texcoords.resize(n * 2);
    for (std::size_t i = 0; i < n; ++i)
      b.texcoords[i * 2] = static_cast<float>(uv[i][0]), b.texcoords[i * 2 + 1] = static_cast<float>(uv[i][1]);
    if (b.texture != tex) b.texture = tex;
  } else {
    b.texcoords.clear();
    b.texture.clear();
  }
  b.indices.resize(tris.size() * 3 + quads.size() * 6);
  std::size_t k = 0;
  bool bad = false;
  for (const Triangle& t : tris) {
    for (unsigned v : t) bad |= v >= n;
    b.indices[k++] = t[0], b.indices[k++] = t[1], b.indices[k++] = t[2];
  }
  for (const Quad& q : quads) {
    for (unsigned v : q) bad |= v >= n;
    b.indices[k++] = q[0], b.indices[k++] = q[1], b.indices[k++] = q[2];
    b.indices[k++] = q[0], b.indices[k++] = q[2], b.indices[k++] = q[3];
  }
  if (bad) {  // an element naming a missing vertex: nothing sensible to draw
    --list.used;
    return;
  }
  b.triangle_count = tris.size();
  b.primitive = static_cast<Batch::Primitive>(m.primitive_index());
  b.quad_indices.clear();
  if (b.primitive == Batch::Primitive::patches || b.primitive == Batch::Primitive::lines_adjacency)
    for (const Quad& q : quads) b.quad_indices.insert(b.quad_indices.end(), q.begin(), q.end());
  if (b.primitive == Batch::Primitive::points) b.point_size = static_cast<float>(m.point_size.get());
  // The material is parsed again only when its text changed (parsing allocates).
  if (!b.shading_parsed || b.material_text != m.material.get() || b.color_text != m.color()) {
    const Material mat = material_of(m);
    b.shading = shading_of(mat);
    // SOFA's OglModel::drawGroup: a group is transparent when its diffuse term is used with
    // an alpha below 1 (the alpha of the lit colour is the diffuse alpha).
    b.translucent = mat.use_diffuse && mat.diffuse[3] < 1.f;
    b.material_text = m.material.get();
    b.color_text = m.color();
    b.shading_parsed = true;
  }
  b.blend = m.blend_translucency.get();
  b.write_depth = m.write_z_transparent.get();
  b.premultiplied = m.premultiplied_alpha.get();
  b.alpha_blend = m.alpha_blend.get();
  b.blend_equation = m.blend_equation_index();
  b.source_factor = m.source_factor_index();
  b.dest_factor = m.dest_factor_index();
  b.depth_test = m.depth_test.get();
  b.cull = m.cull_face.get();
  if (shader.scene) {
    b.shader = scene_shader_index(list, *shader.scene);
    if (b.shader >= 0) add_attributes(b, *shader.scene, *m.node(), n);
  }
  grow_bounds(list, b.positions);
}


using V3f = Eigen::Vector3f;

void push_triangle(Batch& b, std::size_t& k, const V3f& a, const V3f& c1, const V3f& c2, const float* rgba) {
  V3f nrm = (c1 - a).cross(c2 - a);
  const float len = nrm.norm();
  if (len > 0) nrm /= len;
  for (const V3f* p : {&a, &c1, &c2}) {
    for (int c = 0; c < 3; ++c) b.positions[k * 3 + c] = (*p)[c], b.normals[k * 3 + c] = nrm[c];
    for (int c = 0; c < 4; ++c) b.colors[k * 4 + c] = rgba[c];
    ++k;
  }
}

// TetrahedronFEMForceField::draw: each tetrahedron shrunk to 2/3 around its centre, its four
// faces in four blues. HexahedronFEMForceField::draw: each hexahedron shrunk, six face colours.
void add_force_field_mesh(DrawList& list, const Component& ff, const MeshTopologyBase& topo,
                          const std::vector<float>& x, bool wireframe) {
  static const float kTetra[4][4] = {{0, 0, 1, 1}, {0, 0.5f, 1, 1}, {0, 1, 1, 1}, {0.5f, 1, 1, 1}};
  static const float kHexa[6][4] = {{0.7f, 0.7f, 0.1f, 1}, {0.7f, 0, 0, 1},    {0, 0.7f, 0, 1},
                                    {0, 0, 0.7f, 1},       {0.1f, 0.7f, 0.7f, 1}, {0.7f, 0.1f, 0.7f, 1}};
  // Faces of SOFA's hexahedron numbering, as quads.
  static const int kHexaFaces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {1, 0, 4, 5},
                                       {1, 5, 6, 2}, {2, 6, 7, 3}, {0, 3, 7, 4}};
  const auto& tets = topo.tetrahedra();
  const auto& hexas = topo.hexahedra();
  const std::size_t n = x.size() / 3;
  Batch& b = next_batch(list, &ff, Batch::Kind::triangles);
  b.wireframe = wireframe;
  const std::size_t verts = tets.size() * 12 + hexas.size() * 36;
  b.positions.resize(verts * 3);
  b.normals.resize(verts * 3);
  b.colors.resize(verts * 4);
  b.indices.clear();
  auto p = [&](unsigned i) { return V3f(x[i * 3], x[i * 3 + 1], x[i * 3 + 2]); };
  std::size_t k = 0;
  for (const Tetra& t : tets) {
    if (t[0] >= n || t[1] >= n || t[2] >= n || t[3] >= n) continue;
    const V3f a = p(t[0]), bb = p(t[1]), c = p(t[2]), d = p(t[3]);
    const V3f centre = (a + bb + c + d) * 0.125f;
    const V3f pa = (a + centre) * 0.666667f, pb = (bb + centre) * 0.666667f, pc = (c + centre) * 0.666667f,
              pd = (d + centre) * 0.666667f;
    push_triangle(b, k, pa, pb, pc, kTetra[0]);
    push_triangle(b, k, pb, pc, pd, kTetra[1]);
    push_triangle(b, k, pc, pd, pa, kTetra[2]);
    push_triangle(b, k, pd, pa, pb, kTetra[3]);
  }
  for (const Hexa& h : hexas) {
    bool ok = true;
    for (unsigned v : h) ok &= v < n;
    if (!ok) continue;
    V3f centre = V3f::Zero();
    for (unsigned v : h) centre += p(v);
    centre *= 0.125f;
    V3f q[8];
    for (int i = 0; i < 8; ++i) q[i] = centre + (p(h[i]) - centre) * 0.85f;  // shrink 0.15 as SOFA's default
    for (int f = 0; f < 6; ++f) {
      const int* fv = kHexaFaces[f];
      push_triangle(b, k, q[fv[0]], q[fv[1]], q[fv[2]], kHexa[f]);
      push_triangle(b, k, q[fv[0]], q[fv[2]], q[fv[3]], kHexa[f]);
    }
  }
  b.positions.resize(k * 3), b.normals.resize(k * 3), b.colors.resize(k * 4);
  b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.color_ambient = 0.2f;
  if (k == 0) {
    --list.used;
    return;
  }
  grow_bounds(list, b.positions);
}

void add_points(DrawList& list, const MechanicalState& state) {
  Batch& b = next_batch(list, &state, Batch::Kind::points);
  if (!state_positions(state, b.positions) || b.positions.empty()) {
    --list.used;
    return;
  }
  b.normals.clear(), b.indices.clear(), b.colors.clear();
  b.shading = Shading{{0, 0, 0, 0}, {0.9f, 0.9f, 0.9f, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.point_size = 4.f;
  grow_bounds(list, b.positions);
}

// SOFA's visual traversal (tree order without repetition): a node is drawn
// once, reached through the first of its parents visited, with that parent's
// display flags. `seen` lists the nodes with several parents already drawn.
void visit(Node& node, const DisplayFlags& inherited, const ClipSet& inherited_clip, ShaderContext shader,
           DrawList& list, std::vector<float>& scratch, std::vector<Deferred>& deferred,
           std::vector<const Node*>& seen) {
  if (!node.activated.value()) return;
  if (node.parents().size() > 1) {
    if (std::find(seen.begin(), seen.end(), &node) != seen.end()) return;
    seen.push_back(&node);
  }
  Vec3 box_min, box_max;
  const bool boxed = !node.parents().empty() && fixed_box(node, box_min, box_max);
  struct {
    bool has_bounds;
    Vec3 min, max;
  } saved{list.has_bounds, list.min, list.max};
  const std::size_t deferred_before = deferred.size();
  DisplayFlags flags = inherited;
  for (const auto& o : node.objects())
    if (const auto* s = dynamic_cast<const VisualStyle*>(o.get())) flags = flags.merged(s->flags());
  // SOFA's ClipPlane::fwdDraw sets OpenGL plane `id` before its node's models are drawn
  // (an inactive one switches that plane off) and bwdDraw restores it after the subtree:
  // per id, the node's last plane, else the one inherited. Planes of different ids combine.
  ClipSet clip = inherited_clip;
  for (const auto& o : node.objects())
    if (const auto* c = dynamic_cast<const ClipPlane*>(o.get())) {
      if (c->state() != ComponentState::valid) continue;
      const int id = c->id.get();
      if (id >= 0 && id < Batch::kClipPlanes) clip[static_cast<std::size_t>(id)] = c->active.get() ? c : nullptr;
    }
  // SOFA draws a node's models with the nearest shader of the node or above (getShader()).
  for (const auto& o : node.objects())
    if (const auto* sh = dynamic_cast<const OglShader*>(o.get()); sh && sh->state() == ComponentState::valid) {
      if (o->class_name() == "OglShadowShader") shader = {true, nullptr};
      else if (sh->turn_on.get() && !sh->passive.get()) shader = {false, sh};
      else shader = {};
    }

  if (flags.shown(DisplayFlags::visual_models))
    for (const auto& o : node.objects())
      if (const auto* m = dynamic_cast<const OglModel*>(o.get()))
        add_visual_model(list, *m, flags.shown(DisplayFlags::wireframe), clip, shader);
  if (flags.shown(DisplayFlags::visual_models)) add_visual_extras(list, node);
  add_texts(list, node, flags.shown(DisplayFlags::visual_models));
  add_camera_paths(list, node);
  for (const auto& o : node.objects())
    if (const auto* v = dynamic_cast<const OglViewport*>(o.get())) {
      if (v->state() != ComponentState::valid) continue;
      if (v->draw_camera.get()) {
        // OglViewport::draw: its camera as a frame of size 0.1 (drawn whatever the display
        // flags and `enabled`, so in the views too), the orientation taken as a frame's.
        Vec3 p;
        VecN<4> q;
        v->camera(p, q);
        Batch& b = fresh_batch(list, v, Batch::Kind::triangles);
        b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
        b.color_ambient = 0.2f;
        b.shading_parsed = false;
        append_frame(b, p, quat_to_matrix(quat_normalized(Quat::from(q.data()))), 0.1);
        close_batch(list, b);
      }
      // OglViewport::isVisible; with advancedRendering, only under that display flag.
      if (!v->enabled.get()) continue;
      if (v->advanced_rendering.get() && !flags.shown(DisplayFlags::advanced_rendering)) continue;
      const VecNi<2>& at = v->screen_position.get();
      const VecNi<2>& size = v->screen_size.get();
      if (size[0] <= 0 || size[1] <= 0) continue;
      ExtraViewport e;
      e.x = at[0], e.y = at[1], e.width = size[0], e.height = size[1];
      v->camera(e.position, e.orientation);
      e.z_near = v->z_near.get(), e.z_far = v->z_far.get(), e.fovy = v->fovy.get();
      e.swap = v->swap_main_view.get();
      list.viewports.push_back(e);
    }

  if (flags.shown(DisplayFlags::collision_models) || flags.shown(DisplayFlags::bounding_collision_models))
    add_collision_models(list, node, flags);
  if (flags.shown(DisplayFlags::force_fields) || flags.shown(DisplayFlags::interaction_force_fields))
    add_springs(list, node, flags);
  if (flags.shown(DisplayFlags::mappings)) add_mappings(list, node);
  add_constraints(list, node, flags);
  add_rois(list, node, flags.shown(DisplayFlags::behavior_models), flags.shown(DisplayFlags::wireframe));

  MechanicalState* state = node.mechanical_state;
  if (state && state->state() == ComponentState::valid) {
    if (flags.shown(DisplayFlags::force_fields)) {
      const MeshTopologyBase* topo = node.get_mesh_topology_link();
      for (ForceField* ff : node.force_fields) {
        if (!topo || ff->is_interaction() || dynamic_cast<Mass*>(ff) || ff->state() != ComponentState::valid) continue;
        if (topo->tetrahedra().empty() && topo->hexahedra().empty()) continue;
        if (ff->single_state() != state || !state_positions(*state, scratch)) continue;
        add_force_field_mesh(list, *ff, *topo, scratch, flags.shown(DisplayFlags::wireframe));
        break;  // one drawing of the mesh per node
      }
    }
    // Bodies' points: SOFA's MechanicalObject draws them with showObject; the others are kept
    // for the end, drawn only when nothing else is (the picture of a scene without a visual model).
    if (flags.shown(DisplayFlags::behavior_models) && !node.mechanical_mapping) {
      const auto* show = dynamic_cast<const Field<bool>*>(state->find_field("showObject"));
      if (show && show->get()) add_points(list, *state);
      else deferred.push_back({state, false});
    }
  }
  for (Node* child : node.children()) visit(*child, flags, clip, shader, list, scratch, deferred, seen);
  if (boxed) {
    // SOFA's UpdateBoundingBoxVisitor: a node whose bbox is fixed gives its parent that box, not
    // what its subtree holds (the root's own is applied where the view is framed).
    list.has_bounds = saved.has_bounds, list.min = saved.min, list.max = saved.max;
    include_point(list, box_min);
    include_point(list, box_max);
    for (std::size_t i = deferred_before; i < deferred.size(); ++i) deferred[i].boxed = true;
  }
}

}  // namespace

void compute_normals(const std::vector<float>& xs, const std::vector<Triangle>& triangles,
                     const std::vector<Quad>& quads, std::vector<float>& ns, const std::vector<unsigned>* norm_idx) {
  const std::size_t n = xs.size() / 3;
  ns.assign(n * 3, 0.f);
  // With vertNormIdx (OBJ seams), the render vertices that share a normal index share the
  // normal: faces are summed per normal index, then each vertex takes its index's normal.
  std::size_t groups = n;
  if (norm_idx && !norm_idx->empty()) {
    groups = 0;
    for (unsigned g : *norm_idx) groups = std::max<std::size_t>(groups, g + 1);
  } else {
    norm_idx = nullptr;
  }
  auto group = [&](unsigned v) { return norm_idx ? (*norm_idx)[v] : v; };
  // Accumulated in double, as SOFA's Coord (Vec3d); stored as floats for the GPU.
  const auto* x = reinterpret_cast<const float(*)[3]>(xs.data());
  auto X = [&](unsigned i) { return Vec3(x[i][0], x[i][1], x[i][2]); };
  thread_local std::vector<Vec3> acc;
  acc.assign(groups, Vec3::Zero());
  for (const Triangle& t : triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
    const Vec3 v1 = X(t[0]), v2 = X(t[1]), v3 = X(t[2]);
    const Vec3 nrm = (v2 - v1).cross(v3 - v1);
    acc[group(t[0])] += nrm, acc[group(t[1])] += nrm, acc[group(t[2])] += nrm;
  }
  for (const Quad& q : quads) {
    if (q[0] >= n || q[1] >= n || q[2] >= n || q[3] >= n) continue;
    const Vec3 v1 = X(q[0]), v2 = X(q[1]), v3 = X(q[2]), v4 = X(q[3]);
    acc[group(q[0])] += (v2 - v1).cross(v4 - v1);
    acc[group(q[1])] += (v3 - v2).cross(v1 - v2);
    acc[group(q[2])] += (v4 - v3).cross(v2 - v3);
    acc[group(q[3])] += (v1 - v4).cross(v3 - v4);
  }
  for (Vec3& a : acc) {
    const double len = a.norm();
    if (len > 1e-300) a /= len;  // SOFA's normalize leaves a zero vector unchanged
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& u = acc[group(static_cast<unsigned>(i))];
    for (int c = 0; c < 3; ++c) ns[i * 3 + c] = static_cast<float>(u[c]);
  }
}

void gather(Node& root, DrawList& out) {
  out.used = 0;
  out.texts_used = 0;
  out.overlay_rects.clear();
  out.viewports.clear();
  out.shaders_used = 0;
  out.has_bounds = false;
  thread_local std::vector<float> scratch;
  thread_local std::vector<Deferred> deferred;
  thread_local std::vector<const Node*> seen;
  deferred.clear();
  seen.clear();
  visit(root, DisplayFlags::viewer_defaults(), ClipSet{}, ShaderContext{}, out, scratch, deferred, seen);
  out.frame.on = false;
  if (const OglSceneFrame* f = root.find_down<OglSceneFrame>(); f && f->draw.get() && f->state() == ComponentState::valid) {
    static const char* const kStyles[] = {"Arrows", "Cylinders", "CubeCones"};
    static const char* const kCorners[] = {"BottomLeft", "BottomRight", "TopRight", "TopLeft"};
    out.frame.on = true;
    for (int i = 0; i < 3; ++i)
      if (f->style.get() == kStyles[i]) out.frame.style = i;
    for (int i = 0; i < 4; ++i)
      if (f->alignment.get() == kCorners[i]) out.frame.corner = i;
    out.frame.size = f->viewport_size.get();
  }
  // SOFA's visual loop asks the root node's visual managers only.
  const auto* oit = root.find_local<OrderIndependentTransparencyManager>();
  out.oit.on = oit && oit->state() == ComponentState::valid;
  out.oit.depth_scale = oit ? static_cast<float>(oit->depth_scale.get()) : 0.01f;
  out.background_image.clear();
  if (const auto* bg = root.find_down<BackgroundSetting>(); bg && bg->image_found())
    out.background_image = bg->image.get();
  const auto* post = root.find_local<PostProcessManager>();
  out.post = PostProcess{};
  if (post && post->state() == ComponentState::valid && post->shader() &&
      post->shader()->state() == ComponentState::valid && post->shader()->turn_on.get()) {
    out.post.shader = scene_shader_index(out, *post->shader());
    out.post.on = out.post.shader >= 0;
    out.post.z_near = static_cast<float>(post->z_near.get());
    out.post.z_far = static_cast<float>(post->z_far.get());
  }
  Lighting& l = out.lighting;
  l.lights.clear();
  const LightManager* lm = root.find_down<LightManager>();
  l.from_scene = lm && lm->state() == ComponentState::valid;
  l.shadows = l.from_scene && lm->shadows.get();
  l.soft_shadows = l.shadows && lm->soft_shadows.get();
  if (l.from_scene) {
    l.ambient = parse_rgba(lm->ambient.get()).value_or(Rgba{0, 0, 0, 0});
    for (const Light* light : lm->lights())
      if (light->state() == ComponentState::valid) {
        l.lights.push_back(light->source());
        l.lights.back().shadows = l.shadows;  // SOFA's Light::init links them to the manager's
        l.lights.back().soft = l.soft_shadows;
      }
  }
  bool surfaces = false;
  for (std::size_t i = 0; i < out.used; ++i) surfaces |= out.batches[i].kind == Batch::Kind::triangles;
  if (!surfaces)
    for (const Deferred& d : deferred) {
      const bool had = out.has_bounds;
      const Vec3 min = out.min, max = out.max;
      add_points(out, *d.state);
      if (d.boxed) out.has_bounds = had, out.min = min, out.max = max;
    }
  // The root's display flags (lights live at the root in SOFA's scenes).
  DisplayFlags root_flags = DisplayFlags::viewer_defaults();
  for (const auto& o : root.objects())
    if (const auto* st = dynamic_cast<const VisualStyle*>(o.get())) root_flags = root_flags.merged(st->flags());
  add_light_sources(out, root, root_flags.shown(DisplayFlags::visual_models));
}

}  // namespace sinew::render
