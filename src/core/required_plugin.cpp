// RequiredPlugin: SOFA loads plugin libraries at parse time. Every Sinew
// component is built in, so this only records the requested module names.
#include "core/registry.h"

namespace sinew {

namespace {
class RequiredPlugin final : public Component {
 public:
  Field<std::vector<std::string>> plugin_name{this, "pluginName", {}, "names of the required modules", "Plugin"};
  Field<std::vector<std::string>> suffix_map{this, "suffixMap", {}, "library suffixes (unused)", "Plugin"};
  Field<bool> stop_after_first_name{this, "stopAfterFirstNameFound", false, "unused", "Plugin"};
  Field<bool> stop_after_first_suffix{this, "stopAfterFirstSuffixFound", true, "unused", "Plugin"};
  Field<bool> require_one{this, "requireOne", false, "unused", "Plugin"};
  Field<bool> require_all{this, "requireAll", true, "unused", "Plugin"};
  Field<std::vector<std::string>> loaded_plugins{this, "loadedPlugins", {}, "modules considered loaded", "Plugin"};
  void init() override { loaded_plugins.set(plugin_name.value()); }
};
}  // namespace

void register_required_plugin(Registry& r) {
  ComponentInfo info;
  info.name = "RequiredPlugin";
  info.category = "Framework";
  info.description = "declares the SOFA modules a scene needs (all are built into Sinew)";
  info.create = creator<RequiredPlugin>();
  r.add(std::move(info));
}

}  // namespace sinew
