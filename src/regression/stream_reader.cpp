#include "regression/stream_reader.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <locale.h>
#include <string>

namespace sinew::regression {

bool is_stream_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

double strtod_c(const char* text, char** end) {
  // One "C" locale for the whole process: the global locale may have been
  // changed by the application (e.g. a GUI toolkit) and must not change how
  // reference files are read.
  static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(0));
  return strtod_l(text, end, c_locale);
}

bool StreamReader::skip_space() {
  if (failed_) return false;
  while (pos_ < text_.size() && is_stream_space(text_[pos_])) ++pos_;
  if (pos_ == text_.size()) {
    failed_ = true;
    return false;
  }
  return true;
}

bool StreamReader::read(double& value) {
  if (!skip_space()) {
    value = 0.0;
    return false;
  }
  // Collect the characters libstdc++'s num_get accepts for a floating value:
  // [sign] digits and at most one '.', then at most one exponent marker
  // (only after a mantissa digit) with an optional sign, then digits.
  std::string token;
  std::size_t i = pos_;
  const std::size_t n = text_.size();
  if (i < n && (text_[i] == '+' || text_[i] == '-')) token += text_[i++];
  bool found_mantissa = false, found_dec = false, found_sci = false;
  while (i < n) {
    const char c = text_[i];
    if (c == '.' && !found_dec && !found_sci) {
      token += '.';
      found_dec = true;
    } else if (c >= '0' && c <= '9') {
      token += c;
      found_mantissa = true;
    } else if ((c == 'e' || c == 'E') && !found_sci && found_mantissa) {
      token += 'e';
      found_sci = true;
      ++i;
      if (i < n && (text_[i] == '+' || text_[i] == '-')) {
        token += text_[i];
      } else {
        continue;  // re-examine this character as a possible exponent digit
      }
    } else {
      break;
    }
    ++i;
  }
  pos_ = i;  // the stream consumed these characters whatever the outcome
  char* end = nullptr;
  const double v = token.empty() ? 0.0 : strtod_c(token.c_str(), &end);
  if (token.empty() || end != token.c_str() + token.size()) {
    value = 0.0;  // e.g. "", "-", ".", "1e", "1e+"
    failed_ = true;
    return false;
  }
  if (std::isinf(v)) {  // overflow; underflow (0 or subnormal) is accepted
    value = v > 0 ? std::numeric_limits<double>::max() : -std::numeric_limits<double>::max();
    failed_ = true;
    return false;
  }
  value = v;
  return true;
}

bool StreamReader::read(long long& value) {
  if (!skip_space()) {
    value = 0;
    return false;
  }
  std::size_t i = pos_;
  const std::size_t n = text_.size();
  bool negative = false;
  if (i < n && (text_[i] == '+' || text_[i] == '-')) negative = text_[i++] == '-';
  // Accumulate as a negative number so that LLONG_MIN is representable.
  long long acc = 0;
  bool any_digit = false, overflow = false;
  for (; i < n && text_[i] >= '0' && text_[i] <= '9'; ++i) {
    any_digit = true;
    const int d = text_[i] - '0';
    if (acc < (LLONG_MIN + d) / 10) overflow = true;
    if (!overflow) acc = acc * 10 - d;
  }
  pos_ = i;
  if (!any_digit) {
    value = 0;
    failed_ = true;
    return false;
  }
  if (!negative && !overflow && acc == LLONG_MIN) overflow = true;
  if (overflow) {
    value = negative ? LLONG_MIN : LLONG_MAX;
    failed_ = true;
    return false;
  }
  value = negative ? acc : -acc;
  return true;
}

bool StreamReader::read_word(std::string_view& word) {
  if (!skip_space()) return false;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_stream_space(text_[pos_])) ++pos_;
  word = text_.substr(start, pos_ - start);
  return true;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  return lines;
}

}  // namespace sinew::regression
