#include "render/draw_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/node.h"
#include "render/camera_view.h"
#include "render/draw_collision.h"
#include "visual/background_setting.h"
#include "visual/color.h"
#include "visual/drawing/visual_3d_text.h"
#include "visual/drawing/visual_point_cloud.h"
#include "visual/rendering2d/ogl_color_map.h"
#include "visual/rendering2d/ogl_label.h"

namespace sinew::render {

namespace {

constexpr float kGlyphWidth = 0.5f;    // a glyph's width over its height (glText's worldWidth)
constexpr float kIndexPixels = 30.f;   // height of an index label at scale 1 (baseFontPixelHeight)
constexpr float kShadowPixels = 1.5f;  // offset of an index label's shadow
constexpr int kFloatsPerVertex = 10;

Text& next_text(DrawList& list, const Component* source, Text::Kind kind) {
  if (list.texts_used == list.texts.size()) list.texts.emplace_back();
  Text& t = list.texts[list.texts_used++];
  t.source = source;
  t.kind = kind;
  t.text.clear();
  t.points.clear();
  return t;
}

// The next code point of UTF-8 text from byte i (advanced past it). A byte that does not
// start a complete sequence is taken alone, as a Latin-1 character (SOFA's texture reads bytes).
unsigned next_code(const std::string& s, std::size_t& i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(s[k])); };
  const unsigned b0 = byte(i);
  const std::size_t extra = b0 >= 0xF0 && b0 < 0xF8 ? 3 : b0 >= 0xE0 && b0 < 0xF0 ? 2 : b0 >= 0xC0 && b0 < 0xE0 ? 1 : 0;
  if (extra == 0 || i + extra >= s.size()) {
    ++i;
    return b0;
  }
  unsigned code = b0 & (0x3Fu >> extra);
  for (std::size_t k = 1; k <= extra; ++k) {
    const unsigned b = byte(i + k);
    if ((b & 0xC0) != 0x80) {
      ++i;
      return b0;
    }
    code = (code << 6) | (b & 0x3F);
  }
  i += 1 + extra;
  return code;
}

// Texture rectangle of a code's cell: u from the left; v as OpenGL samples an image uploaded
// bottom row first (1 at the top row). Control characters: none (nothing drawn).
bool cell(unsigned code, float& u0, float& u1, float& v_top, float& v_bottom) {
  if (code < 32) return false;
  if (code > 255) code = '?';
  const unsigned k = code - 32, col = k % 16, row = k / 16;
  u0 = static_cast<float>(col) / 16.f;
  u1 = static_cast<float>(col + 1) / 16.f;
  v_top = 1.f - static_cast<float>(row) / 16.f;
  v_bottom = 1.f - static_cast<float>(row + 1) / 16.f;
  return true;
}

void vertex(std::vector<float>& out, const Eigen::Vector4f& clip, float u, float v, const Rgba& c) {
  out.insert(out.end(), {clip[0], clip[1], clip[2], clip[3], u, v, c[0], c[1], c[2], c[3]});
}

// The glyphs of `text` in a plane: glyph j spans x ∈ [x0 + j·w, x0 + (j + 1)·w] and y from
// `top` down to `top − h` (h < 0 for pixel rows growing downwards), mapped to clip space by
// `to_clip`.
template <class ToClip>
void glyph_row(const std::string& text, float x0, float top, float w, float h, const Rgba& color,
               const ToClip& to_clip, std::vector<float>& out) {
  std::size_t i = 0;
  for (int j = 0; i < text.size(); ++j) {
    const unsigned code = next_code(text, i);
    float u0, u1, vt, vb;
    if (!cell(code, u0, u1, vt, vb)) continue;
    const float xa = x0 + static_cast<float>(j) * w, xb = xa + w, yb = top - h;
    const Eigen::Vector4f tl = to_clip(xa, top), tr = to_clip(xb, top), bl = to_clip(xa, yb), br = to_clip(xb, yb);
    vertex(out, tl, u0, vt, color), vertex(out, bl, u0, vb, color), vertex(out, tr, u1, vt, color);
    vertex(out, tr, u1, vt, color), vertex(out, bl, u0, vb, color), vertex(out, br, u1, vb, color);
  }
}

Text& overlay_text(DrawList& list, const Component* source, const char* text, float x, float y, float size,
                   const Rgba& color) {
  Text& t = next_text(list, source, Text::Kind::overlay);
  t.text.assign(text);
  t.anchor = Vec3(x, y, 0);
  t.size = size;
  t.color = color;
  t.depth_test = false;
  return t;
}

// OglColorMap::doDrawVisual's legend.
void add_legend(DrawList& list, const OglColorMap& map, Node& node) {
  const std::vector<Rgba>& palette = map.palette();
  if (palette.empty()) return;
  const float ox = static_cast<float>(map.legend_offset.get().x()), oy = static_cast<float>(map.legend_offset.get().y());
  const std::string& title = map.legend_title.get();
  const float y0 = title.empty() ? 0.f : 2.f * static_cast<float>(map.legend_size.get());
  // The bar, a row of pixels at a time: t from 1 at the top to 0 at the bottom, sampled
  // linearly between texel centres, repeating past the ends (the texture's default wrap).
  const int n = static_cast<int>(palette.size());
  constexpr int kRows = 100;
  for (int r = 0; r < kRows; ++r) {
    const double t = 1.0 - (r + 0.5) / kRows, u = t * n - 0.5, f = u - std::floor(u);
    const int i0 = ((static_cast<int>(std::floor(u)) % n) + n) % n, i1 = (i0 + 1) % n;
    float c[3];
    for (int k = 0; k < 3; ++k) c[k] = static_cast<float>((1 - f) * palette[i0][k] + f * palette[i1][k]);
    const float top = oy + y0 + 20.f + static_cast<float>(r);
    list.overlay_rects.insert(list.overlay_rects.end(), {ox + 10.f, top, ox + 20.f, top + 1.f, c[0], c[1], c[2], 1.f});
  }
  Rgba background{0, 0, 0, 1};  // the viewer's default
  if (const auto* bg = node.root()->find_down<BackgroundSetting>())
    background = parse_rgba(bg->color.get()).value_or(background);
  const float luminance = 0.212f * background[0] + 0.715f * background[1] + 0.072f * background[2];
  const Rgba color = luminance > 0.5f ? Rgba{0, 0, 0, 1} : Rgba{1, 1, 1, 1};
  if (!title.empty())
    overlay_text(list, &map, title.c_str(), std::floor(ox), std::floor(oy), static_cast<float>(map.legend_size.get()),
                 color);
  // As SOFA's ostream << float: the float value, 6 significant digits.
  char text[64];
  const float scale = static_cast<float>(map.legend_range_scale.get());
  std::snprintf(text, sizeof text, "%g", static_cast<double>(static_cast<float>(map.max.get()) * scale));
  overlay_text(list, &map, text, std::floor(ox), y0 + std::floor(oy), 12.f, color);
  std::snprintf(text, sizeof text, "%g", static_cast<double>(static_cast<float>(map.min.get()) * scale));
  overlay_text(list, &map, text, std::floor(ox), y0 + 120.f + std::floor(oy), 12.f, color);
}

}  // namespace

void add_texts(DrawList& list, Node& node, bool visual_models) {
  for (const auto& o : node.objects()) {
    if (o->state() != ComponentState::valid) continue;
    if (const auto* t = dynamic_cast<const Visual3DText*>(o.get())) {
      if (!visual_models || !t->enable.get() || t->text.get().empty()) continue;
      Text& x = next_text(list, t, Text::Kind::world);
      x.text = t->text.get();
      x.anchor = t->position.get();
      x.size = static_cast<float>(t->scale.get());
      x.color = parse_rgba(t->color.get()).value_or(Rgba{1, 1, 1, 1});
      x.depth_test = false;  // Visual3DText::doDrawVisual disables it
    } else if (const auto* l = dynamic_cast<const OglLabel*>(o.get())) {
      if (!visual_models || !l->enable.get()) continue;
      Text& x = next_text(list, l, Text::Kind::overlay);
      l->text(x.text);
      if (x.text.empty()) {
        --list.texts_used;
        continue;
      }
      x.anchor = Vec3(l->x.get(), l->y.get(), 0);
      x.size = static_cast<float>(l->fontsize.get());
      x.color = l->shown_color();
      x.depth_test = false;
    } else if (const auto* cm = dynamic_cast<const OglColorMap*>(o.get())) {
      if (visual_models && cm->show_legend.get()) add_legend(list, *cm, node);
    } else if (const auto* pc = dynamic_cast<const VisualPointCloud*>(o.get())) {
      if (!visual_models || !pc->enable.get() || !pc->show_indices.get()) continue;
      const FlatVec& p = pc->position.get();
      if (p.size() == 0 || p.width <= 0) continue;
      Text& x = next_text(list, pc, Text::Kind::indices);
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 c = pc->centre(i);
        x.points.insert(x.points.end(), {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])});
      }
      x.size = static_cast<float>(pc->indices_scale.get());
      x.color = parse_rgba(pc->indices_color.get()).value_or(Rgba{1, 1, 1, 1});
      x.depth_test = true;
    }
  }
  // MechanicalObject's showIndices (its draw(), whatever the display flags).
  const MechanicalState* s = node.mechanical_state;
  if (!s || s->state() != ComponentState::valid) return;
  const auto* show = dynamic_cast<const Field<bool>*>(s->find_field("showIndices"));
  if (!show || !show->get()) return;
  Text& x = next_text(list, s, Text::Kind::indices);
  if (!state_positions(*s, x.points) || x.points.empty()) {
    --list.texts_used;
    return;
  }
  const auto* scale = dynamic_cast<const Field<double>*>(s->find_field("showIndicesScale"));
  const auto* color = dynamic_cast<const Field<std::vector<double>>*>(s->find_field("showColor"));
  x.size = scale ? static_cast<float>(scale->get()) : 1.f;
  x.color = {1, 1, 1, 1};
  if (color)
    for (std::size_t c = 0; c < 4 && c < color->get().size(); ++c) x.color[c] = static_cast<float>(color->get()[c]);
  x.depth_test = true;
}

void rect_vertices(const DrawList& list, int width, int height, std::vector<float>& out) {
  if (width <= 0 || height <= 0) return;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const auto clip = [w, h](float x, float y) -> Eigen::Vector4f { return {2.f * x / w - 1.f, 1.f - 2.f * y / h, 0.f, 1.f}; };
  const std::vector<float>& r = list.overlay_rects;
  for (std::size_t i = 0; i + 8 <= r.size(); i += 8) {
    const Rgba c{r[i + 4], r[i + 5], r[i + 6], r[i + 7]};
    const Eigen::Vector4f tl = clip(r[i], r[i + 1]), tr = clip(r[i + 2], r[i + 1]), bl = clip(r[i], r[i + 3]),
                          br = clip(r[i + 2], r[i + 3]);
    vertex(out, tl, -1, -1, c), vertex(out, bl, -1, -1, c), vertex(out, tr, -1, -1, c);
    vertex(out, tr, -1, -1, c), vertex(out, bl, -1, -1, c), vertex(out, br, -1, -1, c);
  }
}

void text_vertices(const Text& t, const View& view, int width, int height, std::vector<float>& out) {
  if (width <= 0 || height <= 0) return;
  const Eigen::Matrix4f& P = view.projection;
  const auto eye_to_clip = [&](float z) {
    return [&P, z](float x, float y) -> Eigen::Vector4f { return P * Eigen::Vector4f(x, y, z, 1.f); };
  };
  switch (t.kind) {
    case Text::Kind::world: {
      const Eigen::Vector4f e = view.view * Eigen::Vector4f(static_cast<float>(t.anchor[0]),
                                                            static_cast<float>(t.anchor[1]),
                                                            static_cast<float>(t.anchor[2]), 1.f);
      glyph_row(t.text, e[0], e[1], kGlyphWidth * t.size, t.size, t.color, eye_to_clip(e[2]), out);
      break;
    }
    case Text::Kind::indices: {
      const float p11 = P(1, 1);
      if (p11 == 0.f) return;
      const bool perspective = P(3, 3) < 0.5f;
      const Rgba shadow{0.f, 0.f, 0.f, 0.7f * t.color[3]};
      std::string label;
      for (std::size_t i = 0; i * 3 + 2 < t.points.size(); ++i) {
        const Eigen::Vector4f e =
            view.view * Eigen::Vector4f(t.points[i * 3], t.points[i * 3 + 1], t.points[i * 3 + 2], 1.f);
        const float depth = perspective ? std::max(-e[2], 1e-5f) : 1.f;
        // Eye units per label height: kIndexPixels·size pixels at this depth.
        const float a = kIndexPixels * t.size * 2.f * depth / (p11 * static_cast<float>(height));
        label = std::to_string(i);
        const float left = e[0] - kGlyphWidth * static_cast<float>(label.size()) * a * 0.5f;
        const float top = e[1] + 0.5f * a;
        const float o = kShadowPixels * a / kIndexPixels;
        glyph_row(label, left + o, top - o, kGlyphWidth * a, a, shadow, eye_to_clip(e[2]), out);
        glyph_row(label, left, top, kGlyphWidth * a, a, t.color, eye_to_clip(e[2]), out);
      }
      break;
    }
    case Text::Kind::overlay: {
      const float w = static_cast<float>(width), h = static_cast<float>(height);
      const auto pixel_to_clip = [w, h](float x, float y) -> Eigen::Vector4f {
        return {2.f * x / w - 1.f, 1.f - 2.f * y / h, 0.f, 1.f};
      };
      // Pixel rows grow downwards: the glyph spans [y, y + 2·fontsize].
      glyph_row(t.text, static_cast<float>(t.anchor[0]), static_cast<float>(t.anchor[1]), t.size, -2.f * t.size,
                t.color, pixel_to_clip, out);
      break;
    }
  }
}

}  // namespace sinew::render
