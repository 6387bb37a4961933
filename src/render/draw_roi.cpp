// Region-of-interest engines as SOFA's BaseROI::draw shows them under showBehaviorModels:
// the region itself when drawROI is on (BoxROI's drawBoxes: each aligned and oriented box's
// twelve edges in cyan; SphereROI's drawSphere: its spheres in wireframe and, with edgeAngle
// or triAngle, the cones of those angles, in cyan), then what the engine selected, unlit in
// (1, 0.4, 0.4): points (drawPoints) of max(drawSize, 1) pixels, edges, quads, tetrahedra and
// hexahedra as lines of that width, triangles filled (their edges with showWireframe).
// MeshROI's region (drawROI): its mesh's points in (0.4, 0.4, 1), edges and triangles, and
// its bounding box with drawBox, in (1, 0.4, 0.4) (MeshROI::roiDraw).
// The engines with a draw of their own: PlaneROI (its slabs' boxes only while drawSize is 0,
// whatever drawBoxes says, as SOFA; points of 5 pixels, edges and tetrahedra as lines,
// triangles filled or, with showWireframe, their edges; all cyan), ProximityROI (drawSphere:
// spheres of half the radii in wireframe; drawPoints: 5-pixel points; cyan) and PairBoxROI
// (its two boxes and its points in (1, 0.4, 0.4), drawSize wide, 1 when 0; drawn also
// without showBehaviorModels when drawSize is not 0).
#include <cmath>

#include "core/node.h"
#include "engine/base_roi.h"
#include "engine/box_roi.h"
#include "engine/pair_box_roi.h"
#include "engine/plane_roi.h"
#include "engine/select/proximity_roi.h"
#include "engine/select/mesh_roi.h"
#include "engine/sphere_roi.h"
#include "render/draw_collision.h"
#include "render/draw_shapes.h"

namespace sinew::render {

namespace {

constexpr Rgba kSelected{1.f, 0.4f, 0.4f, 1.f};
constexpr Rgba kRegion{0.f, 1.f, 1.f, 1.f};  // SOFA's RGBAColor::cyan()

void unlit(Batch& b, const Rgba& c, float size) {
  b.shading = Shading{{0, 0, 0, 0}, c, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  b.shading_parsed = false;
  b.lit = false;
  b.line_width = size;
  b.point_size = size;
}

// Point i of a flat coordinate list (1 to 3 coordinates per point; missing ones are 0).
Vec3 point_of(const FlatVec& v, std::size_t i) {
  Vec3 p = Vec3::Zero();
  const std::size_t w = static_cast<std::size_t>(v.width);
  for (std::size_t k = 0; k < std::min<std::size_t>(w, 3); ++k) p[static_cast<Eigen::Index>(k)] = v.data[i * w + k];
  return p;
}

// A lines batch of `elements` over the points `x`, in `color`, `width` pixels: `emit(b, e, segment)`
// draws element e with segment(b, i, j). An element naming a point beyond `x` is skipped (a
// stale selection).
template <class Elements, class Emit>
void add_element_lines(DrawList& list, const Component& source, const FlatVec& x, const Elements& elements,
                       const Rgba& color, float width, Emit&& emit) {
  const std::size_t n = x.size();
  auto segment = [&](Batch& b, unsigned i, unsigned j) { push_point(b, point_of(x, i)), push_point(b, point_of(x, j)); };
  Batch& b = fresh_batch(list, &source, Batch::Kind::lines);
  unlit(b, color, width);
  for (const auto& e : elements) {
    bool ok = true;
    for (unsigned v : e) ok &= v < n;
    if (ok) emit(b, e, segment);
  }
  close_batch(list, b);
}

// Triangles over the points `x` filled in `color` (their edges with showWireframe).
void add_filled_triangles(DrawList& list, const Component& source, const FlatVec& x,
                          const std::vector<Triangle>& triangles, const Rgba& color, float size, bool wireframe) {
  const std::size_t n = x.size();
  Batch& b = fresh_batch(list, &source, Batch::Kind::triangles);
  unlit(b, color, size);
  b.wireframe = wireframe;  // the polygon mode showWireframe set
  for (const Triangle& t : triangles)
    if (t[0] < n && t[1] < n && t[2] < n)
      for (unsigned v : t) push_point(b, point_of(x, v));
  close_batch(list, b);
}

// SOFA's tetrahedron outline in the ROIs' draws: the cycle 0-1-2-3 and the diagonals 0-2, 1-3.
constexpr auto kTetraEdges = [](Batch& b, const Tetra& t, auto& segment) {
  for (unsigned j = 0; j < 4; ++j) segment(b, t[j], t[(j + 1) % 4]);
  segment(b, t[0], t[2]);
  segment(b, t[1], t[3]);
};
constexpr auto kEdge = [](Batch& b, const Edge& e, auto& segment) { segment(b, e[0], e[1]); };

// BoxROI::getPointsFromOrientedBox: the parallelogram p0 p1 p2 (p3 = p0 + p2 − p1) moved by
// depth/2 along its normal, and its copy depth below.
std::array<Vec3, 8> oriented_corners(const VecN<10>& box) {
  std::array<Vec3, 8> p;
  p[0] = Vec3(box[0], box[1], box[2]);
  p[1] = Vec3(box[3], box[4], box[5]);
  p[2] = Vec3(box[6], box[7], box[8]);
  const double depth = box[9];
  const Vec3 a = p[1] - p[0], c = p[2] - p[0];
  Vec3 normal(a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]);
  if (const double n = normal.norm(); n > 0) normal /= n;
  for (int i = 0; i < 3; ++i) p[i] += normal * depth / 2;
  p[3] = p[0] + (p[2] - p[1]);
  p[4] = p[0] - normal * depth;
  p[6] = p[2] - normal * depth;
  p[5] = p[1] - normal * depth;
  p[7] = p[3] - normal * depth;
  return p;
}

void add_box_region(DrawList& list, const BoxROI& roi, float width) {
  Batch& b = fresh_batch(list, &roi, Batch::Kind::lines);
  unlit(b, kRegion, width);
  for (const VecN<6>& box : roi.box.get())
    append_box_edges(b, Vec3(box[0], box[1], box[2]), Vec3(box[3], box[4], box[5]));
  static constexpr int kEdges[12][2] = {{0, 1}, {0, 4}, {0, 3}, {2, 1}, {2, 6}, {2, 3},
                                        {6, 7}, {6, 5}, {4, 5}, {4, 7}, {1, 5}, {3, 7}};
  for (const VecN<10>& box : roi.oriented_box.get()) {
    const auto p = oriented_corners(box);
    for (const auto& e : kEdges) push_point(b, p[static_cast<std::size_t>(e[0])]), push_point(b, p[static_cast<std::size_t>(e[1])]);
  }
  close_batch(list, b);
}

// SphereROI::roiDraw: a centre is drawn only with its own radius (SOFA pairs the two lists
// up to the shorter), as a wireframe sphere, with the cones of half-angle edgeAngle about
// `direction` and triAngle about `normal` when those are positive.
void add_sphere_region(DrawList& list, const SphereROI& roi) {
  const auto& c = roi.centers.get();
  const auto& r = roi.radii.get();
  const std::size_t n = std::min(c.size(), r.size());
  if (n == 0) return;
  Batch& spheres = fresh_batch(list, &roi, Batch::Kind::triangles);
  spheres.shading = Shading{{0, 0, 0, 0}, kRegion, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
  spheres.shading_parsed = false;
  spheres.wireframe = true;
  for (std::size_t i = 0; i < n; ++i) append_sphere(spheres, c[i], r[i]);
  close_batch(list, spheres);
  const double deg = M_PI / 180.0;
  const double edge = roi.edge_angle.get() * deg, tri = roi.tri_angle.get() * deg;
  if (!(roi.edge_angle.get() > 0) && !(roi.tri_angle.get() > 0)) return;
  Batch& cones = fresh_batch(list, &roi, Batch::Kind::triangles);
  cones.shading = spheres.shading;
  cones.shading_parsed = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (roi.edge_angle.get() > 0)
      append_cone(cones, c[i], c[i] + roi.direction.get() * (std::cos(edge) * r[i]), 0, std::sin(edge) * r[i]);
    if (roi.tri_angle.get() > 0)
      append_cone(cones, c[i], c[i] + roi.normal.get() * (std::cos(tri) * r[i]), 0, std::sin(tri) * r[i]);
  }
  close_batch(list, cones);
}

// MeshROI::roiDraw, with the same switches as the selection (drawPoints, drawEdges,
// drawTriangles) applied to the ROI mesh, and drawBox.
void add_mesh_region(DrawList& list, const MeshROI& roi, float size, bool wireframe) {
  const FlatVec& x = roi.roi_position.get();
  if (roi.draw_points.get()) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::points);
    unlit(b, Rgba{0.4f, 0.4f, 1.f, 1.f}, size);
    for (std::size_t i = 0; i < x.size(); ++i) push_point(b, point_of(x, i));
    close_batch(list, b);
  }
  if (roi.draw_edges.get()) add_element_lines(list, roi, x, roi.roi_edges.get(), kSelected, size, kEdge);
  if (roi.draw_triangles.get()) add_filled_triangles(list, roi, x, roi.roi_triangles.get(), kSelected, size, wireframe);
  if (roi.draw_box.get()) {
    const VecN<6>& box = roi.box.get();
    Batch& b = fresh_batch(list, &roi, Batch::Kind::lines);
    unlit(b, kSelected, size);
    append_box_edges(b, Vec3(box[0], box[1], box[2]), Vec3(box[3], box[4], box[5]));
    close_batch(list, b);
  }
}

// PlaneROI::draw. Points and elements are taken from `position` (SOFA's f_X0).
void add_plane_roi(DrawList& list, const PlaneROI& roi, bool wireframe) {
  const float size = static_cast<float>(std::max(roi.draw_size.get(), 1.0));
  if (roi.draw_size.get() == 0) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::lines);
    unlit(b, kRegion, 1.f);
    const std::vector<double>& planes = roi.plane.get();
    for (std::size_t k = 0; k + 10 <= planes.size(); k += 10) {
      const double* p = &planes[k];
      const Vec3 a(p[0], p[1], p[2]), c(p[3], p[4], p[5]), d(p[6], p[7], p[8]);
      const Vec3 u = c - a, v = d - a;
      Vec3 n(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
      if (const double len = n.norm(); len > 0) n /= len;
      const Vec3 half = n * (p[9] / 2);
      const std::array<Vec3, 4> face{a, c, d, a + (d - c)};
      for (std::size_t i = 0; i < 4; ++i) {
        const Vec3 &from = face[i], &to = face[(i + 1) % 4];
        push_point(b, from - half), push_point(b, to - half);  // the face below
        push_point(b, from + half), push_point(b, to + half);  // the face above
        push_point(b, from - half), push_point(b, from + half);
      }
    }
    close_batch(list, b);
  }
  const FlatVec& x = roi.position.get();
  if (roi.draw_points.get()) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::points);
    unlit(b, kRegion, 5.f);
    const FlatVec& in = roi.points_in_roi.get();
    for (std::size_t i = 0; i < in.size(); ++i) push_point(b, point_of(in, i));
    close_batch(list, b);
  }
  if (roi.draw_edges.get()) add_element_lines(list, roi, x, roi.edges_in_roi.get(), kRegion, size, kEdge);
  if (roi.draw_triangles.get())
    add_filled_triangles(list, roi, x, roi.triangles_in_roi.get(), kRegion, size, wireframe);
  if (roi.draw_tetrahedra.get())
    add_element_lines(list, roi, x, roi.tetrahedra_in_roi.get(), kRegion, size, kTetraEdges);
}

// ProximityROI::draw.
void add_proximity_roi(DrawList& list, const ProximityROI& roi) {
  if (roi.draw_sphere.get()) {
    const auto& c = roi.centers.get();
    const auto& r = roi.radii.get();
    Batch& b = fresh_batch(list, &roi, Batch::Kind::triangles);
    b.shading = Shading{{0, 0, 0, 0}, kRegion, {0, 0, 0, 0}, {0, 0, 0, 0}, 1.f};
    b.shading_parsed = false;
    b.wireframe = true;
    for (std::size_t i = 0; i < std::min(c.size(), r.size()); ++i) append_sphere(b, c[i], r[i] * 0.5);
    close_batch(list, b);
  }
  if (roi.draw_points.get()) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::points);
    unlit(b, kRegion, 5.f);
    for (const Vec3& p : roi.points_in_roi.get()) push_point(b, p);
    close_batch(list, b);
  }
}

// PairBoxROI::draw.
void add_pair_box_roi(DrawList& list, const PairBoxROI& roi) {
  const float size = roi.draw_size.get() != 0 ? static_cast<float>(roi.draw_size.get()) : 1.f;
  for (const auto* box : {roi.draw_inclusive_box.get() ? &roi.inclusive_box.get() : nullptr,
                          roi.draw_included_box.get() ? &roi.included_box.get() : nullptr}) {
    if (!box) continue;
    Batch& b = fresh_batch(list, &roi, Batch::Kind::lines);
    unlit(b, kSelected, size);
    append_box_edges(b, Vec3((*box)[0], (*box)[1], (*box)[2]), Vec3((*box)[3], (*box)[4], (*box)[5]));
    close_batch(list, b);
  }
  if (roi.draw_points.get()) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::points);
    unlit(b, kSelected, size);
    const FlatVec& in = roi.points_in_roi.get();
    for (std::size_t i = 0; i < in.size(); ++i) push_point(b, point_of(in, i));
    close_batch(list, b);
  }
}

void add_roi(DrawList& list, const BaseROI& roi, bool wireframe) {
  const float size = static_cast<float>(std::max(roi.draw_size.get(), 1.0));
  if (roi.draw_roi.get()) {
    if (const auto* box = dynamic_cast<const BoxROI*>(&roi)) add_box_region(list, *box, size);
    if (const auto* sphere = dynamic_cast<const SphereROI*>(&roi)) add_sphere_region(list, *sphere);
    if (const auto* mesh = dynamic_cast<const MeshROI*>(&roi)) add_mesh_region(list, *mesh, size, wireframe);
  }

  const FlatVec& x = roi.position.get();
  if (roi.draw_points.get()) {
    Batch& b = fresh_batch(list, &roi, Batch::Kind::points);
    unlit(b, kSelected, size);
    const FlatVec& in = roi.points_in_roi.get();
    if (in.width == x.width)
      for (std::size_t i = 0; i < in.size(); ++i) push_point(b, point_of(in, i));
    close_batch(list, b);
  }
  if (roi.draw_edges.get()) add_element_lines(list, roi, x, roi.edges_in_roi.get(), kSelected, size, kEdge);
  if (roi.draw_triangles.get())
    add_filled_triangles(list, roi, x, roi.triangles_in_roi.get(), kSelected, size, wireframe);
  if (roi.draw_quads.get())
    add_element_lines(list, roi, x, roi.quads_in_roi.get(), kSelected, size, [](Batch& b, const Quad& q, auto& segment) {
      for (unsigned j = 0; j < 4; ++j) segment(b, q[j], q[(j + 1) % 4]);
    });
  if (roi.draw_tetrahedra.get())
    add_element_lines(list, roi, x, roi.tetrahedra_in_roi.get(), kSelected, size, kTetraEdges);
  if (roi.draw_hexahedra.get())
    add_element_lines(list, roi, x, roi.hexahedra_in_roi.get(), kSelected, size, [](Batch& b, const Hexa& h, auto& segment) {
      // SOFA's loop joins each corner j to corner (j + 1) % 4 (not within its own face for
      // the top four), then adds four diagonals.
      for (unsigned j = 0; j < 8; ++j) segment(b, h[j], h[(j + 1) % 4]);
      segment(b, h[0], h[2]);
      segment(b, h[1], h[3]);
      segment(b, h[4], h[5]);
      segment(b, h[6], h[7]);
    });
}

}  // namespace

void add_rois(DrawList& list, Node& node, bool behavior_models, bool wireframe) {
  for (const auto& o : node.objects()) {
    if (o->state() == ComponentState::invalid) continue;
    if (const auto* pair = dynamic_cast<const PairBoxROI*>(o.get())) {
      if (behavior_models || pair->draw_size.get() != 0) add_pair_box_roi(list, *pair);
      continue;
    }
    if (!behavior_models) continue;
    if (const auto* roi = dynamic_cast<const BaseROI*>(o.get())) add_roi(list, *roi, wireframe);
    else if (const auto* plane = dynamic_cast<const PlaneROI*>(o.get())) add_plane_roi(list, *plane, wireframe);
    else if (const auto* proximity = dynamic_cast<const ProximityROI*>(o.get())) add_proximity_roi(list, *proximity);
  }
}

}  // namespace sinew::render
