#include "core/parse.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "core/alloc_check.h"
#include "core/rigid_mass_text.h"

namespace sinew::parse {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Length of the longest prefix that `std::istream >> double` would consume:
// [sign] digits [. digits] [(e|E) [sign] digits]. Returns 0 when no digit.
std::size_t number_prefix(std::string_view s, bool allow_fraction) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  if (allow_fraction && i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (allow_fraction && i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j < s.size() && is_digit(s[j])) {
      while (j < s.size() && is_digit(s[j])) ++j;
      i = j;
    }
  }
  return i;
}

// Reads consecutive numbers from a token list into `out` in groups of `width`
// via `read_one`; drops a trailing incomplete group; stops at a bad token.
template <class T, class ReadOne>
bool read_grouped(std::string_view text, std::size_t width, std::vector<T>& out, ReadOne read_one) {
  out.clear();
  bool ok = true;
  std::vector<T> group;
  for (std::string_view tok : tokens(text)) {
    T value{};
    if (!read_one(tok, value)) {
      ok = false;
      break;
    }
    group.push_back(value);
    if (group.size() == width) {
      out.insert(out.end(), group.begin(), group.end());
      group.clear();
    }
  }
  return ok;
}

}  // namespace

std::vector<std::string_view> tokens(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    std::size_t j = i;
    while (j < text.size() && !is_space(text[j])) ++j;
    if (j > i) out.push_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

bool read_double(std::string_view token, double& out) {
  const std::size_t n = number_prefix(token, true);
  if (n == 0) {
    out = 0;
    return false;
  }
  std::string_view num = token.substr(0, n);
  if (num[0] == '+') num.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), out);
  if (ec == std::errc::result_out_of_range) {
    // As std::istream >> double (libstdc++'s strtod-based conversion): underflow keeps
    // strtod's denormal or zero and succeeds; overflow stores ±DBL_MAX and fails, so
    // "1e400" in a scene is a warning and never an infinity in a field.
    out = std::strtod(std::string(num).c_str(), nullptr);
    if (std::isinf(out)) {
      out = std::copysign(std::numeric_limits<double>::max(), out);
      return false;
    }
    return true;
  }
  return ec == std::errc();
}

std::string_view first_partial_number(std::string_view text, bool joined_ok) {
  for (std::string_view t : tokens(text)) {
    std::size_t n = number_prefix(t, true);
    if (n == 0 || n == t.size()) continue;
    if (joined_ok) {
      std::string_view rest = t.substr(n);
      while (!rest.empty() && (n = number_prefix(rest, true)) > 0) rest.remove_prefix(n);
      if (rest.empty()) continue;
    }
    return t;
  }
  return {};
}

std::size_t count_list_numbers(std::string_view text) {
  std::size_t count = 0;
  for (std::string_view t : tokens(text)) {
    ++count;
    std::size_t n = number_prefix(t, true);
    if (n == 0) continue;
    t.remove_prefix(n);
    while (!t.empty() && (n = number_prefix(t, true)) > 0) {
      ++count;
      t.remove_prefix(n);
    }
  }
  return count;
}

bool read_int(std::string_view token, long long& out) {
  const std::size_t n = number_prefix(token, false);
  if (n == 0) {
    out = 0;
    return false;
  }
  std::string_view num = token.substr(0, n);
  if (num[0] == '+') num.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), out);
  return ec == std::errc();
}

bool read(std::string_view text, double& v) {
  auto t = tokens(text);
  if (t.empty()) return false;
  return read_double(t[0], v);
}
bool read(std::string_view text, float& v) {
  double d = 0;
  const bool ok = read(text, d);
  // istream >> float: beyond FLT_MAX is ±FLT_MAX and a failure, never an infinity.
  if (std::abs(d) > std::numeric_limits<float>::max()) {
    v = std::copysign(std::numeric_limits<float>::max(), static_cast<float>(d));
    return false;
  }
  v = static_cast<float>(d);
  return ok;
}
bool read(std::string_view text, int& v) {
  auto t = tokens(text);
  if (t.empty()) return false;
  long long x = 0;
  const bool ok = read_int(t[0], x);
  v = static_cast<int>(x);
  return ok;
}
bool read(std::string_view text, unsigned& v) {
  auto t = tokens(text);
  if (t.empty()) return false;
  long long x = 0;
  const bool ok = read_int(t[0], x);
  v = static_cast<unsigned>(x < 0 ? 0 : x);
  return ok && x >= 0;
}
bool read(std::string_view text, bool& v) {
  auto t = tokens(text);
  if (t.empty()) return false;
  const char c = t[0][0];
  if (c == 'T' || c == 't') return v = true, true;
  if (c == 'F' || c == 'f') return v = false, true;
  if (is_digit(c) || c == '-' || c == '+') {
    long long x = 0;
    if (!read_int(t[0], x)) return false;
    v = x != 0;
    return true;
  }
  return false;  // "yes", "on", ...: value unchanged
}
bool read(std::string_view text, std::string& v) {
  v.assign(text);
  return true;
}
bool read(std::string_view text, std::vector<double>& v) { return read_flat(text, 1, v); }

namespace {
// Integer lists: plain integers, or ranges "A-B" / "A-B-s" (inclusive, descending when A > B).
template <class I>
bool read_integral_list(std::string_view text, std::vector<I>& v) {
  v.clear();
  bool ok = true;
  auto push = [&](long long x) {
    if constexpr (std::is_unsigned_v<I>) {
      if (x < 0) {
        ok = false;
        x = 0;
      }
    }
    v.push_back(static_cast<I>(x));
  };
  for (std::string_view tok : tokens(text)) {
    const std::size_t dash = tok.find('-', 1);
    if (dash != std::string_view::npos && dash + 1 < tok.size()) {
      long long a = 0, b = 0, s = 1;
      std::string_view rest = tok.substr(dash + 1);
      const std::size_t dash2 = rest.find('-', 1);
      bool good = read_int(tok.substr(0, dash), a);
      if (dash2 != std::string_view::npos) {
        good = read_int(rest.substr(0, dash2), b) && good;
        good = read_int(rest.substr(dash2 + 1), s) && good;
      } else {
        good = read_int(rest, b) && good;
      }
      if (!good || s <= 0) {
        ok = false;
        push(0);
        continue;
      }
      // The count first: a range is a size taken from the scene ("0-888888888" would be
      // 3.5 GB), refused (a failure, the caller warns) when it would not fit in memory;
      // unsigned arithmetic so that ranges near the ends of long long cannot overflow.
      const unsigned long long span = a <= b ? static_cast<unsigned long long>(b) - static_cast<unsigned long long>(a)
                                             : static_cast<unsigned long long>(a) - static_cast<unsigned long long>(b);
      const unsigned long long count = span / static_cast<unsigned long long>(s) + 1;
      if (!allocation_fits(static_cast<double>(v.size()) + static_cast<double>(count), sizeof(I))) {
        ok = false;
        continue;
      }
      for (unsigned long long k = 0; k < count; ++k) {
        const unsigned long long step = k * static_cast<unsigned long long>(s);
        push(static_cast<long long>(a <= b ? static_cast<unsigned long long>(a) + step
                                           : static_cast<unsigned long long>(a) - step));
      }
      continue;
    }
    long long x = 0;
    if (!read_int(tok, x)) ok = false;  // bad token becomes 0 and is kept
    push(x);
  }
  return ok;
}
}  // namespace

bool read(std::string_view text, std::vector<int>& v) { return read_integral_list(text, v); }
bool read(std::string_view text, std::vector<unsigned>& v) { return read_integral_list(text, v); }

bool read(std::string_view text, std::vector<std::string>& v) {
  v.clear();
  // Bracketed quoted form: ["a", "b"] or Python's ['a', 'b'] (SOFA's scenes write both).
  std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '[') {
    std::size_t i = first + 1;
    while (i < text.size()) {
      const std::size_t q = text.find_first_of("\"'", i);
      if (q == std::string_view::npos) break;
      const std::size_t e = text.find(text[q], q + 1);
      if (e == std::string_view::npos) return false;
      v.emplace_back(text.substr(q + 1, e - q - 1));
      i = e + 1;
    }
    return true;
  }
  for (auto t : tokens(text)) v.emplace_back(t);
  return true;
}

bool read_flat(std::string_view text, int width, std::vector<double>& v) {
  // std::istream reads a list number after number: one ends where its syntax
  // ends and the rest of the token starts the next one, so "0-0.7" is two
  // numbers (0, −0.7), as SOFA reads it. Trailing non-numbers are dropped.
  v.clear();
  const std::size_t w = width > 0 ? static_cast<std::size_t>(width) : 1;
  bool ok = true;
  for (std::string_view tok : tokens(text)) {
    double x = 0;
    if (!read_double(tok, x)) {
      ok = false;
      break;
    }
    while (true) {
      v.push_back(x);
      const std::size_t n = number_prefix(tok, true);
      tok.remove_prefix(n);
      if (tok.empty() || number_prefix(tok, true) == 0 || !read_double(tok, x)) break;
    }
  }
  v.resize(v.size() - v.size() % w);  // an incomplete trailing element is dropped
  return ok;
}

namespace {
// `std::istream >> double` from position i of `text`: 1 read (appended to v), 0 at the end of
// the text, −1 on a non-number.
int stream_number(std::string_view text, std::size_t& i, std::vector<double>& v) {
  const std::size_t n = text.size();
  while (i < n && is_space(text[i])) ++i;
  if (i == n) return 0;
  const std::size_t len = number_prefix(text.substr(i), true);
  if (len == 0) return -1;
  double x = 0;
  read_double(text.substr(i, len), x);
  v.push_back(x);
  i += len;
  return 1;
}

// SOFA's `istream >> Mat<3,3>` from position i: blanks and at most one '[' before the first
// row; blanks or commas between rows; each row three numbers. Same return as stream_number
// for the first number that could not be read, 1 when all nine were.
int stream_mat3(std::string_view text, std::size_t& i, std::vector<double>& v) {
  const std::size_t n = text.size();
  while (i < n && (text[i] == ' ' || text[i] == '\n' || text[i] == '[')) {
    if (text[i++] == '[') break;
  }
  for (int row = 0; row < 3; ++row) {
    if (row > 0)
      while (i < n && (text[i] == ' ' || text[i] == ',')) ++i;
    for (int c = 0; c < 3; ++c)
      if (const int r = stream_number(text, i, v); r <= 0) return r;
  }
  return 1;
}
}  // namespace

bool read_rigid3_mass(std::string_view text, std::vector<double>& v) {
  v.clear();
  std::size_t i = 0;
  for (int k = 0; k < 2; ++k)
    if (const int r = stream_number(text, i, v); r <= 0) return r == 0;
  return stream_mat3(text, i, v) >= 0;  // a closing ']' and anything after it are not read
}

bool read_rigid3_mass_list(std::string_view text, std::vector<double>& v) {
  v.clear();
  std::size_t i = 0;
  const std::size_t n = text.size();
  std::vector<double> one;
  while (true) {
    one.clear();
    int r = stream_number(text, i, one);
    if (r == 0) return true;  // the end, between two masses
    if (r > 0) r = stream_number(text, i, one);
    if (r > 0) r = stream_mat3(text, i, one);
    if (r <= 0) return false;  // an incomplete or unreadable mass ends the list
    v.insert(v.end(), one.begin(), one.end());
    // SOFA's Mat reader, after the last row: blanks and at most one ']'.
    while (i < n && (text[i] == ' ' || text[i] == '\n' || text[i] == ']')) {
      if (text[i++] == ']') break;
    }
  }
}

bool read(std::string_view text, Mat3& m) {
  std::vector<double> v;
  std::size_t i = 0;
  const int r = stream_mat3(text, i, v);
  // Entries read so far replace the old ones (row by row); the others are kept.
  for (std::size_t k = 0; k < v.size(); ++k) m(static_cast<int>(k / 3), static_cast<int>(k % 3)) = v[k];
  return r == 1;
}

std::string to_text(const Mat3& m) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    if (r > 0) s += ',';
    for (int c = 0; c < 3; ++c) {
      if (c > 0) s += ' ';
      s += format_double(m(r, c));
    }
  }
  return s + "]";
}

template <int N>
bool read(std::string_view text, VecN<N>& v) {
  auto t = tokens(text);
  for (int i = 0; i < N; ++i) {
    if (i >= static_cast<int>(t.size())) return false;  // missing components unchanged
    double x = 0;
    const bool ok = read_double(t[i], x);
    v[i] = x;
    if (!ok) return false;
  }
  return true;
}
template <int N>
bool read(std::string_view text, VecNi<N>& v) {
  auto t = tokens(text);
  for (int i = 0; i < N; ++i) {
    if (i >= static_cast<int>(t.size())) return false;
    long long x = 0;
    const bool ok = read_int(t[i], x);
    v[i] = static_cast<int>(x);
    if (!ok) return false;
  }
  return true;
}
template <int N>
bool read(std::string_view text, std::vector<VecN<N>>& v) {
  std::vector<double> flat;
  const bool ok = read_flat(text, N, flat);
  v.resize(flat.size() / N);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < N; ++c) v[i][c] = flat[i * N + c];
  return ok;
}
template <std::size_t N>
bool read(std::string_view text, std::vector<std::array<unsigned, N>>& v) {
  std::vector<unsigned> flat;
  const bool ok = read_grouped<unsigned>(text, N, flat, [](std::string_view t, unsigned& x) {
    long long y = 0;
    const bool good = read_int(t, y) && y >= 0;
    x = static_cast<unsigned>(y < 0 ? 0 : y);
    return good;
  });
  v.resize(flat.size() / N);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t c = 0; c < N; ++c) v[i][c] = flat[i * N + c];
  return ok;
}

std::string format_double(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
std::string to_text(double v) { return format_double(v); }
std::string to_text(float v) { return format_double(v); }
std::string to_text(int v) { return std::to_string(v); }
std::string to_text(unsigned v) { return std::to_string(v); }
std::string to_text(bool v) { return v ? "1" : "0"; }
std::string to_text(const std::string& v) { return v; }

namespace {
template <class Seq, class F>
std::string join(const Seq& s, F f) {
  std::string out;
  bool first = true;
  for (const auto& x : s) {
    if (!first) out += ' ';
    first = false;
    out += f(x);
  }
  return out;
}
}  // namespace

std::string flat_to_text(const std::vector<double>& v) { return join(v, [](double x) { return format_double(x); }); }
std::string to_text(const std::vector<double>& v) { return flat_to_text(v); }
std::string to_text(const std::vector<int>& v) { return join(v, [](int x) { return std::to_string(x); }); }
std::string to_text(const std::vector<unsigned>& v) { return join(v, [](unsigned x) { return std::to_string(x); }); }
std::string to_text(const std::vector<std::string>& v) { return join(v, [](const std::string& x) { return x; }); }
template <int N>
std::string to_text(const VecN<N>& v) {
  std::string out;
  for (int i = 0; i < N; ++i) out += (i ? " " : "") + format_double(v[i]);
  return out;
}
template <int N>
std::string to_text(const VecNi<N>& v) {
  std::string out;
  for (int i = 0; i < N; ++i) out += (i ? " " : "") + std::to_string(v[i]);
  return out;
}
template <int N>
std::string to_text(const std::vector<VecN<N>>& v) {
  return join(v, [](const VecN<N>& x) { return to_text<N>(x); });
}
template <std::size_t N>
std::string to_text(const std::vector<std::array<unsigned, N>>& v) {
  return join(v, [](const std::array<unsigned, N>& a) { return join(a, [](unsigned x) { return std::to_string(x); }); });
}

// Explicit instantiations: the few sizes scenes use.
#define SINEW_VEC(N)                                                  \
  template bool read<N>(std::string_view, VecN<N>&);                  \
  template bool read<N>(std::string_view, std::vector<VecN<N>>&);     \
  template std::string to_text<N>(const VecN<N>&);                    \
  template std::string to_text<N>(const std::vector<VecN<N>>&);
SINEW_VEC(1)
SINEW_VEC(2)
SINEW_VEC(3)
SINEW_VEC(4)
SINEW_VEC(6)
SINEW_VEC(7)
SINEW_VEC(9)
SINEW_VEC(10)
SINEW_VEC(16)
#undef SINEW_VEC
template bool read<2>(std::string_view, VecNi<2>&);
template bool read<3>(std::string_view, VecNi<3>&);
template bool read<4>(std::string_view, VecNi<4>&);
template std::string to_text<2>(const VecNi<2>&);
template std::string to_text<3>(const VecNi<3>&);
template std::string to_text<4>(const VecNi<4>&);
#define SINEW_ARR(N)                                                              \
  template bool read<N>(std::string_view, std::vector<std::array<unsigned, N>>&); \
  template std::string to_text<N>(const std::vector<std::array<unsigned, N>>&);
SINEW_ARR(1)
SINEW_ARR(2)
SINEW_ARR(3)
SINEW_ARR(4)
SINEW_ARR(5)
SINEW_ARR(6)
SINEW_ARR(8)
#undef SINEW_ARR

}  // namespace sinew::parse
