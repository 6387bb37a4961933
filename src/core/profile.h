// StepProfile: where one simulation's steps spend their time (`sinew run --timing`).
//
// Owned by the root node, so two simulations in one process (Python, a
// viewer) keep their own figures (MuJoCo keeps its timers in mjData, Box2D
// its b2Profile in the world). The step stages are an enum with one slot
// each; solvers add named sub-scopes ("solve/forces", ...). Timing costs two
// clock reads per scope when enabled and one branch when not.
#pragma once

#include <array>
#include <chrono>
#include <mutex>
#include <string>
#include <vector>

namespace sinew {

// The stages of a step, in the order DefaultAnimationLoop runs them
// (spec/framework.md §4.1). The free-motion loop reuses the same stages.
enum class Stage : int {
  begin_events,           // AnimateBeginEvent; controllers and devices apply inputs
  free_motion,            // FreeMotionAnimationLoop: solvers integrate into the free vectors
  collision,              // reset, broad phase, narrow phase, response (empty without collision models)
  interaction_forces,     // explicit interaction force fields above the solver nodes, into externalForce
  solve,                  // each solver node integrates its subtree
  constraint_correction,  // Lagrangian constraint solve and correction (empty without constraints)
  project_and_propagate,  // projective constraints at t1, then mappings apply x and v
  check_state,            // positions and velocities finite, else the simulation stops with one message
  end_integration,        // externalForce emptied
  advance_time,           // time = t0 + dt, context copied down
  end_events,             // AnimateEndEvent; observers read the new state
};
inline constexpr int kStageCount = static_cast<int>(Stage::end_events) + 1;
const char* stage_name(Stage s);

class StepProfile {
 public:
  struct Entry {
    std::string name;
    double seconds = 0;
    long count = 0;
  };

  void set_enabled(bool on) { enabled_ = on; }
  bool enabled() const { return enabled_; }

  // Whole steps and stages (seconds, summed over the run).
  void add_step(double seconds) {
    step_seconds_ += seconds;
    ++steps_;
  }
  void add_stage(Stage s, double seconds) { stage_seconds_[static_cast<int>(s)] += seconds; }
  long steps() const { return steps_; }
  double step_seconds() const { return step_seconds_; }
  double stage_seconds(Stage s) const { return stage_seconds_[static_cast<int>(s)]; }

  // Named sub-scopes inside stages; thread-safe (parallel solver nodes).
  // `name` is a string literal.
  void add_scope(const char* name, double seconds);
  std::vector<Entry> scopes() const;

  void reset();

 private:
  bool enabled_ = false;
  long steps_ = 0;
  double step_seconds_ = 0;
  std::array<double, kStageCount> stage_seconds_{};
  mutable std::mutex mutex_;
  std::vector<Entry> scopes_;
};

// Times the rest of the enclosing block into a profile's named scope.
class ProfileScope {
 public:
  ProfileScope(StepProfile& p, const char* name) : profile_(p.enabled() ? &p : nullptr), name_(name) {
    if (profile_) start_ = std::chrono::steady_clock::now();
  }
  ~ProfileScope() {
    if (profile_)
      profile_->add_scope(name_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  ProfileScope(const ProfileScope&) = delete;
  ProfileScope& operator=(const ProfileScope&) = delete;

 private:
  StepProfile* profile_;
  const char* name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sinew

#define SINEW_PROFILE_CONCAT2(a, b) a##b
#define SINEW_PROFILE_CONCAT(a, b) SINEW_PROFILE_CONCAT2(a, b)
// SINEW_TIMED(profile, "solve/forces"): times the rest of the enclosing block.
#define SINEW_TIMED(profile, name) \
  ::sinew::ProfileScope SINEW_PROFILE_CONCAT(sinew_timed_, __LINE__)((profile), (name))
