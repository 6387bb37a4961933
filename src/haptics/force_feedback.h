// ForceFeedback: the base of the components that compute the force sent to a
// haptic device (spec/interaction.md §6.1): Data `activate` (false) and `indice`
// (0, tool index of multi-tool drivers). compute_force / compute_wrench are
// called from the servo thread: implementations must be thread-safe with
// respect to the simulation thread.
//
// A driver reaches its force feedback through a ForceFeedbackSlot: the slot's
// calls and a force feedback's destruction are serialised by one mutex, so a
// component removed (or destroyed first at teardown) while the servo thread runs
// is never called again.
#pragma once

#include <mutex>
#include <vector>

#include "core/component.h"
#include "core/field.h"
#include "math/quat.h"
#include "math/types.h"

namespace sinew::haptics {

class ForceFeedbackSlot;

class ForceFeedback : public Component {
 public:
  ~ForceFeedback() override;
  Field<bool> activate{this, "activate", false, "send the computed force to the device", "Haptics"};
  Field<int> indice{this, "indice", 0, "tool index (multi-tool drivers)", "Haptics"};

  // Force at the tool position `p` (scene frame) with orientation `q`.
  virtual Vec3 compute_force(const Vec3& p, const Quat& q) = 0;
  // Force and torque for the tool frame at (p, q) moving at (v, w).
  virtual void compute_wrench(const Vec3& p, const Quat& q, const Vec3& v, const Vec3& w, Vec3& force,
                              Vec3& torque) {
    (void)v, (void)w;
    force = compute_force(p, q);
    torque = Vec3::Zero();
  }

 protected:
  // Empties every slot pointing here (waits for a call in progress). Derived
  // classes whose compute_* read their own members call it first in their
  // destructor: the base destructor runs after those members are gone.
  void detach_slots();

 private:
  friend class ForceFeedbackSlot;
  std::vector<ForceFeedbackSlot*> slots_;  // guarded by the slots' mutex
};

class ForceFeedbackSlot {
 public:
  ForceFeedbackSlot() = default;
  ForceFeedbackSlot(const ForceFeedbackSlot&) = delete;
  ForceFeedbackSlot& operator=(const ForceFeedbackSlot&) = delete;
  ~ForceFeedbackSlot() { set(nullptr); }
  void set(ForceFeedback* f);
  bool empty() const;
  // force = f.compute_force(p, q); false (force untouched) when the slot is empty.
  bool compute(const Vec3& p, const Quat& q, Vec3& force);

 private:
  friend class ForceFeedback;
  static std::mutex& mutex();
  ForceFeedback* ff_ = nullptr;
};

}  // namespace sinew::haptics
