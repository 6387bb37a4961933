#include "core/profile.h"

namespace sinew {

const char* stage_name(Stage s) {
  switch (s) {
    case Stage::begin_events: return "begin events";
    case Stage::free_motion: return "free motion";
    case Stage::collision: return "collision";
    case Stage::interaction_forces: return "interaction forces";
    case Stage::solve: return "solve";
    case Stage::constraint_correction: return "constraint correction";
    case Stage::project_and_propagate: return "project and propagate";
    case Stage::check_state: return "check state";
    case Stage::end_integration: return "end integration";
    case Stage::advance_time: return "advance time";
    case Stage::end_events: return "end events";
  }
  return "?";
}

void StepProfile::add_scope(const char* name, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (Entry& e : scopes_)
    if (e.name == name) {
      e.seconds += seconds;
      ++e.count;
      return;
    }
  scopes_.push_back({name, seconds, 1});
}

std::vector<StepProfile::Entry> StepProfile::scopes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return scopes_;
}

void StepProfile::reset() {
  std::lock_guard<std::mutex> lock(mutex_);
  steps_ = 0;
  step_seconds_ = 0;
  stage_seconds_.fill(0);
  scopes_.clear();
}

}  // namespace sinew
