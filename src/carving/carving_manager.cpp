#include "carving/carving_manager.h"

#include <algorithm>

#include "carving/remove_from_collision_model.h"
#include "core/node.h"
#include "core/path.h"
#include "core/registry.h"

namespace sinew {
namespace {

bool has_tag(const Component& c, const std::string& tag) {
  const auto& tags = c.tags.value();
  return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

}  // namespace

void CarvingManager::init() {
  Node* root = node() ? node()->root() : nullptr;
  if (!root) return;
  std::vector<CollisionModelBase*> models;
  root->collect_down(models);
  if (!tool_model.get())
    for (CollisionModelBase* m : models)
      if (has_tag(*m, "CarvingTool")) {
        tool_model.set(m);
        break;
      }
  surfaces_.clear();
  if (surface_model_path.value().empty()) {
    for (CollisionModelBase* m : models)
      if (has_tag(*m, "CarvingSurface")) surfaces_.push_back(m);
  } else {
    std::string path = surface_model_path.value(), why;
    if (!path.empty() && path[0] == '@') path.erase(0, 1);
    Base* b = resolve_object_path(*node(), this, path,
                                  [](Base* c) { return dynamic_cast<CollisionModelBase*>(c) != nullptr; }, &why);
    if (auto* m = dynamic_cast<CollisionModelBase*>(b)) {
      surfaces_.push_back(m);
    } else {
      msg_error("surfaceModelPath '" + surface_model_path.value() + "' names no collision model" +
                (why.empty() ? "" : " (" + why + ")"));
    }
  }
  if (!narrow_phase.get()) narrow_phase.set(node()->find_up<BVHNarrowPhase>());

  bool ok = true;
  if (!tool_model.get()) {
    msg_error("no tool collision model: set the toolModel link or tag a collision model CarvingTool");
    ok = false;
  }
  if (surfaces_.empty()) {
    msg_error("no surface collision model: tag the carved models CarvingSurface (or set surfaceModelPath)");
    ok = false;
  }
  if (!narrow_phase.get()) {
    msg_error("no narrow phase: add a BVHNarrowPhase to the scene or set the narrowPhaseDetection link");
    ok = false;
  }
  for (const Field<std::string>* k : {&key, &key_switch})
    if (k->value().size() != 1) {
      msg_error(std::string(k == &key ? "key" : "keySwitch") + " must be one character, not '" + k->value() + "'");
      ok = false;
    }
  if (!ok) set_state(ComponentState::invalid);
}

bool CarvingManager::is_surface(const CollisionModelBase* m) const {
  // SOFA carves a model only when it carries the tag; a model named by surfaceModelPath counts too.
  return has_tag(*m, "CarvingSurface") || std::find(surfaces_.begin(), surfaces_.end(), m) != surfaces_.end();
}

std::size_t CarvingManager::carve() {
  if (state() != ComponentState::valid) return 0;
  const CollisionModelBase* tool = tool_model.get();
  const double dist = carving_distance.value();
  // Every pair is resolved on the topology as detected before anything is removed: a removal
  // renumbers the elements the next pair's contacts name.
  std::vector<RemovalRequest> requests;
  for (const PairOutputs& p : narrow_phase->outputs()) {
    const CollisionModelBase* target = nullptr;
    bool tool_first = false;
    if (p.models.first == tool && is_surface(p.models.second)) {
      target = p.models.second;
      tool_first = true;
    } else if (p.models.second == tool && is_surface(p.models.first)) {
      target = p.models.first;
    } else {
      continue;
    }
    picked_.clear();
    for (const DetectionOutput& o : p.outputs)
      if (o.value < dist) picked_.push_back(tool_first ? o.elem2 : o.elem1);
    if (picked_.empty()) continue;
    RemovalRequest r;
    std::string why;
    if (!resolve_removal(*target, picked_, &r, &why)) {
      msg_warning("carving " + target->describe() + " failed: " + why);
      continue;
    }
    if (r.elements.empty()) {
      msg_warning("carving failed: " + std::to_string(picked_.size()) + " elements of " + target->describe() +
                  " were selected, but they belong to no element that can be removed");
      continue;
    }
    merge_request(requests, std::move(r));
  }
  std::size_t removed = 0;
  for (const RemovalRequest& r : requests) {
    std::string why;
    const std::size_t n = apply_removal(r, &why);
    if (n == 0) msg_warning("carving failed: " + why);
    removed += n;
  }
  return removed;
}

void CarvingManager::handle_event(Event& e) {
  if (state() != ComponentState::valid) return;
  switch (e.kind) {
    case Event::Kind::key_pressed:
      if (e.key == key.value()[0]) {
        active.set(true);
      } else if (e.key == key_switch.value()[0]) {
        active.set(!active.value());
      }
      break;
    case Event::Kind::key_released:
      if (e.key == key.value()[0]) active.set(false);
      break;
    case Event::Kind::animate_end:
      if (active.value()) carve();
      break;
    default:
      break;
  }
}

void register_carving_manager(Registry& r) {
  ComponentInfo info;
  info.name = "CarvingManager";
  info.category = "Carving";
  info.description = "removes the volume elements under the surface elements a carving tool touches";
  info.create = creator<CarvingManager>();
  r.add(std::move(info));
}

}  // namespace sinew
