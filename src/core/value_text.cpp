#include "core/value_text.h"

#include <cstdlib>

#include "core/field.h"
#include "core/parse.h"

namespace sinew {

std::string quote_value(std::string_view v) {
  constexpr std::size_t kMax = 80;
  if (v.size() <= kMax) return "\"" + std::string(v) + "\"";
  std::size_t cut = kMax;
  while (cut > 0 && (static_cast<unsigned char>(v[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return "\"" + std::string(v.substr(0, cut)) + "…\" (" + std::to_string(v.size()) + " characters)";
}

std::string value_count_problem(const BaseField& f, std::string_view text) {
  const std::string t = f.type_name();
  int width = 0;
  bool fixed = false;
  if (t.size() > 4 && t.rfind("Vec", 0) == 0 && (t.back() == 'd' || t.back() == 'i')) {
    width = std::atoi(t.c_str() + 3);
    fixed = true;
  } else if (t.rfind("vector<Vec", 0) == 0) {
    width = std::atoi(t.c_str() + 10);
  } else if (t.rfind("vector<", 0) == 0 && t.find(" indices>") != std::string::npos) {
    width = std::atoi(t.c_str() + 7);
  } else if (t == "state vector") {
    width = f.row_width();
  }
  if (width <= 1) return {};
  // Lists count numbers written without spaces ("0-0.7") one by one, as they are read.
  const bool reals = t == "state vector" || (t.rfind("vector<Vec", 0) == 0 && t.ends_with("d>"));
  const std::size_t n = reals ? parse::count_list_numbers(text) : parse::tokens(text).size();
  if (fixed) {
    if (static_cast<int>(n) == width || n == 0) return {};
    return "expected " + std::to_string(width) + " values (" + t + "), got " + std::to_string(n) +
           (static_cast<int>(n) < width ? ": the missing ones keep their default" : ": the extra ones are ignored");
  }
  const std::size_t rest = n % static_cast<std::size_t>(width);
  if (rest == 0) return {};
  return "expected a multiple of " + std::to_string(width) + " values (" + t + "), got " + std::to_string(n) +
         ": the last " + std::to_string(rest) + " " + (rest == 1 ? "is" : "are") + " ignored";
}

}  // namespace sinew
