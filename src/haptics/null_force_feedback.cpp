// NullForceFeedback: a force feedback that always answers zero (SOFA's
// Sofa.Component.Haptics NullForceFeedback).
#include "core/registry.h"
#include "haptics/force_feedback.h"

namespace sinew {
namespace haptics {
namespace {
class NullForceFeedback final : public ForceFeedback {
 public:
  Vec3 compute_force(const Vec3&, const Quat&) override { return Vec3::Zero(); }
};
}  // namespace
}  // namespace haptics

void register_null_force_feedback(Registry& r) {
  ComponentInfo info;
  info.name = "NullForceFeedback";
  info.category = "Haptics";
  info.description = "force feedback that always returns zero";
  info.requirement = Requirement::none;
  info.create = creator<haptics::NullForceFeedback>();
  r.add(std::move(info));
}

}  // namespace sinew
