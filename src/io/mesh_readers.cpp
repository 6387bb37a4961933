#include "io/mesh_readers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <strings.h>
#include <unordered_map>

#include "io/sofa_quat.h"

namespace sinew::io {

namespace {

// ------------------------------------------------------------------ helpers

bool read_file(const std::string& path, std::string& out, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    if (error) *error = "'" + path + "' is a directory, not a mesh file";
    return false;
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    if (error) *error = "cannot open file '" + path + "'";
    return false;
  }
  std::ostringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

bool fail(std::string* error, const std::string& text) {
  if (error) *error = text;
  return false;
}

std::string where(const std::string& path, std::size_t line) { return path + ":" + std::to_string(line) + ": "; }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// Walks whitespace-separated tokens of one line (or any text).
struct Cursor {
  std::string_view s;
  std::size_t i = 0;
  std::string_view next() {
    while (i < s.size() && is_space(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    return s.substr(b, i - b);
  }
  bool at_end() {
    while (i < s.size() && is_space(s[i])) ++i;
    return i >= s.size();
  }
};

// Like `istream >> double`: the longest valid prefix; false when no number.
// A whole token as a number ("1e+", "0,5" or "0.x" are errors, as they make SOFA's stream reads fail).
template <class T>
bool to_number(std::string_view t, T& v) {
  if (t.empty()) return false;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (*b == '+') ++b;
  auto r = std::from_chars(b, e, v);
  return r.ec == std::errc() && r.ptr == e;
}
bool to_int_prefix(std::string_view t, long long& v) {
  if (t.empty()) return false;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (*b == '+') ++b;
  auto r = std::from_chars(b, e, v);
  return r.ec == std::errc();
}
// Whole token must be an integer (SOFA's safeStrToInt).
bool to_int_strict(std::string_view t, long long& v) {
  if (t.empty()) return false;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (*b == '+') ++b;
  auto r = std::from_chars(b, e, v);
  return r.ec == std::errc() && r.ptr == e;
}

// Splits a file into lines (without the '\n'; a trailing '\r' is kept, callers trim it).
std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t b = 0;
  while (b < text.size()) {
    std::size_t e = text.find('\n', b);
    if (e == std::string_view::npos) e = text.size();
    lines.push_back(text.substr(b, e - b));
    b = e + 1;
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower_ext(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return {};
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

template <std::size_t N>
std::array<unsigned, N> maybe_flip(std::array<unsigned, N> a, bool flip) {
  if (flip) std::reverse(a.begin(), a.end());
  return a;
}

std::string dir_of(const std::string& path) {
  const auto s = path.find_last_of("/\\");
  return s == std::string::npos ? std::string() : path.substr(0, s + 1);
}

// Names of the materials of a .mtl file (newmtl lines).
void read_mtl_names(const std::string& path, std::vector<std::string>& names) {
  std::string text;
  if (!read_file(path, text, nullptr)) return;
  for (std::string_view line : split_lines(text)) {
    Cursor c{line};
    if (c.next() == "newmtl") names.emplace_back(c.next());
  }
}

}  // namespace

// ------------------------------------------------------------------ OBJ

std::optional<MeshData> read_obj(const std::string& path, std::string* error, const ReadOptions& opt) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  MeshData m;
  std::vector<Vec3>& positions = m.positions_definition;
  std::vector<Vec2>& texcoords = m.texcoords_definition;
  std::vector<Vec3>& normals = m.normals_definition;

  enum { kEdge = 0, kTriangle = 1, kQuad = 2 };
  std::vector<PrimitiveGroup>* groups[3] = {&m.edges_groups, &m.triangles_groups, &m.quads_groups};
  std::string group_name = "Default_Group", material_name;
  int material_id = -1;
  int nb_faces[3] = {0, 0, 0}, group_first[3] = {0, 0, 0};
  auto close_groups = [&] {
    for (int ft = 0; ft < 3; ++ft)
      if (nb_faces[ft] > group_first[ft]) {
        groups[ft]->push_back({group_first[ft], nb_faces[ft] - group_first[ft], material_name, group_name, material_id});
        group_first[ft] = nb_faces[ft];
      }
  };

  // SOFA reads every v, vn and vt line into one vector declared before its loop, with stream
  // extractions that leave a value untouched once the line has ended: a line with fewer values
  // keeps those of the previous v/vn/vt line (raptorTemperature.obj has only "v 0" lines).
  Vec3 carry = Vec3::Zero();
  const auto lines = split_lines(text);
  for (std::size_t ln = 0; ln < lines.size(); ++ln) {
    std::string_view line = lines[ln];
    if (line.empty()) continue;
    Cursor c{line};
    const std::string_view tok = c.next();
    if (tok == "v" || tok == "vn" || tok == "vt") {
      const int count = tok == "vt" ? 2 : 3;
      for (int k = 0; k < count; ++k) {
        const std::string_view t = c.next();
        if (t.empty()) break;
        if (!to_number(t, carry[k])) {
          if (error)
            *error = where(path, ln + 1) + (tok == "vt" ? "bad texture coordinate in '" : "bad coordinate in '") +
                     std::string(trim(line)) + "'";
          return std::nullopt;
        }
      }
      if (tok == "vt") texcoords.emplace_back(carry[0], carry[1]);
      else (tok == "v" ? positions : normals).push_back(carry);
    } else if (tok == "mtllib") {
      for (std::string_view lib = c.next(); !lib.empty(); lib = c.next())
        read_mtl_names(dir_of(path) + std::string(lib), m.materials);
    } else if (tok == "usemtl" || tok == "g") {
      close_groups();
      if (tok == "usemtl") {
        material_name = std::string(c.next());
        material_id = -1;
        for (std::size_t i = 0; i < m.materials.size(); ++i)
          if (m.materials[i] == material_name) {
            material_id = static_cast<int>(i);
            break;
          }
      } else {
        group_name.clear();
        for (std::string_view g = c.next(); !g.empty(); g = c.next()) {
          if (!group_name.empty()) group_name += " ";
          group_name += std::string(g);
        }
      }
    } else if (tok == "l" || tok == "f") {
      std::vector<int> nodes, tex, nor;
      for (std::string_view item = c.next(); !item.empty(); item = c.next()) {
        int vtn[3] = {-1, -1, -1};
        std::string_view rest = item;
        for (int j = 0; j < 3; ++j) {
          const auto slash = rest.find('/');
          std::string_view part = rest.substr(0, slash);
          rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
          if (part.empty()) continue;
          long long v = 0;
          if (!to_int_strict(part, v) || v == 0) {
            if (error) *error = where(path, ln + 1) + "invalid index '" + std::string(part) + "'";
            return std::nullopt;
          }
          const std::size_t count = j == 0 ? positions.size() : j == 1 ? texcoords.size() : normals.size();
          if (v >= 1) v -= 1;
          else v += static_cast<long long>(count);
          if (v < 0) v = -1;
          vtn[j] = static_cast<int>(v);
        }
        nodes.push_back(vtn[0]);
        tex.push_back(vtn[1]);
        nor.push_back(vtn[2]);
      }
      // As SOFA: 'f' and 'l' are read alike, two vertices make an edge; fewer is an error.
      if (nodes.size() < 2u) {
        if (error)
          *error = where(path, ln + 1) + "'" + std::string(tok) + "' with " + std::to_string(nodes.size()) +
                   " vertices (at least 2 expected; truncated file?)";
        return std::nullopt;
      }
      m.face_positions.push_back(nodes);
      m.face_texcoords.push_back(tex);
      m.face_normals.push_back(nor);
      if (nodes.size() == 2) ++nb_faces[kEdge];
      else if (nodes.size() == 4 && !opt.triangulate) ++nb_faces[kQuad];
      else ++nb_faces[kTriangle];
    }
    // other keywords (#, o, s, ...) are ignored
  }
  close_groups();

  // Positions referenced by faces must exist (SOFA would read out of bounds).
  for (std::size_t f = 0; f < m.face_positions.size(); ++f)
    for (int p : m.face_positions[f])
      if (p < 0 || static_cast<std::size_t>(p) >= positions.size()) {
        if (error)
          *error = path + ": face " + std::to_string(f) + " uses vertex " + std::to_string(p + 1) + " but the file has " +
                   std::to_string(positions.size()) + " vertices";
        return std::nullopt;
      }

  auto add_face = [&](const std::vector<unsigned>& nodes) {
    if (nodes.size() == 2) {
      m.edges.push_back(nodes[0] < nodes[1] ? Edge{nodes[0], nodes[1]} : Edge{nodes[1], nodes[0]});
    } else if (nodes.size() == 4 && !opt.triangulate) {
      m.quads.push_back(maybe_flip(Quad{nodes[0], nodes[1], nodes[2], nodes[3]}, opt.flip_normals));
    } else {
      for (std::size_t j = 2; j < nodes.size(); ++j)
        m.triangles.push_back(maybe_flip(Triangle{nodes[0], nodes[j - 1], nodes[j]}, opt.flip_normals));
    }
  };

  if (!opt.handle_seams) {
    for (const auto& f : m.face_positions) add_face(std::vector<unsigned>(f.begin(), f.end()));
    m.positions = positions;
    const std::size_t n = positions.size();
    m.texcoords.assign(texcoords.empty() ? 0 : n, Vec2::Zero());
    m.normals.assign(normals.empty() ? 0 : n, Vec3::Zero());
    for (std::size_t fi = 0; fi < m.face_positions.size(); ++fi) {
      for (std::size_t i = 0; i < m.face_positions[fi].size(); ++i) {
        const auto pi = static_cast<unsigned>(m.face_positions[fi][i]);
        const auto ti = static_cast<unsigned>(m.face_texcoords[fi][i]);
        const auto ni = static_cast<unsigned>(m.face_normals[fi][i]);
        if (pi >= n) continue;
        if (ti < texcoords.size()) {
          const Vec2& cur = m.texcoords[pi];
          const Vec2 d = texcoords[ti] - cur;
          if ((cur[0] == 0 && cur[1] == 0) || (d[0] * -1 + d[1] * 1) > 0) m.texcoords[pi] = texcoords[ti];
        }
        if (ni < normals.size()) m.normals[pi] += normals[ni];
      }
    }
    for (Vec3& v : m.normals) {
      const double nn = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (nn > std::numeric_limits<double>::epsilon()) v /= nn;
    }
  } else {
    // One output vertex per distinct (texcoord, normal) pair of each position, ordered by the pair.
    const std::size_t nin = positions.size();
    std::vector<std::map<std::pair<int, int>, int>> vmap(nin);
    for (std::size_t fi = 0; fi < m.face_positions.size(); ++fi)
      for (std::size_t i = 0; i < m.face_positions[fi].size(); ++i)
        vmap[m.face_positions[fi][i]][{m.face_texcoords[fi][i], m.face_normals[fi][i]}] = 0;
    std::size_t nout = 0;
    for (const auto& mp : vmap) nout += mp.size();
    const bool split = nout != nin;
    m.positions.assign(nout, Vec3::Zero());
    m.normals.assign(nout, Vec3::Zero());
    m.texcoords.assign(nout, Vec2::Zero());
    if (split) {
      m.vert_pos_idx.assign(nout, 0);
      m.vert_norm_idx.assign(nout, 0);
    }
    unsigned nb_norm_out = 0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < nin; ++i) {
      std::map<int, unsigned> norm_map;
      for (auto& [key, out] : vmap[i]) {
        const int t = key.first, n = key.second;
        if (static_cast<unsigned>(n) < normals.size()) m.normals[j] = normals[n];
        if (static_cast<unsigned>(t) < texcoords.size()) m.texcoords[j] = texcoords[t];
        m.positions[j] = positions[i];
        if (split) {
          m.vert_pos_idx[j] = static_cast<unsigned>(i);
          auto it = norm_map.find(n);
          if (it != norm_map.end()) {
            m.vert_norm_idx[j] = it->second;
          } else {
            m.vert_norm_idx[j] = nb_norm_out;
            norm_map[n] = nb_norm_out++;
          }
        }
        out = static_cast<int>(j++);
      }
    }
    if (split && nb_norm_out == nout) m.vert_norm_idx.clear();
    for (std::size_t fi = 0; fi < m.face_positions.size(); ++fi) {
      std::vector<unsigned> nodes(m.face_positions[fi].size());
      for (std::size_t i = 0; i < nodes.size(); ++i)
        nodes[i] = static_cast<unsigned>(
            vmap[m.face_positions[fi][i]][{m.face_texcoords[fi][i], m.face_normals[fi][i]}]);
      add_face(nodes);
    }
    for (Vec3& v : m.normals) {
      const double nn = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (nn > std::numeric_limits<double>::epsilon()) v /= nn;
    }
  }
  return m;
}

// ------------------------------------------------------------------ Gmsh

namespace {

void add_in_group(std::vector<PrimitiveGroup>& g, int tag) {
  for (auto& p : g)
    if (p.p0 == tag) {
      ++p.nbp;
      return;
    }
  g.push_back({tag, 1, "", "", -1});
}
void normalize_group(std::vector<PrimitiveGroup>& g) {
  int start = 0;
  for (auto& p : g) {
    p.p0 = start;
    start += p.nbp;
  }
}

// Whitespace tokens of a whole text with their line numbers.
struct TokenStream {
  std::string_view s;
  std::size_t i = 0, line = 1;
  std::string_view next() {
    while (i < s.size() && is_space(s[i])) {
      if (s[i] == '\n') ++line;
      ++i;
    }
    const std::size_t b = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    return s.substr(b, i - b);
  }
};

int gmsh_node_count(int type) {
  switch (type) {
    case 15: return 1;
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    case 4: return 4;
    case 5: return 8;
    case 6: return 6;
    case 8: return 3;
    case 9: return 6;
    case 11: return 10;
    default: return -1;
  }
}

// Adds one element (already renumbered) the way SOFA's MeshGmsh does.
void gmsh_add(MeshData& m, int type, const std::vector<unsigned>& n, int tag, std::set<Edge>& edge_set) {
  static const unsigned tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  static const unsigned tet_edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}};
  auto quadratic_edges = [&](const unsigned (*pairs)[2], int count, int mid0) {
    for (int j = 0; j < count; ++j) {
      const unsigned v0 = std::min(n[pairs[j][0]], n[pairs[j][1]]);
      const unsigned v1 = std::max(n[pairs[j][0]], n[pairs[j][1]]);
      const Edge e{v0, v1};
      if (edge_set.insert(e).second) {
        m.edges.push_back(e);
        m.high_order_edge_positions.push_back({n[mid0 + j], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
      }
    }
  };
  switch (type) {
    case 1:
      add_in_group(m.edges_groups, tag);
      m.edges.push_back({n[0], n[1]});
      break;
    case 2:
      add_in_group(m.triangles_groups, tag);
      m.triangles.push_back({n[0], n[1], n[2]});
      break;
    case 3:
      add_in_group(m.quads_groups, tag);
      m.quads.push_back({n[0], n[1], n[2], n[3]});
      break;
    case 4:
      add_in_group(m.tetrahedra_groups, tag);
      m.tetrahedra.push_back({n[0], n[1], n[2], n[3]});
      break;
    case 5:
      add_in_group(m.hexahedra_groups, tag);
      m.hexahedra.push_back({n[0], n[1], n[2], n[3], n[4], n[5], n[6], n[7]});
      break;
    case 8:
      add_in_group(m.edges_groups, tag);
      m.edges.push_back({n[0], n[1]});
      m.high_order_edge_positions.push_back({n[2], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
      break;
    case 9:
      add_in_group(m.triangles_groups, tag);
      m.triangles.push_back({n[0], n[1], n[2]});
      quadratic_edges(tri_edges, 3, 3);
      break;
    case 11:
      add_in_group(m.tetrahedra_groups, tag);
      m.tetrahedra.push_back({n[0], n[1], n[2], n[3]});
      quadratic_edges(tet_edges, 6, 4);
      break;
    default:  // points and prisms are read but not kept (as SOFA)
      break;
  }
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

}  // namespace

std::optional<MeshData> read_gmsh(const std::string& path, std::string* error, const ReadOptions&) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  MeshData m;
  const auto lines = split_lines(text);
  if (lines.empty()) {
    if (error) *error = path + ": empty file, not a Gmsh mesh";
    return std::nullopt;
  }
  unsigned version = 0;
  std::size_t nodes_line = 0;  // index of the line holding "$Nodes" / "$NOD"
  if (starts_with(lines[0], "$MeshFormat")) {
    if (lines.size() < 3) {
      if (error) *error = where(path, 2) + "truncated $MeshFormat section";
      return std::nullopt;
    }
    long long v = 0;
    std::string_view vs = trim(lines[1]);
    vs = vs.substr(0, vs.find(' '));
    if (!to_int_prefix(vs, v) || v < 0) {
      if (error) *error = where(path, 2) + "invalid mesh format version '" + std::string(trim(lines[1])) + "'";
      return std::nullopt;
    }
    version = static_cast<unsigned>(v);
    if (!starts_with(lines[2], "$EndMeshFormat")) {
      if (error) *error = where(path, 3) + "no $EndMeshFormat after the format line";
      return std::nullopt;
    }
    {
      Cursor c{lines[1]};
      c.next();
      if (c.next() == "1") {
        if (error) *error = where(path, 2) + "binary Gmsh files are not supported (ASCII only)";
        return std::nullopt;
      }
    }
    nodes_line = 2;
    while (!starts_with(lines[nodes_line], "$Nodes")) {
      if (++nodes_line >= lines.size()) {
        if (error) *error = path + ": end of file reached without finding the $Nodes section";
        return std::nullopt;
      }
    }
  } else if (starts_with(lines[0], "$NOD")) {
    version = 1;
  } else {
    if (error) *error = where(path, 1) + "not a Gmsh file (first line is neither $MeshFormat nor $NOD)";
    return std::nullopt;
  }

  if (version <= 2) {
    // Token stream starting after the $Nodes/$NOD line.
    std::size_t offset = 0;
    for (std::size_t l = 0; l <= nodes_line; ++l) offset += lines[l].size() + 1;
    TokenStream ts{std::string_view(text).substr(std::min(offset, text.size())), 0, nodes_line + 2};
    auto err = [&](const std::string& what) {
      if (error) *error = where(path, ts.line) + what;
      return std::nullopt;
    };
    long long npoints = 0;
    if (!to_int_strict(ts.next(), npoints) || npoints < 0) return err("bad node count");
    std::unordered_map<long long, int> pmap;  // node id → ordinal (ids may have holes)
    m.positions.reserve(std::min(static_cast<std::size_t>(npoints), text.size()));
    for (long long i = 0; i < npoints; ++i) {
      long long index = 0;
      Vec3 p;
      if (!to_int_strict(ts.next(), index)) return err("bad node line");
      for (int k = 0; k < 3; ++k)
        if (!to_number(ts.next(), p[k])) return err("bad node coordinate");
      m.positions.push_back(p);
      pmap[index] = static_cast<int>(i);
    }
    std::string_view cmd = ts.next();
    if (!starts_with(cmd, "$ENDNOD") && !starts_with(cmd, "$EndNodes"))
      return err("'$ENDNOD' or '$EndNodes' expected, found '" + std::string(cmd) + "'");
    cmd = ts.next();
    if (!starts_with(cmd, "$ELM") && !starts_with(cmd, "$Elements"))
      return err("'$ELM' or '$Elements' expected, found '" + std::string(cmd) + "'");
    long long nelems = 0;
    if (!to_int_strict(ts.next(), nelems) || nelems < 0) return err("bad element count");
    std::set<Edge> edge_set_dummy;
    for (long long e = 0; e < nelems; ++e) {
      long long index = 0, type = 0, nnodes = 0, tag = -1;
      if (!to_int_strict(ts.next(), index) || !to_int_strict(ts.next(), type)) return err("bad element line");
      if (version == 1) {
        long long phys = 0, elem = 0;
        if (!to_int_strict(ts.next(), phys) || !to_int_strict(ts.next(), elem) || !to_int_strict(ts.next(), nnodes) || nnodes < 0 ||
            nnodes > 64)
          return err("bad element line");
      } else {
        long long ntags = 0;
        if (!to_int_strict(ts.next(), ntags) || ntags < 0 || ntags > 64) return err("bad element line");
        for (long long t = 0; t < ntags; ++t)
          if (!to_int_strict(ts.next(), tag)) return err("bad element tag");
        nnodes = gmsh_node_count(static_cast<int>(type));
        if (nnodes < 0) return err("unsupported element type " + std::to_string(type));
      }
      std::vector<unsigned> nodes(static_cast<std::size_t>(nnodes));
      for (auto& n : nodes) {
        long long t = 0;
        if (!to_int_strict(ts.next(), t)) return err("bad element node");
        const auto it = pmap.find(t);
        if (it == pmap.end()) return err("element uses unknown node " + std::to_string(t));
        n = static_cast<unsigned>(it->second);
      }
      if (version == 1 && gmsh_node_count(static_cast<int>(type)) != nnodes && type != 15)
        return err("element of type " + std::to_string(type) + " with " + std::to_string(nnodes) + " nodes");
      std::set<Edge> edge_set;  // v1/v2: deduplication within one element only
      gmsh_add(m, static_cast<int>(type), nodes, static_cast<int>(tag), edge_set);
    }
    cmd = ts.next();
    if (cmd != "$ENDELM" && cmd != "$EndElements")
      return err("'$ENDELM' or '$EndElements' expected, found '" + std::string(cmd) + "'");
  } else {
    std::size_t l = nodes_line + 1;
    auto line_at = [&](std::size_t k) { return k < lines.size() ? lines[k] : std::string_view(); };
    auto err = [&](std::size_t k, const std::string& what) {
      if (error) *error = where(path, k + 1) + what;
      return std::nullopt;
    };
    unsigned long long blocks = 0, nb_nodes = 0;
    {
      Cursor c{line_at(l)};
      long long b = 0, n = 0;
      if (!to_int_strict(c.next(), b) || !to_int_strict(c.next(), n) || b < 0 || n < 0) return err(l, "bad $Nodes header");
      blocks = static_cast<unsigned long long>(b);
      nb_nodes = static_cast<unsigned long long>(n);
    }
    ++l;
    m.positions.reserve(std::min<std::size_t>(nb_nodes, text.size()));
    for (unsigned long long b = 0; b < blocks; ++b) {
      Cursor c{line_at(l)};
      long long dim = 0, etag = 0, param = 0, n = 0;
      if (!to_int_strict(c.next(), dim) || !to_int_strict(c.next(), etag) || !to_int_strict(c.next(), param) || !to_int_strict(c.next(), n) ||
          n < 0)
        return err(l, "bad node entity block header");
      ++l;
      l += static_cast<std::size_t>(n);  // node tags
      for (long long i = 0; i < n; ++i, ++l) {
        if (l >= lines.size()) return err(l, "truncated node block");
        Cursor cc{lines[l]};
        Vec3 p;
        for (int k = 0; k < 3; ++k)
          if (!to_number(cc.next(), p[k])) return err(l, "bad node coordinate");
        m.positions.push_back(p);
      }
    }
    if (!starts_with(line_at(l), "$EndNodes")) return err(l, "'$EndNodes' expected");
    ++l;
    if (!starts_with(line_at(l), "$Elements")) return err(l, "'$Elements' expected");
    ++l;
    {
      Cursor c{line_at(l)};
      long long b = 0;
      if (!to_int_strict(c.next(), b) || b < 0) return err(l, "bad $Elements header");
      blocks = static_cast<unsigned long long>(b);
    }
    ++l;
    std::set<Edge> edge_set;  // v4: deduplication over the whole file
    for (unsigned long long b = 0; b < blocks; ++b) {
      Cursor c{line_at(l)};
      long long dim = 0, etag = 0, type = 0, n = 0;
      if (!to_int_strict(c.next(), dim) || !to_int_strict(c.next(), etag) || !to_int_strict(c.next(), type) || !to_int_strict(c.next(), n) ||
          n < 0)
        return err(l, "bad element entity block header");
      const int nnodes = gmsh_node_count(static_cast<int>(type));
      if (nnodes < 0) return err(l, "unsupported element type " + std::to_string(type));
      ++l;
      for (long long e = 0; e < n; ++e, ++l) {
        if (l >= lines.size()) return err(l, "truncated element block");
        Cursor cc{lines[l]};
        long long tag = 0;
        if (!to_int_strict(cc.next(), tag)) return err(l, "bad element line");
        std::vector<unsigned> nodes(static_cast<std::size_t>(nnodes));
        for (auto& nd : nodes) {
          long long id = 0;
          if (!to_int_strict(cc.next(), id) || id < 1 || static_cast<unsigned long long>(id) > m.positions.size())
            return err(l, "element uses unknown node");
          nd = static_cast<unsigned>(id - 1);
        }
        gmsh_add(m, static_cast<int>(type), nodes, static_cast<int>(tag), edge_set);
      }
    }
    const std::string_view end = trim(line_at(l));
    if (end != "$EndElements" && end != "$ENDELM") return err(l, "'$EndElements' expected");
  }
  normalize_group(m.edges_groups);
  normalize_group(m.triangles_groups);
  normalize_group(m.tetrahedra_groups);
  normalize_group(m.hexahedra_groups);
  return m;
}

// ------------------------------------------------------------------ VTK

namespace {

double decode_value(const unsigned char* p, int size, bool is_float, bool is_signed, bool swap);

// One VTK array: values widened to double, plus whether it was float32.
struct VtkArray {
  std::vector<double> v;
  bool is_float = false;
  bool ok = false;
  std::size_t bad_line = 0;  // text arrays: line of the token that could not be read (0: ran out of data)
  // Legacy binary arrays: the raw bytes, to decode again if the data turn out byte-swapped.
  std::string raw;
  int size = 0;
  bool is_signed = true;
  void redecode_swapped() {
    if (raw.empty()) return;
    const auto* p = reinterpret_cast<const unsigned char*>(raw.data());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = decode_value(p + i * size, size, is_float, is_signed, true);
  }
};

int vtk_type_size(const std::string& t, bool* is_float, bool* is_signed) {
  auto eq = [&](const char* a, const char* b) { return strcasecmp(t.c_str(), a) == 0 || strcasecmp(t.c_str(), b) == 0; };
  *is_float = false;
  *is_signed = true;
  if (eq("char", "Int8")) return 1;
  if (eq("unsigned_char", "UInt8")) return *is_signed = false, 1;
  if (eq("short", "Int16")) return 2;
  if (eq("unsigned_short", "UInt16")) return *is_signed = false, 2;
  if (eq("int", "Int32")) return 4;
  if (eq("unsigned_int", "UInt32")) return *is_signed = false, 4;
  if (eq("long", "Int64")) return 8;
  if (eq("unsigned_long", "UInt64")) return *is_signed = false, 8;
  if (eq("float", "Float32")) return *is_float = true, 4;
  if (eq("double", "Float64")) return *is_float = true, 8;
  return 0;
}

double decode_value(const unsigned char* p, int size, bool is_float, bool is_signed, bool swap) {
  unsigned char b[8];
  for (int k = 0; k < size; ++k) b[k] = swap ? p[size - 1 - k] : p[k];
  if (is_float) {
    if (size == 4) {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  switch (size) {
    case 1: return is_signed ? static_cast<double>(static_cast<int8_t>(b[0])) : b[0];
    case 2: {
      uint16_t u;
      std::memcpy(&u, b, 2);
      return is_signed ? static_cast<double>(static_cast<int16_t>(u)) : u;
    }
    case 4: {
      uint32_t u;
      std::memcpy(&u, b, 4);
      return is_signed ? static_cast<double>(static_cast<int32_t>(u)) : u;
    }
    default: {
      uint64_t u;
      std::memcpy(&u, b, 8);
      return is_signed ? static_cast<double>(static_cast<int64_t>(u)) : static_cast<double>(u);
    }
  }
}

// Legacy-file reader state: a position in the whole file buffer.
struct LegacyIn {
  const std::string& s;
  std::size_t pos = 0;
  std::size_t line = 1;
  bool eof() const { return pos >= s.size(); }
  std::string_view getline() {
    if (pos >= s.size()) {
      pos = s.size() + 1;  // mark eof after an empty read
      return {};
    }
    std::size_t e = s.find('\n', pos);
    if (e == std::string::npos) e = s.size();
    std::string_view r(s.data() + pos, e - pos);
    pos = e + 1;
    ++line;
    return r;
  }
  std::string_view next_nonempty() {
    std::string_view l;
    do l = getline();
    while (pos <= s.size() && l.empty());
    return l;
  }
};

// Reads n values (ASCII: line by line, the rest of the last line dropped; binary: raw big-endian bytes).
VtkArray legacy_read(LegacyIn& in, std::size_t n, const std::string& type, int binary) {
  VtkArray a;
  bool is_signed = true;
  const int size = vtk_type_size(type, &a.is_float, &is_signed);
  if (size == 0) return a;
  // Each value takes at least one byte (binary) or two characters (text): larger counts cannot be satisfied.
  if (n > in.s.size()) return a;
  a.v.resize(n);
  if (binary) {
    const std::size_t bytes = n * static_cast<std::size_t>(size);
    if (in.pos + bytes > in.s.size()) return a;
    const auto* p = reinterpret_cast<const unsigned char*>(in.s.data() + in.pos);
    // Read natively (little-endian) like SOFA; read_vtk_legacy detects byte-swapped (big-endian) files afterwards.
    for (std::size_t i = 0; i < n; ++i) a.v[i] = decode_value(p + i * size, size, a.is_float, is_signed, false);
    a.raw.assign(in.s.data() + in.pos, bytes);
    a.size = size;
    a.is_signed = is_signed;
    for (std::size_t k = 0; k < bytes; ++k)
      if (in.s[in.pos + k] == '\n') ++in.line;
    in.pos += bytes;
  } else {
    std::size_t i = 0;
    while (i < n && !in.eof()) {
      Cursor c{in.getline()};
      for (std::string_view t = c.next(); i < n && !t.empty(); t = c.next()) {
        bool ok = false;
        if (a.is_float && size == 4) {
          float f;
          if ((ok = to_number(t, f))) a.v[i++] = f;
        } else if (a.is_float) {
          double d;
          if ((ok = to_number(t, d))) a.v[i++] = d;
        } else {
          long long k;
          if ((ok = to_int_strict(t, k))) a.v[i++] = static_cast<double>(k);
        }
        if (!ok) {
          a.bad_line = in.line - 1;  // the line just read
          return a;
        }
      }
    }
    if (i < n) return a;
  }
  a.ok = true;
  return a;
}

// Shared conversion of points + cells into MeshData (SOFA's setInputsMesh).
struct VtkCells {
  std::vector<double> polygons;      // legacy POLYGONS: n, i0..in-1, ...
  std::vector<double> cells;         // legacy CELLS (counts included) or XML connectivity
  std::vector<double> offsets;       // XML only
  std::vector<double> types;
  std::size_t number_of_cells = 0;
  bool has_polygons = false, has_cells = false, has_types = false;
};

bool vtk_to_mesh(MeshData& m, const VtkCells& vc, const std::string& path, std::string* error, bool flip) {
  const std::size_t np = m.positions.size();
  auto idx = [&](double d) { return static_cast<unsigned>(static_cast<long long>(d)); };
  auto check = [&](unsigned i) { return i < np; };
  if (vc.has_polygons) {
    const auto& p = vc.polygons;
    std::size_t i = 0;
    int poly = 0;
    while (i < p.size()) {
      if (p[i] < 0) return fail(error, path + ": polygon " + std::to_string(poly) + " has a negative size");
      const auto nv = static_cast<std::size_t>(p[i]);
      ++i;
      if (i + nv > p.size()) return fail(error, path + ": polygon " + std::to_string(poly) + " is truncated");
      for (std::size_t j = 0; j < nv; ++j)
        if (!check(idx(p[i + j])))
          return fail(error, path + ": invalid point " + std::to_string(idx(p[i + j])) + " in polygon " +
                                 std::to_string(poly));
      if (nv == 4) {
        m.quads.push_back(maybe_flip(Quad{idx(p[i]), idx(p[i + 1]), idx(p[i + 2]), idx(p[i + 3])}, flip));
      } else if (nv >= 3) {
        unsigned f0 = idx(p[i]), f1 = idx(p[i + 1]);
        for (std::size_t j = 2; j < nv; ++j) {
          const unsigned f2 = idx(p[i + j]);
          m.triangles.push_back(maybe_flip(Triangle{f0, f1, f2}, flip));
          f1 = f2;
        }
      }
      i += nv;
      ++poly;
    }
    return true;
  }
  if (!(vc.has_cells && vc.has_types)) return true;
  static const unsigned tri_edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  static const unsigned tet_edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
  std::set<Edge> edge_set;
  const auto& c = vc.cells;
  std::size_t i = 0;
  for (std::size_t cell = 0; cell < vc.number_of_cells; ++cell) {
    if (cell >= vc.types.size()) return fail(error, path + ": fewer cell types than cells");
    const int t = static_cast<int>(vc.types[cell]);
    std::size_t nv = 0;
    if (!vc.offsets.empty()) {
      const double b0 = cell == 0 ? 0.0 : vc.offsets[cell - 1], e0 = vc.offsets[cell];
      if (b0 < 0 || e0 < 0 || e0 > static_cast<double>(c.size()))
        return fail(error, path + ": cell " + std::to_string(cell) + " has invalid offsets");
      i = static_cast<std::size_t>(b0);
      const std::size_t end = static_cast<std::size_t>(e0);
      nv = end >= i ? end - i : 0;
    } else {
      if (i >= c.size()) return fail(error, path + ": cell " + std::to_string(cell) + " is missing");
      if (c[i] < 0) return fail(error, path + ": cell " + std::to_string(cell) + " has a negative size");
      nv = static_cast<std::size_t>(c[i]);
      ++i;
    }
    if (i + nv > c.size()) return fail(error, path + ": cell " + std::to_string(cell) + " is truncated");
    std::vector<unsigned> v(nv);
    for (std::size_t k = 0; k < nv; ++k) {
      v[k] = idx(c[i + k]);
      if (!check(v[k]))
        return fail(error, path + ": cell " + std::to_string(cell) + " uses point " + std::to_string(v[k]) +
                               " but the file has " + std::to_string(np) + " points");
    }
    auto need = [&](std::size_t k) {
      if (nv < k)
        return fail(error, path + ": cell " + std::to_string(cell) + " of type " + std::to_string(t) + " has " +
                               std::to_string(nv) + " points");
      return true;
    };
    auto quad_edges = [&](const unsigned (*pairs)[2], int count, int mid0) {
      for (int j = 0; j < count; ++j) {
        const unsigned a = std::min(v[pairs[j][0]], v[pairs[j][1]]), b = std::max(v[pairs[j][0]], v[pairs[j][1]]);
        if (edge_set.insert({a, b}).second) {
          m.edges.push_back({a, b});
          m.high_order_edge_positions.push_back({v[mid0 + j], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
        }
      }
    };
    switch (t) {
      case 0:
      case 1:
      case 2: break;
      case 3:
        if (!need(2)) return false;
        m.edges.push_back({v[0], v[1]});
        break;
      case 4: m.polylines.push_back(v); break;
      case 5:
        if (!need(3)) return false;
        m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, flip));
        break;
      case 6:
        for (std::size_t j = 0; j + 2 < nv; ++j)
          m.triangles.push_back(maybe_flip(
              (j & 1) ? Triangle{v[j], v[j + 1], v[j + 2]} : Triangle{v[j], v[j + 2], v[j + 1]}, flip));
        break;
      case 7:
        for (std::size_t j = 2; j < nv; ++j) m.triangles.push_back(maybe_flip(Triangle{v[0], v[j - 1], v[j]}, flip));
        break;
      case 8:
        if (!need(4)) return false;
        m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[3], v[2]}, flip));
        break;
      case 9:
        if (!need(4)) return false;
        m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[2], v[3]}, flip));
        break;
      case 10:
        if (!need(4)) return false;
        m.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
        break;
      case 11:
        if (!need(8)) return false;
        m.hexahedra.push_back({v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6]});
        break;
      case 12:
        if (!need(8)) return false;
        m.hexahedra.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]});
        break;
      case 13:
        if (!need(6)) return false;
        m.prisms.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
        break;
      case 14:
        if (!need(5)) return false;
        m.pyramids.push_back({v[0], v[1], v[2], v[3], v[4]});
        break;
      case 21:
        if (!need(3)) return false;
        m.edges.push_back({v[0], v[1]});
        m.high_order_edge_positions.push_back({v[2], static_cast<unsigned>(m.edges.size() - 1), 1, 1});
        break;
      case 22:
        if (!need(6)) return false;
        m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, flip));
        quad_edges(tri_edges, 3, 3);
        break;
      case 24:
        if (!need(10)) return false;
        m.tetrahedra.push_back({v[0], v[1], v[2], v[3]});
        quad_edges(tet_edges, 6, 4);
        break;
      default: return fail(error, path + ": unsupported VTK cell type " + std::to_string(t));
    }
    if (vc.offsets.empty()) i += nv;
  }
  return true;
}

void set_points(MeshData& m, const VtkArray& a) {
  m.positions.resize(a.v.size() / 3);
  for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = Vec3(a.v[3 * i], a.v[3 * i + 1], a.v[3 * i + 2]);
}

std::optional<MeshData> read_vtk_legacy(const std::string& path, const std::string& text, std::string* error,
                                        const ReadOptions& opt) {
  LegacyIn in{text, 0, 1};
  auto err = [&](const std::string& what) {
    if (error) *error = where(path, in.line) + what;
    return std::nullopt;
  };
  // A text array that could not be read: the line of the bad value, else "end of data".
  auto arr_err = [&](const VtkArray& a, const std::string& what) {
    if (error)
      *error = a.bad_line ? where(path, a.bad_line) + "bad value while reading " + what
                          : where(path, std::min(in.line, static_cast<std::size_t>(std::count(in.s.begin(), in.s.end(), '\n') + 1))) +
                                "unexpected end of data while reading " + what;
    return std::nullopt;
  };
  std::string_view line = in.getline();
  if (line.substr(0, 23) != "# vtk DataFile Version ") return err("unrecognized VTK header");
  in.getline();  // title
  line = trim(in.getline());
  int binary = 0;
  if (line == "BINARY") binary = 1;
  else if (line == "ASCII") binary = 0;
  else return err("unrecognized format '" + std::string(line) + "' (ASCII or BINARY expected)");
  do line = in.getline();
  while (line.empty() && !in.eof());
  line = trim(line);
  if (line != "DATASET POLYDATA" && line != "DATASET UNSTRUCTURED_GRID")
    return err("unsupported dataset '" + std::string(line) + "' (POLYDATA or UNSTRUCTURED_GRID expected)");

  MeshData m;
  VtkCells vc;
  VtkArray points, normals, polygons, cells, types;
  bool has_points = false;
  while (!in.eof()) {
    line = in.next_nonempty();
    Cursor c{line};
    const std::string kw(c.next());
    if (kw.empty()) break;
    if (kw == "POINTS") {
      long long n = 0;
      if (!to_int_strict(c.next(), n) || n < 0) return err("bad POINTS line");
      const std::string type(c.next());
      bool f = false, s = true;
      const int size = vtk_type_size(type, &f, &s);
      if (size == 0 || !f) return err("type of coordinates '" + type + "' not supported (float or double)");
      points = legacy_read(in, static_cast<std::size_t>(3 * n), type, binary);
      if (!points.ok) return arr_err(points, std::to_string(n) + " points");
      has_points = true;
    } else if (kw == "POLYGONS") {
      long long n = 0, ni = 0;
      if (!to_int_strict(c.next(), n) || !to_int_strict(c.next(), ni) || ni < 0) return err("bad POLYGONS line");
      polygons = legacy_read(in, static_cast<std::size_t>(ni), "int", binary);
      if (!polygons.ok) return arr_err(polygons, "polygons");
      vc.has_polygons = true;
    } else if (kw == "CELLS" || kw == "LINES") {
      long long n = 0, ni = 0;
      if (!to_int_strict(c.next(), n) || !to_int_strict(c.next(), ni) || ni < 0 || n < 0) return err("bad " + kw + " line");
      cells = legacy_read(in, static_cast<std::size_t>(ni), "int", binary);
      if (!cells.ok) return arr_err(cells, "cells");
      vc.has_cells = true;
      vc.number_of_cells = static_cast<std::size_t>(n);
      if (kw == "LINES") {
        types = VtkArray{};
        types.v.assign(static_cast<std::size_t>(n), 4.0);
        types.ok = true;
        vc.has_types = true;
      }
    } else if (kw == "CELL_TYPES") {
      long long n = 0;
      if (!to_int_strict(c.next(), n) || n < 0) return err("bad CELL_TYPES line");
      types = legacy_read(in, static_cast<std::size_t>(n), "int", binary);
      if (!types.ok) return arr_err(types, "cell types");
      vc.has_types = true;
    } else if (kw == "CELL_DATA" || kw == "POINT_DATA") {
      const bool cell = kw == "CELL_DATA";
      long long nb = 0;
      to_int_strict(c.next(), nb);
      auto& out = cell ? m.cell_data : m.point_data;
      while (!in.eof()) {
        const std::size_t save_pos = in.pos, save_line = in.line;
        std::string_view l = in.next_nonempty();
        if (l.empty()) break;
        Cursor d{l};
        const std::string ds(d.next());
        if (ds == "SCALARS") {
          const std::string name(d.next()), type(d.next());
          long long comps = 1;
          if (!to_int_strict(d.next(), comps) || comps < 1) comps = 1;
          const std::size_t p2 = in.pos, l2 = in.line;
          Cursor lk{in.getline()};
          if (lk.next() != "LOOKUP_TABLE") in.pos = p2, in.line = l2;
          auto a = legacy_read(in, static_cast<std::size_t>(nb), type, binary);
          if (a.ok) out.push_back({name, 1, std::move(a.v)});
        } else if (ds == "NORMALS" || ds == "VECTORS") {
          const std::string name(d.next()), type(d.next());
          auto a = legacy_read(in, static_cast<std::size_t>(3 * nb), type, binary);
          if (!a.ok) return arr_err(a, ds + " '" + name + "'");
          if (ds == "NORMALS") normals = std::move(a);
          else out.push_back({name, 3, std::move(a.v)});
        } else if (ds == "FIELD") {
          std::string fname(d.next());
          long long arrays = 0;
          to_int_strict(d.next(), arrays);
          for (long long k = 0; k < arrays; ++k) {
            Cursor fl{in.next_nonempty()};
            const std::string name(fl.next());
            long long comps = 1, count = 0;
            to_int_strict(fl.next(), comps);
            to_int_strict(fl.next(), count);
            const std::string type(fl.next());
            auto a = legacy_read(in, static_cast<std::size_t>(comps * count), type, binary);
            if (!a.ok) return arr_err(a, "field array '" + name + "'");
            out.push_back({name, static_cast<int>(comps), std::move(a.v)});
          }
        } else if (ds == "LOOKUP_TABLE") {
          std::string tname(d.next());
          long long n = 0;
          to_int_strict(d.next(), n);
          legacy_read(in, static_cast<std::size_t>(4 * n), binary ? "UInt8" : "Float32", binary);
        } else {
          in.pos = save_pos;
          in.line = save_line;
          break;
        }
      }
    }
    // other keywords (METADATA, ...) are skipped
  }
  if (!has_points) return err("no POINTS section");
  if (binary) {
    // SOFA's check: the data are byte-swapped when the first polygon size / cell type read natively is larger
    // than its byte-swapped value (always the case for standard big-endian files).
    const VtkArray* probe = vc.has_polygons ? &polygons : (vc.has_cells && vc.has_types) ? &types : nullptr;
    if (probe && !probe->raw.empty() && probe->raw.size() >= 4) {
      const auto* p = reinterpret_cast<const unsigned char*>(probe->raw.data());
      const auto native = static_cast<uint32_t>(static_cast<int32_t>(decode_value(p, 4, false, true, false)));
      const auto swapped = static_cast<uint32_t>(static_cast<int32_t>(decode_value(p, 4, false, true, true)));
      if (native > swapped)
        for (VtkArray* a : {&points, &normals, &polygons, &cells, &types}) a->redecode_swapped();
    }
  }
  vc.polygons = std::move(polygons.v);
  vc.cells = std::move(cells.v);
  vc.types = std::move(types.v);
  set_points(m, points);
  if (normals.ok) {
    m.normals.resize(normals.v.size() / 3);
    for (std::size_t i = 0; i < m.normals.size(); ++i)
      m.normals[i] = Vec3(normals.v[3 * i], normals.v[3 * i + 1], normals.v[3 * i + 2]);
  }
  if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
  return m;
}

// --- minimal XML for VTK files

struct XmlElem {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;
  std::vector<XmlElem> children;
  const XmlElem* child(const std::string& n) const {
    for (const auto& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
  std::string attr(const std::string& n, const std::string& def = {}) const {
    auto it = attrs.find(n);
    return it == attrs.end() ? def : it->second;
  }
};

struct XmlParser {
  const std::string& s;
  std::size_t i = 0;
  std::string error;
  void skip_ws() {
    while (i < s.size() && is_space(s[i])) ++i;
  }
  void skip_misc() {
    for (;;) {
      skip_ws();
      if (s.compare(i, 4, "<!--") == 0) {
        auto e = s.find("-->", i);
        i = e == std::string::npos ? s.size() : e + 3;
      } else if (s.compare(i, 2, "<?") == 0) {
        auto e = s.find("?>", i);
        i = e == std::string::npos ? s.size() : e + 2;
      } else {
        return;
      }
    }
  }
  bool parse(XmlElem& e) {
    skip_misc();
    if (i >= s.size() || s[i] != '<') return (error = "element expected"), false;
    ++i;
    std::size_t b = i;
    while (i < s.size() && !is_space(s[i]) && s[i] != '>' && s[i] != '/') ++i;
    e.name = s.substr(b, i - b);
    for (;;) {
      skip_ws();
      if (i >= s.size()) return (error = "unterminated tag <" + e.name + ">"), false;
      if (s[i] == '/') {
        if (s.compare(i, 2, "/>") != 0) return (error = "bad tag <" + e.name + ">"), false;
        i += 2;
        return true;
      }
      if (s[i] == '>') {
        ++i;
        break;
      }
      b = i;
      while (i < s.size() && s[i] != '=' && !is_space(s[i])) ++i;
      std::string key = s.substr(b, i - b);
      skip_ws();
      if (i >= s.size() || s[i] != '=') return (error = "bad attribute in <" + e.name + ">"), false;
      ++i;
      skip_ws();
      if (i >= s.size() || (s[i] != '"' && s[i] != '\'')) return (error = "bad attribute in <" + e.name + ">"), false;
      const char q = s[i++];
      b = i;
      while (i < s.size() && s[i] != q) ++i;
      e.attrs[key] = s.substr(b, i - b);
      ++i;
    }
    for (;;) {
      b = i;
      while (i < s.size() && s[i] != '<') ++i;
      e.text += s.substr(b, i - b);
      if (i >= s.size()) return (error = "unterminated element <" + e.name + ">"), false;
      if (s.compare(i, 2, "</") == 0) {
        auto end = s.find('>', i);
        if (end == std::string::npos) return (error = "unterminated closing tag"), false;
        i = end + 1;
        return true;
      }
      if (s.compare(i, 4, "<!--") == 0 || s.compare(i, 2, "<?") == 0) {
        skip_misc();
        continue;
      }
      e.children.emplace_back();
      if (!parse(e.children.back())) return false;
    }
  }
};

bool base64_decode(std::string_view in, std::vector<unsigned char>& out) {
  static int table[256];
  static bool init = false;
  if (!init) {
    std::fill(std::begin(table), std::end(table), -1);
    const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int k = 0; k < 64; ++k) table[static_cast<unsigned char>(a[k])] = k;
    init = true;
  }
  unsigned buf = 0;
  int bits = 0;
  for (char ch : in) {
    if (is_space(ch)) continue;
    if (ch == '=') {
      // padding: a new block may start after it (VTK concatenates header and data encodings)
      bits = 0;
      buf = 0;
      continue;
    }
    const int v = table[static_cast<unsigned char>(ch)];
    if (v < 0) return false;
    buf = (buf << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buf >> bits) & 0xFF));
    }
  }
  return true;
}

bool xml_array(const XmlElem& da, const std::string& header_type, bool swap, VtkArray& a, std::string& why,
               bool ascii_as_double = false) {
  const std::string type = da.attr("type");
  bool is_signed = true;
  const int size = vtk_type_size(type, &a.is_float, &is_signed);
  if (size == 0) return (why = "unsupported DataArray type '" + type + "'"), false;
  const std::string format = da.attr("format", "ascii");
  if (format == "ascii") {
    Cursor c{da.text};
    for (std::string_view t = c.next(); !t.empty(); t = c.next()) {
      if (a.is_float && size == 4 && !ascii_as_double) {
        float f;
        if (!to_number(t, f)) return (why = "bad number '" + std::string(t) + "'"), false;
        a.v.push_back(f);
      } else if (a.is_float) {
        double d;
        if (!to_number(t, d)) return (why = "bad number '" + std::string(t) + "'"), false;
        a.v.push_back(d);
      } else {
        long long k;
        if (!to_int_strict(t, k)) return (why = "bad integer '" + std::string(t) + "'"), false;
        a.v.push_back(static_cast<double>(k));
      }
    }
  } else if (format == "binary") {
    std::vector<unsigned char> bytes;
    if (!base64_decode(da.text, bytes)) return (why = "bad base64 data"), false;
    const std::size_t hs = header_type == "UInt64" ? 8 : 4;
    if (bytes.size() < hs) return (why = "truncated binary DataArray"), false;
    const auto nbytes = static_cast<std::size_t>(decode_value(bytes.data(), static_cast<int>(hs), false, false, swap));
    if (bytes.size() < hs + nbytes) return (why = "truncated binary DataArray"), false;
    const std::size_t n = nbytes / static_cast<std::size_t>(size);
    a.v.resize(n);
    for (std::size_t k = 0; k < n; ++k) a.v[k] = decode_value(bytes.data() + hs + k * size, size, a.is_float, is_signed, swap);
  } else {
    return (why = "DataArray format '" + format + "' is not supported (ascii or binary)"), false;
  }
  a.ok = true;
  return true;
}

std::optional<MeshData> read_vtk_xml(const std::string& path, const std::string& text, std::string* error,
                                     const ReadOptions& opt) {
  XmlParser p{text, 0, {}};
  XmlElem root;
  if (!p.parse(root)) {
    if (error) *error = path + ": XML error: " + p.error;
    return std::nullopt;
  }
  auto err = [&](const std::string& what) {
    if (error) *error = path + ": " + what;
    return std::nullopt;
  };
  if (root.name != "VTKFile") return err("root element is <" + root.name + ">, <VTKFile> expected");
  if (!root.attr("compressor").empty()) return err("compressed VTK XML files are not supported");
  // Binary arrays (and their byte-count headers) are in the file's byte order; ASCII arrays have none.
  const std::string byte_order = root.attr("byte_order", "LittleEndian");
  if (byte_order != "LittleEndian" && byte_order != "BigEndian")
    return err("unknown byte_order '" + byte_order + "' (LittleEndian or BigEndian expected)");
  const bool swap = byte_order == "BigEndian";
  const std::string header_type = root.attr("header_type", "UInt32");
  const std::string type = root.attr("type");
  const XmlElem* grid = root.child(type);
  if (!grid || (type != "UnstructuredGrid" && type != "PolyData"))
    return err("VTK XML type '" + type + "' is not supported (UnstructuredGrid or PolyData)");
  const XmlElem* piece = grid->child("Piece");
  if (!piece) return err("no <Piece> element");
  MeshData m;
  std::string why;
  const XmlElem* pts = piece->child("Points");
  if (!pts || !pts->child("DataArray")) return err("no <Points> data");
  VtkArray points;
  // SOFA stores XML point coordinates as Float64 (ASCII values are not rounded to float).
  if (!xml_array(*pts->child("DataArray"), header_type, swap, points, why, true)) return err("Points: " + why);
  set_points(m, points);
  VtkCells vc;
  auto read_cells = [&](const XmlElem& cells, int fixed_type) -> bool {
    VtkArray conn, offs, types;
    for (const auto& da : cells.children) {
      const std::string name = da.attr("Name");
      VtkArray* t = name == "connectivity" ? &conn : name == "offsets" ? &offs : name == "types" ? &types : nullptr;
      if (t && !xml_array(da, header_type, swap, *t, why)) return false;
    }
    if (!conn.ok || !offs.ok) return (why = "missing connectivity or offsets"), false;
    if (fixed_type < 0 && !types.ok) return (why = "missing cell types"), false;
    vc.cells = std::move(conn.v);
    vc.offsets = std::move(offs.v);
    vc.number_of_cells = vc.offsets.size();
    vc.types = fixed_type < 0 ? std::move(types.v) : std::vector<double>(vc.offsets.size(), fixed_type);
    vc.has_cells = vc.has_types = true;
    return true;
  };
  if (type == "UnstructuredGrid") {
    const XmlElem* cells = piece->child("Cells");
    if (cells && !read_cells(*cells, -1)) return err("Cells: " + why);
    if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
  } else {
    // PolyData: only Polys are read (as SOFA): 2 vertices → line, 3 → triangle, 4 → quad, more → polyline.
    if (const XmlElem* polys = piece->child("Polys")) {
      if (!read_cells(*polys, 0)) return err("Polys: " + why);
      for (std::size_t c = 0; c < vc.offsets.size(); ++c) {
        const double n = c == 0 ? vc.offsets[0] : vc.offsets[c] - vc.offsets[c - 1];
        vc.types[c] = n == 2 ? 3 : n == 3 ? 5 : n == 4 ? 9 : 4;
      }
      if (!vtk_to_mesh(m, vc, path, error, opt.flip_normals)) return std::nullopt;
    }
  }
  for (const char* section : {"PointData", "CellData"}) {
    const XmlElem* s = piece->child(section);
    if (!s) continue;
    for (const auto& da : s->children) {
      VtkArray a;
      if (!xml_array(da, header_type, swap, a, why)) return err(std::string(section) + ": " + why);
      long long comps = 1;
      to_int_strict(da.attr("NumberOfComponents", "1"), comps);
      const std::string name = da.attr("Name");  // normals too stay point data (SOFA's XML reader)
      (std::string(section) == "PointData" ? m.point_data : m.cell_data)
          .push_back({name, static_cast<int>(comps), std::move(a.v)});
    }
  }
  return m;
}

}  // namespace

std::optional<MeshData> read_vtk(const std::string& path, std::string* error, const ReadOptions& opt) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  const auto first_line = text.substr(0, text.find('\n'));
  if (first_line.find("<VTKFile") != std::string::npos ||
      (first_line.rfind("<?xml", 0) == 0 && text.find("<VTKFile") != std::string::npos))
    return read_vtk_xml(path, text, error, opt);
  if (first_line.rfind("# vtk DataFile", 0) == 0) return read_vtk_legacy(path, text, error, opt);
  if (error) *error = path + ":1: not a VTK file (neither '# vtk DataFile' nor <VTKFile>)";
  return std::nullopt;
}

// ------------------------------------------------------------------ STL

std::optional<MeshData> read_stl(const std::string& path, std::string* error, const ReadOptions& opt) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  MeshData m;
  std::map<std::array<double, 3>, unsigned> seen;
  auto index_of = [&](const Vec3& p) {
    const std::array<double, 3> key{p[0], p[1], p[2]};
    auto it = seen.find(key);
    if (it != seen.end()) return it->second;
    const auto i = static_cast<unsigned>(m.positions.size());
    seen.emplace(key, i);
    m.positions.push_back(p);
    return i;
  };
  Cursor first{text};
  const bool ascii = !opt.force_binary && first.next() == "solid";
  if (ascii) {
    const auto lines = split_lines(text);
    Triangle tri{0, 0, 0};
    unsigned counter = 0;
    for (std::size_t ln = 0; ln < lines.size(); ++ln) {
      Cursor c{lines[ln]};
      const std::string_view w = c.next();
      if (w == "facet") {
        c.next();  // "normal"
        Vec3 n = Vec3::Zero();
        for (int k = 0; k < 3; ++k) to_number(c.next(), n[k]);
        m.normals.push_back(n);
      } else if (w == "vertex") {
        Vec3 p;
        for (int k = 0; k < 3; ++k)
          if (!to_number(c.next(), p[k])) {
            if (error) *error = where(path, ln + 1) + "bad vertex '" + std::string(trim(lines[ln])) + "'";
            return std::nullopt;
          }
        if (counter >= 3) {
          if (error) *error = where(path, ln + 1) + "more than 3 vertices in a facet";
          return std::nullopt;
        }
        tri[counter++] = index_of(p);
      } else if (w == "endfacet") {
        if (counter != 3) {
          if (error) *error = where(path, ln + 1) + "facet without 3 vertices";
          return std::nullopt;
        }
        m.triangles.push_back(maybe_flip(tri, opt.flip_normals));
        counter = 0;
      } else if (w == "endsolid" || w == "end") {
        break;
      }
    }
    return m;
  }
  // Binary: header, uint32 facet count, 50 bytes per facet.
  if (text.size() < 84) {
    if (error) *error = path + ": too small for a binary STL file (" + std::to_string(text.size()) + " bytes)";
    return std::nullopt;
  }
  uint32_t count = 0;
  std::memcpy(&count, text.data() + 80, 4);
  const std::size_t expected = static_cast<std::size_t>(count) * 50 + 84;
  if (text.size() != expected) {
    if (error)
      *error = path + ": not a binary STL file: size expected to be " + std::to_string(expected) + " (with " +
               std::to_string(count) + " triangles) but it is " + std::to_string(text.size());
    return std::nullopt;
  }
  std::size_t pos = std::min<std::size_t>(opt.header_size, 256);
  std::memcpy(&count, text.data() + pos, 4);
  pos += 4;
  if (pos + static_cast<std::size_t>(count) * 50 > text.size()) {
    if (error) *error = path + ": truncated binary STL file";
    return std::nullopt;
  }
  m.normals.resize(count);
  auto rd = [&](std::size_t at) {
    float f;
    std::memcpy(&f, text.data() + at, 4);
    return static_cast<double>(f);
  };
  for (uint32_t i = 0; i < count; ++i, pos += 50) {
    m.normals[i] = Vec3(rd(pos), rd(pos + 4), rd(pos + 8));
    Triangle t;
    for (int j = 0; j < 3; ++j) {
      const std::size_t at = pos + 12 + 12 * j;
      t[j] = index_of(Vec3(rd(at), rd(at + 4), rd(at + 8)));
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // degenerate: dropped (as SOFA)
    m.triangles.push_back(maybe_flip(t, opt.flip_normals));
  }
  return m;
}

// ------------------------------------------------------------------ SPH

std::optional<MeshData> read_sph(const std::string& path, std::string* error) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  MeshData m;
  const auto lines = split_lines(text);
  // The first line is the format tag ("sph 1.0"); it is skipped.
  TokenStream ts{std::string_view(text).substr(lines.empty() ? text.size() : std::min(text.size(), lines[0].size() + 1)),
                 0, 2};
  for (;;) {
    const std::string_view cmd = ts.next();
    if (cmd.empty()) break;
    const std::size_t line = ts.line;
    auto skip_line = [&] {
      while (ts.i < ts.s.size() && ts.s[ts.i] != '\n') ++ts.i;
    };
    if (cmd == "nums") {
      long long n = 0;
      if (!to_int_strict(ts.next(), n) || n < 0) {
        if (error) *error = where(path, line) + "bad sphere count after 'nums'";
        return std::nullopt;
      }
      m.positions.reserve(std::min(static_cast<std::size_t>(n), text.size()));
    } else if (cmd == "sphe") {
      long long index = 0;
      double v[4] = {0, 0, 0, 1};
      bool ok = to_int_strict(ts.next(), index);
      for (double& x : v) ok = ok && to_number(ts.next(), x);
      if (!ok) {
        if (error) *error = where(path, line) + "bad 'sphe' line (sphe index x y z radius expected)";
        return std::nullopt;
      }
      m.positions.emplace_back(v[0], v[1], v[2]);
      m.radii.push_back(v[3]);
    } else if (cmd[0] == '#') {
      skip_line();
    } else {
      skip_line();  // unknown keyword: SOFA warns and skips the line
    }
  }
  return m;
}

// ------------------------------------------------------------------ OFF

std::optional<MeshData> read_off(const std::string& path, std::string* error, const ReadOptions& opt) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  Cursor head{text};
  if (head.next() != "OFF") {
    if (error) *error = path + ":1: not an OFF file (the first word must be 'OFF')";
    return std::nullopt;
  }
  // Lines after the keyword (the rest of its line first); empty and '#' lines are skipped.
  const std::size_t first_nl = text.find('\n');
  std::vector<std::pair<std::size_t, std::string_view>> lines;  // (1-based line, text)
  {
    std::size_t ln = 1;
    lines.emplace_back(ln, std::string_view(text).substr(head.i, first_nl == std::string::npos ? std::string::npos
                                                                                                : first_nl - head.i));
    if (first_nl != std::string::npos) {
      const auto rest = split_lines(std::string_view(text).substr(first_nl + 1));
      for (std::string_view l : rest) lines.emplace_back(++ln, l);
    }
  }
  std::size_t k = 0;
  auto next_line = [&]() -> const std::pair<std::size_t, std::string_view>* {
    while (k < lines.size()) {
      const auto& l = lines[k++];
      if (trim(l.second).empty() || l.second[0] == '#') continue;
      return &l;
    }
    return nullptr;
  };
  auto err = [&](std::size_t line, const std::string& what) {
    if (error) *error = where(path, line) + what;
    return std::nullopt;
  };
  long long nv = 0, nf = 0;
  const auto* counts = next_line();
  if (!counts) return err(lines.size(), "missing vertex/face counts");
  {
    Cursor c{counts->second};
    if (!to_int_strict(c.next(), nv) || !to_int_strict(c.next(), nf) || nv < 0 || nf < 0)
      return err(counts->first, "bad counts line '" + std::string(trim(counts->second)) + "'");
  }
  MeshData m;
  for (long long i = 0; i < nv; ++i) {
    const auto* l = next_line();
    if (!l) return err(lines.size(), "unexpected end of file after " + std::to_string(i) + " vertices");
    Cursor c{l->second};
    Vec3 p;
    for (int d = 0; d < 3; ++d)
      if (!to_number(c.next(), p[d])) return err(l->first, "bad vertex '" + std::string(trim(l->second)) + "'");
    m.positions.push_back(p);
  }
  for (long long f = 0; f < nf;) {
    const auto* l = next_line();
    if (!l) return err(lines.size(), "unexpected end of file after " + std::to_string(f) + " faces");
    Cursor c{l->second};
    long long n = 0;
    if (!to_int_strict(c.next(), n)) return err(l->first, "bad face '" + std::string(trim(l->second)) + "'");
    if (n < 3 || n > 4) continue;  // SOFA skips (and does not count) other polygons
    std::array<unsigned, 4> v{};
    for (long long j = 0; j < n; ++j) {
      long long x = 0;
      if (!to_int_strict(c.next(), x) || x < 0 || static_cast<unsigned long long>(x) >= m.positions.size())
        return err(l->first, "bad or out-of-range vertex index in face '" + std::string(trim(l->second)) + "'");
      v[j] = static_cast<unsigned>(x);
    }
    if (n == 3) m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, opt.flip_normals));
    else m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[2], v[3]}, opt.flip_normals));
    ++f;
  }
  return m;
}

std::optional<MeshData> read_mesh(const std::string& path, std::string* error, const ReadOptions& opt) {
  const std::string e = lower_ext(path);
  if (e == "obj") return read_obj(path, error, opt);
  if (e == "msh") return read_gmsh(path, error, opt);
  if (e == "vtk" || e == "vtu" || e == "vtp") return read_vtk(path, error, opt);
  if (e == "stl") return read_stl(path, error, opt);
  if (e == "sph") return read_sph(path, error);
  if (e == "off") return read_off(path, error, opt);
  if (error) *error = path + ": unknown mesh file extension '." + e + "'";
  return std::nullopt;
}

// ------------------------------------------------------------------ post-processing

std::array<double, 16> trs_matrix(const Vec3& t, const Vec3& rot_deg, const Vec3& s) {
  using M4 = std::array<double, 16>;
  auto mul = [](const M4& a, const M4& b) {
    M4 r{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) {
        const double aik = a[i * 4 + k];
        for (int j = 0; j < 4; ++j) r[i * 4 + j] += aik * b[k * 4 + j];
      }
    return r;
  };
  M4 T{1, 0, 0, t[0], 0, 1, 0, t[1], 0, 0, 1, t[2], 0, 0, 0, 1};
  const Vec3 rad(rot_deg[0] * M_PI / 180.0, rot_deg[1] * M_PI / 180.0, rot_deg[2] * M_PI / 180.0);
  const auto R3 = SQuat::from_euler(rad).matrix();
  M4 R{R3[0], R3[1], R3[2], 0, R3[3], R3[4], R3[5], 0, R3[6], R3[7], R3[8], 0, 0, 0, 0, 1};
  M4 S{s[0], 0, 0, 0, 0, s[1], 0, 0, 0, 0, s[2], 0, 0, 0, 0, 1};
  return mul(mul(T, R), S);
}

Vec3 transform_point(const std::array<double, 16>& M, const Vec3& v) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    r[i] = M[i * 4 + 0] * v[0];
    for (int j = 1; j < 3; ++j) r[i] += M[i * 4 + j] * v[j];
    r[i] += M[i * 4 + 3];
  }
  return r;
}

namespace {

template <std::size_t N>
std::array<unsigned, N> sorted(std::array<unsigned, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

template <std::size_t N>
void append_unique(std::vector<std::array<unsigned, N>>& list, std::set<std::array<unsigned, N>>& seen,
                   const std::array<unsigned, N>& e) {
  if (seen.insert(sorted(e)).second) list.push_back(e);
}

template <std::size_t N>
std::set<std::array<unsigned, N>> sorted_set(const std::vector<std::array<unsigned, N>>& list) {
  std::set<std::array<unsigned, N>> s;
  for (const auto& e : list) s.insert(sorted(e));
  return s;
}

bool near_identity(const std::array<double, 16>& M) {
  // SOFA compares matrices row by row with Vec equality (1e-6).
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (!(std::abs(M[i * 4 + j] - (i == j ? 1.0 : 0.0)) < 1e-6)) return false;
  return true;
}

}  // namespace

void finish_mesh(MeshData& m, const FinishOptions& opt) {
  // 1. Transformation (replaces translation/rotation/scale when not the identity).
  std::array<double, 16> M = opt.transformation;
  if (near_identity(M)) M = trs_matrix(opt.translation, opt.rotation, opt.scale);
  if (!near_identity(M)) {
    bool is_transform = std::abs(M[15] - 1.0) <= 1e-6;
    for (int j = 0; j < 3; ++j) is_transform = is_transform && std::abs(M[12 + j]) <= 1e-6;
    if (is_transform)
      for (Vec3& p : m.positions) p = transform_point(M, p);
  }

  // 2. updateElements
  if (opt.triangulate) {
    for (const Quad& q : m.quads) {
      m.triangles.push_back(maybe_flip(Triangle{q[0], q[1], q[2]}, opt.flip_normals));
      m.triangles.push_back(maybe_flip(Triangle{q[0], q[2], q[3]}, opt.flip_normals));
    }
    m.quads.clear();
  }
  if (opt.create_subelements) {
    if (!m.hexahedra.empty()) {
      auto seen = sorted_set(m.quads);
      for (const Hexa& h : std::vector<Hexa>(m.hexahedra)) {
        const Quad f[6] = {{h[0], h[3], h[2], h[1]}, {h[4], h[5], h[6], h[7]}, {h[0], h[1], h[5], h[4]},
                           {h[1], h[2], h[6], h[5]}, {h[2], h[3], h[7], h[6]}, {h[3], h[0], h[4], h[7]}};
        for (const Quad& q : f) append_unique(m.quads, seen, q);
      }
    }
    if (!m.prisms.empty()) {
      auto qs = sorted_set(m.quads);
      auto ts = sorted_set(m.triangles);
      for (const Prism& p : std::vector<Prism>(m.prisms)) {
        append_unique(m.quads, qs, Quad{p[0], p[3], p[4], p[1]});
        append_unique(m.quads, qs, Quad{p[0], p[2], p[5], p[3]});
        append_unique(m.quads, qs, Quad{p[1], p[4], p[5], p[2]});
        append_unique(m.triangles, ts, Triangle{p[0], p[1], p[2]});
        append_unique(m.triangles, ts, Triangle{p[4], p[3], p[5]});
      }
    }
    if (!m.pyramids.empty()) {
      auto qs = sorted_set(m.quads);
      auto ts = sorted_set(m.triangles);
      for (const Pyramid& p : std::vector<Pyramid>(m.pyramids)) {
        append_unique(m.quads, qs, Quad{p[0], p[3], p[2], p[1]});
        append_unique(m.triangles, ts, Triangle{p[0], p[1], p[4]});
        append_unique(m.triangles, ts, Triangle{p[1], p[2], p[4]});
        append_unique(m.triangles, ts, Triangle{p[3], p[4], p[2]});
        append_unique(m.triangles, ts, Triangle{p[0], p[4], p[3]});
      }
    }
    if (!m.tetrahedra.empty()) {
      auto ts = sorted_set(m.triangles);
      for (const Tetra& t : m.tetrahedra) {
        append_unique(m.triangles, ts, Triangle{t[0], t[2], t[1]});
        append_unique(m.triangles, ts, Triangle{t[0], t[1], t[3]});
        append_unique(m.triangles, ts, Triangle{t[0], t[3], t[2]});
        append_unique(m.triangles, ts, Triangle{t[1], t[2], t[3]});
      }
    }
    if (!m.quads.empty()) {
      auto es = sorted_set(m.edges);
      for (const Quad& q : m.quads)
        for (int j = 0; j < 4; ++j) append_unique(m.edges, es, Edge{q[(j + 1) % 4], q[(j + 2) % 4]});
    }
    if (!m.triangles.empty()) {
      auto es = sorted_set(m.edges);
      for (const Triangle& t : m.triangles)
        for (int j = 0; j < 3; ++j) append_unique(m.edges, es, Edge{t[(j + 1) % 3], t[(j + 2) % 3]});
    }
  }

  // 3. updatePoints
  if (opt.only_attached_points) {
    std::set<unsigned> attached;
    auto collect = [&](const auto& list) {
      for (const auto& e : list)
        for (unsigned v : e) attached.insert(v);
    };
    collect(m.edges);
    collect(m.triangles);
    collect(m.quads);
    collect(m.tetrahedra);
    collect(m.prisms);
    collect(m.pyramids);
    collect(m.hexahedra);
    if (attached.size() != m.positions.size()) {
      std::vector<unsigned> old2new(m.positions.size(), 0);
      unsigned p = 0;
      for (unsigned v : attached) {
        if (v >= m.positions.size()) continue;
        old2new[v] = p;
        if (p != v) m.positions[p] = m.positions[v];
        ++p;
      }
      m.positions.resize(p);
      auto renumber = [&](auto& list) {
        for (auto& e : list)
          for (unsigned& v : e) v = v < old2new.size() ? old2new[v] : v;
      };
      renumber(m.edges);
      renumber(m.triangles);
      renumber(m.quads);
      renumber(m.tetrahedra);
      renumber(m.prisms);
      renumber(m.pyramids);
      renumber(m.hexahedra);
    }
  }

  // 4. updateNormals
  if (opt.compute_normals && m.normals.size() != m.positions.size()) {
    const std::size_t n = m.positions.size();
    m.normals.resize(n, Vec3::Zero());
    auto normalize = [](Vec3& v) {
      const double nn = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (nn > std::numeric_limits<double>::epsilon()) v /= nn;
    };
    for (const Triangle& t : m.triangles) {
      if (t[0] >= n || t[1] >= n || t[2] >= n) continue;
      const Vec3 &v1 = m.positions[t[0]], &v2 = m.positions[t[1]], &v3 = m.positions[t[2]];
      Vec3 nn = cross3((v2 - v1), v3 - v1);
      normalize(nn);
      m.normals[t[0]] += nn;
      m.normals[t[1]] += nn;
      m.normals[t[2]] += nn;
    }
    for (const Quad& q : m.quads) {
      if (q[0] >= n || q[1] >= n || q[2] >= n || q[3] >= n) continue;
      const Vec3 &v1 = m.positions[q[0]], &v2 = m.positions[q[1]], &v3 = m.positions[q[2]], &v4 = m.positions[q[3]];
      Vec3 n1 = cross3((v2 - v1), v4 - v1), n2 = cross3((v3 - v2), v1 - v2), n3 = cross3((v4 - v3), v2 - v3),
           n4 = cross3((v1 - v4), v3 - v4);
      normalize(n1);
      normalize(n2);
      normalize(n3);
      normalize(n4);
      m.normals[q[0]] += n1;
      m.normals[q[1]] += n2;
      m.normals[q[2]] += n3;
      m.normals[q[3]] += n4;
    }
    for (Vec3& v : m.normals) normalize(v);
  }
}

}  // namespace sinew::io
