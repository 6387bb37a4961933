// The device-agnostic haptic interface (spec/interaction.md §6.5).
//
// A backend (HapticDevice) gives the device's state and takes the command sent
// back to it. States are in the device frame with units already normalised by
// the backend (Geomagic: millimetres × 0.1); the driver component places them in
// the scene (positionBase, orientationBase, scale, orientationTool).
//
// Threads: read() and write() are called by the servo thread (haptics/servo_loop.h)
// only, except for backends clocked by the simulation (scripted, emulator), whose
// read(t) the simulation thread also calls with its own time: those must be safe to
// call from both (ScriptedDevice is immutable after load; the emulator locks).
#pragma once

#include <array>
#include <string>

#include "math/quat.h"
#include "math/types.h"

namespace sinew::haptics {

struct DeviceState {
  Vec3 position = Vec3::Zero();          // tool tip in the device frame (normalised units)
  Quat orientation{};                    // tool orientation in the device frame
  Vec3 linear_velocity = Vec3::Zero();   // d position / dt
  Vec3 angular_velocity = Vec3::Zero();  // in the device frame
  unsigned buttons = 0;                  // bit i: button i pressed
  std::array<double, 3> joints{};        // Geomagic joint angles (rad)
  std::array<double, 3> gimbals{};       // Geomagic gimbal angles (rad)
  double timestamp = 0;                  // seconds (device clock or trajectory time)
};

struct DeviceCommand {
  Vec3 force = Vec3::Zero();   // in the device frame
  Vec3 torque = Vec3::Zero();
};

class HapticDevice {
 public:
  virtual ~HapticDevice() = default;
  // Opens the device; false with the reason in `why`.
  virtual bool open(std::string& why) = 0;
  virtual void close() {}
  // The state at time t (seconds). Hardware ignores t and returns the latest sample.
  virtual DeviceState read(double t) = 0;
  virtual void write(const DeviceCommand&) {}
  // True when the state is a function of the simulation time (scripted, emulated):
  // the driver then samples it at the simulation's time, so runs are reproducible.
  virtual bool clocked_by_simulation() const { return false; }
  // Servo rate the backend asks for (Hz).
  virtual double rate_hz() const { return 1000.0; }
  virtual const char* kind() const = 0;
};

// No device attached: a fixed state (the device's home pose), forces dropped.
class RestDevice final : public HapticDevice {
 public:
  RestDevice() = default;
  explicit RestDevice(const DeviceState& rest) : rest_(rest) {}
  bool open(std::string&) override { return true; }
  DeviceState read(double t) override {
    DeviceState s = rest_;
    s.timestamp = t;
    return s;
  }
  bool clocked_by_simulation() const override { return true; }
  const char* kind() const override { return "rest"; }

 private:
  DeviceState rest_{};
};

}  // namespace sinew::haptics
