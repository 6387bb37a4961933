#include "visual/visual_style.h"

#include <cctype>
#include <sstream>
#include <vector>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

using Leaf = DisplayFlags::Leaf;

// The tree of SOFA's DisplayFlags: a word and the leaves it sets.
struct Word {
  const char* name;  // without the show/hide prefix
  std::vector<Leaf> leaves;
};

const std::vector<Word>& words() {
  static const std::vector<Word> w = {
      {"All",
       {Leaf::visual_models, Leaf::behavior_models, Leaf::force_fields, Leaf::interaction_force_fields,
        Leaf::collision_models, Leaf::bounding_collision_models, Leaf::detection_outputs, Leaf::mappings,
        Leaf::mechanical_mappings}},
      {"Visual", {Leaf::visual_models}},
      {"VisualModels", {Leaf::visual_models}},
      {"Behavior", {Leaf::behavior_models, Leaf::force_fields, Leaf::interaction_force_fields}},
      {"BehaviorModels", {Leaf::behavior_models}},
      {"ForceFields", {Leaf::force_fields}},
      {"InteractionForceFields", {Leaf::interaction_force_fields}},
      {"Collision", {Leaf::collision_models, Leaf::bounding_collision_models, Leaf::detection_outputs}},
      {"CollisionModels", {Leaf::collision_models}},
      {"BoundingCollisionModels", {Leaf::bounding_collision_models}},
      {"DetectionOutputs", {Leaf::detection_outputs}},
      {"Mapping", {Leaf::mappings, Leaf::mechanical_mappings}},
      {"Mappings", {Leaf::mappings}},
      {"MechanicalMappings", {Leaf::mechanical_mappings}},
      {"Options", {Leaf::advanced_rendering, Leaf::wireframe, Leaf::normals}},
      {"AdvancedRendering", {Leaf::advanced_rendering}},
      {"Rendering", {Leaf::advanced_rendering}},
      {"Wireframe", {Leaf::wireframe}},
      {"Normals", {Leaf::normals}},
  };
  return w;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace

DisplayFlags DisplayFlags::viewer_defaults() {
  DisplayFlags f;
  f.leaf.fill(State::hidden);
  f.leaf[visual_models] = State::shown;
  return f;
}

DisplayFlags DisplayFlags::merged(const DisplayFlags& over) const {
  DisplayFlags out = *this;
  for (int i = 0; i < kLeafCount; ++i)
    if (over.leaf[i] != State::neutral) out.leaf[i] = over.leaf[i];
  return out;
}

DisplayFlags DisplayFlags::parse(const std::string& text, const std::function<void(const std::string&)>& warn) {
  DisplayFlags f;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    bool matched = false;
    for (const char* prefix : {"show", "hide"}) {
      for (const Word& w : words()) {
        const std::string exact = std::string(prefix) + w.name;
        if (!iequals(token, exact)) continue;
        if (token != exact && warn) warn("display flag '" + token + "' has the wrong case; read as '" + exact + "'");
        for (Leaf l : w.leaves) f.leaf[l] = prefix[0] == 's' ? State::shown : State::hidden;
        matched = true;
        break;
      }
      if (matched) break;
    }
    if (!matched && warn) warn("unknown display flag '" + token + "' ignored");
  }
  return f;
}

void VisualStyle::init() {
  flags_ = DisplayFlags::parse(display_flags.get(), [this](const std::string& m) { msg_warning(m); });
  parsed_version_ = display_flags.version();
}

const DisplayFlags& VisualStyle::flags() const {
  const std::string& text = display_flags.get();
  if (display_flags.version() != parsed_version_) {
    flags_ = DisplayFlags::parse(text);
    parsed_version_ = display_flags.version();
  }
  return flags_;
}

DisplayFlags display_flags_at(const Node& node) {
  std::vector<const Node*> chain;
  for (const Node* n = &node; n; n = n->parent()) chain.push_back(n);
  DisplayFlags f = DisplayFlags::viewer_defaults();
  for (auto it = chain.rbegin(); it != chain.rend(); ++it)
    for (const auto& o : (*it)->objects())
      if (const auto* s = dynamic_cast<const VisualStyle*>(o.get())) f = f.merged(s->flags());
  return f;
}

void register_visual_style(Registry& r) {
  ComponentInfo info;
  info.name = "VisualStyle";
  info.category = "Visual";
  info.description = "display flags of a node and its subtree (read by the viewer and `sinew render`)";
  info.create = creator<VisualStyle>();
  r.add(std::move(info));
}

}  // namespace sinew
