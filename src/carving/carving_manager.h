// CarvingManager (SofaCarving, spec/interaction.md §7.5): after each step, removes the
// elements of the carving surfaces that the tool touched — every contact of the last
// collision detection between the tool model and a surface model whose distance is
// below carvingDistance names a surface element, and that element is carried down to
// the volume that owns it (remove_from_collision_model.h) and removed.
//
// The tool is the `toolModel` link, else the first collision model tagged CarvingTool
// from the root; the surfaces are the models tagged CarvingSurface (or the one at
// `surfaceModelPath`); the contacts are read from the `narrowPhaseDetection` link, else
// the first narrow phase from this node upwards. Keys: `key` carves while held down,
// `keySwitch` toggles `active`.
#pragma once

#include <string>
#include <vector>

#include "collision/collision_model.h"
#include "collision/narrow_phase.h"
#include "core/component.h"

namespace sinew {

class CarvingManager final : public Component {
 public:
  CarvingManager() { listening.set(true); }

  Link<CollisionModelBase> tool_model{this, "toolModel",
                                      "the tool's collision model (default: the first model tagged CarvingTool)"};
  Link<BVHNarrowPhase> narrow_phase{this, "narrowPhaseDetection",
                                    "narrow phase whose contacts are read (default: the first one from this node up)"};
  Field<std::string> surface_model_path{this, "surfaceModelPath", "",
                                        "path of the carved collision model (default: models tagged CarvingSurface)",
                                        "Carving"};
  Field<double> carving_distance{this, "carvingDistance", 0.0,
                                 "contacts closer than this (distance minus contact distance) carve", "Carving",
                                 "length"};
  Field<bool> active{this, "active", false, "carve after each step (keys can change it)", "Carving"};
  Field<std::string> key{this, "key", "1", "key carving while it is held down", "Carving"};
  Field<std::string> key_switch{this, "keySwitch", "4", "key switching `active` on and off", "Carving"};

  void init() override;
  void handle_event(Event& e) override;

  // One carving pass over the last detection's contacts; returns the number of volume
  // elements removed.
  std::size_t carve();

  CollisionModelBase* tool() const { return tool_model.get(); }
  const std::vector<CollisionModelBase*>& surfaces() const { return surfaces_; }

 private:
  bool is_surface(const CollisionModelBase* m) const;

  std::vector<CollisionModelBase*> surfaces_;
};

}  // namespace sinew
