// STL, ASCII or binary: triangles on merged vertices, as SOFA's MeshSTLLoader.
#include "io/mesh_readers.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>

#include "io/reader_text.h"

namespace sinew::io {

using namespace internal;

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
  // Raw floats may be NaN or infinite: refused here rather than met as a diverged state.
  std::size_t bad = 0;
  if (!all_finite(m.positions, &bad)) {
    if (error) *error = path + ": vertex " + std::to_string(bad) + " has a non-finite coordinate";
    return std::nullopt;
  }
  if (!all_finite(m.normals, &bad)) {
    if (error) *error = path + ": facet " + std::to_string(bad) + " has a non-finite normal";
    return std::nullopt;
  }
  return m;
}

}  // namespace sinew::io
