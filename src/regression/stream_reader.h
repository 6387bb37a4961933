// Reads words and numbers out of text with the rules of C++ formatted stream
// input (`std::istream >> x` in the classic "C" locale).
//
// Why not strtod or from_chars directly: SOFA's comparer reads reference files
// with `>>`, and those rules decide where a vector ends. `>>` accepts only a
// plain decimal number ("nan", "inf" and hex floats fail), it stops at the first
// character that cannot continue a number ("1.5abc" yields 1.5 and leaves
// "abc"), an overflowing value fails while an underflowing one is accepted, and
// a failure is sticky. Reproducing these rules makes our reading of a reference
// line stop exactly where SOFA's does.
#pragma once

#include <string_view>
#include <vector>

namespace sinew::regression {

// A cursor over `text` that behaves like an std::istringstream on it.
// Precondition: `text` outlives the reader (only a view is kept).
class StreamReader {
 public:
  explicit StreamReader(std::string_view text) : text_(text) {}

  // `in >> double`. On failure returns false and sets `value` like C++11 does:
  // 0 when no number could be read, +/-DBL_MAX on overflow.
  bool read(double& value);
  // `in >> long long` (base 10). On failure: 0, or LLONG_MAX/LLONG_MIN on overflow.
  bool read(long long& value);
  // `in >> std::string`: skips whitespace, returns the next run of non-space
  // characters. Leaves `word` unchanged on failure (nothing left).
  bool read_word(std::string_view& word);

  // True once any read has failed; every later read fails too (like failbit).
  bool failed() const { return failed_; }
  // Unread text (starts right after the last extracted character).
  std::string_view rest() const { return text_.substr(pos_); }

 private:
  // Skips whitespace; false (and failbit) if nothing is left.
  bool skip_space();

  std::string_view text_;
  std::size_t pos_ = 0;
  bool failed_ = false;
};

// True for the characters the classic locale calls whitespace: " \t\n\v\f\r".
bool is_stream_space(char c);

// Splits text into lines the way repeated std::getline does: on '\n' only
// (a '\r' stays in the line); a final line without '\n' is still a line, and
// a trailing '\n' does not produce an extra empty line.
std::vector<std::string_view> split_lines(std::string_view text);

// strtod in the "C" locale on a NUL-terminated string, independent of the
// process locale. Sets *end like strtod does.
double strtod_c(const char* text, char** end);

}  // namespace sinew::regression
