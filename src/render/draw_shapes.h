// Tessellated shapes appended to a triangle batch (positions, normals, indices; per-vertex
// colours when a colour is given): what SOFA's DrawTool draws as spheres, cylinders, cones
// and frames. Internal to src/render.
#pragma once

#include <array>

#include "render/draw_list.h"

namespace sinew::render {

// A sphere as a latitude–longitude mesh of 8 × 12 quads.
void append_sphere(Batch& b, const Vec3& centre, double radius, const std::array<float, 4>* color = nullptr);

// A truncated cone from `a` (radius ra) to `b` (radius rb), its side only, 12 facets; ra = rb:
// a cylinder, rb = 0: a cone. Nothing when a = b.
void append_cone(Batch& b, const Vec3& a, const Vec3& tip, double ra, double rb,
                 const std::array<float, 4>* color = nullptr);

// SOFA's gl::Frame of size L at `origin` with axes the columns of `axes`: per axis a shaft of
// radius L/10 and length L, then a cone of length and base radius L/5; x red, y green, z blue.
void append_frame(Batch& b, const Vec3& origin, const Mat3& axes, double length);

// The twelve edges of the axis-aligned box [lo, hi], appended to a line batch (positions only):
// each joins two corners differing in one coordinate.
void append_box_edges(Batch& b, const Vec3& lo, const Vec3& hi);

// An axis-aligned box [lo, hi] by its six faces.
void append_box(Batch& b, const Vec3& lo, const Vec3& hi, const std::array<float, 4>& color);

// OglSceneFrame's axes at the origin, unit length: style 0 arrows (a shaft of radius 0.05 to
// 0.8, a cone of base 0.125 to 1: DrawTool's drawArrow), 1 cylinders (radius 0.05), 2 a dark
// cube of half-side 0.25 with a cone per half axis (coloured on the positive side, grey on the
// negative); x red, y green, z blue.
void append_scene_frame(Batch& b, int style);

}  // namespace sinew::render
