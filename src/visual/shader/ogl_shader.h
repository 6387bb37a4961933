// OglShader (SOFA's Sofa.GL.Component.Shader): a GLSL program the viewer uses
// for the visual models of its node and below (the nearest shader up the graph,
// as SOFA's getShader), with the #defines, uniforms, attributes and textures of
// the shader elements around it. The renderer runs it (render/scene_shader.h).
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

class OglShader : public VisualComponent {
 public:
  OglShader();
  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  Field<bool> turn_on{this, "turnOn", true, "use the shader", "Shader"};
  Field<bool> passive{this, "passive", false, "activated by another component rather than automatically", "Shader"};
  Field<std::vector<std::string>> vertex{this, "fileVertexShaders", {"shaders/toonShading.vert"},
                                         "vertex shader file per shader version", "Shader"};
  Field<std::vector<std::string>> fragment{this, "fileFragmentShaders", {"shaders/toonShading.frag"},
                                           "fragment shader file per shader version", "Shader"};
  Field<std::vector<std::string>> geometry{this, "fileGeometryShaders", {},
                                           "geometry shader file per shader version", "Shader"};
  Field<std::vector<std::string>> tess_control{this, "fileTessellationControlShaders", {},
                                               "tessellation control shader file per shader version", "Shader"};
  Field<std::vector<std::string>> tess_eval{this, "fileTessellationEvaluationShaders", {},
                                            "tessellation evaluation shader file per shader version", "Shader"};
  Field<int> geometry_input_type{this, "geometryInputType", -1, "input primitive type of the geometry shader (GL enum)",
                                 "Shader"};
  Field<int> geometry_output_type{this, "geometryOutputType", -1,
                                  "output primitive type of the geometry shader (GL enum)", "Shader"};
  Field<int> geometry_vertices_out{this, "geometryVerticesOut", -1,
                                   "maximum number of vertices the geometry shader emits", "Shader"};
  Field<double> tess_outer{this, "tessellationOuterLevel", 1.0,
                           "outer tessellation level when there is no control shader", "Shader"};
  Field<double> tess_inner{this, "tessellationInnerLevel", 1.0,
                           "inner tessellation level when there is no control shader", "Shader"};
  Field<unsigned> index_active_shader{this, "indexActiveShader", 0u, "shader version in use", "Shader"};
  Field<bool> backface_writing{this, "backfaceWriting", false, "the vertex shader writes gl_BackColor", "Shader"};
  Field<bool> clamp_vertex_color{this, "clampVertexColor", true, "clamp vertex colours to [0, 1]", "Shader"};

  void init() override;
  // The files of the version in use (indexActiveShader); empty when the shader has none.
  const std::string& file_of(const Field<std::vector<std::string>>& files) const;
};

}  // namespace sinew
