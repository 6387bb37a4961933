// OglXxxVariable and OglXxxAttribute (SOFA's Sofa.GL.Component.Shader):
// uniforms and per-vertex attributes a SOFA viewer passes to the shader of
// the node (the renderer reads them through input(), render/scene_shader.h).
// Values are parsed with their SOFA types, so a bad value is a load error
// naming the component and field, and scripts read them back as in SOFA.
#include <string>
#include <type_traits>
#include <vector>

#include "core/registry.h"
#include "visual/shader/shader_element.h"

namespace sinew {

namespace {

// SOFA's default values: zero (Eigen's fixed vectors are not initialised by T{}).
template <class T>
T zero_value() {
  if constexpr (requires { T::Zero(); }) return T::Zero();
  else return T{};
}

// A value as flat floats: `width` numbers per item, `array` when it is a list.
template <class T>
void flatten(const T& v, ShaderInput& in) {
  if constexpr (std::is_arithmetic_v<T>) {
    in.values.push_back(static_cast<float>(v));
  } else if constexpr (requires { v.size(); v.begin(); typename T::value_type; } &&
                       !requires { T::RowsAtCompileTime; }) {
    in.array = true;
    for (const auto& item : v) flatten(item, in);
    if constexpr (requires { T::value_type::RowsAtCompileTime; })
      in.width = static_cast<int>(T::value_type::RowsAtCompileTime);
  } else {
    in.width = static_cast<int>(T::RowsAtCompileTime);
    for (int k = 0; k < in.width; ++k) in.values.push_back(static_cast<float>(v[k]));
  }
}

template <class T>
constexpr bool integer_valued() {
  if constexpr (std::is_integral_v<T>) return true;
  else if constexpr (requires { typename T::Scalar; }) return std::is_integral_v<typename T::Scalar>;
  else if constexpr (requires { typename T::value_type; }) return integer_valued<typename T::value_type>();
  else return false;
}

template <class T>
class OglVariable final : public ShaderElement {
 public:
  OglVariable() { value.add_alias("values"); }  // SOFA accepts both names
  Field<T> value{this, "value", zero_value<T>(), "uniform value", "Shader"};
  void input(ShaderInput& in) const override {
    in.reset();
    in.kind = integer_valued<T>() ? ShaderInput::Kind::int_uniform : ShaderInput::Kind::float_uniform;
    flatten(value.get(), in);
  }
};

// Values stored flat whose count must be a multiple of `width` (Mat4x4f lists,
// Vec4i lists): the type Sinew's fields have no row form for.
template <int Width>
class FlatShaderValue : public ShaderElement {
 public:
  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    ShaderElement::parse(attrs, diag);
    check(diag);
  }
  void check(Diagnostics& diag) {
    const std::size_t n = flat.value().size();
    if (flat.link_path().empty() && n % Width != 0)
      diag.error(where, describe() + ": value has " + std::to_string(n) + " numbers, not a multiple of " +
                            std::to_string(Width));
  }

 protected:
  explicit FlatShaderValue(const char* what) : flat(this, "value", {}, what, "Shader") {}

 public:
  Field<std::vector<double>> flat;
};

class OglMatrix4VectorVariable final : public FlatShaderValue<16> {
 public:
  OglMatrix4VectorVariable() : FlatShaderValue<16>("list of 4x4 matrices (16 numbers each, row by row)") {
    flat.add_alias("values");
  }
  Field<bool> transpose{this, "transpose", false, "transpose the matrices when sent to the shader", "Shader"};
  void input(ShaderInput& in) const override {
    in.reset();
    in.kind = ShaderInput::Kind::matrix_uniform;
    in.width = 16;
    in.array = true;
    in.transpose = transpose.get();
    for (double d : flat.get()) in.values.push_back(static_cast<float>(d));
  }
};

template <class T>
class OglAttribute final : public ShaderElement {
 public:
  Field<T> value{this, "value", T{}, "one value per vertex", "Shader"};
  Field<bool> handle_dynamic_topology{this, "handleDynamicTopology", true,
                                      "resize the values when the topology changes", "Shader"};
  void input(ShaderInput& in) const override {
    in.reset();
    in.kind = ShaderInput::Kind::attribute;
    flatten(value.get(), in);
    in.array = false;
  }
};

// Vec4i per vertex: four integers per vertex, given flat.
class OglInt4Attribute final : public FlatShaderValue<4> {
 public:
  OglInt4Attribute() : FlatShaderValue<4>("four integers per vertex") {}
  Field<bool> handle_dynamic_topology{this, "handleDynamicTopology", true,
                                      "resize the values when the topology changes", "Shader"};
  void input(ShaderInput& in) const override {
    in.reset();
    in.kind = ShaderInput::Kind::attribute;
    in.width = 4;
    for (double d : flat.get()) in.values.push_back(static_cast<float>(d));
  }
  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    FlatShaderValue<4>::parse(attrs, diag);
    for (double d : flat.value())
      if (d != static_cast<double>(static_cast<int>(d))) {
        diag.error(where, describe() + ": value holds a non-integer number");
        break;
      }
  }
};

template <class C>
void add(Registry& r, const char* name, const char* what) {
  ComponentInfo info;
  info.name = name;
  info.category = "Visual";
  info.description = std::string(what) + " (viewer only)";
  info.create = creator<C>();
  r.add(std::move(info));
}

}  // namespace

void register_ogl_variable(Registry& r) {
  add<OglVariable<int>>(r, "OglIntVariable", "integer uniform of the node's shader");
  add<OglVariable<VecNi<2>>>(r, "OglInt2Variable", "ivec2 uniform of the node's shader");
  add<OglVariable<VecNi<3>>>(r, "OglInt3Variable", "ivec3 uniform of the node's shader");
  add<OglVariable<VecNi<4>>>(r, "OglInt4Variable", "ivec4 uniform of the node's shader");
  add<OglVariable<double>>(r, "OglFloatVariable", "float uniform of the node's shader");
  add<OglVariable<VecN<2>>>(r, "OglFloat2Variable", "vec2 uniform of the node's shader");
  add<OglVariable<VecN<3>>>(r, "OglFloat3Variable", "vec3 uniform of the node's shader");
  add<OglVariable<VecN<4>>>(r, "OglFloat4Variable", "vec4 uniform of the node's shader");
  add<OglVariable<std::vector<int>>>(r, "OglIntVectorVariable", "int array uniform of the node's shader");
  add<OglVariable<std::vector<double>>>(r, "OglFloatVectorVariable", "float array uniform of the node's shader");
  add<OglVariable<std::vector<VecN<2>>>>(r, "OglFloatVector2Variable", "vec2 array uniform of the node's shader");
  add<OglVariable<std::vector<VecN<3>>>>(r, "OglFloatVector3Variable", "vec3 array uniform of the node's shader");
  add<OglVariable<std::vector<VecN<4>>>>(r, "OglFloatVector4Variable", "vec4 array uniform of the node's shader");
  add<OglMatrix4VectorVariable>(r, "OglMatrix4VectorVariable", "mat4 array uniform of the node's shader");
  add<OglAttribute<std::vector<double>>>(r, "OglFloatAttribute", "float vertex attribute of the node's shader");
  add<OglAttribute<std::vector<VecN<2>>>>(r, "OglFloat2Attribute", "vec2 vertex attribute of the node's shader");
  add<OglAttribute<std::vector<VecN<3>>>>(r, "OglFloat3Attribute", "vec3 vertex attribute of the node's shader");
  add<OglAttribute<std::vector<VecN<4>>>>(r, "OglFloat4Attribute", "vec4 vertex attribute of the node's shader");
  add<OglAttribute<std::vector<int>>>(r, "OglIntAttribute", "int vertex attribute of the node's shader");
  add<OglInt4Attribute>(r, "OglInt4Attribute", "ivec4 vertex attribute of the node's shader");
}

}  // namespace sinew
