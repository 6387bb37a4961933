// OglShader, OglShadowShader and OglShaderDefineMacro (SOFA's
// Sofa.GL.Component.Shader): GLSL programs a SOFA viewer compiles and uses
// for the models of their node and below. Sinew's renderer keeps its own
// shading (docs/render.md); the shader files named in the scene are checked
// at init so a wrong path is reported as SOFA would report it.
#include <algorithm>
#include <filesystem>

#include "core/registry.h"
#include "core/value_text.h"
#include "visual/shader/shader_element.h"

namespace sinew {

void ShaderElement::init() {
  if (id.value().empty()) id.set(name.value());
}

void warn_missing_files(const Component& c, const std::string& what, const std::vector<std::string>& files) {
  std::error_code ec;
  for (const std::string& f : files)
    if (!f.empty() && !std::filesystem::exists(f, ec))
      c.msg_warning(what + ": file " + quote_value(f) + " not found (searched the scene folder and the data paths)");
}

namespace {

class OglShader : public VisualComponent {
 public:
  OglShader() {
    for (auto* f : {&vertex, &fragment, &geometry, &tess_control, &tess_eval}) f->set_file(true, /*required=*/false);
    // tessellationLevel sets both levels (SOFA puts the alias on the two Data): the outer
    // level reads it as an alias, parse() copies it to the inner one.
    tess_outer.add_alias("tessellationLevel");
  }
  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    const std::string* level = attrs.peek("tessellationLevel");
    const std::string both = level ? *level : std::string();
    const bool inner_given = attrs.peek("tessellationInnerLevel") != nullptr;
    Component::parse(attrs, diag);
    if (level && !inner_given && both.rfind('@', 0) != 0) tess_inner.read(both);
  }
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

  void init() override {
    // The files of the scene only: the defaults live in SOFA's share folder.
    for (auto* f : {&vertex, &fragment, &geometry, &tess_control, &tess_eval})
      if (f->is_set()) warn_missing_files(*this, f->name(), f->get());
    std::size_t versions = 0;
    for (auto* f : {&vertex, &fragment, &geometry, &tess_control, &tess_eval})
      versions = std::max(versions, f->value().size());
    if (index_active_shader.value() >= std::max<std::size_t>(versions, 1))
      msg_warning("indexActiveShader " + std::to_string(index_active_shader.value()) + " is past the " +
                  std::to_string(versions) + " shader version(s)");
  }
};

// The shader of SOFA's shadow mapping: two versions (without, with shadows).
class OglShadowShader final : public OglShader {
 public:
  OglShadowShader() {
    // Defaults, not values given by the scene (raw: the field stays unset).
    vertex.raw() = {"shaders/hardShadows/shadowMapping.vert", "shaders/hardShadows/shadowMapping.vert"};
    fragment.raw() = {"shaders/hardShadows/shadowMapping.frag", "shaders/hardShadows/shadowMapping.frag"};
  }
};

class OglShaderDefineMacro final : public ShaderElement {
 public:
  Field<std::string> value{this, "value", "", "value of the #define (the macro name is `id`)", "Shader"};
};

}  // namespace

void register_ogl_shader(Registry& r) {
  ComponentInfo s;
  s.name = "OglShader";
  s.category = "Visual";
  s.description = "GLSL shader of a SOFA viewer (files checked; Sinew's renderer uses its own shading)";
  s.create = creator<OglShader>();
  r.add(std::move(s));
  ComponentInfo sh;
  sh.name = "OglShadowShader";
  sh.category = "Visual";
  sh.description = "shadow-mapping shader of a SOFA viewer (Sinew's renderer uses its own shading)";
  sh.create = creator<OglShadowShader>();
  r.add(std::move(sh));
  ComponentInfo m;
  m.name = "OglShaderDefineMacro";
  m.category = "Visual";
  m.description = "#define added to the shader of the node (viewer only)";
  m.create = creator<OglShaderDefineMacro>();
  r.add(std::move(m));
}

}  // namespace sinew
