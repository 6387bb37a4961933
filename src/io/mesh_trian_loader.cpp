#include "io/mesh_trian_loader.h"

#include <fstream>

#include "core/registry.h"

namespace sinew {

MeshTrianLoader::MeshTrianLoader() {
  add_input(&trian2);
  add_output(&neighbor_table);
  add_output(&edges_on_border);
  add_output(&triangles_on_border);
}

namespace {
bool fail(std::string* error, const std::string& why) {
  if (error) *error = why;
  return false;
}
}  // namespace

bool MeshTrianLoader::read_mesh(io::MeshData& out, std::string* error) {
  neighbors_.clear();
  border_edges_.clear();
  border_triangles_.clear();
  const std::string& path = filename.get();
  std::ifstream in(path);
  if (!in) return fail(error, "cannot open '" + path + "'");
  auto read_points = [&](std::vector<Vec3>& pts, std::size_t n, const char* what) {
    for (std::size_t i = 0; i < n; ++i) {
      double x, y, z;
      if (!(in >> x >> y >> z))
        return fail(error, "'" + path + "': " + what + " " + std::to_string(i) + " of " + std::to_string(n) +
                               " cannot be read");
      pts.emplace_back(x, y, z);
    }
    return true;
  };
  std::size_t nv = 0, nt = 0;
  if (!trian2.get()) {
    if (!(in >> nv)) return fail(error, "'" + path + "': no vertex count");
    if (!read_points(out.positions, nv, "vertex")) return false;
    if (!(in >> nt)) return fail(error, "'" + path + "': no triangle count after the vertices");
    for (std::size_t i = 0; i < nt; ++i) {
      long long v[3];
      int ngh[3];
      if (!(in >> v[0] >> v[1] >> v[2] >> ngh[0] >> ngh[1] >> ngh[2]))
        return fail(error, "'" + path + "': triangle " + std::to_string(i) + " of " + std::to_string(nt) +
                               " cannot be read");
      for (long long k : v)
        if (k < 0 || static_cast<std::size_t>(k) >= nv)
          return fail(error, "'" + path + "': triangle " + std::to_string(i) + " has vertex " + std::to_string(k) +
                                 ", not one of the " + std::to_string(nv) + " vertices");
      const Triangle t{static_cast<unsigned>(v[0]), static_cast<unsigned>(v[1]), static_cast<unsigned>(v[2])};
      out.triangles.push_back(t);
      neighbors_.insert(neighbors_.end(), ngh, ngh + 3);
      if (ngh[0] == -1) border_edges_.push_back({t[1], t[2]});
      if (ngh[1] == -1) border_edges_.push_back({t[2], t[0]});
      if (ngh[2] == -1) border_edges_.push_back({t[0], t[1]});
      if (ngh[0] == -1 || ngh[1] == -1 || ngh[2] == -1) border_triangles_.push_back(static_cast<unsigned>(i));
    }
    return true;
  }
  // trian2: 13 lines of material parameters (not used by SOFA either).
  std::string line;
  for (int i = 0; i < 13; ++i) std::getline(in, line);
  std::string tag;
  if (!(in >> tag >> nv)) return fail(error, "'" + path + "': no vertex block after the 13 header lines");
  if (!read_points(out.positions, nv, "vertex")) return false;
  std::size_t nn = 0;
  if (!(in >> tag >> nn)) return fail(error, "'" + path + "': no normal block after the vertices");
  if (!read_points(out.normals, nn, "normal")) return false;
  if (!(in >> tag >> nt)) return fail(error, "'" + path + "': no triangle block after the normals");
  for (std::size_t i = 0; i < nt; ++i) {
    long long v[3];
    if (!(in >> v[0] >> v[1] >> v[2]))
      return fail(error, "'" + path + "': triangle " + std::to_string(i) + " of " + std::to_string(nt) +
                             " cannot be read");
    for (long long k : v)
      if (k < 0 || static_cast<std::size_t>(k) >= nv)
        return fail(error, "'" + path + "': triangle " + std::to_string(i) + " has vertex " + std::to_string(k) +
                               ", not one of the " + std::to_string(nv) + " vertices");
    out.triangles.push_back({static_cast<unsigned>(v[0]), static_cast<unsigned>(v[1]), static_cast<unsigned>(v[2])});
  }
  return true;
}

void MeshTrianLoader::publish_extra(const io::MeshData&) {
  neighbor_table.set(neighbors_);
  edges_on_border.set(border_edges_);
  triangles_on_border.set(border_triangles_);
}

void register_mesh_trian_loader(Registry& r) {
  ComponentInfo info;
  info.name = "MeshTrianLoader";
  info.category = "Loader";
  info.description = "loads .trian triangulations (with their neighbour tables) and trian2 files";
  info.create = creator<MeshTrianLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
