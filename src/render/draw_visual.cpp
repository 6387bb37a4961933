// VisualBoundingBox as SOFA draws it: the twelve edges of the box, in its
// colour, unlit; DataDisplay's coloured mesh; VisualPointCloud's points, spheres or frames;
// CylinderVisualModel's cylinders. Lines are `thickness` pixels wide.
#include "render/draw_visual.h"

#include "core/node.h"
#include "math/quat.h"
#include "render/draw_collision.h"
#include "render/draw_list.h"
#include "render/draw_shapes.h"
#include "visual/color.h"
#include "visual/color_map.h"
#include "visual/drawing/cylinder_visual_model.h"
#include "visual/drawing/data_display.h"
#include "visual/drawing/line_axis.h"
#include "visual/drawing/ogl_fluid_model.h"
#include "visual/drawing/point_splat_model.h"
#include "visual/drawing/trail_renderer.h"
#include "visual/drawing/visual_bounding_box.h"
#include "visual/drawing/visual_grid.h"
#include "visual/drawing/visual_mesh.h"
#include "visual/drawing/visual_point_cloud.h"
#include "visual/recorded_camera.h"
#include "visual/shader/light.h"

namespace sinew::render {

namespace {

void add_box(DrawList& list, const VisualBoundingBox& vb) {
  if (!vb.enable.get() || vb.state() != ComponentState::valid) return;
  const auto box = vb.box();
  if (!box) return;
  Batch& b = fresh_batch(list, &vb, Batch::Kind::lines);
  b.line_width = static_cast<float>(vb.thickness.get());
  // The colour text is parsed again only when it changed (parsing allocates).
  if (!b.shading_parsed || b.material_text != vb.color.get()) {
    const Rgba c = parse_rgba(vb.color.get()).value_or(Rgba{1, 1, 0, 1});
    b.shading.diffuse = c;
    b.material_text = vb.color.get();
    b.shading_parsed = true;
  }
  append_box_edges(b, box->first, box->second);
  close_batch(list, b);
}

void push_color(Batch& b, const Rgba& c) {
  for (float v : c) b.colors.push_back(v);
}

// DataDisplay::drawVisual: the range first (it updates currentMin/currentMax), then the mesh
// coloured per point (indexed, smooth), per face or per face corner (each face with its own
// vertices), or coloured points when there is no mesh. Differences with SOFA's fixed-function
// drawing: faces coloured by cell data are lit like the rest (SOFA draws them unlit), and the
// transparency is not blended (the renderer draws opaque surfaces).
void add_data_display(DrawList& list, DataDisplay& dd) {
  if (!dd.enable.get() || dd.state() != ComponentState::valid) return;
  const DataDisplay::Range r = dd.update_range();
  if (!r.point_data && !r.cell_data) return;
  const std::vector<double>& x = dd.position.get().data;
  const std::size_t n = x.size() / 3;
  const MeshTopologyBase* topo = dd.mesh();
  auto color = [&](double v) { return dd.color_of(v, r.min, r.max); };
  if (r.point_data && (r.cell_data || !topo)) {
    Batch& b = fresh_batch(list, &dd, Batch::Kind::points);
    const auto& pt = dd.point_data.get();
    for (std::size_t i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(x[i * 3 + c]));
      push_color(b, color(pt[i]));
    }
    b.point_size = 10.f;
    close_batch(list, b);
    return;
  }
  const auto& tris = topo->triangles();
  const auto& quads = topo->quads();
  for (const Triangle& t : tris)
    for (unsigned v : t)
      if (v >= n) return;  // the mesh names points the state does not have: nothing sensible to draw
  for (const Quad& q : quads)
    for (unsigned v : q)
      if (v >= n) return;
  Batch& b = fresh_batch(list, &dd, Batch::Kind::triangles);
  thread_local std::vector<float> xf, nf;
  xf.resize(n * 3);
  for (std::size_t i = 0; i < n * 3; ++i) xf[i] = static_cast<float>(x[i]);
  compute_normals(xf, tris, quads, nf);
  b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  if (r.point_data) {  // shared vertices, one colour each
    b.positions = xf;
    b.normals = nf;
    const auto& pt = dd.point_data.get();
    for (std::size_t i = 0; i < n; ++i) push_color(b, color(pt[i]));
    for (const Triangle& t : tris) b.indices.insert(b.indices.end(), t.begin(), t.end());
    for (const Quad& q : quads)
      for (int k : {0, 1, 2, 0, 2, 3}) b.indices.push_back(q[k]);
    close_batch(list, b);
    return;
  }
  // Cell data: each face gets its own vertices (triangles then quads, as SOFA draws them).
  const auto& tri = dd.triangle_data.get();
  const auto& ptri = dd.point_triangle_data.get();
  const auto& quad = dd.quad_data.get();
  const auto& pquad = dd.point_quad_data.get();
  auto vertex = [&](unsigned v, const Rgba& c) {
    for (int k = 0; k < 3; ++k) b.positions.push_back(xf[v * 3 + k]), b.normals.push_back(nf[v * 3 + k]);
    push_color(b, c);
  };
  if (!tri.empty() || !ptri.empty())
    for (std::size_t i = 0; i < tris.size(); ++i)
      for (int k = 0; k < 3; ++k) vertex(tris[i][k], color(!tri.empty() ? tri[i] : ptri[i * 3 + k]));
  if (!quad.empty() || !pquad.empty())
    for (std::size_t i = 0; i < quads.size(); ++i)
      for (int k : {0, 1, 2, 0, 2, 3}) vertex(quads[i][k], color(!quad.empty() ? quad[i] : pquad[i * 4 + k]));
  close_batch(list, b);
}

// The batch's colour from a colour field's text, parsed again only when the text changed.
void set_color(Batch& b, const std::string& text, bool lit) {
  if (b.shading_parsed && b.material_text == text) return;
  const Rgba c = parse_rgba(text).value_or(Rgba{1, 1, 1, 1});
  b.shading = Shading{lit ? Rgba{0.2f * c[0], 0.2f * c[1], 0.2f * c[2], 1} : Rgba{0, 0, 0, 0}, c, {0, 0, 0, 0},
                      {0, 0, 0, 0}, 1.f};
  b.material_text = text;
  b.shading_parsed = true;
}

// VisualPointCloud::doDrawVisual: unlit points of `pointSize` pixels; lit spheres whose radii
// are sphereRadius, padded with its last value (1 when empty); or, for rigid frames, SOFA's
// coordinate frame of size pointSize at each (the colour does not apply to frames, as in SOFA).
// `showIndices`: render/draw_text.h.
void add_point_cloud(DrawList& list, const VisualPointCloud& pc) {
  if (!pc.enable.get() || pc.state() != ComponentState::valid) return;
  const FlatVec& x = pc.position.get();
  const int w = x.width;
  const std::size_t n = x.size();
  if (n == 0 || w <= 0) return;
  auto centre = [&](std::size_t i) { return pc.centre(i); };
  const std::string& mode = pc.draw_mode.get();
  if (mode == "Point") {
    Batch& b = fresh_batch(list, &pc, Batch::Kind::points);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 c = centre(i);
      for (int k = 0; k < 3; ++k) b.positions.push_back(static_cast<float>(c[k]));
    }
    set_color(b, pc.color.get(), false);
    b.point_size = static_cast<float>(pc.point_size.get());
    close_batch(list, b);
  } else if (mode == "Sphere") {
    Batch& b = fresh_batch(list, &pc, Batch::Kind::triangles);
    const std::vector<double>& radii = pc.sphere_radius.get();
    const double pad = radii.empty() ? 1.0 : radii.back();
    for (std::size_t i = 0; i < n; ++i) append_sphere(b, centre(i), i < radii.size() ? radii[i] : pad);
    set_color(b, pc.color.get(), true);
    close_batch(list, b);
  } else if (mode == "Frame" && pc.rigid()) {
    Batch& b = fresh_batch(list, &pc, Batch::Kind::triangles);
    b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    b.color_ambient = 0.2f;
    b.shading_parsed = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double* p = &x.data[i * w];
      Mat3 axes = Mat3::Identity();
      if (w == 7) {
        axes = quat_to_matrix(quat_normalized(Quat::from(p + 3)));
      } else {  // Rigid2d: a rotation by θ about z
        axes << std::cos(p[2]), -std::sin(p[2]), 0, std::sin(p[2]), std::cos(p[2]), 0, 0, 0, 1;
      }
      append_frame(b, centre(i), axes, pc.point_size.get());
    }
    close_batch(list, b);
  }
}

// CylinderVisualModel::doDrawVisual: a lit cylinder of `radius` along each edge.
void add_cylinders(DrawList& list, const CylinderVisualModel& cm) {
  if (!cm.enable.get() || cm.state() != ComponentState::valid) return;
  const std::vector<double>& x = cm.position.get().data;
  const std::size_t n = x.size() / 3;
  Batch& b = fresh_batch(list, &cm, Batch::Kind::triangles);
  for (const Edge& e : cm.edges.get()) {
    if (e[0] >= n || e[1] >= n) continue;
    const Vec3 a(x[e[0] * 3], x[e[0] * 3 + 1], x[e[0] * 3 + 2]), c(x[e[1] * 3], x[e[1] * 3 + 1], x[e[1] * 3 + 2]);
    append_cone(b, a, c, cm.radius.get(), cm.radius.get());
  }
  set_color(b, cm.color.get(), true);
  close_batch(list, b);
}

// PointSplatModel::drawTransparent: each point of the node's state (or of its topology's node)
// a camera-facing disc of `radius` whose opacity falls as alpha·cos(π/2·r/radius), in
// color × (0.5 + 2·pointData/255) when pointData is given, blended back to front after the
// opaque models. (SOFA samples a textureSize² texture of that falloff; here it is evaluated
// per pixel.)
void add_point_splats(DrawList& list, const PointSplatModel& ps, Node& node) {
  if (!ps.enable.get() || ps.state() != ComponentState::valid) return;
  const MeshTopologyBase* topo = node.get_mesh_topology_link();
  const MechanicalState* state =
      topo && topo->node() ? topo->node()->get_mechanical_state() : node.get_mechanical_state();
  if (!state || state->state() != ComponentState::valid) return;
  const int w = state->info().coord_width, dim = std::min(3, state->info().spatial_dim);
  if (w <= 0 || dim <= 0) return;
  const std::vector<double>& x = state->read(kPosition);
  const std::size_t n = state->size();
  Batch& b = fresh_batch(list, &ps, Batch::Kind::points);
  set_color(b, ps.color.get(), false);
  const Rgba c = b.shading.diffuse;
  const std::vector<unsigned>& data = ps.point_data.get();
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) b.positions.push_back(k < dim ? static_cast<float>(x[i * w + k]) : 0.f);
    const float m = data.empty() ? 1.f : 0.5f + 2.f * static_cast<float>(i < data.size() ? data[i] : 0) / 255.f;
    b.colors.insert(b.colors.end(), {m * c[0], m * c[1], m * c[2], c[3]});
  }
  b.splat = Batch::Splat::soft;
  b.splat_radius = static_cast<float>(ps.radius.get());
  b.splat_alpha = static_cast<float>(ps.alpha.get());
  b.translucent = true;
  close_batch(list, b);
}

// OglFluidModel: its particles and the Data of its screen-space surface (render/fluid_surface.h).
void add_fluid(DrawList& list, const OglFluidModel& fm) {
  if (!fm.enable.get() || fm.state() != ComponentState::valid) return;
  const std::vector<Vec3>& x = fm.position.get();
  if (x.empty()) return;
  Batch& b = fresh_batch(list, &fm, Batch::Kind::points);
  for (const Vec3& p : x)
    for (int k = 0; k < 3; ++k) b.positions.push_back(static_cast<float>(p[k]));
  set_color(b, fm.sprite_diffuse_color.get(), false);
  b.splat = Batch::Splat::fluid;
  b.splat_radius = static_cast<float>(fm.sprite_radius.get());
  FluidLook& f = b.fluid;
  f.radius = b.splat_radius;
  f.thickness = static_cast<float>(fm.sprite_thickness.get());
  f.blur_radius = static_cast<float>(fm.sprite_blur_radius.get());
  f.blur_scale = static_cast<float>(fm.sprite_blur_scale.get());
  f.blur_falloff = static_cast<float>(fm.sprite_blur_depth_falloff.get());
  f.color = b.shading.diffuse;
  f.debug = fm.debug_fbo.get();
  close_batch(list, b);
}

void push_line(Batch& b, const Vec3& p, const Vec3& q) {
  for (const Vec3* v : {&p, &q})
    for (int k = 0; k < 3; ++k) b.positions.push_back(static_cast<float>((*v)[k]));
}

// VisualGrid::doDrawVisual: its lines, unlit, in its colour.
void add_grid(DrawList& list, const VisualGrid& g) {
  thread_local std::vector<Vec3> pts;
  g.lines(pts);
  Batch& b = fresh_batch(list, &g, Batch::Kind::lines);
  b.line_width = static_cast<float>(g.thickness.get());
  for (std::size_t i = 0; i + 1 < pts.size(); i += 2) push_line(b, pts[i], pts[i + 1]);
  set_color(b, g.color.get(), false);
  close_batch(list, b);
}

// LineAxis::doDrawVisual: x red, y green, z blue, each from −size/2 to size/2 through the
// origin; `infinite` lines span the scene's bounds (what SOFA's infinite lines show in its view)
// and do not count in the bounds the default view frames.
void add_axes(DrawList& list, const LineAxis& a) {
  static const Rgba kAxis[3] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
  Batch& b = fresh_batch(list, &a, Batch::Kind::lines);
  b.line_width = static_cast<float>(a.thickness.get());
  double half = 0.5 * a.size.get();
  if (a.infinite.get()) {
    half = 1.0;
    if (list.has_bounds) half = std::max(half, 2.0 * (list.max - list.min).norm());
  }
  for (int k = 0; k < 3; ++k) {
    if (!a.draws(k)) continue;
    Vec3 p = Vec3::Zero(), q = Vec3::Zero();
    p[k] = -half, q[k] = half;
    push_line(b, p, q);
    for (int v = 0; v < 2; ++v) b.colors.insert(b.colors.end(), kAxis[k].begin(), kAxis[k].end());
  }
  b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  if (b.positions.empty()) {
    --list.used;
  } else if (!a.infinite.get()) {
    grow_bounds(list, b.positions);
  }
}

// TrailRenderer::doDrawVisual: per point, the line strip of its stored positions, the i-th
// sample coloured by the colour map at i over [0, nbSteps].
void add_trails(DrawList& list, const TrailRenderer& t) {
  Batch& b = fresh_batch(list, &t, Batch::Kind::lines);
  b.line_width = static_cast<float>(t.thickness.get());
  b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  // The palette is parsed again only when the text differs from the last trail's.
  thread_local std::vector<Rgba> palette;
  thread_local std::string palette_text = "\x01";
  if (palette_text != t.color.get()) {
    palette = parse_color_map(t.color.get());
    if (palette.empty()) palette = {Rgba{0, 1, 0, 1}};  // SOFA's default: green
    palette_text = t.color.get();
  }
  const double steps = static_cast<double>(t.nb_steps.get());
  for (const auto& q : t.trail()) {
    for (std::size_t i = 0; i + 1 < q.size(); ++i) {
      push_line(b, q[i], q[i + 1]);
      for (std::size_t j : {i, i + 1}) {
        const Rgba c = evaluate_palette(palette, 0.0, steps, static_cast<double>(j));
        b.colors.insert(b.colors.end(), c.begin(), c.end());
      }
    }
  }
  close_batch(list, b);
}

}  // namespace

// RecordedCamera::draw with drawRotation: the rotation's 100-point circle, closed, and lines
// from four of its points to the point looked at, in (0, 1, 0.5); whatever the display flags
// (a component's draw()), and out of the bounds the default view frames (not the scene's).
void add_camera_paths(DrawList& list, Node& node) {
  for (const auto& o : node.objects()) {
    const auto* c = dynamic_cast<const RecordedCamera*>(o.get());
    if (!c || c->state() != ComponentState::valid) continue;
    if (c->draw_rotation.get()) {
      const std::vector<Vec3> path = c->rotation_path();
      if (path.empty()) continue;  // SOFA's draw returns, skipping the translation's path too
      Batch& b = fresh_batch(list, c, Batch::Kind::lines);
      for (std::size_t i = 0; i < path.size(); ++i) push_line(b, path[i], path[(i + 1) % path.size()]);
      for (std::size_t i = 0; i < 4; ++i) push_line(b, path[i * path.size() / 4], c->rotation_look_at.get());
      set_color(b, "0 1 0.5 1", false);
    }
    // drawTranslation: the segments between consecutive cameraPositions (not closed).
    const std::vector<Vec3>& positions = c->camera_positions.get();
    if (c->draw_translation.get() && positions.size() >= 2) {
      Batch& b = fresh_batch(list, c, Batch::Kind::lines);
      for (std::size_t i = 0; i + 1 < positions.size(); ++i) push_line(b, positions[i], positions[i + 1]);
      set_color(b, "0 1 0.5 1", false);
    }
  }
}

// Light::drawSource, after the traversal (the scene's box is then known) and out of it: a
// PositionalLight as an unlit sphere of 1 % of the box's diagonal; a SpotLight as a wireframe
// sphere of radius zNear/10 and a wireframe cone from zNear to zFar along its direction, of
// radius zFar·tan(cutoff) at its base and half of that scaled by zNear/zFar at its tip; zNear
// and zFar the light's, else the box's depth range along the direction with SOFA's margins
// (SpotLight::computeClippingPlane, whose own frame is a mirrored one). In the light's colour.
void add_light_sources(DrawList& list, Node& root, bool visual_models) {
  if (!visual_models) return;
  thread_local std::vector<PositionalLight*> lights;
  lights.clear();
  root.collect_down(lights);
  const Vec3 lo = list.has_bounds ? list.min : Vec3::Zero(), hi = list.has_bounds ? list.max : Vec3::Zero();
  for (const PositionalLight* l : lights) {
    if (!l->draw_source.get() || l->state() != ComponentState::valid) continue;
    const Rgba c = parse_rgba(l->color.get()).value_or(Rgba{1, 1, 1, 1});
    const Rgba color{c[0], c[1], c[2], 1.f};
    const Vec3 pos = l->position.get();
    Batch& b = fresh_batch(list, l, Batch::Kind::triangles);
    b.texcoords.clear();
    b.texture.clear();
    b.lit = false;
    b.translucent = false;
    const auto* spot = dynamic_cast<const SpotLight*>(l);
    b.wireframe = spot != nullptr;
    if (!spot) {
      append_sphere(b, pos, 0.01 * (hi - lo).norm(), &color);
    } else {
      Vec3 dir = spot->direction.get();
      if (spot->lookat.get()) dir -= pos;
      if (dir.norm() > 0) dir.normalize();
      double z_near = spot->z_near.get(), z_far = spot->z_far.get();
      if (!spot->z_near.is_set() || !spot->z_far.is_set()) {
        z_near = 1e10, z_far = -1e10;
        for (int k = 0; k < 8; ++k) {
          const Vec3 p(k & 1 ? lo.x() : hi.x(), k & 2 ? lo.y() : hi.y(), k & 4 ? lo.z() : hi.z());
          const double z = (p - pos).dot(dir);
          z_near = std::min(z_near, z), z_far = std::max(z_far, z);
        }
        if (z_near <= 0) z_near = 1;
        if (z_far >= 1000) z_far = 1000;
        if (z_far <= 0) z_near = 0.01, z_far = 100;  // the view's planes in SOFA
        if (z_near > 0 && z_far < 1000) {
          z_near *= 0.8, z_far *= 1.2;
          z_near = std::max({z_near, z_far * 0.01, 0.1});
          z_far = std::max(z_far, 2.0);
        }
      }
      const double base = z_far * std::tan(spot->cutoff.get() * M_PI / 180), tip = base * 0.5 * z_near / z_far;
      append_sphere(b, pos, z_near * 0.1, &color);
      append_cone(b, pos + dir * z_far, pos + dir * z_near, base, tip, &color);
    }
    if (b.positions.empty()) --list.used;  // not in the scene's box, as in SOFA
  }
}

void add_visual_extras(DrawList& list, Node& node) {
  for (const auto& o : node.objects()) {
    if (const auto* vb = dynamic_cast<const VisualBoundingBox*>(o.get())) add_box(list, *vb);
    else if (auto* dd = dynamic_cast<DataDisplay*>(o.get())) add_data_display(list, *dd);
    else if (const auto* pc = dynamic_cast<const VisualPointCloud*>(o.get())) add_point_cloud(list, *pc);
    else if (const auto* cm = dynamic_cast<const CylinderVisualModel*>(o.get())) add_cylinders(list, *cm);
    else if (const auto* vm = dynamic_cast<const VisualMesh*>(o.get())) add_visual_mesh(list, *vm);
    else if (const auto* ps = dynamic_cast<const PointSplatModel*>(o.get())) add_point_splats(list, *ps, node);
    else if (const auto* fm = dynamic_cast<const OglFluidModel*>(o.get())) add_fluid(list, *fm);
    else if (const auto* g = dynamic_cast<const VisualGrid*>(o.get())) add_grid(list, *g);
    else if (const auto* a = dynamic_cast<const LineAxis*>(o.get())) add_axes(list, *a);
    else if (const auto* tr = dynamic_cast<const TrailRenderer*>(o.get())) add_trails(list, *tr);
  }
}

}  // namespace sinew::render
