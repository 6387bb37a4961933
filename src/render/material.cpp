#include "render/material.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

#include "visual/color.h"
#include "visual/ogl_model.h"

namespace sinew::render {

void Material::set_color(const Rgba& c) {
  ambient = {c[0] * 0.2f, c[1] * 0.2f, c[2] * 0.2f, c[3]};
  diffuse = specular = emissive = c;
}

std::optional<Rgba> parse_color(const std::string& raw) { return parse_rgba(raw); }

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
