#include "core/component.h"

#include "core/node.h"
#include "core/parse.h"
#include "core/value_text.h"

namespace sinew {

const std::string* AttributeMap::take(std::string_view name) {
  auto it = values_.find(name);
  if (it == values_.end()) return nullptr;
  it->second.used = true;
  return &it->second.value;
}

const std::string* AttributeMap::peek(std::string_view name) const {
  auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second.value;
}

Component::Component() {
  // Never propagated by src="@loader" (spec/framework.md §2.4 step 4).
  for (BaseField* f : {static_cast<BaseField*>(&name), static_cast<BaseField*>(&print_log),
                       static_cast<BaseField*>(&tags), static_cast<BaseField*>(&listening)})
    f->set_autolink(false);
}
Component::~Component() = default;

void Component::set_state(ComponentState s) {
  if (s == state_) return;
  state_ = s;
  if (node_) node_->bump_structure_version();
}

std::string Component::describe() const {
  return "component '" + name.value() + "' (" + class_name_ + ")";
}

void Component::parse(AttributeMap& attrs, Diagnostics& diag) {
  // printLog first, then every other attribute alphabetically (map order).
  auto parse_one = [&](const std::string& key, AttributeMap::Entry& e) {
    if (key == "type" || key == "template" || key == "src") {
      e.used = true;
      return;
    }
    if (BaseField* f = find_field(key)) {
      e.used = true;
      if (!e.value.empty() && e.value[0] == '@') {
        f->set_link_path(e.value);  // resolved by the builder
        f->mark_set();
        return;
      }
      const bool read_ok = f->read(e.value);
      if (const std::string count = value_count_problem(*f, e.value); !count.empty()) {
        diag.warning(where, describe() + ": field '" + key + "': " + count + ": " + quote_value(e.value));
      } else if (!read_ok && !e.value.empty()) {
        diag.warning(where, describe() + ": could not read value for field '" + key + "': " + quote_value(e.value));
      } else if (const std::string t = f->type_name();
                 t == "double" || t == "float" || t == "vector<double>" || t == "state vector" ||
                 (t.rfind("Vec", 0) == 0 && t.back() == 'd') || t.rfind("vector<Vec", 0) == 0) {
        // Real numbers are read like std::istream (a valid prefix is kept): say so.
        const bool list = t != "double" && t != "float" && t.rfind("Vec", 0) != 0;
        if (const std::string_view bad = parse::first_partial_number(e.value, list); !bad.empty())
          diag.warning(where, describe() + ": field '" + key + "': " + quote_value(bad) +
                                  " is not a number (only its numeric prefix is used)");
      }
      return;
    }
    if (BaseLink* l = find_link(key)) {
      e.used = true;
      l->set_path(e.value);
    }
  };
  if (auto it = attrs.entries().find("printLog"); it != attrs.entries().end()) parse_one(it->first, it->second);
  for (auto& [key, e] : attrs.entries())
    if (!e.used) parse_one(key, e);
}

void Component::msg_error(const std::string& text) const {
  if (!node_) return;
  node_->diagnostics().add(Severity::error, where, describe(), text);
}
void Component::msg_warning(const std::string& text) const {
  if (!node_) return;
  node_->diagnostics().add(Severity::warning, where, describe(), text);
}
void Component::msg_info(const std::string& text) const {
  if (!node_) return;
  node_->diagnostics().add(Severity::info, where, describe(), text);
}

}  // namespace sinew
