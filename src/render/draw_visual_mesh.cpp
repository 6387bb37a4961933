// VisualMesh as SOFA's DrawMesh draws it (sofa/core/visual/DrawMesh.h): every element shrunk
// towards its centre by `elementSpace` (p' = c + (p − c)(1 − s)), coloured by its place:
// - a topology with volume elements draws them only: tetrahedra by the face opposite each
//   vertex (blue, black, azure, cyan), hexahedra by their six faces (SOFA's six face colours),
//   prisms (two triangles, three quads) and pyramids (one quad, four triangles) in green,
//   teal, navy, gold, purple;
// - else its triangles (green, teal, blue, by index mod 3) and quads (green, orange);
// - else its edges (lime, silver, by index mod 2).
// With `vertexValues` (one per vertex at least), each vertex takes its value's colour in
// `colorMap` between the values' minimum and maximum instead. `lighting` off: unlit colours.
#include <Eigen/Geometry>

#include <algorithm>

#include "render/draw_collision.h"
#include "render/draw_visual.h"
#include "topology/mesh_topology.h"
#include "visual/color.h"
#include "visual/color_map.h"
#include "visual/drawing/visual_mesh.h"

namespace sinew::render {

namespace {

using V3f = Eigen::Vector3f;

constexpr Rgba kLime{0.5f, 1, 0, 1}, kSilver{0.75f, 0.75f, 0.75f, 1}, kGreen{0, 1, 0, 1}, kTeal{0, 0.5f, 0.5f, 1},
    kBlue{0, 0, 1, 1}, kOrange{1, 0.5f, 0, 1}, kBlack{0, 0, 0, 1}, kAzure{0, 0.5f, 1, 1}, kCyan{0, 1, 1, 1},
    kNavy{0, 0, 0.5f, 1}, kGold{1, 0.84f, 0, 1}, kPurple{0.5f, 0, 0.5f, 1};
constexpr Rgba kHexa[6] = {{0.7f, 0.7f, 0.1f, 1}, {0.7f, 0, 0, 1},      {0, 0.7f, 0, 1},
                           {0, 0, 0.7f, 1},       {0.1f, 0.7f, 0.7f, 1}, {0.7f, 0.1f, 0.7f, 1}};
// SOFA's hexahedron faces in its quadsInHexahedron order.
constexpr int kHexaFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// The mesh of one VisualMesh being filled: shrunk corners, flat normals, colours.
struct Filler {
  Batch& b;
  const std::vector<Vec3>& x;
  const std::vector<Rgba>* vertex_colors;  // per mesh vertex, or null
  float keep;                              // 1 − elementSpace

  template <std::size_t N>
  V3f centre(const std::array<unsigned, N>& e) const {
    V3f c = V3f::Zero();
    for (unsigned v : e) c += x[v].cast<float>();
    return c / static_cast<float>(N);
  }
  // Triangle (a, b, c) of mesh vertices, shrunk towards `c0`, in `color` (or the vertices').
  void triangle(unsigned a, unsigned bb, unsigned c, const V3f& c0, const Rgba& color) {
    const unsigned ids[3] = {a, bb, c};
    V3f p[3];
    for (int k = 0; k < 3; ++k) p[k] = c0 + (x[ids[k]].cast<float>() - c0) * keep;
    V3f n = (p[1] - p[0]).cross(p[2] - p[0]);
    if (n.norm() > 0) n.normalize();
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d) b.positions.push_back(p[k][d]), b.normals.push_back(n[d]);
      const Rgba& col = vertex_colors ? (*vertex_colors)[ids[k]] : color;
      b.colors.insert(b.colors.end(), col.begin(), col.end());
    }
  }
  void quad(unsigned a, unsigned bb, unsigned c, unsigned d, const V3f& c0, const Rgba& color) {
    triangle(a, bb, c, c0, color);
    triangle(a, c, d, c0, color);
  }
};

template <std::size_t N>
bool in_range(const std::array<unsigned, N>& e, std::size_t n) {
  return std::all_of(e.begin(), e.end(), [n](unsigned v) { return v < n; });
}

// The colours of the vertex values through the VisualMesh's colour map (HSV when empty, SOFA's
// default map).
std::vector<Rgba> value_colors(const VisualMesh& m) {
  const std::vector<double>& values = m.vertex_values.get();
  std::vector<Rgba> palette = parse_color_map(m.color_map.get());
  if (palette.empty()) palette = build_palette(256, "HSV");  // SOFA's ColorMap::getDefault()
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  std::vector<Rgba> out;
  out.reserve(values.size());
  for (double v : values) out.push_back(evaluate_palette(palette, *lo, *hi, v));
  return out;
}

}  // namespace

void add_visual_mesh(DrawList& list, const VisualMesh& m) {
  if (!m.enable.get() || m.state() != ComponentState::valid || !m.topology.get()) return;
  const MeshTopologyBase& t = *m.topology;
  const std::vector<Vec3>& x = m.position.get();
  const std::size_t n = x.size();
  std::vector<Rgba> colors;
  if (!m.vertex_values.get().empty() && m.vertex_values.get().size() >= n) colors = value_colors(m);
  const auto& tets = t.tetrahedra();
  const auto& hexas = t.hexahedra();
  const auto& prisms = prisms_of(t);
  const auto& pyramids = pyramids_of(t);
  const bool volume = !tets.empty() || !hexas.empty() || !prisms.empty() || !pyramids.empty();
  const float keep = static_cast<float>(1.0 - m.element_space.get());
  if (!volume && t.triangles().empty() && t.quads().empty()) {
    Batch& l = fresh_batch(list, &m, Batch::Kind::lines);
    static constexpr Rgba kEdge[2] = {kLime, kSilver};
    const auto& edges = t.edges();
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (!in_range(edges[i], n)) continue;
      const V3f c = (x[edges[i][0]].cast<float>() + x[edges[i][1]].cast<float>()) * 0.5f;
      for (unsigned v : edges[i]) {
        const V3f p = c + (x[v].cast<float>() - c) * keep;
        for (int d = 0; d < 3; ++d) l.positions.push_back(p[d]);
        const Rgba& col = colors.empty() ? kEdge[i % 2] : colors[v];
        l.colors.insert(l.colors.end(), col.begin(), col.end());
      }
    }
    l.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    close_batch(list, l);
    return;
  }
  Batch& b = fresh_batch(list, &m, Batch::Kind::triangles);
  b.shading = Shading{{0, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.color_ambient = 0.2f;
  b.lit = m.lighting.get();
  Filler f{b, x, colors.empty() ? nullptr : &colors, keep};
  if (volume) {
    static constexpr Rgba kTetra[4] = {kBlue, kBlack, kAzure, kCyan};
    for (const Tetra& e : tets) {
      if (!in_range(e, n)) continue;
      const V3f c = f.centre(e);
      for (int j = 0; j < 4; ++j)  // the face opposite vertex j
        f.triangle(e[(j + 1) % 4], e[(j + 2) % 4], e[(j + 3) % 4], c, kTetra[j]);
    }
    for (const Hexa& e : hexas) {
      if (!in_range(e, n)) continue;
      const V3f c = f.centre(e);
      for (int j = 0; j < 6; ++j) {
        const int* q = kHexaFaces[j];
        f.quad(e[q[0]], e[q[1]], e[q[2]], e[q[3]], c, kHexa[j]);
      }
    }
    for (const Prism& e : prisms) {
      if (!in_range(e, n)) continue;
      const V3f c = f.centre(e);
      f.triangle(e[0], e[1], e[2], c, kGreen);
      f.triangle(e[5], e[4], e[3], c, kTeal);
      f.quad(e[0], e[2], e[5], e[3], c, kNavy);
      f.quad(e[0], e[3], e[4], e[1], c, kGold);
      f.quad(e[1], e[4], e[5], e[2], c, kPurple);
    }
    for (const Pyramid& e : pyramids) {
      if (!in_range(e, n)) continue;
      const V3f c = f.centre(e);
      f.quad(e[0], e[3], e[2], e[1], c, kGreen);
      f.triangle(e[0], e[1], e[4], c, kTeal);
      f.triangle(e[1], e[2], e[4], c, kNavy);
      f.triangle(e[3], e[4], e[2], c, kGold);
      f.triangle(e[0], e[4], e[3], c, kPurple);
    }
  } else if (!t.triangles().empty() || !t.quads().empty()) {
    static constexpr Rgba kTri[3] = {kGreen, kTeal, kBlue};
    static constexpr Rgba kQuad[2] = {kGreen, kOrange};
    const auto& tris = t.triangles();
    for (std::size_t i = 0; i < tris.size(); ++i)
      if (in_range(tris[i], n)) f.triangle(tris[i][0], tris[i][1], tris[i][2], f.centre(tris[i]), kTri[i % 3]);
    const auto& quads = t.quads();
    for (std::size_t i = 0; i < quads.size(); ++i)
      if (in_range(quads[i], n))
        f.quad(quads[i][0], quads[i][1], quads[i][2], quads[i][3], f.centre(quads[i]), kQuad[i % 2]);
  }
  close_batch(list, b);
}

}  // namespace sinew::render
