// Base: anything that owns fields and links (components and nodes).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.h"

namespace sinew {

class BaseField;
class BaseLink;

class Base;

// Called with every Base being destroyed, when set: handles held outside the
// graph (Python objects) learn that what they point to is gone. One global,
// set once by a front end; a plain function pointer (nothing to do otherwise).
using BaseDestroyedHook = void (*)(const Base*);
void set_base_destroyed_hook(BaseDestroyedHook hook);

class Base {
 public:
  Base() = default;
  Base(const Base&) = delete;
  Base& operator=(const Base&) = delete;
  virtual ~Base();

  const std::vector<BaseField*>& fields() const { return fields_; }
  const std::vector<BaseLink*>& links() const { return links_; }
  // By XML name or alias; nullptr when absent.
  BaseField* find_field(std::string_view name) const;
  BaseLink* find_link(std::string_view name) const;

  // Human-readable identity for messages: "component 'name' (Type)" or "node 'name'".
  virtual std::string describe() const = 0;

  // Where this object was declared (for file:line messages).
  SourceLocation where;

  // Registration hooks used by Field/Link constructors.
  void register_field(BaseField* f) { fields_.push_back(f); }
  void register_link(BaseLink* l) { links_.push_back(l); }

 private:
  std::vector<BaseField*> fields_;
  std::vector<BaseLink*> links_;
};

}  // namespace sinew
