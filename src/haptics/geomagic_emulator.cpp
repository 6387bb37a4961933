// GeomagicEmulator: SOFA's emulated Geomagic device (Geomagic plugin). The
// driver's Data and outputs, plus `speedFactor` (0.1); the arm starts at SOFA's
// recorded pose (joint, gimbal angles and 4×4 transform below). Keys move the
// angles as SOFA's (1/3 joint 1, 4/6 joint 2, 7/9 joint 3, -/+ gimbal 1, 8/2
// gimbal 2, by ±speedFactor); like SOFA's, the transform does not follow them
// (its computeTransform is empty). In batch runs the `trajectory` Data scripts it.
#include <mutex>

#include "core/registry.h"
#include "haptics/geomagic_driver.h"

namespace sinew {
namespace haptics {
namespace {

// SOFA's initial emulated state: the transform is column-major with translation in mm.
DeviceState emulator_home() {
  static constexpr double joints[3] = {0.0, 0.26889, -0.370813};
  static constexpr double gimbals[3] = {0.000108409, 0.797273, -1.94046};
  static constexpr double T[16] = {-0.361371, 0.848922,  -0.385672, 0, -0.932422, -0.328976, 0.149546, 0,
                                   7.57409e-05, 0.413651, 0.910436, 0, 0,          -65.5107, -88.1142, 1};
  DeviceState s;
  for (int i = 0; i < 3; ++i) s.joints[i] = joints[i], s.gimbals[i] = gimbals[i];
  s.position = Vec3(T[12], T[13], T[14]) * 0.1;  // OpenHaptics mm → scene units
  Mat3 R;
  for (int u = 0; u < 3; ++u)
    for (int k = 0; k < 3; ++k) R(u, k) = T[4 * k + u];
  s.orientation = quat_from_matrix(R);
  return s;
}

// The emulated arm: its home pose with angles the keys change.
class EmulatedDevice final : public HapticDevice {
 public:
  bool open(std::string&) override { return true; }
  DeviceState read(double t) override {
    std::lock_guard<std::mutex> lock(m_);
    DeviceState s = state_;
    s.timestamp = t;
    return s;
  }
  bool clocked_by_simulation() const override { return true; }
  const char* kind() const override { return "emulator"; }
  void move(bool joint, int i, double v) {
    std::lock_guard<std::mutex> lock(m_);
    (joint ? state_.joints : state_.gimbals)[static_cast<std::size_t>(i)] += v;
  }

 private:
  std::mutex m_;
  DeviceState state_ = emulator_home();
};

class GeomagicEmulator final : public GeomagicDriver {
 public:
  Field<double> speed_factor{this, "speedFactor", 0.1, "angle step of a key press (rad)", "Device"};

  void init() override {
    if (!device_ && trajectory.value().empty()) {
      auto d = std::make_unique<EmulatedDevice>();
      emulated_ = d.get();
      device_ = std::move(d);
    }
    GeomagicDriver::init();
  }
  void handle_event(Event& e) override {
    if (e.kind == Event::Kind::key_pressed && emulated_) {
      const double f = speed_factor.value();
      switch (e.key) {
        case '1': emulated_->move(true, 0, f); break;
        case '3': emulated_->move(true, 0, -f); break;
        case '4': emulated_->move(true, 1, f); break;
        case '6': emulated_->move(true, 1, -f); break;
        case '7': emulated_->move(true, 2, f); break;
        case '9': emulated_->move(true, 2, -f); break;
        case '-': emulated_->move(false, 0, f); break;
        case '+': emulated_->move(false, 0, -f); break;
        case '8': emulated_->move(false, 1, f); break;
        case '2': emulated_->move(false, 1, -f); break;
        default: break;
      }
      return;
    }
    GeomagicDriver::handle_event(e);
  }

 protected:
  DeviceState rest_state() const override { return emulator_home(); }

 private:
  EmulatedDevice* emulated_ = nullptr;
};

}  // namespace
}  // namespace haptics

void register_geomagic_emulator(Registry& r) {
  ComponentInfo info;
  info.name = "GeomagicEmulator";
  info.category = "Haptics";
  info.description = "emulated Geomagic device (keys in the viewer, a trajectory in batch)";
  info.requirement = Requirement::none;
  info.create = creator<haptics::GeomagicEmulator>();
  r.add(std::move(info));
}

}  // namespace sinew
