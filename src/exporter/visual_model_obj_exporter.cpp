#include "exporter/visual_model_obj_exporter.h"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/node.h"
#include "core/registry.h"
#include "render/material.h"
#include "visual/ogl_model.h"

namespace sinew {
namespace {

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

void write_material(FILE* mtl, const std::string& name, const render::Material& m) {
  std::fprintf(mtl, "newmtl %s\nillum 4\n", name.c_str());
  if (m.use_ambient) std::fprintf(mtl, "Ka %g %g %g\n", m.ambient[0], m.ambient[1], m.ambient[2]);
  if (m.use_diffuse) std::fprintf(mtl, "Kd %g %g %g\n", m.diffuse[0], m.diffuse[1], m.diffuse[2]);
  std::fprintf(mtl, "Tf 1.00 1.00 1.00\nNi 1.00\n");
  if (m.use_specular) std::fprintf(mtl, "Ks %g %g %g\n", m.specular[0], m.specular[1], m.specular[2]);
  if (m.use_shininess) std::fprintf(mtl, "Ns %g\n", m.shininess);
  if (m.use_diffuse && m.diffuse[3] < 1.f) std::fprintf(mtl, "Tf %g %g %g\n", m.diffuse[3], m.diffuse[3], m.diffuse[3]);
}

struct Offsets {
  std::size_t v = 0, n = 0, t = 0;
};

void write_model(FILE* out, FILE* mtl, OglModel& model, int k, Offsets& off) {
  const std::string group = std::to_string(k) + "_" + model.name.get();
  const std::string mat = "mat" + std::to_string(k);
  std::fprintf(out, "g %s\n", group.c_str());
  write_material(mtl, mat, render::material_of(model));
  std::fprintf(out, "usemtl %s\n", mat.c_str());

  const FlatVec& x = model.position.get();
  const std::vector<Vec3>& normals = model.normal.get();
  const std::vector<Vec2>& tex = model.texcoords.get();
  const std::vector<unsigned>& pos_idx = model.vert_pos_idx.get();
  const std::vector<unsigned>& norm_idx = model.vert_norm_idx.get();
  const std::size_t w = static_cast<std::size_t>(std::max(x.width, 1)), nv = x.size();
  for (std::size_t i = 0; i < nv; ++i) {
    const double* p = &x.data[i * w];
    std::fprintf(out, "v %f %f %f\n", p[0], w > 1 ? p[1] : 0.0, w > 2 ? p[2] : 0.0);
  }
  // Normals: one per render vertex, or (with vertNormIdx) one per distinct normal index,
  // taken from the last render vertex using it, as SOFA writes them.
  std::size_t nn = 0;
  if (norm_idx.empty()) {
    nn = normals.size();
    for (const Vec3& v : normals) std::fprintf(out, "vn %f %f %f\n", v.x(), v.y(), v.z());
  } else {
    for (unsigned j : norm_idx) nn = std::max<std::size_t>(nn, j + 1u);
    std::vector<std::size_t> vertex_of(nn, 0);
    for (std::size_t i = 0; i < norm_idx.size(); ++i) vertex_of[norm_idx[i]] = i;
    for (std::size_t j = 0; j < nn; ++j) {
      const Vec3 v = vertex_of[j] < normals.size() ? normals[vertex_of[j]] : Vec3::Zero();
      std::fprintf(out, "vn %f %f %f\n", v.x(), v.y(), v.z());
    }
  }
  for (const Vec2& t : tex) std::fprintf(out, "vt %f %f\n", t.x(), t.y());
  auto face = [&](const auto& corners) {
    std::fputc('f', out);
    for (unsigned i0 : corners) {
      const std::size_t ip = pos_idx.empty() ? i0 : pos_idx.at(i0);
      const std::size_t in = norm_idx.empty() ? i0 : norm_idx.at(i0);
      if (tex.empty())
        std::fprintf(out, " %zu//%zu", ip + off.v + 1, in + off.n + 1);
      else
        std::fprintf(out, " %zu/%zu/%zu", ip + off.v + 1, i0 + off.t + 1, in + off.n + 1);
    }
    std::fputc('\n', out);
  };
  for (const Edge& e : model.edges.get()) face(e);
  for (const Triangle& t : model.triangles.get()) face(t);
  for (const Quad& q : model.quads.get()) face(q);
  std::fputc('\n', out);
  off.v += nv;
  off.n += nn;
  off.t += tex.size();
}

}  // namespace

bool VisualModelOBJExporter::write() {
  const std::string base = target_path(base_name(), true);
  if (base.empty() || !node()) return false;
  const bool has_ext = base.size() > 4 && base.compare(base.size() - 4, 4, ".obj") == 0;
  obj_path_ = has_ext ? base : base + ".obj";
  mtl_path_ = (has_ext ? base.substr(0, base.size() - 4) : base) + ".mtl";
  File obj(std::fopen(obj_path_.c_str(), "w"), &std::fclose);
  File mtl(std::fopen(mtl_path_.c_str(), "w"), &std::fclose);
  if (!obj || !mtl) {
    msg_error("filename: cannot open '" + (obj ? mtl_path_ : obj_path_) + "' for writing");
    return false;
  }
  std::fprintf(obj.get(), "mtllib %s\n", std::filesystem::path(mtl_path_).filename().string().c_str());
  std::vector<OglModel*> models;
  node()->collect_down(models);
  Offsets off;
  int k = 0;
  for (OglModel* m : models) write_model(obj.get(), mtl.get(), *m, ++k, off);
  if (std::ferror(obj.get()) || std::ferror(mtl.get())) {
    msg_error("filename: write error on '" + obj_path_ + "'");
    return false;
  }
  if (print_log.get()) msg_info("exported " + obj_path_ + " with " + mtl_path_);
  return true;
}

void register_visual_model_obj_exporter(Registry& r) {
  ComponentInfo info;
  info.name = "VisualModelOBJExporter";
  info.category = "Exporter";
  info.description = "writes the visual models of its node and below to a Wavefront OBJ with its MTL";
  info.create = creator<VisualModelOBJExporter>();
  r.add(std::move(info));
}

}  // namespace sinew
