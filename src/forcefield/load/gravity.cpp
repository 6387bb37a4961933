// Gravity: sets the gravity of its node's context (and so of the subtree
// below it), SOFA's Gravity context object. Masses read their node's gravity.
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {

class Gravity final : public ContextObject {
 public:
  Field<Vec3> gravity{this, "gravity", Vec3::Zero(), "gravity in world coordinates", "Context", "length/time²"};

  // Non-finite values never get here: the parser refuses them with a warning.
  void apply(Node& node) override { node.gravity.set(gravity.value()); }
};

}  // namespace

void register_gravity(Registry& r) {
  ComponentInfo info;
  info.name = "Gravity";
  info.category = "MechanicalLoad";
  info.description = "gravity of the node it is in and of the subtree below";
  info.create = creator<Gravity>();
  r.add(std::move(info));
}

}  // namespace sinew
