#include "mapping/articulated/articulated_hierarchy.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void ArticulatedHierarchyContainer::init() {
  if (!filename.value().empty()) {
    msg_error("filename: building the hierarchy from a BVH file is not supported; describe it with "
              "ArticulationCenter and Articulation components below this node");
    set_state(ComponentState::invalid);
    return;
  }
  gather();
}

void ArticulatedHierarchyContainer::gather() {
  centers_.clear();
  if (!node()) return;
  gathered_version_ = node()->structure_version();
  node()->collect_down(centers_);
  for (ArticulationCenter* c : centers_) {
    c->articulations.clear();
    if (!c->node()) continue;
    // Below the centre's child nodes only: articulations beside the centre are not its own (SOFA).
    for (Node* child : c->node()->children()) child->collect_down(c->articulations);
  }
}

const std::vector<ArticulationCenter*>& ArticulatedHierarchyContainer::centers() {
  if (node() && node()->structure_version() != gathered_version_) gather();
  return centers_;
}

void ArticulatedHierarchyContainer::ancestors(int index, std::vector<ArticulationCenter*>& out) {
  out.clear();
  const std::vector<ArticulationCenter*>& all = centers();
  while (index != 0) {
    ArticulationCenter* found = nullptr;
    for (ArticulationCenter* c : all)
      if (c->child_index.value() == index) {
        found = c;
        break;
      }
    // A chain longer than the number of centres goes round a loop (SOFA would not stop).
    if (!found || out.size() == all.size()) {
      if (!warned_ancestors_) {
        warned_ancestors_ = true;
        msg_error(found ? "the articulation centres form a loop through frame " + std::to_string(index)
                        : "frame " + std::to_string(index) +
                              " is the child of no articulation centre: its chain stops there");
      }
      return;
    }
    out.push_back(found);
    index = found->parent_index.value();
  }
}

void register_articulated_hierarchy(Registry& r) {
  ComponentInfo info;
  info.category = "Mapping/Articulated";
  info.name = "ArticulatedHierarchyContainer";
  info.description = "gathers the articulation centres of an articulated rigid system";
  info.create = creator<ArticulatedHierarchyContainer>();
  r.add(info);
  info.name = "ArticulationCenter";
  info.description = "a joint between two frames of an articulated system, holding its articulations";
  info.create = creator<ArticulationCenter>();
  r.add(info);
  info.name = "Articulation";
  info.description = "one coordinate of a joint: a rotation about or a translation along an axis";
  info.create = creator<Articulation>();
  r.add(std::move(info));
}

}  // namespace sinew
