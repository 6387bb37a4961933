// Sphere files (.sph): "sphe index x y z radius" lines, as SOFA's SphereLoader.
#include "io/mesh_readers.h"

#include <algorithm>

#include "io/reader_text.h"

namespace sinew::io {

using namespace internal;

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
      if (!to_number(ts.next(), n) || n < 0) {
        if (error) *error = where(path, line) + "bad sphere count after 'nums'";
        return std::nullopt;
      }
      m.positions.reserve(std::min(static_cast<std::size_t>(n), text.size()));
    } else if (cmd == "sphe") {
      long long index = 0;
      double v[4] = {0, 0, 0, 1};
      bool ok = to_number(ts.next(), index);
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

}  // namespace sinew::io
