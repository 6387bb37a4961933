// OglShader, OglShadowShader and OglShaderDefineMacro. The shader files named in
// the scene are checked at init so a wrong path is reported as SOFA would
// report it; OglShadowShader's own shading is render/shadow_maps.h's.
#include "visual/shader/ogl_shader.h"

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

OglShader::OglShader() {
  for (auto* f : {&vertex, &fragment, &geometry, &tess_control, &tess_eval}) f->set_file(true, /*required=*/false);
  // tessellationLevel sets both levels (SOFA puts the alias on the two Data): the outer
  // level reads it as an alias, parse() copies it to the inner one.
  tess_outer.add_alias("tessellationLevel");
}

void OglShader::parse(AttributeMap& attrs, Diagnostics& diag) {
  const std::string* level = attrs.peek("tessellationLevel");
  const std::string both = level ? *level : std::string();
  const bool inner_given = attrs.peek("tessellationInnerLevel") != nullptr;
  Component::parse(attrs, diag);
  if (level && !inner_given && both.rfind('@', 0) != 0) tess_inner.read(both);
}

void OglShader::init() {
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

const std::string& OglShader::file_of(const Field<std::vector<std::string>>& files) const {
  static const std::string none;
  const auto& list = files.get();
  const std::size_t i = index_active_shader.get();
  return i < list.size() ? list[i] : none;
}

namespace {

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
  void input(ShaderInput& in) const override {
    in.reset();
    in.kind = ShaderInput::Kind::macro;
    in.text = value.get();
  }
};

}  // namespace

void register_ogl_shader(Registry& r) {
  ComponentInfo s;
  s.name = "OglShader";
  s.category = "Visual";
  s.description = "GLSL shader the viewer runs for the visual models of its node and below";
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
