// ScriptedDevice: a haptic device replaying a trajectory file, for tests, demos
// and headless runs of haptic scenes (spec/interaction.md §6.5).
//
// CSV, one sample a line: `time, x, y, z, qx, qy, qz, qw, buttons` (9 columns,
// commas or blanks; '#' starts a comment; a first line that is not numeric is a
// header). Times strictly increasing; positions in the device frame, normalised
// units (the driver applies positionBase/orientationBase/scale, not the 0.1 mm
// factor of OpenHaptics); quaternions normalised on load; buttons a bitmask.
//
// Between samples: position linear, orientation spherical-linear (shortest arc),
// buttons those of the sample at or before t, velocities the segment's slope.
// Before the first sample and after the last the pose holds (zero velocity).
#pragma once

#include <string>
#include <vector>

#include "haptics/device.h"

namespace sinew::haptics {

struct TrajectorySample {
  double t = 0;
  Vec3 p = Vec3::Zero();
  Quat q{};
  unsigned buttons = 0;
};

// Parses the CSV text; false with `error` naming the line when malformed.
bool parse_trajectory(const std::string& text, std::vector<TrajectorySample>& out, std::string& error);

// The state at time t of a trajectory (see above); the list must not be empty.
DeviceState sample_trajectory(const std::vector<TrajectorySample>& samples, double t);

class ScriptedDevice final : public HapticDevice {
 public:
  explicit ScriptedDevice(std::string path) : path_(std::move(path)) {}
  explicit ScriptedDevice(std::vector<TrajectorySample> samples) : samples_(std::move(samples)) {}
  bool open(std::string& why) override;
  DeviceState read(double t) override { return sample_trajectory(samples_, t); }
  void write(const DeviceCommand& c) override { last_ = c; }
  bool clocked_by_simulation() const override { return true; }
  const char* kind() const override { return "scripted"; }
  const std::vector<TrajectorySample>& samples() const { return samples_; }

 private:
  std::string path_;
  std::vector<TrajectorySample> samples_;
  DeviceCommand last_{};
};

}  // namespace sinew::haptics
