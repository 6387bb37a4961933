// GeomagicDriver (alias DefaultHapticsDevice): SOFA's Geomagic plugin driver
// (spec/interaction.md §6.3, user-interfaces.md §6) over Sinew's device interface.
//
// Sinew is built without OpenHaptics: the driver says once that no device is
// attached and holds the device's home pose (identity transform, zero angles), so
// positionDevice = (positionBase, orientationBase·orientationTool). With the Sinew
// extension Data `trajectory` (a CSV file, haptics/scripted_device.h) it replays a
// scripted device instead. Backends clocked by the simulation are sampled at the
// end time of the step being started (t + dt), so positionDevice after N steps is
// the trajectory's pose at N·dt.
//
// Threads: a servo thread (haptics/servo_loop.h, 1 kHz) reads the device and, with
// a ForceFeedback, sends orientationBase⁻¹·F·forceScale to it, F computed at the
// tool position in the scene (positionBase + orientationBase·(scale·p)); without
// one, F = inputForceFeedback clamped to the norm maxInputForceFeedback. The
// simulation thread publishes the device state at AnimateBeginEvent. The two share
// one mutex-guarded block (parameters one way, the last device state the other);
// the thread is stopped and joined when the driver is destroyed.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "core/component.h"
#include "core/field.h"
#include "haptics/device.h"
#include "haptics/force_feedback.h"
#include "haptics/servo_loop.h"

namespace sinew::haptics {

class GeomagicDriver : public Component {
 public:
  GeomagicDriver();
  ~GeomagicDriver() override;

  Field<std::string> device_name{this, "deviceName", "Default Device", "OpenHaptics device configuration name",
                                 "Device"};
  Field<Vec3> position_base{this, "positionBase", Vec3::Zero(), "device base position in the scene", "Device",
                            "length"};
  Field<VecN<4>> orientation_base{this, "orientationBase", VecN<4>(0, 0, 0, 1),
                                  "device base orientation in the scene (quaternion x y z w)", "Device"};
  Field<VecN<4>> orientation_tool{this, "orientationTool", VecN<4>(0, 0, 0, 1),
                                  "rotation applied to the tool (quaternion x y z w)", "Device"};
  Field<double> scale{this, "scale", 1.0, "scale of the device motion", "Device"};
  Field<double> force_scale{this, "forceScale", 1.0, "scale of the force sent to the device", "Device"};
  Field<double> max_input_force_feedback{this, "maxInputForceFeedback", 1.0,
                                         "norm clamp of inputForceFeedback (must be > 0)", "Device", "force"};
  Field<Vec3> input_force_feedback{this, "inputForceFeedback", Vec3::Zero(),
                                   "force sent when no force feedback component is found", "Device", "force"};
  Field<bool> manual_start{this, "manualStart", false, "do not open the device at init", "Device"};
  Field<bool> emit_button_event{this, "emitButtonEvent", false,
                                "send script events button<i>pressed/released from the root", "Device"};
  Field<bool> draw_device_frame{this, "drawDeviceFrame", false, "draw the tool frame (viewer)", "Visualization"};
  Field<bool> draw_device{this, "drawDevice", false, "draw a model of the device arm (viewer)", "Visualization"};
  Field<FlatVec> position_device{this, "positionDevice", FlatVec{7, {0, 0, 0, 0, 0, 0, 1}},
                                 "tool pose in the scene (Rigid3d coordinate, output)", "Outputs"};
  Field<Vec6> angle{this, "angle", Vec6::Zero(), "joint and gimbal angles (rad, output)", "Outputs"};
  Field<bool> button1{this, "button1", false, "button 1 state (output)", "Outputs"};
  Field<bool> button2{this, "button2", false, "button 2 state (output)", "Outputs"};
  Link<ForceFeedback> force_feedback{this, "forceFeedBack",
                                     "force feedback component (default: the first one found from the root)"};
  // Sinew extension: replay a scripted device (CSV: time, x y z, qx qy qz qw, buttons).
  Field<std::string> trajectory{this, "trajectory", "",
                                "Sinew: CSV trajectory replayed as the device (time, x y z, qx qy qz qw, buttons)",
                                "Device"};

  void init() override;
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }

  // Opens the backend and starts the servo thread (init does it unless manualStart).
  void start_device();
  // Stops the servo thread (joins it).
  void stop_device();
  // Replaces the backend (tests, front ends); call before start_device().
  void set_device(std::unique_ptr<HapticDevice> d) { device_ = std::move(d); }
  HapticDevice* device() const { return device_.get(); }
  const ServoLoop& servo() const { return servo_; }
  // The last command sent to the device by the servo thread.
  DeviceCommand last_command() const;

 protected:
  // The device's home pose when no device is attached (the emulator's initial arm pose).
  virtual DeviceState rest_state() const { return {}; }
  // Publishes the outputs from a device state (SOFA's updatePosition).
  void publish(const DeviceState& s);
  std::unique_ptr<HapticDevice> device_;

 private:
  void servo_tick();
  void update_buttons(unsigned buttons);
  struct Params {
    Vec3 base = Vec3::Zero();
    Quat qbase{};
    double scale = 1, force_scale = 1, max_input = 1;
    Vec3 input_force = Vec3::Zero();
  };
  mutable std::mutex mutex_;  // guards params_, servo_state_, command_, time_
  Params params_;
  DeviceState servo_state_{};
  DeviceCommand command_{};
  double time_ = 0;             // simulation time last published (scripted backends in the servo)
  bool started_ = false;        // AnimateBegin seen (the servo sends forces from then on)
  bool warned_clamp_ = false;
  bool warned_max_ = false;
  bool servo_has_state_ = false;
  unsigned buttons_ = 0;
  ForceFeedbackSlot slot_;
  ServoLoop servo_;
};

}  // namespace sinew::haptics
