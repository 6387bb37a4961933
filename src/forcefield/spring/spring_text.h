// Reading the `spring` text of the rigid springs (JointSpringForceField,
// GearSpringForceField): white-space tokens and strict numbers.
#pragma once

#include <charconv>
#include <initializer_list>
#include <string>
#include <string_view>

namespace sinew::spring_text {

// Splits on white space (spaces, tabs, new lines: the XML attribute keeps them).
struct Tokens {
  std::string_view text;
  std::size_t pos = 0;
  bool next(std::string_view& tok) {
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; };
    while (pos < text.size() && space(text[pos])) ++pos;
    if (pos >= text.size()) return false;
    const std::size_t b = pos;
    while (pos < text.size() && !space(text[pos])) ++pos;
    tok = text.substr(b, pos - b);
    return true;
  }
};

// The whole token is the number (a leading '+' allowed).
inline bool to_double(std::string_view t, double& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

inline bool to_unsigned(std::string_view t, unsigned& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

// Reads one number per slot after keyword `key`; "" on success, else what is
// wrong, prefixed by `where` (the spring).
inline std::string read_numbers(Tokens& in, const std::string& where, std::string_view key,
                                std::initializer_list<double*> slots) {
  for (double* d : slots) {
    std::string_view t;
    if (!in.next(t)) return where + ": " + std::string(key) + " needs " + std::to_string(slots.size()) + " numbers";
    if (!to_double(t, *d)) return where + ": " + std::string(key) + " expects numbers, found '" + std::string(t) + "'";
  }
  return "";
}

}  // namespace sinew::spring_text
