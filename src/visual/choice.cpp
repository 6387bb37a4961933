#include "visual/choice.h"

#include "core/value_text.h"

namespace sinew {

bool check_choice(const Component& c, Field<std::string>& f, std::initializer_list<const char*> items,
                  Diagnostics& diag) {
  std::string list;
  for (const char* i : items) {
    if (f.value() == i) return true;
    list += list.empty() ? "" : ", ";
    list += i;
  }
  diag.warning(c.where, c.describe() + ": " + f.name() + " " + quote_value(f.value()) + " is not one of " + list +
                            "; falls back to " + *items.begin() + " (as SOFA)");
  f.set(std::string(*items.begin()));
  return false;
}

}  // namespace sinew
