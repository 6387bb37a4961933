#include "topology/dynamic/point_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/point_set_topology_container.h"

namespace sinew {

void PointSetTopologyModifier::init() {
  container_ = nullptr;
  // SOFA: getContext()->get(container), i.e. this node first, then its ancestors.
  for (Node* n = node(); n && !container_; n = n->parent())
    for (const auto& o : n->objects())
      if (accepts(*o)) {
        container_ = static_cast<MeshContainer*>(static_cast<PointSetTopologyContainer*>(o.get()));
        break;
      }
  if (!container_) {
    msg_error(std::string("no ") + container_kind() + " found in this node or its ancestors");
    set_state(ComponentState::invalid);
  }
}

bool PointSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const PointSetTopologyContainer*>(&c) != nullptr; }

void register_point_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "PointSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a point topology";
  info.create = creator<PointSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
