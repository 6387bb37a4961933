// Colours and materials of visual models as SOFA reads them.
//
// - Colours (RGBAColor::read): a name (red, green, blue, white, black, gray,
//   cyan, magenta, yellow, darkgray, lightgray, orange, purple, pink, brown,
//   olive, silver, navy, teal, ...), "#rrggbb[aa]" or "#rgb[a]", or 3–4 numbers.
// - Materials (sofa::type::Material's text): "name Diffuse u r g b a Ambient u r g b a
//   Specular u r g b a Emissive u r g b a Shininess u s", each u a use flag.
// - OglModel's `color` pseudo-attribute is Material::setColor: ambient = 0.2·c,
//   diffuse = specular = emissive = c, use flags unchanged.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace sinew {
class OglModel;
}

namespace sinew::render {

using Rgba = std::array<float, 4>;

struct Material {
  Rgba ambient{0.2f, 0.2f, 0.2f, 1.f}, diffuse{0.75f, 0.75f, 0.75f, 1.f}, specular{1.f, 1.f, 1.f, 1.f},
      emissive{0.f, 0.f, 0.f, 0.f};
  float shininess = 45.f;
  bool use_ambient = true, use_diffuse = true, use_specular = false, use_emissive = false, use_shininess = false;
  void set_color(const Rgba& c);
};

std::optional<Rgba> parse_color(const std::string& text);
// Reads the fields present over `m`; false when the text is not a material.
bool parse_material(const std::string& text, Material& m);

// What a fragment needs: the terms of OglModel::drawGroup after the use flags.
struct Shading {
  Rgba ambient, diffuse, specular, emissive;
  float shininess;
};
Shading shading_of(const Material& m);

// The material of an OglModel: its `material` field, then its `color` pseudo-attribute.
Material material_of(const OglModel& model);

}  // namespace sinew::render
