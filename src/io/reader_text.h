// Text helpers shared by the mesh readers (internal to src/io, not part of the API):
// reading a whole file, "file:line: " prefixes, whitespace tokens, and numbers read with
// the rules of SOFA's stream reads.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

namespace sinew::io::internal {

// Whole file into `out`; false with "cannot open file '...'" (or "... is a directory") in *error.
bool read_file(const std::string& path, std::string& out, std::string* error);

// Writes `text` to *error (when non-null) and returns false, for `return fail(error, ...)`.
bool fail(std::string* error, const std::string& text);

// "path:line: ", the prefix of every parse error.
std::string where(const std::string& path, std::size_t line);

// The lines of a text, without their '\n' (a trailing '\r' is kept: callers trim or tokenise).
std::vector<std::string_view> split_lines(std::string_view text);

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// Walks the whitespace-separated tokens of one line (or of any text); an empty token means the end.
struct Cursor {
  std::string_view s;
  std::size_t i = 0;
  std::string_view next() {
    while (i < s.size() && is_space(s[i])) ++i;
    const std::size_t b = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    return s.substr(b, i - b);
  }
  bool at_end() {
    while (i < s.size() && is_space(s[i])) ++i;
    return i >= s.size();
  }
};

// Tokens of a whole text, counting lines so that errors can name the line of the last token.
struct TokenStream {
  std::string_view s;
  std::size_t i = 0, line = 1;
  std::string_view next() {
    while (i < s.size() && is_space(s[i])) {
      if (s[i] == '\n') ++line;
      ++i;
    }
    const std::size_t b = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    return s.substr(b, i - b);
  }
};

// A whole token as a number (double, float or an integer type), with an optional leading '+'.
// "1e+", "0,5", "0.x" or "2.5" for an integer are errors: each makes SOFA's stream read (or its
// safeStrToInt) fail, so accepting their valid prefix would build a mesh SOFA does not have.
// So are "nan", "inf" and values beyond the type's range, which std::from_chars would accept
// or saturate (and SOFA's stream read refuses): a mesh never brings a non-finite number.
template <class T>
bool to_number(std::string_view t, T& v) {
  if (t.empty()) return false;
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (*b == '+') ++b;
  T x{};
  const auto r = std::from_chars(b, e, x);
  if (r.ec != std::errc() || r.ptr != e) return false;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(x)) return false;
  v = x;
  return true;
}

// Whether every coordinate of `points` is finite; otherwise the index of the first one
// that is not in *bad. Binary formats (STL, VTK BINARY, VTU base64) carry raw floats.
template <class V>
bool all_finite(const std::vector<V>& points, std::size_t* bad) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) {
      *bad = i;
      return false;
    }
  return true;
}

// Reverses an element's vertex order when the loader flips normals.
template <std::size_t N>
std::array<unsigned, N> maybe_flip(std::array<unsigned, N> a, bool flip) {
  if (flip) std::reverse(a.begin(), a.end());
  return a;
}

}  // namespace sinew::io::internal
