// Text in pictures, as SOFA's GL draw tool writes it (sofa/gl/glText.cpp): glyphs taken from
// SOFA's ASCII font texture (`textures/texture_ascii_smooth.png` of SOFA's share tree: 16 × 16
// cells, the first one for code 32), each glyph a quad half as wide as high, the texture's
// alpha modulating the colour. Three forms:
// - world (Visual3DText, SOFA's draw3DText): facing the camera, its top-left corner at a 3D
//   point, glyphs `size` world units high; no depth test (Visual3DText disables it);
// - indices (showIndices: MechanicalObject, VisualPointCloud; draw3DText_Indices): each
//   point's index centred on it, 30·size pixels high whatever the depth, over a drop shadow
//   (black, 70 % of the colour's alpha, 1.5·size px right and down); depth-tested;
// - overlay (OglLabel, writeOverlayText): at pixel (x, y) from the top-left corner, glyphs
//   `size` (fontsize) pixels wide and twice as high; no depth test.
// OglColorMap's legend (showLegend) is made of overlay texts and rectangles: a bar 10 px wide
// and 100 px high of the palette (max at the top, sampled as SOFA's 1D texture: linear,
// repeating), `legendTitle` above it, max and min beside its ends (fontsize 12); white, or black
// on a background whose luminance (0.212 r + 0.715 g + 0.072 b) exceeds 0.5.
// Text is Latin-1 in SOFA's texture; UTF-8 input is decoded (code points 32–255 drawn, others
// shown as '?').
#pragma once

#include <string>
#include <vector>

#include "render/draw_list.h"

namespace sinew {
class Node;
}

namespace sinew::render {

struct View;

// SOFA's font texture, relative to a data folder (front ends find it: runner::find_data_file).
inline constexpr const char* kFontFile = "textures/texture_ascii_smooth.png";

// Appends the texts of `node`'s components (not of its children) to list.texts. Visual3DText
// needs the visual-model flag (`visual_models`); indices are drawn whatever the flags, as SOFA's
// components draw them in their draw().
void add_texts(DrawList& list, Node& node, bool visual_models);

// Triangles of the overlay rectangles of `list` (DrawList::overlay_rects), in the same vertex
// format as text_vertices with u = v = -1 (no texture). Appends to `out`.
void rect_vertices(const DrawList& list, int width, int height, std::vector<float>& out);

// Triangles of `t` for a width × height picture: per vertex clip-space x y z w, texture u v
// (the font texture uploaded bottom row first, as OpenGL reads images) and colour r g b a, 10
// floats; two triangles per glyph (the drop shadow's first for indices). Appends to `out`.
void text_vertices(const Text& t, const View& view, int width, int height, std::vector<float>& out);

}  // namespace sinew::render
