// SOFA's lights (Sofa.GL.Component.Shader: LightManager, DirectionalLight, PositionalLight,
// SpotLight). A light attaches at init to the LightManager of its node or the nearest above
// (at most 8, in init order, as SOFA's MAX_NUMBER_OF_LIGHTS); a scene with a LightManager is
// lit by its lights instead of the viewer's headlight (src/render). Lights are fixed-function
// OpenGL lights: each light's colour is its ambient, diffuse and specular intensity; a
// position or direction is in world coordinates (SOFA sets them under the camera's modelview;
// PositionalLight's `fixed` changes the projection matrix, which OpenGL does not apply to
// light positions, so it has no effect there and none here). Shadows: models under an
// OglShadowShader are shaded as SOFA's shadow-mapping shaders do, with shadow maps of the spot
// and directional lights when the LightManager's `shadows` is on (src/render, docs/render.md).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class Light;

class LightManager final : public VisualComponent {
 public:
  static constexpr std::size_t kMaxLights = 8;

  Field<bool> shadows{this, "shadows", false, "shadows of the spot and directional lights on models under an OglShadowShader", "Visualization"};
  Field<bool> soft_shadows{this, "softShadows", false, "soft shadows (variance shadow maps)", "Visualization"};
  Field<std::string> ambient{this, "ambient", "0 0 0 0", "global ambient light (GL_LIGHT_MODEL_AMBIENT)",
                             "Visualization"};
  Field<bool> debug_draw{this, "debugDraw", false, "draw the lights' shadow textures (not drawn)", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  // The lights attached so far, in init order (at most kMaxLights).
  const std::vector<const Light*>& lights() const { return lights_; }
  // Called by Light::init; false (and a warning) past kMaxLights.
  bool put_light(const Light& l);

 private:
  std::vector<const Light*> lights_;
};

// A light as the renderer uses it: world position (w = 1) or direction towards the light
// (w = 0), colour, and for spots the direction, cut-off (degrees; 180: no cone) and exponent;
// its shadow parameters (used under an OglShadowShader).
struct LightSource {
  enum class Type { directional = 0, positional = 1, spot = 2 };  // SOFA's getLightType()
  Type type = Type::directional;
  double position[4] = {0, 0, 1, 0};
  float color[3] = {1, 1, 1};
  double spot_direction[3] = {0, 0, -1};
  float cutoff = 180.f, exponent = 0.f, linear_attenuation = 0.f;
  // Shadows: on when the LightManager's `shadows` is (SOFA links each light's shadowsEnabled
  // and softShadows to its LightManager's); shadow map size (0: from the picture's size) and
  // the light view's near and far planes (0: fitted to the scene).
  bool shadows = false, soft = false;
  unsigned texture_size = 0;
  double z_near = 0, z_far = 0;
  float shadow_factor = 1.f, vsm_light_bleeding = 0.05f, vsm_min_variance = 0.001f;
};

class Light : public VisualComponent {
 public:
  Field<std::string> color{this, "color", "1 1 1 1", "colour (intensity) of the light", "Visualization"};
  Field<unsigned> shadow_texture_size{this, "shadowTextureSize", 0u, "size of the shadow map (0: from the picture's size)",
                                      "Visualization"};
  Field<bool> draw_source{this, "drawSource", false, "draw the light source", "Visualization"};
  Field<double> z_near{this, "zNear", 0.0, "near plane of the light's shadow view (0: fitted to the scene)", "Visualization"};
  Field<double> z_far{this, "zFar", 0.0, "far plane of the light's shadow view (0: fitted to the scene)", "Visualization"};
  Field<bool> shadows_enabled{this, "shadowsEnabled", true, "shadows from this light (taken from the LightManager's shadows, as SOFA)", "Visualization"};
  Field<bool> soft_shadows{this, "softShadows", false, "soft shadows (taken from the LightManager's softShadows, as SOFA)", "Visualization"};
  Field<double> shadow_factor{this, "shadowFactor", 1.0, "darkness of the shadows (1: no direct light in them)", "Visualization"};
  Field<double> vsm_light_bleeding{this, "VSMLightBleeding", 0.05, "soft shadows: light-bleeding reduction",
                                   "Visualization"};
  Field<double> vsm_min_variance{this, "VSMMinVariance", 0.001, "soft shadows: minimal variance",
                                 "Visualization"};
  Field<unsigned> texture_unit{this, "textureUnit", 1u, "texture unit of the shadow map (SOFA's; not needed here)",
                               "Visualization"};
  Field<std::vector<double>> model_view_matrix{this, "modelViewMatrix", {}, "the light's view matrix (output)",
                                               "Visualization"};
  Field<std::vector<double>> projection_matrix{this, "projectionMatrix", {}, "the light's projection (output)",
                                               "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  // The light for the renderer (the colour parsed; white if it cannot be).
  virtual LightSource source() const;
};

class DirectionalLight final : public Light {
 public:
  Field<Vec3> direction{this, "direction", Vec3(0, 0, -1), "direction towards the light (OpenGL's w = 0 position)",
                        "Visualization"};
  LightSource source() const override;
};

class PositionalLight : public Light {
 public:
  Field<bool> fixed{this, "fixed", false, "fix the light to the camera (no effect in SOFA, see above)",
                    "Visualization"};
  Field<Vec3> position{this, "position", Vec3(-0.7, 0.3, 0.0), "position of the light", "Visualization", "length"};
  Field<double> attenuation{this, "attenuation", 0.0, "linear attenuation with the distance", "Visualization"};
  LightSource source() const override;
};

class SpotLight final : public PositionalLight {
 public:
  Field<Vec3> direction{this, "direction", Vec3(0, 0, -1), "direction of the spot", "Visualization"};
  Field<double> cutoff{this, "cutoff", 30.0, "half angle of the cone (degrees)", "Visualization"};
  Field<double> exponent{this, "exponent", 1.0, "concentration of the light in the cone", "Visualization"};
  Field<bool> lookat{this, "lookat", false, "direction is the point the spot looks at", "Visualization"};
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  LightSource source() const override;
};

}  // namespace sinew
