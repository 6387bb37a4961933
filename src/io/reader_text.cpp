#include "io/reader_text.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sinew::io::internal {

bool read_file(const std::string& path, std::string& out, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return fail(error, "'" + path + "' is a directory, not a mesh file");
  std::ifstream f(path, std::ios::binary);
  if (!f) return fail(error, "cannot open file '" + path + "'");
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

}  // namespace sinew::io::internal
