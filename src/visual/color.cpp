// SOFA's RGBAColor text forms, shared by the visual components (which
// validate their colours at load) and the renderer (which draws them).
#include "visual/color.h"

#include <cctype>
#include <sstream>
#include <vector>

namespace sinew {

namespace {

struct Named {
  const char* name;
  Rgba rgba;
};
// SOFA's RGBAColor names (type/RGBAColor.cpp).
const Named kNames[] = {
    {"white", {1, 1, 1, 1}},           {"black", {0, 0, 0, 1}},         {"red", {1, 0, 0, 1}},
    {"green", {0, 1, 0, 1}},           {"blue", {0, 0, 1, 1}},          {"cyan", {0, 1, 1, 1}},
    {"magenta", {1, 0, 1, 1}},         {"yellow", {1, 1, 0, 1}},        {"gray", {0.5f, 0.5f, 0.5f, 1}},
    {"grey", {0.5f, 0.5f, 0.5f, 1}},   {"darkgray", {0.25f, 0.25f, 0.25f, 1}},
    {"lightgray", {0.75f, 0.75f, 0.75f, 1}}, {"orange", {1, 0.5f, 0, 1}}, {"purple", {0.5f, 0, 1, 1}},
    {"pink", {1, 0, 0.5f, 1}},         {"brown", {0.6f, 0.3f, 0, 1}},   {"olive", {0.5f, 0.5f, 0, 1}},
    {"silver", {0.75f, 0.75f, 0.75f, 1}}, {"navy", {0, 0, 0.5f, 1}},  {"teal", {0, 0.5f, 0.5f, 1}},
    {"lime", {0.5f, 1, 0, 1}},         {"aqua", {0, 1, 1, 1}},          {"transparent", {0, 0, 0, 0}},
};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::optional<Rgba> parse_rgba(const std::string& raw) {
  std::string text = raw;
  text.erase(0, text.find_first_not_of(" \t\n"));
  text.erase(text.find_last_not_of(" \t\n") + 1);
  if (text.empty()) return std::nullopt;
  if (text[0] == '#') {
    const std::string h = text.substr(1);
    std::vector<int> d;
    for (char c : h) {
      const int v = hex_digit(c);
      if (v < 0) return std::nullopt;
      d.push_back(v);
    }
    Rgba out{0, 0, 0, 1};
    if (d.size() == 3 || d.size() == 4) {
      for (std::size_t i = 0; i < d.size(); ++i) out[i] = (d[i] * 17) / 255.f;
    } else if (d.size() == 6 || d.size() == 8) {
      for (std::size_t i = 0; i < d.size() / 2; ++i) out[i] = (d[2 * i] * 16 + d[2 * i + 1]) / 255.f;
    } else {
      return std::nullopt;
    }
    return out;
  }
  if (std::isalpha(static_cast<unsigned char>(text[0]))) {
    std::string lower = text;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const Named& n : kNames)
      if (lower == n.name) return n.rgba;
    return std::nullopt;
  }
  std::istringstream in(text);
  std::vector<float> v;
  float x;
  while (in >> x) v.push_back(x);
  if (!in.eof() || v.size() < 3 || v.size() > 4) return std::nullopt;
  return Rgba{v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.f};
}


}  // namespace sinew

#include "core/component.h"
#include "core/diagnostics.h"
#include "core/value_text.h"

namespace sinew {

void check_color_field(const Component& c, const Field<std::string>& f, Diagnostics& diag) {
  if (!f.link_path().empty() || parse_rgba(f.value())) return;
  diag.error(c.where, c.describe() + ": " + f.name() + " " + quote_value(f.value()) +
                          " is not a colour (a name such as red, #rrggbb[aa] or r g b [a])");
}

}  // namespace sinew
