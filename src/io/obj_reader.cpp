// Wavefront OBJ: what SOFA's MeshOBJLoader::readOBJ puts in its Data (spec/mechanics.md §7.2),
// faces as written plus, per vertex (or per seam-split vertex), texcoords and normals.
#include "io/mesh_readers.h"

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "io/reader_text.h"

namespace sinew::io {

using namespace internal;

namespace {

std::string dir_of(const std::string& path) {
  const auto s = path.find_last_of("/\\");
  return s == std::string::npos ? std::string() : path.substr(0, s + 1);
}

// The materials of a .mtl file (SOFA's MeshOBJLoader::readMTL): for each `newmtl`, its name
// and its text in sofa::type::Material's format ("name Diffuse u r g b a Ambient u ... Shininess
// u s"), from SOFA's defaults (diffuse 0.75, ambient 0.2, specular 1, shininess 45, only ambient
// and diffuse used). Kd/Ka/Ks set a colour and its use flag, Ns the shininess as written, a
// keyword starting with d or T the diffuse alpha; the rest (Ni, illum, Ke, maps) is skipped.
void read_mtl(const std::string& path, std::vector<std::string>& names, std::vector<std::string>& texts) {
  std::string text;
  if (!read_file(path, text, nullptr)) return;
  struct Mtl {
    std::string name;
    float diffuse[4] = {0.75f, 0.75f, 0.75f, 1}, ambient[4] = {0.2f, 0.2f, 0.2f, 1}, specular[4] = {1, 1, 1, 1},
          emissive[4] = {0, 0, 0, 0}, shininess = 45;
    bool use_diffuse = true, use_ambient = true, use_specular = false, use_emissive = false, use_shininess = false;
  };
  auto flush = [&](const Mtl& m) {
    std::ostringstream o;
    auto colour = [&](const char* key, bool use, const float* c) {
      o << key << ' ' << use << ' ' << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << c[3] << ' ';
    };
    o << m.name << ' ';
    colour("Diffuse", m.use_diffuse, m.diffuse);
    colour("Ambient", m.use_ambient, m.ambient);
    colour("Specular", m.use_specular, m.specular);
    colour("Emissive", m.use_emissive, m.emissive);
    o << "Shininess " << m.use_shininess << ' ' << m.shininess;
    names.push_back(m.name);
    texts.push_back(o.str());
  };
  std::optional<Mtl> cur;
  auto number = [](Cursor& c, float& out) {
    double d = 0;
    if (to_number(c.next(), d)) out = static_cast<float>(d);
  };
  for (std::string_view line : split_lines(text)) {
    Cursor c{line};
    const std::string_view key = c.next();
    if (key.empty() || key[0] == '#') continue;
    if (key == "newmtl") {
      if (cur) flush(*cur);
      cur.emplace();
      cur->name = std::string(c.next());
    } else if (!cur) {
      continue;
    } else if (key == "Ns") {
      number(c, cur->shininess);
      cur->use_shininess = true;
    } else if (key == "Kd" || key == "Ks" || key == "Ka") {
      float* rgb = key == "Kd" ? cur->diffuse : key == "Ks" ? cur->specular : cur->ambient;
      for (int i = 0; i < 3; ++i) number(c, rgb[i]);
      (key == "Kd" ? cur->use_diffuse : key == "Ks" ? cur->use_specular : cur->use_ambient) = true;
    } else if (key[0] == 'd' || key[0] == 'T') {
      number(c, cur->diffuse[3]);
    }
  }
  if (cur) flush(*cur);
}

}  // namespace

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
        read_mtl(dir_of(path) + std::string(lib), m.materials, m.material_texts);
    } else if (tok == "usemtl" || tok == "g") {
      close_groups();
      if (tok == "usemtl") {
        material_name = std::string(c.next());
        material_id = -1;
        for (std::size_t i = 0; i < m.materials.size(); ++i)
          if (m.materials[i] == material_name) {
            material_id = static_cast<int>(i);
            // SOFA's defaultMaterial: the first material a usemtl names.
            if (m.default_material.empty()) m.default_material = m.material_texts[i];
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
          if (!to_number(part, v) || v == 0) {
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

}  // namespace sinew::io
