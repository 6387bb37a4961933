// Named timing scopes: where a step spends its time (`sinew run --timing`).
//
// A scope costs two clock reads when timing is enabled and one branch when it
// is not. Totals are per name, accumulated over the run, thread-safe.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace sinew::timing {

// Enables or disables every scope (disabled by default).
void set_enabled(bool on);
bool enabled();

// Adds `seconds` to the total of `name` (a string literal: names are compared by address first).
void record(const char* name, double seconds);

struct Entry {
  std::string name;
  double seconds = 0;
  long count = 0;
};
// Totals so far, in first-recorded order.
std::vector<Entry> report();
void reset();

class Scope {
 public:
  explicit Scope(const char* name) : name_(name), on_(enabled()) {
    if (on_) start_ = std::chrono::steady_clock::now();
  }
  ~Scope() {
    if (on_) record(name_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

 private:
  const char* name_;
  bool on_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sinew::timing

#define SINEW_TIMED_CONCAT2(a, b) a##b
#define SINEW_TIMED_CONCAT(a, b) SINEW_TIMED_CONCAT2(a, b)
// SINEW_TIMED("stage"): times the rest of the enclosing block under "stage".
#define SINEW_TIMED(name) ::sinew::timing::Scope SINEW_TIMED_CONCAT(sinew_timed_, __LINE__)(name)
