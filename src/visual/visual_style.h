// VisualStyle and SOFA's display flags (Sofa/framework/Core/.../visual/DisplayFlags.cpp,
// spec/user-interfaces.md §3.5).
//
// The flags are a tri-state tree: every leaf is shown, hidden or neutral
// (inherit). A group word (showBehavior, hideAll, ...) sets all its leaves.
// A VisualStyle's flags apply to its node and the subtree below, merged over
// the flags inherited from above; at the root the viewer's defaults apply
// (only visual models shown).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "core/roles.h"

namespace sinew {

class Node;
class Diagnostics;

struct DisplayFlags {
  enum Leaf {
    visual_models,
    behavior_models,
    force_fields,
    interaction_force_fields,
    collision_models,
    bounding_collision_models,
    detection_outputs,
    mappings,
    mechanical_mappings,
    advanced_rendering,
    wireframe,
    normals,
    kLeafCount
  };
  enum class State : signed char { neutral = -1, hidden = 0, shown = 1 };
  std::array<State, kLeafCount> leaf;

  DisplayFlags() { leaf.fill(State::neutral); }
  // The viewer's flags at the root: visual models shown, everything else hidden.
  static DisplayFlags viewer_defaults();
  // The non-neutral leaves of `over` replace those of this.
  DisplayFlags merged(const DisplayFlags& over) const;
  bool shown(Leaf l) const { return leaf[l] == State::shown; }

  // Parses "showBehaviorModels hideVisual ...", in order (a later word wins).
  // Wrong case is accepted with a warning, unknown words are warned about and skipped;
  // `warn` may be empty (no messages).
  static DisplayFlags parse(const std::string& text, const std::function<void(const std::string&)>& warn = {});
};

class VisualStyle final : public VisualComponent {
 public:
  Field<std::string> display_flags{this, "displayFlags", "", "display flags of this node and below (showVisual, "
                                   "showBehaviorModels, hideCollision, showWireframe, ...)", "Display"};
  void init() override;
  // Parsed flags; re-read when the field changed (the viewer may edit it).
  const DisplayFlags& flags() const;

 private:
  mutable DisplayFlags flags_;
  mutable std::uint64_t parsed_version_ = ~std::uint64_t{0};
};

// Flags in force at `node`: the viewer defaults merged with the VisualStyles of the root down to `node`.
DisplayFlags display_flags_at(const Node& node);

}  // namespace sinew
