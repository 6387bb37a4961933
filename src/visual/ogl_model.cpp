#include "visual/ogl_model.h"

#include <algorithm>
#include <fstream>

#include <Eigen/Geometry>

#include "core/node.h"
#include "core/parse.h"
#include "core/pseudo_attribute.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "io/mesh_readers.h"

namespace sinew {

namespace {
FlatVec empty3() {
  FlatVec v;
  v.width = 3;
  return v;
}
}  // namespace

OglModel::OglModel()
    : position(this, "position", empty3(), "vertex positions", "Vector"),
      rest_position(this, "restPosition", empty3(), "vertex rest positions", "Vector") {
  filename.add_alias("fileMesh");
  filename.set_file(true);
  texturename.set_file(true, false);  // resolved like meshes; a missing texture is only a warning
  edges.set_autolink(false);  // SOFA: edges are not linked by src=
  for (BaseField* f : {static_cast<BaseField*>(&translation), static_cast<BaseField*>(&rotation),
                       static_cast<BaseField*>(&scale3d)})
    f->set_autolink(false);
}

void OglModel::visual_resize(std::size_t n) { position.edit().data.resize(n * 3, 0.0); }

std::vector<double>* OglModel::visual_vec(int id) {
  if (id == kRestPosition) return &rest_position.edit().data;
  if (id == kPosition || id >= kFirstDynamicVec) return &position.edit().data;
  return nullptr;
}

void OglModel::parse(AttributeMap& attrs, Diagnostics& diag) {
  Component::parse(attrs, diag);
  // Pseudo-attributes read after the fields (VisualModelImpl::parse), numbers as floats.
  auto get_float = [&](const char* key, double def, bool& any) {
    if (const std::string* s = attrs.take(key)) {
      double d = 0;
      read_pseudo_number(*this, diag, key, *s, d);
      any = true;
      return static_cast<double>(static_cast<float>(d));
    }
    return def;
  };
  auto get_int = [&](const char* key, bool& present) {
    long long v = 1;
    if (const std::string* s = attrs.take(key)) {
      present = true;
      if (!parse::read_int(*s, v)) v = 1;
    }
    return v;
  };
  bool present = false;
  const long long n = get_int("normals", present);
  if (present) use_normals.set(n != 0);
  present = false;
  get_int("castshadow", present);
  if (attrs.take("flip")) flip_ = true;
  if (const std::string* c = attrs.take("color")) color_ = *c;
  if (attrs.take("isToPrint")) diag.warning(where, describe() + ": the 'isToPrint' attribute is deprecated");
  bool any = false;
  Vec2 st(get_float("su", 1.0, any), get_float("sv", 1.0, any));
  if (any) scale_tex.set(st);
  any = false;
  Vec2 dt(get_float("du", 0.0, any), get_float("dv", 0.0, any));
  if (any) translation_tex.set(dt);
  any = false;
  Vec3 r(get_float("rx", 0.0, any), get_float("ry", 0.0, any), get_float("rz", 0.0, any));
  if (any) rotation.set(r);
  any = false;
  Vec3 t(get_float("dx", 0.0, any), get_float("dy", 0.0, any), get_float("dz", 0.0, any));
  if (any) translation.set(t);
  any = false;
  const double s = get_float("scale", 1.0, any);
  if (any) {
    scale3d.set(Vec3(s, s, s));
    for (const char* k : {"sx", "sy", "sz"}) attrs.take(k);
  } else {
    Vec3 sc(get_float("sx", 1.0, any), get_float("sy", 1.0, any), get_float("sz", 1.0, any));
    if (any) scale3d.set(sc);
  }
}

bool OglModel::load_file() {
  const std::string& file = filename.get();
  if (!position.get().data.empty() || !vertices.get().empty()) return true;
  const bool obj = file.size() > 4 && (file.compare(file.size() - 4, 4, ".obj") == 0 ||
                                       file.compare(file.size() - 4, 4, ".OBJ") == 0);
  if (!obj) {
    msg_error("loading a mesh file directly inside the visual model is only supported for .obj files; use a "
              "MeshLoader and src=\"@loader\" (file " + quote_value(file) + ")");
    return false;
  }
  msg_warning("loading an obj file directly inside the visual model is deprecated; use a MeshOBJLoader and "
              "src=\"@loader\"");
  std::string error;
  io::ReadOptions opt;
  auto mesh = io::read_obj(file, &error, opt);
  if (!mesh) {
    msg_error(error.empty() ? "cannot load " + quote_value(file) : error);
    return false;
  }
  std::vector<double>& x = position.edit().data;
  x.clear();
  for (const Vec3& p : mesh->positions) x.insert(x.end(), {p[0], p[1], p[2]});
  if (init_rest_positions.value()) rest_position.edit().data = x;
  auto& tri = triangles.edit();
  auto& qua = quads.edit();
  auto& edg = edges.edit();
  for (const auto& face : mesh->face_positions) {
    if (face.size() == 2) {
      if (keep_lines.value()) edg.push_back({static_cast<unsigned>(face[0]), static_cast<unsigned>(face[1])});
    } else if (face.size() == 4) {
      qua.push_back({static_cast<unsigned>(face[0]), static_cast<unsigned>(face[1]), static_cast<unsigned>(face[2]),
                     static_cast<unsigned>(face[3])});
    } else {
      for (std::size_t j = 2; j < face.size(); ++j)
        tri.push_back({static_cast<unsigned>(face[0]), static_cast<unsigned>(face[j - 1]),
                       static_cast<unsigned>(face[j])});
    }
  }
  if (!mesh->texcoords.empty()) texcoords.set(mesh->texcoords);
  return true;
}

void OglModel::from_topology() {
  if (!topology && node()) topology.set(node()->get_mesh_topology_link());
  MeshTopologyBase* t = topology.get();
  if (!t) return;
  if (position.get().data.empty() && vertices.get().empty()) {
    std::vector<double>& x = position.edit().data;
    if (t->has_positions()) {
      const std::size_t n = t->nb_points();
      x.resize(n * 3);
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 p = t->point(i);
        x[i * 3] = p[0], x[i * 3 + 1] = p[1], x[i * 3 + 2] = p[2];
      }
    } else if (t->node()) {
      if (MechanicalState* s = t->node()->get_mechanical_state()) {
        const int w = s->info().coord_width, dim = std::min(3, s->info().spatial_dim);
        const std::vector<double>& sx = s->read(kPosition);
        const std::size_t n = s->size();
        x.assign(n * 3, 0.0);
        for (std::size_t i = 0; i < n; ++i)
          for (int c = 0; c < dim; ++c) x[i * 3 + c] = sx[i * w + c];
      }
    }
  }
  take_elements(*t);
  // A topology whose lists never change keeps its versions: following it costs two compares a step.
  follows_topology_ = handle_dynamic_topology.value();
}

void OglModel::take_elements(const MeshTopologyBase& t) {
  triangles.set(t.triangles());
  quads.set(t.quads());
  tri_version_ = t.elements_version(MeshTopologyBase::Elements::triangles);
  quad_version_ = t.elements_version(MeshTopologyBase::Elements::quads);
}

void OglModel::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_end) return;
  follow_topology();
  update_bbox();
}

void OglModel::update_bbox() {
  const std::vector<double>& x = position.value().data;
  if (x.size() < 3) return;  // SOFA keeps an empty (inverted) box: nothing to show
  double lo[3] = {x[0], x[1], x[2]}, hi[3] = {x[0], x[1], x[2]};
  for (std::size_t i = 3; i + 2 < x.size(); i += 3)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], x[i + c]);
      hi[c] = std::max(hi[c], x[i + c]);
    }
  std::vector<double>& b = bbox.raw();
  const bool same = b.size() == 6 && b[0] == lo[0] && b[1] == lo[1] && b[2] == lo[2] && b[3] == hi[0] &&
                    b[4] == hi[1] && b[5] == hi[2];
  if (same) return;
  // Stable size: after the first step this writes in place (no allocation per step).
  b.resize(6);
  for (int c = 0; c < 3; ++c) b[c] = lo[c], b[3 + c] = hi[c];
  bbox.edit();  // announce the change to linked fields
}

void OglModel::follow_topology() {
  const MeshTopologyBase* t = topology.get();
  if (!follows_topology_ || !t) return;
  if (t->elements_version(MeshTopologyBase::Elements::triangles) == tri_version_ &&
      t->elements_version(MeshTopologyBase::Elements::quads) == quad_version_)
    return;
  take_elements(*t);
  if (flip_) {
    for (auto& tr : triangles.edit()) std::swap(tr[1], tr[2]);
    for (auto& qd : quads.edit()) std::swap(qd[1], qd[3]);
  }
}

namespace {

constexpr const char* kBlendEquations[] = {"GL_FUNC_ADD", "GL_FUNC_SUBTRACT", "GL_MIN", "GL_MAX"};
constexpr const char* kBlendFactors[] = {"GL_ZERO", "GL_ONE", "GL_SRC_ALPHA", "GL_ONE_MINUS_SRC_ALPHA"};
constexpr const char* kPrimitives[] = {"DEFAULT", "LINES_ADJACENCY", "PATCHES", "POINTS"};

// The index of `value` in `options`, -1 when absent.
template <std::size_t N>
int option_index(const std::string& value, const char* const (&options)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (value == options[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace

int OglModel::blend_equation_index() const {
  const int i = option_index(blend_equation.get(), kBlendEquations);
  return i < 0 ? 0 : i;
}
int OglModel::source_factor_index() const {
  const int i = option_index(source_factor.get(), kBlendFactors);
  return i < 0 ? 2 : i;
}
int OglModel::dest_factor_index() const {
  const int i = option_index(dest_factor.get(), kBlendFactors);
  return i < 0 ? 3 : i;
}
int OglModel::primitive_index() const {
  const int i = option_index(primitive_type.get(), kPrimitives);
  return i < 0 ? 0 : i;
}

void OglModel::init() {
  // SOFA's option lists for alpha blending: another value keeps the default.
  if (option_index(blend_equation.get(), kBlendEquations) < 0)
    msg_warning("blendEquation '" + blend_equation.get() +
                "' is not one of GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_MIN, GL_MAX: GL_FUNC_ADD is used");
  if (option_index(source_factor.get(), kBlendFactors) < 0)
    msg_warning("sfactor '" + source_factor.get() +
                "' is not one of GL_ZERO, GL_ONE, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: GL_SRC_ALPHA is used");
  if (option_index(dest_factor.get(), kBlendFactors) < 0)
    msg_warning("dfactor '" + dest_factor.get() +
                "' is not one of GL_ZERO, GL_ONE, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: GL_ONE_MINUS_SRC_ALPHA is used");
  if (option_index(primitive_type.get(), kPrimitives) < 0)
    msg_warning("primitiveType '" + primitive_type.get() +
                "' is not one of DEFAULT, LINES_ADJACENCY, PATCHES, POINTS: DEFAULT is used");
  if (cull_face.get() < 0 || cull_face.get() > 2)
    msg_warning("cullFace " + std::to_string(cull_face.get()) + " is not 0, 1 or 2: no culling");
  if (!filename.get().empty()) {
    if (!load_file()) {
      set_state(ComponentState::invalid);
      return;
    }
  } else if (position.get().data.empty() || (!triangles.is_set() && !quads.is_set())) {
    from_topology();
  }
  if (!topology && position.get().data.empty()) {
    msg_warning("neither an .obj file nor a topology is present for this visual model");
    return;
  }
  std::vector<double>& x = position.edit().data;
  std::vector<double>* rest = init_rest_positions.value() ? &rest_position.edit().data : nullptr;
  // Scale, then rotation (Euler angles in degrees, Rz·Ry·Rx), then translation.
  const Vec3 s = scale3d.get(), r = rotation.get(), t = translation.get();
  const double to_rad = M_PI / 180.0;
  const Eigen::Quaterniond q = Eigen::AngleAxisd(r.z() * to_rad, Vec3::UnitZ()) *
                               Eigen::AngleAxisd(r.y() * to_rad, Vec3::UnitY()) *
                               Eigen::AngleAxisd(r.x() * to_rad, Vec3::UnitX());
  for (std::vector<double>* v : {&x, rest}) {
    if (!v) continue;
    for (std::size_t i = 0; i < v->size() / 3; ++i) {
      Vec3 p((*v)[i * 3], (*v)[i * 3 + 1], (*v)[i * 3 + 2]);
      p = Vec3(p[0] * s[0], p[1] * s[1], p[2] * s[2]);
      if (r != Vec3::Zero()) p = q * p;
      p += t;
      (*v)[i * 3] = p[0], (*v)[i * 3 + 1] = p[1], (*v)[i * 3 + 2] = p[2];
    }
  }
  translation.set(Vec3::Zero());
  rotation.set(Vec3::Zero());
  scale3d.set(Vec3::Ones());
  // VisualModelImpl::applyUVTransformation: texture coordinates scaled, then translated, once.
  if (scale_tex.get() != Vec2(1, 1) || translation_tex.get() != Vec2(0, 0)) {
    const Vec2 st = scale_tex.get(), tt = translation_tex.get();
    for (Vec2& uv : texcoords.edit()) uv = Vec2(uv[0] * st[0] + tt[0], uv[1] * st[1] + tt[1]);
    scale_tex.set(Vec2(1, 1));
    translation_tex.set(Vec2(0, 0));
  }
  // SOFA logs an error and draws the model without its texture; Sinew warns (the scene runs).
  if (const std::string& tex = texturename.get(); !tex.empty() && !std::ifstream(tex).good())
    msg_warning("texture " + quote_value(tex) + " not found: the model is drawn without it");
  if (flip_) {
    for (auto& e : edges.edit()) std::swap(e[0], e[1]);
    for (auto& tr : triangles.edit()) std::swap(tr[1], tr[2]);
    for (auto& qd : quads.edit()) std::swap(qd[1], qd[3]);
  }
  if (alpha_blend.get())
    msg_warning("alphaBlend: custom blending (blendEquation, sfactor, dfactor) is not drawn; the model is drawn "
                "opaque, or translucent by its material's alpha");
  update_bbox();
}

void register_ogl_model(Registry& r) {
  ComponentInfo info;
  info.name = "OglModel";
  info.category = "Visual";
  info.description = "visual model (surface points, normals, faces); no rendering in batch runs";
  info.create = creator<OglModel>();
  r.add(std::move(info));
  ComponentInfo impl;
  impl.name = "VisualModelImpl";
  impl.category = "Visual";
  impl.description = "generic visual model (no rendering in batch runs)";
  impl.aliases = {"VisualModel"};
  impl.create = creator<OglModel>();
  r.add(std::move(impl));
  // SOFA's OglShaderVisualModel is an OglModel that also sends tangents to the
  // node's shader; Sinew draws it with its own shading, as an OglModel.
  ComponentInfo shader;
  shader.name = "OglShaderVisualModel";
  shader.category = "Visual";
  shader.description = "visual model drawn with the node's shader in SOFA (Sinew: its own shading)";
  shader.create = creator<OglModel>();
  r.add(std::move(shader));
}

}  // namespace sinew
