// MechanicalStateController (Vec1d, Rigid3d): SOFA's Sofa.Component.Controller
// component driving the node's state from the mouse or a device, applied at every
// AnimateBeginEvent (spec/interaction.md §6.4).
//
// Vec1d (a gripper's opening): the rest positions x0[0] (and x0[1]) follow SOFA's
// rule: buttonDeviceState pressed closes x0[0] by 0.01 up to −0.1, released opens
// it by 0.05 down to −0.5; then SOFA's second block sets x0[0] = x0[1] = 0 (−0.4
// while the middle mouse button is held), which overrides the first. A state of
// fewer than two points is refused at init (SOFA reads out of bounds).
// Rigid3d: the device and mouse paths change the DoF `index`; Sinew has no mouse
// events for components yet (viewer work left), so the batch path remains: positions
// and velocities projected (at t = 0, as SOFA's visitor) and propagated through the
// mappings below the controller's node.
#pragma once

#include <memory>

#include "core/component.h"
#include "core/field.h"
#include "core/mechanical_ops.h"
#include "math/types.h"

namespace sinew::haptics {

class MechanicalStateController final : public Component {
 public:
  Field<unsigned> index{this, "index", 0u, "index of the controlled DoF", "Controller"};
  Field<bool> only_translation{this, "onlyTranslation", false, "control the DoF in translation only",
                               "Controller"};
  Field<bool> button_device_state{this, "buttonDeviceState", false, "state of the device button", "Controller"};
  Field<Vec3> main_direction{this, "mainDirection", Vec3(0, 0, -1),
                             "main direction and orientation of the controlled DoF", "Controller"};
  Field<bool> handle_event_triggers_update{this, "handleEventTriggersUpdate", false,
                                           "input events (mouse) apply the controller at once", "Controller"};

  void init() override;
  void handle_event(Event& e) override;
  // One application of SOFA's applyController (called at AnimateBegin).
  void apply();

 private:
  MechanicalState* state_ = nullptr;
  bool rigid_ = false;
  bool button_ = false;
  std::unique_ptr<MechanicalOps> ops_;  // the controller's node, gathered at init
};

}  // namespace sinew::haptics
