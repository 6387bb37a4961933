#include "render/material.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

#include "visual/ogl_model.h"

namespace sinew::render {

void Material::set_color(const Rgba& c) {
  ambient = {c[0] * 0.2f, c[1] * 0.2f, c[2] * 0.2f, c[3]};
  diffuse = specular = emissive = c;
}

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

std::optional<Rgba> parse_color(const std::string& raw) {
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

bool parse_material(const std::string& text, Material& m) {
  std::istringstream in(text);
  std::string word;
  if (!(in >> word)) return false;  // the material's name
  bool any = false;
  auto read_rgba = [&](bool& use, Rgba& c) {
    int u = 0;
    if (!(in >> u >> c[0] >> c[1] >> c[2] >> c[3])) return false;
    use = u != 0;
    return true;
  };
  while (in >> word) {
    bool ok = true;
    if (word == "Diffuse") ok = read_rgba(m.use_diffuse, m.diffuse);
    else if (word == "Ambient") ok = read_rgba(m.use_ambient, m.ambient);
    else if (word == "Specular") ok = read_rgba(m.use_specular, m.specular);
    else if (word == "Emissive") ok = read_rgba(m.use_emissive, m.emissive);
    else if (word == "Shininess") {
      int u = 0;
      ok = static_cast<bool>(in >> u >> m.shininess);
      m.use_shininess = u != 0;
    } else {
      continue;  // texture names and future keywords
    }
    if (!ok) return any;
    any = true;
  }
  return any;
}

Shading shading_of(const Material& m) {
  // OglModel::drawGroup: a term whose use flag is off is black; no shininess means 45;
  // a shininess of 0 turns specular off.
  Shading s;
  const Rgba zero{0, 0, 0, 0};
  s.ambient = m.use_ambient ? m.ambient : zero;
  s.diffuse = m.use_diffuse ? m.diffuse : zero;
  s.specular = m.use_specular ? m.specular : zero;
  s.emissive = m.use_emissive ? m.emissive : zero;
  s.shininess = m.use_shininess ? std::min(m.shininess, 128.f) : 45.f;
  if (s.shininess == 0.f) {
    s.specular = zero;
    s.shininess = 1.f;
  }
  // Transparency comes from the diffuse alpha (blending off here: opaque).
  return s;
}

Material material_of(const OglModel& model) {
  Material m;
  if (!model.material.get().empty()) parse_material(model.material.get(), m);
  if (!model.color().empty())
    if (auto c = parse_color(model.color())) m.set_color(*c);
  return m;
}

}  // namespace sinew::render
