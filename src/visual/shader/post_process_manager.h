// PostProcessManager (Sofa.GL.Component.Shader): in the root node, the viewer draws the
// scene into an off-screen picture (colour and depth textures) through a 60° perspective of
// aspect 1 between zNear and zFar — the manager's own projection, whatever the camera's —
// then covers the view with one quad drawn by the OglShader of the manager's node or above
// (SOFA's depthOfField.vert/.frag in its example), reading `colorTexture` (unit 0),
// `depthTexture` (unit 1) and `pixelSize` (1/width, 1/height). Drawn by src/render
// (docs/render.md). Without such a shader SOFA applies no pass (a warning here).
#pragma once

#include "core/roles.h"

namespace sinew {

class OglShader;

class PostProcessManager final : public VisualComponent {
 public:
  Field<double> z_near{this, "zNear", 1.0, "near distance of the pass's projection (for the depth buffer)",
                       "Visualization", "length"};
  Field<double> z_far{this, "zFar", 100.0, "far distance of the pass's projection (for the depth buffer)",
                      "Visualization", "length"};
  void init() override;
  // The shader the pass is drawn with (found at init); null: no pass.
  const OglShader* shader() const { return shader_; }

 private:
  const OglShader* shader_ = nullptr;
};

}  // namespace sinew
