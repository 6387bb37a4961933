#include "io/text_file.h"

#include <zlib.h>

namespace sinew::io {

std::optional<std::string> read_text_maybe_gzip(const std::string& path, std::string* error) {
  // gzread passes files that are not gzip through unchanged.
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) {
    if (error) *error = "cannot open file '" + path + "'";
    return std::nullopt;
  }
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const int n = gzread(f, buf, sizeof buf);
    if (n < 0) {
      int code = 0;
      const char* msg = gzerror(f, &code);
      if (error) *error = "cannot read '" + path + "': " + (msg ? msg : "corrupt data");
      gzclose(f);
      return std::nullopt;
    }
    if (n == 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  gzclose(f);
  return out;
}

}  // namespace sinew::io
