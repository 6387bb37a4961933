// Text → value parsing with SOFA's rules (spec/framework.md §2.2, trap T13).
//
// Every reader parses *into the existing value* and returns false on failure,
// leaving whatever a partial read produced, because SOFA scenes rely on that:
// a bad number becomes 0, a bad bool keeps its old value, a vector keeps the
// elements read before a bad token and silently drops an incomplete trailing
// element. Numbers use the "C" locale.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "math/types.h"

namespace sinew::parse {

// One whitespace-separated token → double, like `std::istream >> double`:
// a valid prefix is accepted ("1.5abc" → 1.5); no digits → value 0, false.
bool read_double(std::string_view token, double& out);
bool read_int(std::string_view token, long long& out);
// The first token of `text` that is a number followed by other characters
// ("1e3x", "0,5"): read_double accepts its prefix, the caller may warn. Empty if none.
// With `joined_ok` (lists of reals), a token made only of numbers written
// without spaces ("0-0.7") is not reported: lists read every one of them.
std::string_view first_partial_number(std::string_view text, bool joined_ok = false);

// How many values a list of reals holds once numbers written without
// spaces are split ("1 0-0.7" → 3); a token that is not a number counts one.
std::size_t count_list_numbers(std::string_view text);

// Splits on ASCII whitespace.
std::vector<std::string_view> tokens(std::string_view text);

bool read(std::string_view text, double& v);
bool read(std::string_view text, float& v);
bool read(std::string_view text, int& v);
bool read(std::string_view text, unsigned& v);
bool read(std::string_view text, bool& v);
bool read(std::string_view text, std::string& v);
bool read(std::string_view text, std::vector<double>& v);
bool read(std::string_view text, std::vector<int>& v);
// Index lists accept ranges "A-B" and "A-B-s"; negative values become 0 (failure).
bool read(std::string_view text, std::vector<unsigned>& v);
bool read(std::string_view text, std::vector<std::string>& v);

template <int N>
bool read(std::string_view text, VecN<N>& v);
template <int N>
bool read(std::string_view text, VecNi<N>& v);
template <int N>
bool read(std::string_view text, std::vector<VecN<N>>& v);
template <std::size_t N>
bool read(std::string_view text, std::vector<std::array<unsigned, N>>& v);

// A Rigid3d mass as SOFA's RigidMass<3> stream reader takes it: mass, volume,
// then the 3×3 inertia matrix by rows, optionally wrapped in one "[" "]" pair
// with rows separated by spaces or commas ("1 1 [1 0 0,0 1 0,0 0 1]"). Up to
// 11 values go into `v`; the text may stop early (then fewer values), and
// whatever follows the matrix is ignored. False when something other than a
// number stands where a number is expected (`v` keeps the values read before).
bool read_rigid3_mass(std::string_view text, std::vector<double>& v);

// A 3×3 matrix as SOFA's Mat stream reader takes it: rows of three numbers,
// optionally wrapped in "[" "]" with rows separated by commas
// ("[0.7 -0.7 0,0.7 0.7 0,0 0 1]" or "1 0 0 0 1 0 0 0 1"). Entries not read keep their value.
bool read(std::string_view text, Mat3& m);
std::string to_text(const Mat3& m);  // "[a b c,d e f,g h i]", as SOFA writes it

// Reads a flat list of doubles in groups of `width`; the trailing incomplete
// group is dropped. Used for state vectors whose element width is dynamic.
bool read_flat(std::string_view text, int width, std::vector<double>& v);

// Value → text, as SOFA writes values back (default stream precision: 6 significant digits).
std::string format_double(double v);
std::string to_text(double v);
std::string to_text(float v);
std::string to_text(int v);
std::string to_text(unsigned v);
std::string to_text(bool v);
std::string to_text(const std::string& v);
std::string to_text(const std::vector<double>& v);
std::string to_text(const std::vector<int>& v);
std::string to_text(const std::vector<unsigned>& v);
std::string to_text(const std::vector<std::string>& v);
template <int N>
std::string to_text(const VecN<N>& v);
template <int N>
std::string to_text(const VecNi<N>& v);
template <int N>
std::string to_text(const std::vector<VecN<N>>& v);
template <std::size_t N>
std::string to_text(const std::vector<std::array<unsigned, N>>& v);
std::string flat_to_text(const std::vector<double>& v);

}  // namespace sinew::parse
