#include "core/timer.h"

#include <atomic>
#include <mutex>

namespace sinew::timing {

namespace {
std::atomic<bool> g_enabled{false};
std::mutex g_mutex;
std::vector<Entry>& table() {
  static std::vector<Entry> t;
  return t;
}
}  // namespace

void set_enabled(bool on) { g_enabled = on; }
bool enabled() { return g_enabled.load(std::memory_order_relaxed); }

void record(const char* name, double seconds) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (Entry& e : table())
    if (e.name == name) {
      e.seconds += seconds;
      ++e.count;
      return;
    }
  table().push_back({name, seconds, 1});
}

std::vector<Entry> report() {
  std::lock_guard<std::mutex> lock(g_mutex);
  return table();
}

void reset() {
  std::lock_guard<std::mutex> lock(g_mutex);
  table().clear();
}

}  // namespace sinew::timing
