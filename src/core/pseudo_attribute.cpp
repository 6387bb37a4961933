#include "core/pseudo_attribute.h"

#include "core/component.h"
#include "core/parse.h"
#include "core/value_text.h"

namespace sinew {

bool read_pseudo_number(const Component& c, Diagnostics& diag, std::string_view key, const std::string& text,
                        double& out) {
  if (parse::read(text, out)) return true;
  if (!text.empty() && text[0] == '@')
    diag.warning(c.where, c.describe() + ": '" + std::string(key) + "' is not a data field and cannot be linked (" +
                              quote_value(text) + "); read as " + parse::format_double(out));
  else
    diag.warning(c.where, c.describe() + ": could not read a number for '" + std::string(key) + "': " +
                              quote_value(text) + "; read as " + parse::format_double(out));
  return false;
}

}  // namespace sinew
