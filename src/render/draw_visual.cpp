// VisualBoundingBox as SOFA draws it: the twelve edges of the box, in its
// colour, unlit; DataDisplay's coloured mesh. Core-profile OpenGL has no wide lines everywhere, so
// `thickness` is not honoured (lines are one pixel wide).
#include "render/draw_visual.h"

#include "core/node.h"
#include "render/draw_collision.h"
#include "render/draw_list.h"
#include "visual/color.h"
#include "visual/data_display.h"
#include "visual/visual_bounding_box.h"

namespace sinew::render {

namespace {

void add_box(DrawList& list, const VisualBoundingBox& vb) {
  if (!vb.enable.get() || vb.state() != ComponentState::valid) return;
  const auto box = vb.box();
  if (!box) return;
  Batch& b = fresh_batch(list, &vb, Batch::Kind::lines);
  // The colour text is parsed again only when it changed (parsing allocates).
  if (!b.shading_parsed || b.material_text != vb.color.get()) {
    const Rgba c = parse_rgba(vb.color.get()).value_or(Rgba{1, 1, 0, 1});
    b.shading.diffuse = c;
    b.material_text = vb.color.get();
    b.shading_parsed = true;
  }
  const Vec3& lo = box->first;
  const Vec3& hi = box->second;
  auto corner = [&](int i) {
    return Vec3(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
  };
  // Edges join corners differing in one coordinate bit.
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit))
        for (const Vec3& p : {corner(i), corner(i | bit)})
          for (int c = 0; c < 3; ++c) b.positions.push_back(static_cast<float>(p[c]));
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

}  // namespace

void add_visual_extras(DrawList& list, Node& node) {
  for (const auto& o : node.objects()) {
    if (const auto* vb = dynamic_cast<const VisualBoundingBox*>(o.get())) add_box(list, *vb);
    else if (auto* dd = dynamic_cast<DataDisplay*>(o.get())) add_data_display(list, *dd);
  }
}

}  // namespace sinew::render
