// Runs a scene's OglShader (SOFA's GLSL files, translated by render/legacy_glsl.h) for the
// visual models under it. The fixed-function state those shaders read is set as OpenGL's
// would be for SOFA's viewer: the modelview (the camera; visual models are in world
// coordinates), the projection, the normal matrix; the model's material (front and back
// alike); the LightManager's lights in eye space, or without one SOFA's viewer light 0 (a
// point at (−0.7, 0.3, 0) in eye space, ambient 0.5, diffuse 0.9, specular 1; no global
// ambient; as runSofa's and HeadlessRecorder's initializeGL); the products of the two. Then
// the uniforms of the shader's elements (OglXxxVariable), its textures (OglTexture, on GL
// units past the renderer's own), and per-vertex attributes (OglXxxAttribute).
//
// A shader that does not compile or link is reported once on stderr with the compiler's log
// and its models are drawn with the renderer's own shading.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/camera_view.h"
#include "render/draw_list.h"

namespace sinew::render {

class SceneShaders {
 public:
  SceneShaders() = default;
  ~SceneShaders();  // the GL context must be current
  SceneShaders(const SceneShaders&) = delete;
  SceneShaders& operator=(const SceneShaders&) = delete;

  // Binds the program of `s` and sets what it reads for drawing `b`; false (nothing bound)
  // when it cannot run. Precondition: the batch's vertex array is bound; its per-vertex
  // attributes are added to it, in `attribute_buffers` (grown as needed, with their capacity).
  bool bind(const SceneShader& s, const Batch& b, const View& view, const Lighting& lighting,
            std::vector<unsigned>& attribute_buffers, std::vector<std::size_t>& attribute_capacity);

  // GL texture units the scene's textures use: kFirstUnit + OglTexture's textureUnit.
  static constexpr int kFirstUnit = 11;
  static constexpr int kUnits = 16;

 private:
  // A linked program and where its uniforms are (read once at link: a frame builds no names).
  struct Light {
    int ambient = -1, diffuse = -1, specular = -1, position = -1, half = -1, spot_direction = -1;
    int scalars[6] = {-1, -1, -1, -1, -1, -1};  // exponent, cutoff, cos cutoff, attenuations
    int products[3] = {-1, -1, -1};             // gl_FrontLightProduct ambient, diffuse, specular
  };
  struct Program {
    std::uint64_t key = 0;  // hash of the files, defines, uniform and sampler names
    unsigned id = 0;        // 0: failed
    int matrices[7] = {-1, -1, -1, -1, -1, -1, -1}, normal_matrix = -1, texture_matrix = -1;
    Light lights[8];
    int material[5] = {-1, -1, -1, -1, -1};  // emission, ambient, diffuse, specular, shininess
    int model_ambient = -1, scene_color = -1;
    std::vector<int> uniforms, samplers;  // by index in SceneShader::uniforms / textures
    std::vector<std::pair<std::uint64_t, unsigned>> textures;  // (input's hash, texture) by sampler
  };
  Program* program_for(const SceneShader& s);  // null when it cannot run
  void locate(Program& p, const SceneShader& s);
  unsigned texture_for(const ShaderInput& t, std::uint64_t hash);
  std::vector<Program> programs_;
  std::vector<std::pair<std::uint64_t, unsigned>> textures_;  // by the input's hash
};

}  // namespace sinew::render
