// RuleBasedContactManager (spec/interaction.md §4.1): a CollisionResponse
// whose response is chosen per pair of models by ordered rules
// "name1 name2 response" (a model name, a group id, or * for any model),
// with $variable$ substitution from Data declared by `variables`.
#include <memory>
#include <sstream>

#include "collision/contact_manager.h"
#include "core/registry.h"

namespace sinew {

namespace {

struct Rule {
  std::string name1, name2, response;
  int group1 = 0, group2 = 0;  // used when the name is a number (then the name is empty)

  static bool is_number(const std::string& s) {
    return !s.empty() && s.find_first_not_of("-0123456789") == std::string::npos;
  }
  // A purely numeric token is a group id (SOFA reads it with a checked conversion).
  static void read(std::string& name, int& group) {
    if (!is_number(name)) return;
    try {
      group = std::stoi(name);
      name.clear();
    } catch (const std::exception&) {
      group = 0;
    }
  }
  static bool match_one(const std::string& name, int group, const CollisionModelBase& m) {
    if (!name.empty()) return name == "*" || name == m.name.value();
    const auto& g = m.group.value();
    return std::find(g.begin(), g.end(), group) != g.end();
  }
  bool match(const CollisionModelBase& m1, const CollisionModelBase& m2) const {
    return match_one(name1, group1, m1) && match_one(name2, group2, m2);
  }
};

class RuleBasedContactManager final : public CollisionResponse {
 public:
  Field<std::string> variables{this, "variables", "", "names of string Data usable as $name$ inside the rules",
                               "Collision"};
  Field<std::vector<std::string>> rules{this, "rules", {},
                                        "ordered triplets: model name (or group id, or *), model name (or group id, "
                                        "or *), response; the first matching rule wins",
                                        "Collision"};

  // The variables become Data of this component before the attributes are read.
  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    if (const std::string* v = attrs.peek("variables")) {
      std::istringstream in(*v);
      std::string name;
      while (in >> name) {
        const std::size_t sep = name.find('_');
        vars_.push_back(std::make_unique<Field<std::string>>(
            this, name, "", "rule variable", sep == std::string::npos ? "Variables" : name.substr(0, sep)));
      }
    }
    CollisionResponse::parse(attrs, diag);
  }

  void init() override {
    CollisionResponse::init();
    // Complete triplets only: SOFA stops at the first incomplete one ("default" gives no rule).
    parsed_.clear();
    const auto& t = rules.value();
    for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
      Rule r{t[i], t[i + 1], t[i + 2]};
      Rule::read(r.name1, r.group1);
      Rule::read(r.name2, r.group2);
      parsed_.push_back(std::move(r));
    }
  }

 protected:
  std::string response_for(const CollisionModelBase& m1, const CollisionModelBase& m2) const override {
    if (!m1.contact_response.value().empty()) return m1.contact_response.value();
    if (!m2.contact_response.value().empty()) return m2.contact_response.value();
    for (const Rule& r : parsed_)
      if (r.match(m1, m2) || r.match(m2, m1)) return substitute(r.response);
    return substitute(CollisionResponse::response_for(m1, m2));
  }

 private:
  // Replaces each $name$ by the value of variable `name`.
  std::string substitute(const std::string& text) const {
    std::string out;
    std::size_t next = 0;
    while (next < text.size()) {
      const std::size_t var = text.find('$', next);
      if (var == std::string::npos) {
        out.append(text, next, std::string::npos);
        break;
      }
      out.append(text, next, var - next);
      const std::size_t end = text.find('$', var + 1);
      if (end == std::string::npos) {
        msg_error("unterminated $variable$ in response \"" + text + "\"");
        out.append(text, var, std::string::npos);
        break;
      }
      const std::string name = text.substr(var + 1, end - var - 1);
      const Field<std::string>* f = nullptr;
      for (const auto& v : vars_)
        if (v->name() == name) f = v.get();
      if (f) out += f->value();
      else msg_error("unknown variable $" + name + "$ in response \"" + text + "\" (declare it in 'variables')");
      next = end + 1;
    }
    return out;
  }

  std::vector<std::unique_ptr<Field<std::string>>> vars_;
  std::vector<Rule> parsed_;
};

}  // namespace

void register_rule_based_contact_manager(Registry& r) {
  ComponentInfo info;
  info.name = "RuleBasedContactManager";
  info.category = "Collision/Response";
  info.description = "contact manager choosing each pair's response by ordered rules on model names and groups";
  info.create = creator<RuleBasedContactManager>();
  r.add(std::move(info));
}

}  // namespace sinew
