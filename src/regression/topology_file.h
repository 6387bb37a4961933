// Topology reference files (regression-protocol.md §3.5): one block per step,
//   T= <time>
//     Edges= <n>
//   <2n indices>
//     Triangles= <n>      (3 per element)
//     Quads= <n>          (4)
//     Tetrahedra= <n>     (4)
//     Hexahedra= <n>      (8)
// Header lines have two leading spaces, index lines none.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::regression {

// The element types of a topology block, in file order.
enum class ElementType : int { edges = 0, triangles, quads, tetrahedra, hexahedra };
inline constexpr std::size_t kElementTypeCount = 5;
inline constexpr std::array<std::size_t, kElementTypeCount> kVerticesPerElement{2, 3, 4, 4, 8};
inline constexpr std::array<std::string_view, kElementTypeCount> kElementHeaders{
    "Edges=", "Triangles=", "Quads=", "Tetrahedra=", "Hexahedra="};

// One reference block.
struct TopologyBlock {
  double time = 0.0;
  // Count n from each header line (0 when the header is absent).
  std::array<long long, kElementTypeCount> counts{};
  // Indices of the line following each header, read like `>>` into integers
  // up to the first token that is not an integer. Normally counts*k values.
  std::array<std::vector<long long>, kElementTypeCount> indices;
};

// A live topology: for each type, all elements' vertex indices concatenated
// (element i occupies [i*k, i*k + k)). Precondition: each span's size is a
// multiple of the type's kVerticesPerElement.
struct TopologyView {
  std::array<std::span<const std::uint32_t>, kElementTypeCount> indices;
  std::size_t count(std::size_t type) const {
    return indices[type].size() / kVerticesPerElement[type];
  }
};

// Parses topology-file text. "T=" starts a block (time read with `>>` rules,
// unreadable → 0); a line whose first word is a header sets that type's count
// and takes the next line of the same block as its index line; other lines
// are ignored, as are lines before the first "T=".
std::vector<TopologyBlock> parse_topology_text(std::string_view text);

// Reads (plain or gzip, truncation accepted, see read_text_file) and parses.
// Returns nullopt and sets *error (if non-null) if the file cannot be read.
std::optional<std::vector<TopologyBlock>> read_topology_file(const std::string& path,
                                                             std::string* error = nullptr);

// Appends one block in the writer's exact format (time via format_g6, indices
// as plain decimals separated by single spaces; an empty index line for a
// zero count).
void append_topology_block(std::string& out, double time, const TopologyView& topology);

// Same as append_topology_block, returning the block text.
std::string format_topology_block(double time, const TopologyView& topology);

}  // namespace sinew::regression
