// Shadow maps of SOFA's shadow-mapping shaders (OglShadowShader with a LightManager whose
// `shadows` is on): how a spot or directional light sees the scene, and the size of its map.
// Pure functions; the passes are GlRenderer's.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "core/roles.h"
#include "visual/shader/light.h"

namespace sinew::render {

// A light's view for its shadow map: world → the light's clip space, and the depth stored in
// the map: a spot's eye depth over its far plane (clip.w / far), a directional light's
// 0.5·ndc.z + 0.5 (linear, orthographic).
struct LightView {
  Eigen::Matrix4f view_projection = Eigen::Matrix4f::Identity();
  bool perspective = false;
  float far = 1.f;
};

// The view of a spot (from its position along its direction, a square frustum of twice its
// cut-off, at most 170°) or of a directional light (an orthographic box around [min, max] along
// its `direction`, the way SOFA's shadow shader reads it: the direction the light travels); the
// frame's up is y, or ∓z when the light is vertical (SOFA's choice). Near and far: the light's
// zNear and zFar when given, else fitted to the corners of [min, max]. nullopt for a positional
// light (SOFA's shadow shaders have none), an empty box or a scene wholly behind a spot.
std::optional<LightView> light_view(const LightSource& s, const Vec3& min, const Vec3& max);

// SOFA's Light::computeShadowMapSize: shadowTextureSize when given, else 1024, 512, 256 or 128,
// the largest the picture holds in both directions.
int shadow_map_size(unsigned texture_size, int width, int height);

}  // namespace sinew::render
