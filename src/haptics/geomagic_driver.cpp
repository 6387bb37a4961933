#include "haptics/geomagic_driver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/node.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "haptics/scripted_device.h"

namespace sinew::haptics {

namespace {
Quat to_quat(const VecN<4>& v) { return {v[0], v[1], v[2], v[3]}; }
}  // namespace

GeomagicDriver::GeomagicDriver() {
  trajectory.set_file(true, false);
}

GeomagicDriver::~GeomagicDriver() { stop_device(); }

void GeomagicDriver::init() {
  if (scale.value() == 0 || !std::isfinite(scale.value()))
    msg_warning("scale = " + std::to_string(scale.value()) + ": the device does not move the tool");
  if (!force_feedback && node()) {
    // SOFA: the first ForceFeedback found from the root that carries all of the driver's tags.
    const auto& mine = tags.value();
    auto tagged = [&](const Component& c) {
      const auto& theirs = c.tags.value();
      return std::all_of(mine.begin(), mine.end(),
                         [&](const std::string& t) { return std::find(theirs.begin(), theirs.end(), t) != theirs.end(); });
    };
    ForceFeedback* found = nullptr;
    for_each_node(*node()->root(), [&](Node& n) {
      if (found) return;
      for (const auto& o : n.objects())
        if (auto* f = dynamic_cast<ForceFeedback*>(o.get()); f && tagged(*f)) {
          found = f;
          return;
        }
    });
    force_feedback.set(found);
  }
  if (!force_feedback)
    msg_warning("no force feedback component found: only the motion of the tool is simulated");
  slot_.set(force_feedback.get());
  if (!device_) {
    if (!trajectory.value().empty()) {
      device_ = std::make_unique<ScriptedDevice>(trajectory.value());
    } else {
      msg_info("no haptic device attached (Sinew is built without OpenHaptics): '" + device_name.value() +
               "' holds its rest pose");
      device_ = std::make_unique<RestDevice>(rest_state());
    }
  }
  std::string why;
  if (!device_->open(why)) {
    msg_error("trajectory: " + why);
    set_state(ComponentState::invalid);
    device_ = std::make_unique<RestDevice>(rest_state());
    publish(device_->read(0));
    return;
  }
  publish(device_->read(node() ? node()->time.value() : 0.0));
  if (!manual_start.value()) start_device();
}

void GeomagicDriver::start_device() {
  if (!device_ || servo_.running()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    params_.base = position_base.value();
    params_.qbase = to_quat(orientation_base.value());
    params_.scale = scale.value();
    params_.force_scale = force_scale.value();
    params_.max_input = max_input_force_feedback.value();
    params_.input_force = input_force_feedback.value();
  }
  // No device, nothing to serve.
  if (dynamic_cast<RestDevice*>(device_.get())) return;
  servo_.start(device_->rate_hz(), [this] { servo_tick(); });
}

void GeomagicDriver::stop_device() { servo_.stop(); }

DeviceCommand GeomagicDriver::last_command() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return command_;
}

// One servo tick (servo thread): read the device, compute and send the force.
void GeomagicDriver::servo_tick() {
  Params p;
  double t;
  bool started;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    p = params_;
    t = time_;
    started = started_;
  }
  const DeviceState s = device_->read(t);
  DeviceCommand cmd;
  if (started) {
    Vec3 f = Vec3::Zero();
    const Vec3 p_world = p.base + quat_rotate(p.qbase, s.position * p.scale);
    if (!slot_.compute(p_world, Quat{}, f)) {
      if (p.max_input > 0) {
        f = p.input_force;
        const double n = f.norm();
        if (n > p.max_input) f *= p.max_input / n;
      }
    }
    cmd.force = quat_inverse_rotate(p.qbase, f) * p.force_scale;
    device_->write(cmd);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  servo_state_ = s;
  servo_has_state_ = true;
  command_ = cmd;
}

void GeomagicDriver::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin || state() != ComponentState::valid || !device_) return;
  const double t = (node() ? node()->time.value() : 0.0) + e.dt;
  // Manual force: SOFA clamps the Data itself (with a warning) when it exceeds the max.
  Vec3 input = input_force_feedback.value();
  const double max_in = max_input_force_feedback.value();
  if (max_in > 0 && input.norm() > max_in) {
    if (!warned_clamp_)
      msg_warning("inputForceFeedback (norm " + std::to_string(input.norm()) + ") exceeds maxInputForceFeedback (" +
                  std::to_string(max_in) + "): clamped");
    warned_clamp_ = true;
    input *= max_in / input.norm();
    input_force_feedback.set(input);
  } else if (!(max_in > 0) && !warned_max_ && !force_feedback) {
    msg_error("maxInputForceFeedback = " + std::to_string(max_in) + ": it must be > 0 (no force is sent)");
    warned_max_ = true;
  }
  DeviceState s;
  bool have = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    started_ = true;
    time_ = t;
    params_.base = position_base.value();
    params_.qbase = to_quat(orientation_base.value());
    params_.scale = scale.value();
    params_.force_scale = force_scale.value();
    params_.max_input = max_in;
    params_.input_force = input;
    if (!device_->clocked_by_simulation()) {
      s = servo_state_;
      have = servo_has_state_;
    }
  }
  if (device_->clocked_by_simulation()) s = device_->read(t);
  if (have) publish(s);
}

void GeomagicDriver::update_buttons(unsigned buttons) {
  const unsigned old = buttons_;
  buttons_ = buttons;
  button1.set((buttons & 1u) != 0);
  button2.set((buttons & 2u) != 0);
  if (!emit_button_event.value() || old == buttons || !node()) return;
  for (int i = 0; i < 2; ++i) {
    const bool was = (old >> i) & 1u, is = (buttons >> i) & 1u;
    if (was == is) continue;
    Event ev{Event::Kind::script};
    ev.sender = node();
    ev.name = "button" + std::to_string(i) + (is ? "pressed" : "released");
    propagate_event(*node()->root(), ev);
  }
}

// SOFA's updatePosition: angles, then the tool pose placed in the scene.
void GeomagicDriver::publish(const DeviceState& s) {
  update_buttons(s.buttons);
  constexpr double half_pi = std::numbers::pi / 2;
  Vec6 a;
  a << s.joints[0], s.joints[1], -half_pi + s.joints[2] - s.joints[1], -half_pi - s.gimbals[0], s.gimbals[1],
      -half_pi - s.gimbals[2];
  angle.set(a);
  const Quat qb = to_quat(orientation_base.value());
  const Vec3 c = position_base.value() + quat_rotate(qb, s.position * scale.value());
  const Quat q = quat_mul(quat_mul(qb, s.orientation), to_quat(orientation_tool.value()));
  position_device.set(FlatVec{7, {c[0], c[1], c[2], q.x, q.y, q.z, q.w}});
}

}  // namespace sinew::haptics

namespace sinew {
void register_geomagic_driver(Registry& r) {
  ComponentInfo info;
  info.name = "GeomagicDriver";
  info.aliases = {"DefaultHapticsDevice"};
  info.category = "Haptics";
  info.description = "Geomagic (OpenHaptics) haptic device driver; rest pose or scripted trajectory without a device";
  info.requirement = Requirement::none;
  info.create = creator<haptics::GeomagicDriver>();
  r.add(std::move(info));
}
}  // namespace sinew
