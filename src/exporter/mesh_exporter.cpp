#include "exporter/mesh_exporter.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {
namespace {

constexpr const char* kFormats[] = {"ALL", "vtkxml", "vtk", "netgen", "tetgen", "gmsh", "obj"};

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

// Triangles to write beside tetrahedra in netgen/tetgen files: the surface ones (fewer than
// two tetrahedra share them). SOFA counts these but then writes every triangle, which gives
// files whose counts disagree with their content; Sinew writes the surface it counts.
std::vector<Triangle> surface_triangles(const io::VtkMesh& m) {
  if (m.tetrahedra.empty()) return m.triangles;
  std::map<std::array<unsigned, 3>, int> uses;
  for (const Tetra& t : m.tetrahedra) {
    static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    for (const auto& f : kFaces) {
      std::array<unsigned, 3> key{t[f[0]], t[f[1]], t[f[2]]};
      std::sort(key.begin(), key.end());
      ++uses[key];
    }
  }
  std::vector<Triangle> out;
  for (const Triangle& tri : m.triangles) {
    std::array<unsigned, 3> key = tri;
    std::sort(key.begin(), key.end());
    const auto it = uses.find(key);
    if (it == uses.end() || it->second < 2) out.push_back(tri);
  }
  return out;
}

}  // namespace

MeshExporter::MeshExporter()
    : position(this, "position", FlatVec{3, {}},
               "points written (default: the mechanical state's positions, else the topology's points)", "Export",
               "length") {}

void MeshExporter::do_init() {
  topology_ = node() ? node()->get_mesh_topology_link() : nullptr;
  state_ = node() ? node()->get_mechanical_state() : nullptr;
  if (!topology_) {
    msg_error("no topology: put one in this node or above");
    set_state(ComponentState::invalid);
    return;
  }
  if (std::find(std::begin(kFormats), std::end(kFormats), format.get()) == std::end(kFormats)) {
    msg_error("format '" + format.get() + "' is not one of ALL, vtkxml, vtk, netgen, tetgen, gmsh, obj");
    set_state(ComponentState::invalid);
    return;
  }
  set_state(ComponentState::valid);
}

std::string MeshExporter::mesh_filename(const io::VtkMesh& m, const char* ext) {
  const std::size_t nbp = m.points.size(), nbce = m.cell_count();
  std::size_t nbe = m.tetrahedra.size() + m.hexahedra.size();
  if (!nbe) nbe = m.triangles.size() + m.quads.size();
  if (!nbe) nbe = m.edges.size();
  if (!nbe) nbe = nbp;
  const std::string pattern = base_name();
  std::string name;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%' || i + 1 >= pattern.size()) {
      name += pattern[i];
      continue;
    }
    const char c = pattern[++i];
    switch (c) {
      case 'n': name += std::to_string(step_counter()); break;
      case 'p': name += std::to_string(nbp); break;
      case 'E': name += std::to_string(nbce); break;
      case 'e': name += std::to_string(nbe); break;
      default: msg_error(std::string("filename: unknown pattern %") + c + " (known: %n %p %E %e)"); break;
    }
  }
  const std::string path = target_path(name, true);
  return path.empty() ? path : path + ext;
}

bool MeshExporter::write() {
  if (state() != ComponentState::valid || !topology_) return false;
  io::VtkMesh mesh;
  mesh.points = export_points(position, state_, topology_);
  select_cells(*topology_, {edges.get(), triangles.get(), quads.get(), tetras.get(), hexas.get()}, mesh);
  const std::string& f = format.get();
  const bool all = f == "ALL";
  bool ok = true;
  std::string error;
  auto report = [&](bool written, const std::string& path) {
    if (!written) {
      msg_error("filename: " + (error.empty() ? "cannot write " + path : error));
      ok = false;
    } else if (print_log.get()) {
      msg_info("exported " + path);
    }
  };
  if (all || f == "vtkxml") {
    const std::string p = mesh_filename(mesh, ".vtu");
    report(!p.empty() && io::write_vtu(p, mesh, &error), p);
  }
  if (all || f == "vtk") {
    const std::string p = mesh_filename(mesh, ".vtk");
    report(!p.empty() && io::write_vtk(p, mesh, "SOFA Exported Mesh file", &error), p);
  }
  const std::vector<Triangle> faces = (all || f == "netgen" || f == "tetgen") ? surface_triangles(mesh)
                                                                               : std::vector<Triangle>{};
  if (all || f == "netgen") ok = write_netgen(mesh, faces) && ok;
  if (all || f == "tetgen") ok = write_tetgen(mesh, faces) && ok;
  if (all || f == "gmsh") ok = write_gmsh(mesh) && ok;
  if (all || f == "obj") ok = write_obj(mesh) && ok;
  return ok;
}

namespace {

File open_file(MeshExporter& c, const std::string& path) {
  File f(path.empty() ? nullptr : std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) c.msg_error("filename: cannot open '" + path + "' for writing");
  return f;
}

void point_line(FILE* out, const Vec3& p) { std::fprintf(out, "%.17g %.17g %.17g", p.x(), p.y(), p.z()); }

template <class List>
void one_based(FILE* out, const List& c) {
  for (unsigned v : c) std::fprintf(out, " %u", v + 1);
  std::fputc('\n', out);
}

}  // namespace

// Netgen's neutral format: points, volume elements (subdomain + 1-based vertices), surface elements.
bool MeshExporter::write_netgen(const io::VtkMesh& m, const std::vector<Triangle>& faces) {
  File f = open_file(*this, mesh_filename(m, ".mesh"));
  if (!f) return false;
  FILE* out = f.get();
  std::fprintf(out, "%zu\n", m.points.size());
  for (const Vec3& p : m.points) point_line(out, p), std::fputc('\n', out);
  std::fprintf(out, "%zu\n", m.tetrahedra.size());
  for (const Tetra& t : m.tetrahedra) std::fputc('0', out), one_based(out, t);
  std::fprintf(out, "%zu\n", faces.size());
  for (const Triangle& t : faces) std::fputc('0', out), one_based(out, t);
  return std::ferror(out) == 0;
}

// TetGen: .node (points), .ele (tetrahedra, positively oriented as TetGen wants), .face.
bool MeshExporter::write_tetgen(const io::VtkMesh& m, const std::vector<Triangle>& faces) {
  {
    File f = open_file(*this, mesh_filename(m, ".node"));
    if (!f) return false;
    std::fprintf(f.get(), "%zu 3 0 0\n", m.points.size());
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      std::fprintf(f.get(), "%zu ", i + 1);
      point_line(f.get(), m.points[i]);
      std::fputc('\n', f.get());
    }
  }
  if (tetras.get()) {
    File f = open_file(*this, mesh_filename(m, ".ele"));
    if (!f) return false;
    std::fprintf(f.get(), "%zu 4 0\n", m.tetrahedra.size());
    for (std::size_t i = 0; i < m.tetrahedra.size(); ++i) {
      Tetra t = m.tetrahedra[i];
      const Vec3& a = m.points.at(t[0]);
      // SOFA swaps the last two vertices of a tetrahedron with a positive triple product.
      if ((m.points.at(t[1]) - a).dot((m.points.at(t[2]) - a).cross(m.points.at(t[3]) - a)) > 0) std::swap(t[2], t[3]);
      std::fprintf(f.get(), "%zu", i + 1);
      one_based(f.get(), t);
    }
  }
  if (triangles.get()) {
    File f = open_file(*this, mesh_filename(m, ".face"));
    if (!f) return false;
    std::fprintf(f.get(), "%zu 0\n", faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      std::fprintf(f.get(), "%zu", i + 1);
      one_based(f.get(), faces[i]);
    }
  }
  return true;
}

// Gmsh MSH 2.1 text: nodes 1-based, elements "id type 0 vertices" (types 1 line, 2 triangle,
// 3 quad, 4 tetrahedron, 5 hexahedron), as SOFA writes them.
bool MeshExporter::write_gmsh(const io::VtkMesh& m) {
  File f = open_file(*this, mesh_filename(m, ".gmsh"));
  if (!f) return false;
  FILE* out = f.get();
  std::fprintf(out, "$MeshFormat\n2.1 0 8\n$EndMeshFormat\n$Nodes\n%zu\n", m.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    std::fprintf(out, "%zu ", i + 1);
    point_line(out, m.points[i]);
    std::fputc('\n', out);
  }
  std::fprintf(out, "$EndNodes\n$Elements\n%zu\n", m.cell_count());
  std::size_t id = 0;
  auto cells = [&](const auto& list, int type) {
    for (const auto& c : list) {
      std::fprintf(out, "%zu %d 0", ++id, type);
      one_based(out, c);
    }
  };
  cells(m.edges, 1);
  cells(m.triangles, 2);
  cells(m.quads, 3);
  cells(m.tetrahedra, 4);
  cells(m.hexahedra, 5);
  std::fprintf(out, "$EndElements\n");
  return std::ferror(out) == 0;
}

// OBJ: points, edges as "l", then the triangles, or the quads when triangles are off (SOFA).
bool MeshExporter::write_obj(const io::VtkMesh& m) {
  File f = open_file(*this, mesh_filename(m, ".obj"));
  if (!f) return false;
  FILE* out = f.get();
  std::fprintf(out, "#Export in obj format from SOFA\n#\no %s\n\n#Points (total = %zu pts)\n", base_name().c_str(),
               m.points.size());
  for (const Vec3& p : m.points) std::fputs("v ", out), point_line(out, p), std::fputc('\n', out);
  std::fputc('\n', out);
  for (const Edge& e : m.edges) std::fputc('l', out), one_based(out, e);
  if (triangles.get()) {
    for (const Triangle& t : m.triangles) std::fputc('f', out), one_based(out, t);
  } else {
    for (const Quad& q : m.quads) std::fputc('f', out), one_based(out, q);
  }
  return std::ferror(out) == 0;
}

void register_mesh_exporter(Registry& r) {
  ComponentInfo info;
  info.name = "MeshExporter";
  info.category = "Exporter";
  info.description = "writes the node's topology and points as vtkxml, vtk, netgen, tetgen, gmsh or obj files";
  info.create = creator<MeshExporter>();
  r.add(std::move(info));
}

}  // namespace sinew
