#include "regression/number_format.h"

#include <charconv>
#include <cmath>

#include "regression/stream_reader.h"

namespace sinew::regression {

char* write_g6(char* first, double x) {
  // to_chars with an explicit precision is specified "as if by printf in the
  // C locale", so it yields exactly the "%.6g" text, including "-nan".
  const auto result = std::to_chars(first, first + kG6MaxChars, x, std::chars_format::general, 6);
  return result.ptr;
}

std::string format_g6(double x) {
  char buffer[kG6MaxChars];
  return std::string(buffer, write_g6(buffer, x));
}

void append_g6(std::string& out, double x) {
  char buffer[kG6MaxChars];
  out.append(buffer, write_g6(buffer, x));
}

double round_g6(double x) {
  if (!std::isfinite(x)) return x;
  char buffer[kG6MaxChars];
  char* end = write_g6(buffer, x);
  double value = 0.0;
  const auto result = std::from_chars(buffer, end, value);
  if (result.ec == std::errc() && result.ptr == end) return value;
  // from_chars may refuse a subnormal result that `>>` accepts; take the slow,
  // exact path for those rare values.
  StreamReader reader(std::string_view(buffer, static_cast<std::size_t>(end - buffer)));
  reader.read(value);
  return value;
}

}  // namespace sinew::regression
