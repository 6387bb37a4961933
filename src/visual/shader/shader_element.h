// What SOFA's shader-side components share (OglShaderElement): an `id`
// (the GLSL name of the uniform, attribute, macro or sampler; the
// component's name when empty) and `indexShader` (which of the shader's
// versions it applies to). Sinew's renderer draws with its own shading
// (docs/render.md), so these components are accepted, validated and kept
// for scripts and viewers; none of them changes a batch run.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class ShaderElement : public VisualComponent {
 public:
  Field<std::string> id{this, "id", "", "GLSL name this element sets (the component's name when empty)", "Shader"};
  Field<unsigned> index_shader{this, "indexShader", 0u, "index of the shader version this element applies to",
                               "Shader"};
  void init() override;
};

// Warns once per listed shader or texture file that does not exist (SOFA logs
// the failed load when the viewer compiles the shader); `what` names the field.
void warn_missing_files(const Component& c, const std::string& what, const std::vector<std::string>& files);

}  // namespace sinew
