#include "engine/texture_interpolation.h"

#include <algorithm>
#include <string>

#include "core/registry.h"

namespace sinew {

TextureInterpolation::TextureInterpolation(int width)
    : input_states(this, "input_states", FlatVec{width, {}}, "field values per point", "Inputs") {
  add_input(&input_states);
  add_input(&scalar_field);
  add_input(&min_value);
  add_input(&max_value);
  add_input(&manual_scale);
  add_output(&output_coordinates);
}

void TextureInterpolation::init() {
  set_dirty();
  if (!input_states.is_set()) planar_mapping();
}

// SOFA's standardLinearInterpolation: the bounding box (from ±1e5), the last flat axis
// dropped, the other two scaled to [0, 1].
void TextureInterpolation::planar_mapping() {
  const auto& coords = input_coordinates.get();
  double lo[3] = {100000, 100000, 100000}, hi[3] = {-100000, -100000, -100000};
  for (const Vec3& p : coords)
    for (int j = 0; j < 3; ++j) {
      if (p[j] < lo[j]) lo[j] = p[j];
      if (p[j] > hi[j]) hi[j] = p[j];
    }
  int flat = 0;
  for (int j = 0; j < 3; ++j)
    if (lo[j] == hi[j]) flat = j;
  int a1 = 0, a2 = 1;
  if (flat == 0) {
    a1 = 1;
    a2 = 2;
  } else if (flat == 1) {
    a1 = 2;
    a2 = 0;
  }
  const double us = 1 / (hi[a1] - lo[a1]), vs = 1 / (hi[a2] - lo[a2]);
  std::vector<Vec2>& out = output_coordinates.edit();
  out.assign(coords.size(), Vec2::Zero());
  for (std::size_t i = 0; i < coords.size(); ++i)
    out[i] = Vec2((coords[i][a1] - lo[a1]) * us, (coords[i][a2] - lo[a2]) * vs);
}

void TextureInterpolation::do_update() {
  if (!input_states.is_set()) return;
  const FlatVec& in = input_states.get();
  const std::size_t n = in.size();
  const int w = in.width;
  std::vector<Vec2>& out = output_coordinates.edit();
  out.resize(n);
  if (n == 0) return;
  std::vector<double> s(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!scalar_field.get() && w > 1) {
      double sum = 0;
      for (int j = 0; j < w; ++j) sum += in.data[i * w + j];
      s[i] = sum / w;
    } else {
      s[i] = in.data[i * w];
    }
  }
  double lo = 0, hi = 0;
  if (manual_scale.get()) {
    if (min_value.get() < max_value.get()) {
      lo = min_value.get();
      hi = max_value.get();
    } else {
      msg_error("min_value (" + std::to_string(min_value.get()) + ") is not smaller than max_value (" +
                std::to_string(max_value.get()) + ")");
    }
  } else {
    lo = *std::min_element(s.begin(), s.end());
    hi = *std::max_element(s.begin(), s.end());
  }
  const double scale = 1 / (hi - lo);
  for (std::size_t i = 0; i < n; ++i) out[i] = Vec2((s[i] - lo) * scale, 0.0);
}

void register_texture_interpolation(Registry& r) {
  ComponentInfo info;
  info.name = "TextureInterpolation";
  info.category = "Engine/Generate";
  info.description = "texture coordinates showing a field's values on a surface (colour map)";
  info.templates = {"Vec1d", "Vec2d", "Vec3d"};
  info.default_template = "Vec3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t == "Vec1d") return std::make_unique<TextureInterpolation>(1);
    if (t == "Vec2d") return std::make_unique<TextureInterpolation>(2);
    if (t == "Vec3d") return std::make_unique<TextureInterpolation>(3);
    return nullptr;
  };
  r.add(std::move(info));
}

}  // namespace sinew
