#include "visual/shader/light.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "visual/color.h"

namespace sinew {

void LightManager::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, ambient, diag);
}

void LightManager::init() {}

bool LightManager::put_light(const Light& l) {
  for (const Light* k : lights_)
    if (k == &l) return true;  // initialised again
  if (lights_.size() >= kMaxLights) {
    msg_warning("the maximum of " + std::to_string(kMaxLights) + " lights is reached: " + l.describe() +
                " is not used");
    return false;
  }
  lights_.push_back(&l);
  return true;
}

void Light::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  check_color_field(*this, color, diag);
}

void Light::init() {
  LightManager* lm = node() ? node()->find_up<LightManager>() : nullptr;
  if (!lm) {
    msg_warning("no LightManager in this node or above: the light is not used");
    return;
  }
  lm->put_light(*this);
}

LightSource Light::source() const {
  LightSource s;
  const Rgba c = parse_rgba(color.get()).value_or(Rgba{1, 1, 1, 1});
  s.color[0] = c[0], s.color[1] = c[1], s.color[2] = c[2];
  s.texture_size = shadow_texture_size.get();
  s.z_near = z_near.get(), s.z_far = z_far.get();
  s.shadow_factor = static_cast<float>(shadow_factor.get());
  s.vsm_light_bleeding = static_cast<float>(vsm_light_bleeding.get());
  s.vsm_min_variance = static_cast<float>(vsm_min_variance.get());
  return s;
}

LightSource DirectionalLight::source() const {
  LightSource s = Light::source();
  const Vec3 d = direction.get();
  s.type = LightSource::Type::directional;
  s.position[0] = d.x(), s.position[1] = d.y(), s.position[2] = d.z(), s.position[3] = 0;
  return s;
}

LightSource PositionalLight::source() const {
  LightSource s = Light::source();
  const Vec3 p = position.get();
  s.type = LightSource::Type::positional;
  s.position[0] = p.x(), s.position[1] = p.y(), s.position[2] = p.z(), s.position[3] = 1;
  s.linear_attenuation = static_cast<float>(attenuation.get());
  return s;
}

void SpotLight::parse(AttributeMap& attrs, Diagnostics& diag) {
  PositionalLight::parse(attrs, diag);
  // OpenGL refuses a cut-off outside [0, 90] other than 180, and an exponent outside [0, 128],
  // keeping its default (180: no cone; 0: even light): what SOFA's spot then shows.
  const double c = cutoff.value();
  if (!((c >= 0 && c <= 90) || c == 180))
    diag.warning(where, describe() + ": cutoff " + std::to_string(c) +
                            " is not in [0, 90] nor 180; OpenGL ignores it: no cone (180)");
  if (!(exponent.value() >= 0 && exponent.value() <= 128))
    diag.warning(where, describe() + ": exponent " + std::to_string(exponent.value()) +
                            " is not in [0, 128]; OpenGL ignores it: exponent 0");
}

LightSource SpotLight::source() const {
  LightSource s = PositionalLight::source();
  s.type = LightSource::Type::spot;
  Vec3 d = direction.get();
  if (lookat.get()) d -= position.get();
  if (d.norm() > 0) d.normalize();
  s.spot_direction[0] = d.x(), s.spot_direction[1] = d.y(), s.spot_direction[2] = d.z();
  const double c = cutoff.get(), e = exponent.get();
  s.cutoff = (c >= 0 && c <= 90) ? static_cast<float>(c) : 180.f;
  s.exponent = (e >= 0 && e <= 128) ? static_cast<float>(e) : 0.f;
  return s;
}

void register_lights(Registry& r) {
  auto add = [&r](const char* name, const char* what, decltype(ComponentInfo::create) create) {
    ComponentInfo info;
    info.name = name;
    info.category = "Visual";
    info.description = what;
    info.create = std::move(create);
    r.add(std::move(info));
  };
  add("LightManager", "collects the lights of its subtree; a scene with one is lit by them", creator<LightManager>());
  add("DirectionalLight", "a light at infinity in a direction", creator<DirectionalLight>());
  add("PositionalLight", "a point light", creator<PositionalLight>());
  add("SpotLight", "a point light limited to a cone", creator<SpotLight>());
}

}  // namespace sinew
