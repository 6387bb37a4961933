#include "exporter/stl_exporter.h"

#include <Eigen/Geometry>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

#include "core/node.h"
#include "core/registry.h"
#include "visual/ogl_model.h"

namespace sinew {

STLExporter::STLExporter()
    : position(this, "position", FlatVec{3, {}}, "points of the surface (default: the visual model's or topology's)",
               "Export", "length") {
  triangle.add_alias("triangles");
  quad.add_alias("quads");
}

void STLExporter::do_init() {
  Node* n = node();
  if (!n) return;
  if (!position.is_set() && !position.parent()) {
    // SOFA looks in this node only: its visual model first, else its topology.
    Base* source = n->find_local<OglModel>();
    if (!source) source = n->mesh_topology;
    if (!source) {
      msg_error("no position given and no visual model or topology in this node to take the surface from");
      set_state(ComponentState::invalid);
      return;
    }
    if (BaseField* p = source->find_field("position")) position.set_parent(p);
    if (!triangle.is_set() && !triangle.parent())
      if (BaseField* t = source->find_field("triangles")) triangle.set_parent(t);
    if (!quad.is_set() && !quad.parent())
      if (BaseField* q = source->find_field("quads")) quad.set_parent(q);
  }
  set_state(ComponentState::valid);
}

bool STLExporter::write_file(bool numbered) {
  if (state() != ComponentState::valid) return false;
  const FlatVec& x = position.get();
  if (x.data.empty() || x.width < 3) {
    msg_error("position: no points to write");
    return false;
  }
  std::vector<Triangle> tris = triangle.get();
  if (tris.empty()) {
    for (const Quad& q : quad.get()) {
      tris.push_back({q[0], q[1], q[2]});
      tris.push_back({q[0], q[2], q[3]});
    }
  }
  if (tris.empty()) {
    msg_error("triangle, quad: no triangles nor quads to write");
    return false;
  }
  const std::size_t np = x.size(), w = static_cast<std::size_t>(x.width);
  auto point = [&](unsigned i) { return Vec3(x.data[i * w], x.data[i * w + 1], x.data[i * w + 2]); };
  for (const Triangle& t : tris)
    for (unsigned v : t)
      if (v >= np) {
        msg_error("triangle: vertex " + std::to_string(v) + " is out of the " + std::to_string(np) + " points");
        return false;
      }
  const std::string base = target_path(base_name(), numbered);
  if (base.empty()) return false;
  const std::string path = base + ".stl";
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), binary_format.get() ? "wb" : "w"), &std::fclose);
  if (!f) {
    msg_error("filename: cannot open '" + path + "' for writing");
    return false;
  }
  FILE* out = f.get();
  auto normal = [&](const Triangle& t) {
    Vec3 nrm = (point(t[1]) - point(t[0])).cross(point(t[2]) - point(t[0]));
    const double len = nrm.norm();
    return len > 0 ? Vec3(nrm / len) : Vec3(Vec3::Zero());
  };
  if (binary_format.get()) {
    char header[80] = {};
    std::strncpy(header, "Exported from Sinew", sizeof header - 1);
    std::fwrite(header, 1, 80, out);
    const std::uint32_t n = static_cast<std::uint32_t>(tris.size());
    std::fwrite(&n, 4, 1, out);  // STL is little-endian, as this machine
    for (const Triangle& t : tris) {
      float v[12];
      const Vec3 nrm = normal(t);
      for (int k = 0; k < 3; ++k) v[k] = static_cast<float>(nrm[k]);
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) v[3 + 3 * j + k] = static_cast<float>(point(t[j])[k]);
      std::fwrite(v, 4, 12, out);
      const std::uint16_t attributes = 0;
      std::fwrite(&attributes, 2, 1, out);
    }
  } else {
    std::fprintf(out, "solid Exported from Sofa\n");
    for (const Triangle& t : tris) {
      const Vec3 nrm = normal(t);
      std::fprintf(out, "facet normal %g %g %g\nouter loop\n", nrm.x(), nrm.y(), nrm.z());
      for (unsigned v : t) {
        const Vec3 p = point(v);
        std::fprintf(out, "vertex %f %f %f\n", p.x(), p.y(), p.z());
      }
      std::fprintf(out, "endloop\nendfacet\n");
    }
    std::fprintf(out, "endsolid Exported from Sofa\n");
  }
  if (std::ferror(out)) {
    msg_error("filename: write error on '" + path + "'");
    return false;
  }
  if (print_log.get()) msg_info("exported " + path);
  return true;
}

void STLExporter::handle_event(Event& e) {
  // SOFA's GUI event "STLExport" writes an unnumbered file; a script sends it by name here.
  if (e.kind == Event::Kind::script && e.name == "STLExport") {
    write_file(false);
    return;
  }
  SimulationExporter::handle_event(e);
}

void register_stl_exporter(Registry& r) {
  ComponentInfo info;
  info.name = "STLExporter";
  info.category = "Exporter";
  info.description = "writes a surface (triangles, or quads split in two) to an STL file";
  info.create = creator<STLExporter>();
  r.add(std::move(info));
}

}  // namespace sinew
