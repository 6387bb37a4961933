#include "regression/topology_file.h"

#include <charconv>

#include "regression/gzip_text.h"
#include "regression/number_format.h"
#include "regression/stream_reader.h"

namespace sinew::regression {
namespace {

// Index of the header named `word`, or -1.
int header_index(std::string_view word) {
  for (std::size_t i = 0; i < kElementTypeCount; ++i) {
    if (word == kElementHeaders[i]) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace

std::vector<TopologyBlock> parse_topology_text(std::string_view text) {
  std::vector<TopologyBlock> blocks;
  const std::vector<std::string_view> lines = split_lines(text);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    StreamReader reader(lines[l]);
    std::string_view word;
    if (!reader.read_word(word)) continue;
    if (word == "T=") {
      TopologyBlock block;
      reader.read(block.time);  // on failure the value is set the C++ way
      blocks.push_back(std::move(block));
      continue;
    }
    const int type = header_index(word);
    if (blocks.empty() || type < 0) continue;
    TopologyBlock& block = blocks.back();
    long long count = 0;
    reader.read(count);
    block.counts[type] = count;
    std::vector<long long>& indices = block.indices[type];
    indices.clear();
    // The index line is the next line, unless that line starts the next block.
    if (l + 1 < lines.size()) {
      StreamReader next(lines[l + 1]);
      std::string_view first;
      if (next.read_word(first) && first == "T=") continue;
      ++l;
      StreamReader values(lines[l]);
      for (long long v; values.read(v);) indices.push_back(v);
    }
  }
  return blocks;
}

std::optional<std::vector<TopologyBlock>> read_topology_file(const std::string& path,
                                                             std::string* error) {
  auto text = read_text_file(path, error);
  if (!text) return std::nullopt;
  return parse_topology_text(*text);
}

void append_topology_block(std::string& out, double time, const TopologyView& topology) {
  out += "T= ";
  append_g6(out, time);
  out += '\n';
  char buffer[24];
  for (std::size_t type = 0; type < kElementTypeCount; ++type) {
    out += "  ";
    out += kElementHeaders[type];
    out += ' ';
    out += std::to_string(topology.count(type));
    out += '\n';
    const auto& indices = topology.indices[type];
    const std::size_t n = topology.count(type) * kVerticesPerElement[type];
    for (std::size_t i = 0; i < n; ++i) {
      if (i) out += ' ';
      out.append(buffer, std::to_chars(buffer, buffer + sizeof(buffer), indices[i]).ptr);
    }
    out += '\n';
  }
}

std::string format_topology_block(double time, const TopologyView& topology) {
  std::string out;
  append_topology_block(out, time, topology);
  return out;
}

}  // namespace sinew::regression
