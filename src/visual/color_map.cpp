#include "visual/color_map.h"

#include <cstdlib>
#include <sstream>

#include <cmath>

namespace sinew {

namespace {

// RGBAColor::fromHSVA: h in degrees, s, v, a in [0, 1], single precision as SOFA.
Rgba from_hsva(float h, float s, float v, float a) {
  Rgba c{0, 0, 0, a};
  const int i = static_cast<int>(std::floor(h / 60.0f)) % 6;
  const float f = h / 60.0f - std::floor(h / 60.0f);
  const float p = v * (1 - s);
  const float q = v * (1 - s * f);
  const float t = v * (1 - (1 - f) * s);
  switch (i) {
    case 0: c[0] = v, c[1] = t, c[2] = p; break;
    case 1: c[0] = q, c[1] = v, c[2] = p; break;
    case 2: c[0] = p, c[1] = v, c[2] = t; break;
    case 3: c[0] = p, c[1] = q, c[2] = v; break;
    case 4: c[0] = t, c[1] = p, c[2] = v; break;
    case 5: c[0] = v, c[1] = p, c[2] = q; break;
    default: break;
  }
  return c;
}

}  // namespace

const std::vector<std::string>& color_map_schemes() {
  static const std::vector<std::string> kSchemes = {
      "Red to Blue",    "Blue to Red",     "HSV",           "Red",          "Green",
      "Blue",           "Yellow to Cyan",  "Cyan to Yellow", "Red to Yellow", "Yellow to Red",
      "Yellow to Green", "Green to Yellow", "Green to Cyan", "Cyan to Green", "Cyan to Blue",
      "Blue to Cyan",   "BlueInv",         "GreenInv",      "RedInv",       "Custom"};
  return kSchemes;
}

std::vector<Rgba> build_palette(unsigned n, const std::string& s) {
  if (n < 2) n = 256;
  std::vector<Rgba> p;
  p.reserve(n);
  const float lin = 1.0f / static_cast<float>(n);  // the RGB ramps' step
  const float ramp = 1.4f / static_cast<float>(n);  // the two-part single-hue ramps' step
  if (s == "Red to Blue" || s == "Blue to Red") {
    const float step = (2.0f / 3.0f) / static_cast<float>(n - 1);
    for (unsigned i = 0; i < n; ++i) {
      const float h = s == "Red to Blue" ? i * step * 360 : (2.0f / 3.0f - i * step) * 360;
      p.push_back(from_hsva(h, 1.0f, 1.0f, 1.0f));
    }
  } else if (s == "Yellow to Cyan" || s == "Cyan to Yellow") {
    const float step = (0.5f - 1.0f / 6.0f) / static_cast<float>(n - 1);
    for (unsigned i = 0; i < n; ++i) {
      const float h = s == "Yellow to Cyan" ? (1.0f / 6.0f + i * step) * 360 : (0.5f - i * step) * 360;
      p.push_back(from_hsva(h, 1.0f, 1.0f, 1.0f));
    }
  } else if (s == "Yellow to Red") {
    for (unsigned i = 0; i < n; ++i) p.push_back({1.0f, 1.0f - i * lin, 0.0f, 1.0f});
  } else if (s == "Yellow to Green") {
    for (unsigned i = 0; i < n; ++i) p.push_back({1.0f - i * lin, 1.0f, 0.0f, 1.0f});
  } else if (s == "Green to Yellow") {
    for (unsigned i = 0; i < n; ++i) p.push_back({i * lin, 1.0f, 0.0f, 1.0f});
  } else if (s == "Green to Cyan") {
    for (unsigned i = 0; i < n; ++i) p.push_back({0.0f, 1.0f, i * lin, 1.0f});
  } else if (s == "Cyan to Green") {
    for (unsigned i = 0; i < n; ++i) p.push_back({0.0f, 1.0f, 1.0f - i * lin, 1.0f});
  } else if (s == "Cyan to Blue") {
    for (unsigned i = 0; i < n; ++i) p.push_back({0.0f, 1.0f - i * lin, 1.0f, 1.0f});
  } else if (s == "Blue to Cyan") {
    for (unsigned i = 0; i < n; ++i) p.push_back({0.0f, i * lin, 1.0f, 1.0f});
  } else if (s == "Red" || s == "Green" || s == "Blue") {
    const int k = s == "Red" ? 0 : s == "Green" ? 1 : 2;
    for (unsigned i = 0; i < n / 2; ++i) {
      Rgba c{0.0f, 0.0f, 0.0f, 1.0f};
      c[k] = 0.3f + i * ramp;
      p.push_back(c);
    }
    for (unsigned i = 0; i < n - n / 2; ++i) {
      Rgba c{i * ramp, i * ramp, i * ramp, 1.0f};
      c[k] = 1.0f;
      p.push_back(c);
    }
  } else if (s == "RedInv" || s == "GreenInv" || s == "BlueInv") {
    const int k = s == "RedInv" ? 0 : s == "GreenInv" ? 1 : 2;
    for (unsigned i = 0; i < n - n / 2; ++i) {
      Rgba c{0.7f - i * ramp, 0.7f - i * ramp, 0.7f - i * ramp, 1.0f};
      c[k] = 1.0f;
      p.push_back(c);
    }
    for (unsigned i = 0; i < n / 2; ++i) {
      Rgba c{0.0f, 0.0f, 0.0f, 1.0f};
      c[k] = 1.0f - i * ramp;
      p.push_back(c);
    }
  } else {  // "HSV", and the names SOFA's ColorMap does not know
    const float step = 1.0f / static_cast<float>(n - 1);
    for (unsigned i = 0; i < n; ++i) p.push_back(from_hsva(i * step * 360, 1.0f, 1.0f, 1.0f));
  }
  return p;
}

Rgba evaluate_palette(const std::vector<Rgba>& palette, double vmin, double vmax, double v) {
  const double scale = vmax == vmin ? 0.0 : static_cast<double>(palette.size() - 1) / (vmax - vmin);
  const double e = (v - vmin) * scale;
  if (e < 0) return palette.front();
  const auto i = static_cast<unsigned>(e);
  if (i >= palette.size() - 1) return palette.back();
  const Rgba& a = palette[i];
  const Rgba& b = palette[i + 1];
  const float t = static_cast<float>(e - i);
  Rgba c;
  for (int k = 0; k < 4; ++k) c[k] = a[k] + (b[k] - a[k]) * t;
  return c;
}

std::vector<Rgba> parse_color_map(const std::string& text) {
  const std::size_t a = text.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return {};
  const std::string t = text.substr(a, text.find_last_not_of(" \t\r\n") + 1 - a);
  static const char* const schemes[] = {"Red to Blue",   "Blue to Red",   "Yellow to Cyan",  "Cyan to Yellow",
                                        "Red to Yello",  "Yellow to Red", "Yellow to Green", "Green to Yellow",
                                        "Green to Cyan", "Cyan to Green", "Cyan to Blue",    "Blue to Cyan",
                                        "Red",           "RedInv",        "Green",           "GreenInv",
                                        "Blue",          "BlueInv",       "HSV"};
  for (const char* s : schemes)
    if (t == s) return build_palette(256, t);
  std::vector<std::string> words;
  std::istringstream in(t);
  for (std::string w; in >> w;) words.push_back(w);
  auto number = [](const std::string& w, float& v) {
    char* end = nullptr;
    v = std::strtof(w.c_str(), &end);
    return end && *end == '\0' && end != w.c_str();
  };
  std::vector<Rgba> out;
  for (std::size_t i = 0; i < words.size();) {
    float v = 0;
    if (number(words[i], v)) {
      Rgba c{0, 0, 0, 1};
      int k = 0;
      while (k < 4 && i < words.size() && number(words[i], v)) c[k++] = v, ++i;
      if (k < 3) return {};
      out.push_back(c);
    } else if (auto c = parse_rgba(words[i])) {
      out.push_back(*c);
      ++i;
    } else {
      return {};
    }
  }
  return out;
}

}  // namespace sinew
