// Object File Format (.off): counts, vertices, then "n i0 … in-1" faces, as SOFA's MeshOffLoader.
#include "io/mesh_readers.h"

#include "io/reader_text.h"

namespace sinew::io {

using namespace internal;

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
    if (!to_number(c.next(), nv) || !to_number(c.next(), nf) || nv < 0 || nf < 0)
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
    if (!to_number(c.next(), n)) return err(l->first, "bad face '" + std::string(trim(l->second)) + "'");
    if (n < 3 || n > 4) continue;  // SOFA skips (and does not count) other polygons
    std::array<unsigned, 4> v{};
    for (long long j = 0; j < n; ++j) {
      long long x = 0;
      if (!to_number(c.next(), x) || x < 0 || static_cast<unsigned long long>(x) >= m.positions.size())
        return err(l->first, "bad or out-of-range vertex index in face '" + std::string(trim(l->second)) + "'");
      v[j] = static_cast<unsigned>(x);
    }
    if (n == 3) m.triangles.push_back(maybe_flip(Triangle{v[0], v[1], v[2]}, opt.flip_normals));
    else m.quads.push_back(maybe_flip(Quad{v[0], v[1], v[2], v[3]}, opt.flip_normals));
    ++f;
  }
  return m;
}

}  // namespace sinew::io
