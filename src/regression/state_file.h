// State reference files (regression-protocol.md §3.4): blocks of
//   T= <time>
//     X= <scalars...>
//     V= <scalars...>
// written by the state writer and read by the state comparer.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::regression {

// One vector line of a block.
struct StateLine {
  char tag = 'X';              // 'X' (positions) or 'V' (velocities)
  std::vector<double> values;  // scalars up to the first token that is not a number
};

struct StateBlock {
  double time = 0.0;
  std::vector<StateLine> lines;  // in file order; X and/or V, possibly repeated
};

// Parses state-file text with the comparer's rules. A line belongs to the
// current block; its first word decides its role: "T=" starts a block (time
// read with `>>` rules: unreadable → 0, overflow → ±DBL_MAX, like C++),
// "X="/"V=" give a vector line, anything else ("X0=", "F=", empty lines,
// "X=1" without a space) is ignored. Vector scalars are read like
// `std::istream >> double` and stop at the first token that does not read
// as a plain decimal number (e.g. "nan", "inf"), so only that prefix is kept.
// Lines before the first "T=" are ignored.
std::vector<StateBlock> parse_state_text(std::string_view text);

// Reads (plain or gzip, see read_text_file) and parses a state file.
// Returns nullopt and sets *error (if non-null) if the file cannot be read.
std::optional<std::vector<StateBlock>> read_state_file(const std::string& path,
                                                       std::string* error = nullptr);

// Appends one block in the writer's exact format:
//   "T= <t>\n  X= <x0> <x1> ...\n  V= <v0> ...\n"
// with every number formatted by format_g6 and single spaces. A vector line is
// omitted when its pointer is null; an empty vector (non-null, size 0) gives
// "  X= \n" as SOFA's writer does (tag, one space, no scalars).
// Preconditions: x (resp. v) points to nx (resp. nv) scalars, all points
// concatenated (Vec3: x y z; Rigid3 positions: x y z qx qy qz qw).
void append_state_block(std::string& out, double time, const double* x, std::size_t nx,
                        const double* v, std::size_t nv);

// Same as append_state_block, returning the block text.
std::string format_state_block(double time, const double* x, std::size_t nx, const double* v,
                               std::size_t nv);

}  // namespace sinew::regression
