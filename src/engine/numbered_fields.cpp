#include "engine/numbered_fields.h"

#include <cctype>

namespace sinew {

unsigned read_field_count(Component& c, Field<unsigned>& field, AttributeMap& attrs, Diagnostics& diag,
                          const std::vector<std::string>& prefixes) {
  if (const std::string* p = attrs.peek(field.name()); p && !p->empty() && (*p)[0] != '@') {
    field.read(*p);  // the base parse reads it again and reports a bad value
  }
  unsigned n = field.value();
  if (n > kMaxNumberedFields) {
    diag.error(c.where, c.describe() + ": " + field.name() + " = " + std::to_string(n) + " is more than the " +
                            std::to_string(kMaxNumberedFields) + " inputs supported: clamped");
    n = kMaxNumberedFields;
  }
  for (auto& [key, e] : attrs.entries()) {
    for (const std::string& prefix : prefixes) {
      if (key.size() <= prefix.size() || key.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string digits = key.substr(prefix.size());
      bool all_digits = digits.size() <= 9;
      for (char ch : digits) all_digits = all_digits && std::isdigit(static_cast<unsigned char>(ch));
      if (!all_digits || digits[0] == '0') continue;
      const unsigned k = static_cast<unsigned>(std::stoul(digits));
      if (k > n) {
        e.used = true;
        diag.warning(c.where, c.describe() + ": attribute '" + key + "' ignored: " + field.name() + " is " +
                                  std::to_string(n));
      }
    }
  }
  return n;
}

}  // namespace sinew
