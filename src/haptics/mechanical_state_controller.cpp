#include "haptics/mechanical_state_controller.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew::haptics {

void MechanicalStateController::init() {
  state_ = node() ? node()->get_mechanical_state() : nullptr;
  if (!state_) {
    msg_error("no mechanical state in the node to control");
    set_state(ComponentState::invalid);
    return;
  }
  const StateType t = state_->state_type();
  if (t != StateType::vec1 && t != StateType::rigid3) {
    msg_error(std::string("the node's state is ") + state_->info().name + ": only Vec1d and Rigid3d are supported");
    set_state(ComponentState::invalid);
    return;
  }
  rigid_ = t == StateType::rigid3;
  if (!rigid_ && state_->size() < 2) {
    msg_error("the Vec1d rule sets the rest positions of DoFs 0 and 1 but the state has " +
              std::to_string(state_->size()) + " DoF(s)");
    set_state(ComponentState::invalid);
    return;
  }
  if (rigid_ && index.value() >= state_->size())
    msg_warning("index " + std::to_string(index.value()) + " is beyond the state's " +
                std::to_string(state_->size()) + " DoFs (used by the mouse and device modes only)");
  const Vec3 d = main_direction.value();
  if (d.norm() == 0) msg_warning("mainDirection is zero");
  ops_ = std::make_unique<MechanicalOps>(*node());
}

void MechanicalStateController::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid || !state_) return;
  button_ = button_device_state.value();
  apply();
}

void MechanicalStateController::apply() {
  if (!rigid_) {
    if (state_->size() < 2) {
      msg_error("the state has fewer than 2 DoFs: the controller stops");
      set_state(ComponentState::invalid);
      return;
    }
    std::vector<double>& x0 = state_->write(kRestPosition);
    if (button_) x0[0] = x0[0] < -0.1 ? x0[0] + 0.01 : -0.1;  // closing, up to −0.1
    else x0[0] = x0[0] > -0.5 ? x0[0] - 0.05 : -0.5;           // opening, down to −0.5
    // SOFA's second block (no middle button held: no mouse events in Sinew yet).
    x0[0] = 0.0;
    x0[1] = 0.0;
    return;
  }
  // Rigid3d: no device or mouse input to apply; project (SOFA's visitor at t = 0)
  // and propagate positions and velocities below the node.
  ops_->sync();
  ops_->project_position(kPosition, 0.0);
  ops_->project_velocity(kVelocity, 0.0);
  ops_->propagate_x_and_v(kPosition, kVelocity);
}

}  // namespace sinew::haptics

namespace sinew {
void register_mechanical_state_controller(Registry& r) {
  ComponentInfo info;
  info.name = "MechanicalStateController";
  info.category = "Controller";
  info.description = "drives a Vec1d or Rigid3d state from the mouse or a device at each step";
  info.templates = {"Vec1d", "Rigid3d"};
  info.default_template = "Vec1d";
  info.requirement = Requirement::state;
  info.create = creator<haptics::MechanicalStateController>();
  r.add(std::move(info));
}
}  // namespace sinew
