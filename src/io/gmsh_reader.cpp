// Gmsh ASCII meshes: v1 ($NOD/$ELM), v2 and v4 ($MeshFormat), as SOFA's MeshGmshLoader reads them.
#include "io/mesh_readers.h"

#include <algorithm>
#include <charconv>
#include <set>
#include <unordered_map>

#include "io/reader_text.h"

namespace sinew::io {

using namespace internal;

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

// The leading integer of a token ("2.2" → 2), as a stream read of an integer stops at the '.'.
bool to_int_prefix(std::string_view t, long long& v) {
  if (t.empty()) return false;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (*b == '+') ++b;
  auto r = std::from_chars(b, e, v);
  return r.ec == std::errc();
}

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
    if (!to_number(ts.next(), npoints) || npoints < 0) return err("bad node count");
    std::unordered_map<long long, int> pmap;  // node id → ordinal (ids may have holes)
    m.positions.reserve(std::min(static_cast<std::size_t>(npoints), text.size()));
    for (long long i = 0; i < npoints; ++i) {
      long long index = 0;
      Vec3 p;
      if (!to_number(ts.next(), index)) return err("bad node line");
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
    if (!to_number(ts.next(), nelems) || nelems < 0) return err("bad element count");
    std::set<Edge> edge_set_dummy;
    for (long long e = 0; e < nelems; ++e) {
      long long index = 0, type = 0, nnodes = 0, tag = -1;
      if (!to_number(ts.next(), index) || !to_number(ts.next(), type)) return err("bad element line");
      if (version == 1) {
        long long phys = 0, elem = 0;
        if (!to_number(ts.next(), phys) || !to_number(ts.next(), elem) || !to_number(ts.next(), nnodes) || nnodes < 0 ||
            nnodes > 64)
          return err("bad element line");
      } else {
        long long ntags = 0;
        if (!to_number(ts.next(), ntags) || ntags < 0 || ntags > 64) return err("bad element line");
        for (long long t = 0; t < ntags; ++t)
          if (!to_number(ts.next(), tag)) return err("bad element tag");
        nnodes = gmsh_node_count(static_cast<int>(type));
        if (nnodes < 0) return err("unsupported element type " + std::to_string(type));
      }
      std::vector<unsigned> nodes(static_cast<std::size_t>(nnodes));
      for (auto& n : nodes) {
        long long t = 0;
        if (!to_number(ts.next(), t)) return err("bad element node");
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
      if (!to_number(c.next(), b) || !to_number(c.next(), n) || b < 0 || n < 0) return err(l, "bad $Nodes header");
      blocks = static_cast<unsigned long long>(b);
      nb_nodes = static_cast<unsigned long long>(n);
    }
    ++l;
    m.positions.reserve(std::min<std::size_t>(nb_nodes, text.size()));
    for (unsigned long long b = 0; b < blocks; ++b) {
      Cursor c{line_at(l)};
      long long dim = 0, etag = 0, param = 0, n = 0;
      if (!to_number(c.next(), dim) || !to_number(c.next(), etag) || !to_number(c.next(), param) || !to_number(c.next(), n) ||
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
      if (!to_number(c.next(), b) || b < 0) return err(l, "bad $Elements header");
      blocks = static_cast<unsigned long long>(b);
    }
    ++l;
    std::set<Edge> edge_set;  // v4: deduplication over the whole file
    for (unsigned long long b = 0; b < blocks; ++b) {
      Cursor c{line_at(l)};
      long long dim = 0, etag = 0, type = 0, n = 0;
      if (!to_number(c.next(), dim) || !to_number(c.next(), etag) || !to_number(c.next(), type) || !to_number(c.next(), n) ||
          n < 0)
        return err(l, "bad element entity block header");
      const int nnodes = gmsh_node_count(static_cast<int>(type));
      if (nnodes < 0) return err(l, "unsupported element type " + std::to_string(type));
      ++l;
      for (long long e = 0; e < n; ++e, ++l) {
        if (l >= lines.size()) return err(l, "truncated element block");
        Cursor cc{lines[l]};
        long long tag = 0;
        if (!to_number(cc.next(), tag)) return err(l, "bad element line");
        std::vector<unsigned> nodes(static_cast<std::size_t>(nnodes));
        for (auto& nd : nodes) {
          long long id = 0;
          if (!to_number(cc.next(), id) || id < 1 || static_cast<unsigned long long>(id) > m.positions.size())
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

}  // namespace sinew::io
