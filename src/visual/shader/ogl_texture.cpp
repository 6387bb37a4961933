// OglTexture and OglTexture2D (SOFA's Sofa.GL.Component.Shader): an image
// bound to a texture unit of the node's shader (a sampler named `id`), read
// by the renderer through input(). The files named are checked at init (a
// missing one is a warning, as SOFA's failed load). Cube maps are accepted
// and checked, not bound (no example shader samples one).
#include "core/registry.h"
#include "visual/shader/shader_element.h"

namespace sinew {

namespace {

class OglTexture : public ShaderElement {
 public:
  OglTexture() {
    filename.add_alias("textureFilename");
    for (auto* f : {&filename, &pos_x, &pos_y, &pos_z, &neg_x, &neg_y, &neg_z}) f->set_file(true, /*required=*/false);
  }
  Field<std::string> filename{this, "filename", "", "image file", "Shader"};
  Field<unsigned> texture_unit{this, "textureUnit", 1u, "texture unit the image is bound to", "Shader"};
  Field<bool> enabled{this, "enabled", true, "bind the texture", "Shader"};
  Field<bool> repeat{this, "repeat", false, "repeat the image outside [0, 1] (else clamp)", "Shader"};
  Field<bool> linear_interpolation{this, "linearInterpolation", true, "linear filtering (else nearest)", "Shader"};
  Field<bool> generate_mipmaps{this, "generateMipmaps", true, "build mipmaps", "Shader"};
  Field<bool> srgb_colorspace{this, "srgbColorspace", false, "the image is in sRGB colour space", "Shader"};
  Field<double> min_lod{this, "minLod", -1000.0, "minimum mipmap level of detail", "Shader"};
  Field<double> max_lod{this, "maxLod", 1000.0, "maximum mipmap level of detail", "Shader"};
  Field<unsigned> procedural_width{this, "proceduralTextureWidth", 0u, "width of a procedural texture", "Shader"};
  Field<unsigned> procedural_height{this, "proceduralTextureHeight", 0u, "height of a procedural texture", "Shader"};
  Field<unsigned> procedural_bits{this, "proceduralTextureNbBits", 1u, "bits per colour of a procedural texture",
                                  "Shader"};
  Field<std::vector<unsigned>> procedural_data{this, "proceduralTextureData", {},
                                               "texel values of a procedural texture", "Shader"};
  Field<std::string> pos_x{this, "cubemapFilenamePosX", "", "image of the +X cube map face", "Shader"};
  Field<std::string> pos_y{this, "cubemapFilenamePosY", "", "image of the +Y cube map face", "Shader"};
  Field<std::string> pos_z{this, "cubemapFilenamePosZ", "", "image of the +Z cube map face", "Shader"};
  Field<std::string> neg_x{this, "cubemapFilenameNegX", "", "image of the -X cube map face", "Shader"};
  Field<std::string> neg_y{this, "cubemapFilenameNegY", "", "image of the -Y cube map face", "Shader"};
  Field<std::string> neg_z{this, "cubemapFilenameNegZ", "", "image of the -Z cube map face", "Shader"};

  void init() override {
    ShaderElement::init();
    for (auto* f : {&filename, &pos_x, &pos_y, &pos_z, &neg_x, &neg_y, &neg_z})
      if (f->is_set()) warn_missing_files(*this, f->name(), {f->get()});
    if (min_lod.value() > max_lod.value()) msg_warning("minLod is greater than maxLod");
  }
  void input(ShaderInput& in) const override {
    in.reset();
    if (!enabled.get()) return;
    in.kind = ShaderInput::Kind::texture;
    in.text = filename.get();
    in.unit = texture_unit.get();
    in.repeat = repeat.get();
    in.linear = linear_interpolation.get();
    if (in.text.empty()) {  // a procedural image: one channel, `proceduralTextureNbBits` per texel
      in.texture_width = static_cast<int>(procedural_width.get());
      in.texture_height = static_cast<int>(procedural_height.get());
      for (unsigned v : procedural_data.get()) in.values.push_back(static_cast<float>(v));
    }
  }
};

// Deprecated in SOFA: the file is `texture2DFilename`, copied into `filename` at init.
class OglTexture2D final : public OglTexture {
 public:
  OglTexture2D() { texture2d.set_file(true, /*required=*/false); }
  Field<std::string> texture2d{this, "texture2DFilename", "", "image file (copied into filename)", "Shader"};
  void init() override {
    msg_warning("OglTexture2D is deprecated: use OglTexture");
    filename.set(texture2d.get());
    OglTexture::init();
  }
};

}  // namespace

void register_ogl_texture(Registry& r) {
  ComponentInfo t;
  t.name = "OglTexture";
  t.category = "Visual";
  t.description = "image bound to a texture unit of the node's shader (viewer only)";
  t.create = creator<OglTexture>();
  r.add(std::move(t));
  ComponentInfo t2;
  t2.name = "OglTexture2D";
  t2.category = "Visual";
  t2.description = "deprecated form of OglTexture (viewer only)";
  t2.create = creator<OglTexture2D>();
  r.add(std::move(t2));
}

}  // namespace sinew
