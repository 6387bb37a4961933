#include "regression/state_file.h"

#include "regression/gzip_text.h"
#include "regression/number_format.h"
#include "regression/stream_reader.h"

namespace sinew::regression {

std::vector<StateBlock> parse_state_text(std::string_view text) {
  std::vector<StateBlock> blocks;
  for (std::string_view line : split_lines(text)) {
    StreamReader reader(line);
    std::string_view word;
    if (!reader.read_word(word)) continue;
    if (word == "T=") {
      StateBlock block;
      reader.read(block.time);  // on failure the value is set the C++ way
      blocks.push_back(std::move(block));
      continue;
    }
    if (blocks.empty() || (word != "X=" && word != "V=")) continue;
    StateLine vec;
    vec.tag = word[0];
    for (double value; reader.read(value);) vec.values.push_back(value);
    blocks.back().lines.push_back(std::move(vec));
  }
  return blocks;
}

std::optional<std::vector<StateBlock>> read_state_file(const std::string& path,
                                                       std::string* error) {
  auto text = read_text_file(path, error);
  if (!text) return std::nullopt;
  return parse_state_text(*text);
}

namespace {

void append_vector(std::string& out, const char* tag, const double* values, std::size_t n) {
  out += tag;
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ' ';
    append_g6(out, values[i]);
  }
  out += '\n';
}

}  // namespace

void append_state_block(std::string& out, double time, const double* x, std::size_t nx,
                        const double* v, std::size_t nv) {
  out += "T= ";
  append_g6(out, time);
  out += '\n';
  if (x) append_vector(out, "  X= ", x, nx);
  if (v) append_vector(out, "  V= ", v, nv);
}

std::string format_state_block(double time, const double* x, std::size_t nx, const double* v,
                               std::size_t nv) {
  std::string out;
  out.reserve(16 + (nx + nv) * 10);
  append_state_block(out, time, x, nx, v, nv);
  return out;
}

}  // namespace sinew::regression
