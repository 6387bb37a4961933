#include "io/gid_mesh_loader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/registry.h"

namespace sinew {

namespace {
bool fail(std::string* error, const std::string& why) {
  if (error) *error = why;
  return false;
}
// Lower case, surrounding white space (a trailing '\r' included) removed.
std::string normal_line(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}
}  // namespace

bool GIDMeshLoader::read_mesh(io::MeshData& out, std::string* error) {
  const std::string& path = filename.get();
  std::ifstream file(path);
  if (!file) return fail(error, "cannot open '" + path + "'");
  std::string line;
  std::getline(file, line);
  std::istringstream head(line);
  std::string word;
  head >> word;
  if (word != "MESH") return fail(error, "'" + path + "': bad GiD header (no MESH)");
  while (head >> word && word != "dimension") {
  }
  int dim = 0;
  if (word != "dimension" || !(head >> dim) || dim < 1 || dim > 3)
    return fail(error, "'" + path + "': bad GiD header (dimension)");
  std::string type;
  if (!(head >> word) || word != "ElemType" || !(head >> type))
    return fail(error, "'" + path + "': bad GiD header (missing ElemType)");
  int width = 0;
  if (type == "Linear") width = 2;
  else if (type == "Triangle") width = 3;
  else if (type == "Quadrilateral") width = 4;
  else if (type == "Tetrahedra") width = 4;
  else if (type == "Hexahedra") width = 8;
  else if (type == "Prism" || type == "Pyramid" || type == "Sphere" || type == "Circle")
    return fail(error, "'" + path + "': element type " + type + " is not supported (nor by SOFA)");
  else
    return fail(error, "'" + path + "': unknown element type '" + type + "'");
  int nnode = 0;
  if (!(head >> word) || word != "Nnode" || !(head >> nnode))
    return fail(error, "'" + path + "': bad GiD header (missing Nnode)");
  const std::vector<int> allowed = type == "Linear"          ? std::vector<int>{2, 3}
                                   : type == "Triangle"      ? std::vector<int>{3, 6}
                                   : type == "Quadrilateral" ? std::vector<int>{4, 8, 9}
                                   : type == "Tetrahedra"    ? std::vector<int>{4, 10}
                                                             : std::vector<int>{8, 20, 27};
  if (std::find(allowed.begin(), allowed.end(), nnode) == allowed.end())
    return fail(error, "'" + path + "': " + std::to_string(nnode) + " nodes per element is not possible for " + type);
  if (nnode != width)
    msg_warning("only the first " + std::to_string(width) + " nodes of the " + std::to_string(nnode) + "-node " +
                type + " elements are used (as SOFA)");

  auto seek = [&](const char* what) {
    while (std::getline(file, line))
      if (normal_line(line) == what) return true;
    return false;
  };
  if (!seek("coordinates")) return fail(error, "'" + path + "': no Coordinates block");
  bool ended = false;
  while (std::getline(file, line)) {
    const std::string l = normal_line(line);
    if (l == "end coordinates") {
      ended = true;
      break;
    }
    if (l.empty()) continue;
    std::istringstream is(l);
    long long id;
    Vec3 p = Vec3::Zero();
    is >> id;
    for (int d = 0; d < dim; ++d)
      if (!(is >> p[d])) return fail(error, "'" + path + "': bad coordinate line '" + l + "'");
    out.positions.push_back(p);
  }
  if (!ended) return fail(error, "'" + path + "': unexpected end of file in the Coordinates block");
  if (!seek("elements")) return fail(error, "'" + path + "': no Elements block");
  ended = false;
  while (std::getline(file, line)) {
    const std::string l = normal_line(line);
    if (l == "end elements") {
      ended = true;
      break;
    }
    if (l.empty()) continue;
    std::istringstream is(l);
    long long id;
    is >> id;
    unsigned v[8];
    for (int k = 0; k < width; ++k) {
      long long n;
      if (!(is >> n)) return fail(error, "'" + path + "': expecting a node index in '" + l + "'");
      if (n < 1 || static_cast<std::size_t>(n) > out.positions.size())
        return fail(error, "'" + path + "': node " + std::to_string(n) + " of element " + std::to_string(id) +
                               " is not one of the " + std::to_string(out.positions.size()) + " nodes");
      v[k] = static_cast<unsigned>(n - 1);
    }
    if (type == "Linear") out.edges.push_back({v[0], v[1]});
    else if (type == "Triangle") out.triangles.push_back({v[0], v[1], v[2]});
    else if (type == "Quadrilateral") out.quads.push_back({v[0], v[1], v[2], v[3]});
    else if (type == "Tetrahedra") out.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
    else out.hexahedra.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]});
  }
  if (!ended) return fail(error, "'" + path + "': unexpected end of file in the Elements block");
  return true;
}

void register_gid_mesh_loader(Registry& r) {
  ComponentInfo info;
  info.name = "GIDMeshLoader";
  info.category = "Loader";
  info.description = "loads GiD meshes (edges, triangles, quads, tetrahedra or hexahedra)";
  info.create = creator<GIDMeshLoader>();
  r.add(std::move(info));
}

}  // namespace sinew
