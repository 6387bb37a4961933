#include "carving/carving_manager.h"

#include <algorithm>
#include <memory>

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

namespace {

// The elements one pair's contacts picked, kept naming the same elements while the removals of
// the pairs before it renumber their topology: every removal event of their kind is applied to
// them as the container applies it (removed ones leave, the last one takes the freed slot).
class PickedElements final : public TopologyHandler {
 public:
  PickedElements(const CollisionModelBase& target, std::vector<unsigned> elements)
      : target_(&target), elements_(std::move(elements)) {
    switch (target.kind()) {
      case CollisionModelBase::Kind::triangle: kind_ = TopologyChangeType::triangles_removed; break;
      case CollisionModelBase::Kind::line: kind_ = TopologyChangeType::edges_removed; break;
      default: kind_ = TopologyChangeType::points_removed; break;
    }
    attach(collision_topology(target));
  }
  const CollisionModelBase& target() const { return *target_; }
  const std::vector<unsigned>& elements() const { return elements_; }

  void apply(const MeshTopologyBase& t, const TopologyChange& c) override {
    if (c.type != kind_) return;
    // Removal events arrive before the container changes: the count is the one they apply to.
    std::size_t n = kind_ == TopologyChangeType::triangles_removed ? t.triangles().size()
                    : kind_ == TopologyChangeType::edges_removed   ? t.edges().size()
                                                                   : t.nb_points();
    for (unsigned r : c.indices) {
      if (r >= n) continue;
      const auto last = static_cast<unsigned>(n - 1);
      for (unsigned& e : elements_) {
        if (e == r) {
          e = kGone;
        } else if (e == last) {
          e = r;
        }
      }
      --n;
    }
    std::erase(elements_, kGone);
  }

 private:
  static constexpr unsigned kGone = ~0u;
  const CollisionModelBase* target_;
  std::vector<unsigned> elements_;
  TopologyChangeType kind_;
};

}  // namespace

std::size_t CarvingManager::carve() {
  if (state() != ComponentState::valid) return 0;
  const CollisionModelBase* tool = tool_model.get();
  const double dist = carving_distance.value();
  // Picks of every pair first, then one removal per pair in the detection's order, as SOFA: a
  // later pair is resolved on the topology the earlier removals left (the triangles around a
  // touched point are then those of the new surface). Its indices are renamed along with the
  // removals (PickedElements), where SOFA reads them unchanged.
  std::vector<std::unique_ptr<PickedElements>> picks;
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
    std::vector<unsigned> picked;
    for (const DetectionOutput& o : p.outputs)
      if (o.value < dist) picked.push_back(tool_first ? o.elem2 : o.elem1);
    if (!picked.empty()) picks.push_back(std::make_unique<PickedElements>(*target, std::move(picked)));
  }
  std::size_t removed = 0;
  for (auto& pick : picks) {
    if (pick->elements().empty()) continue;  // all removed by the pairs before
    RemovalRequest r;
    std::string why;
    if (!resolve_removal(pick->target(), pick->elements(), &r, &why)) {
      msg_warning("carving " + pick->target().describe() + " failed: " + why);
      continue;
    }
    pick->attach(nullptr);
    if (r.elements.empty()) continue;  // the volume elements under them are gone already
    const std::size_t n = apply_removal(r, &why);
    if (n == 0) msg_warning("carving failed: " + std::to_string(r.elements.size()) + " elements were selected, but " +
                            (why.empty() ? std::string("none was removed") : why));
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
