#include "haptics/force_feedback.h"

#include <algorithm>

namespace sinew::haptics {

std::mutex& ForceFeedbackSlot::mutex() {
  static std::mutex m;
  return m;
}

ForceFeedback::~ForceFeedback() { detach_slots(); }

void ForceFeedback::detach_slots() {
  std::lock_guard<std::mutex> lock(ForceFeedbackSlot::mutex());
  for (ForceFeedbackSlot* s : slots_) s->ff_ = nullptr;
  slots_.clear();
}

void ForceFeedbackSlot::set(ForceFeedback* f) {
  std::lock_guard<std::mutex> lock(mutex());
  if (ff_) std::erase(ff_->slots_, this);
  ff_ = f;
  if (ff_) ff_->slots_.push_back(this);
}

bool ForceFeedbackSlot::empty() const {
  std::lock_guard<std::mutex> lock(mutex());
  return ff_ == nullptr;
}

bool ForceFeedbackSlot::compute(const Vec3& p, const Quat& q, Vec3& force) {
  std::lock_guard<std::mutex> lock(mutex());
  if (!ff_) return false;
  force = ff_->compute_force(p, q);
  return true;
}

}  // namespace sinew::haptics
