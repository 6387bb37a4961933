// What SOFA's shader-side components share (OglShaderElement): an `id`
// (the GLSL name of the uniform, attribute, macro or sampler; the
// component's name when empty) and `indexShader` (which of the shader's
// versions it applies to), and what the renderer reads of them to run the
// shader of their node (render/scene_shader.h): a #define, a uniform's
// values, a vertex attribute's values or a texture.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

// What an element gives the shader, as the renderer reads it: `values` flat, `width`
// numbers per item (a vec3 uniform: 3; a mat4 array: 16 per matrix; an attribute: per vertex).
struct ShaderInput {
  enum class Kind { none, macro, int_uniform, float_uniform, matrix_uniform, attribute, texture };
  Kind kind = Kind::none;
  int width = 1;
  bool array = false;      // a uniform array (`name[0]`), else one value
  bool transpose = false;  // matrices given row by row, sent transposed (OglMatrix4VectorVariable)
  std::vector<float> values;  // a procedural texture's texels (0-255, one channel)
  std::string text;  // a macro's value; a texture's image file (empty: procedural)
  // Textures: the unit, wrapping and filtering, a procedural image's size.
  unsigned unit = 0;
  bool repeat = false, linear = true;
  int texture_width = 0, texture_height = 0;
  // Back to the defaults, keeping the storage of `values` and `text`.
  void reset() {
    kind = Kind::none;
    width = 1;
    array = transpose = false;
    values.clear();
    text.clear();
    unit = 0;
    repeat = false, linear = true;
    texture_width = texture_height = 0;
  }
};

class ShaderElement : public VisualComponent {
 public:
  Field<std::string> id{this, "id", "", "GLSL name this element sets (the component's name when empty)", "Shader"};
  Field<unsigned> index_shader{this, "indexShader", 0u, "index of the shader version this element applies to",
                               "Shader"};
  void init() override;
  // What it gives the shader now (links followed), written into `in` (reset first; its
  // storage reused, so a frame that reads the same sizes again allocates nothing).
  virtual void input(ShaderInput& in) const { in.reset(); }
};

// Warns once per listed shader or texture file that does not exist (SOFA logs
// the failed load when the viewer compiles the shader); `what` names the field.
void warn_missing_files(const Component& c, const std::string& what, const std::vector<std::string>& files);

}  // namespace sinew
