// Registry: which component classes exist, their templates and aliases.
//
// The XML tag (or `type=`) names a class; `template=` (after alias
// resolution) picks a variant. When the template is absent or unusable the
// class's default template is tried, then the others in lexicographic order,
// keeping the first whose requirement holds in the context (spec/framework.md
// §1.3). A single-state component therefore takes its template from the
// node's MechanicalObject.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/component.h"

namespace sinew {

class Node;

// What a template needs from the context to be created.
enum class Requirement {
  none,         // no state needed (solvers, loaders, topologies, ...)
  state,        // the node's mechanical state (or `mstate=`) must have the template's type
  mapping,      // input/output states of the template's "In,Out" types
};

struct ComponentInfo {
  std::string name;                           // SOFA class name (XML tag)
  std::string category;                       // e.g. "Mass", "ForceField", "Solver/ODE"
  std::string description;                    // one line
  std::vector<std::string> templates;         // empty: not templated
  std::string default_template;
  std::vector<std::string> aliases;           // old names still accepted
  Requirement requirement = Requirement::none;
  std::function<std::unique_ptr<Component>(const std::string& tmpl)> create;
};

class Registry {
 public:
  void add(ComponentInfo info);
  const ComponentInfo* find(std::string_view name) const;  // by name or alias
  std::vector<std::string> names() const;                  // sorted class names
  const std::map<std::string, ComponentInfo, std::less<>>& all() const { return classes_; }

  struct Created {
    std::unique_ptr<Component> component;
    std::string used_template;
    // Why nothing was created, or (with a component) why a different template was used.
    std::vector<std::string> errors;
    std::vector<std::string> warnings;  // template fallbacks, deprecated names
  };
  // Creates `type<tmpl>` for insertion in `node`; `attrs` supplies mstate/input/output paths.
  Created create(std::string_view type, std::string_view tmpl, Node& node, const AttributeMap& attrs) const;

 private:
  std::map<std::string, ComponentInfo, std::less<>> classes_;
  std::map<std::string, std::string, std::less<>> aliases_;
};

// SOFA's renamed components (FixedConstraint → FixedProjectiveConstraint, ...).
std::string_view renamed_component(std::string_view name);
// Template alias resolution for one comma-separated template string ("Vec3" → "Vec3d").
std::string resolve_template_alias(std::string_view tmpl, std::vector<std::string>* deprecations = nullptr);

// The process-wide registry with every built-in component (filled by register_all_components()).
Registry& registry();

// Helper for component files: ComponentInfo for a class with a default constructor.
template <class T>
std::function<std::unique_ptr<Component>(const std::string&)> creator() {
  return [](const std::string&) { return std::make_unique<T>(); };
}

}  // namespace sinew
