#include "haptics/haptics_report.h"

#include <cstdio>
#include <vector>

#include "core/node.h"
#include "haptics/geomagic_driver.h"
#include "haptics/lcp_force_feedback.h"

namespace sinew::haptics {

std::string haptics_report(const Node& root, std::int64_t from_ns, std::int64_t to_ns) {
  std::vector<GeomagicDriver*> drivers;
  root.collect_down(drivers);
  std::string out;
  char line[512];
  for (GeomagicDriver* d : drivers) {
    const ServoLoop& s = d->servo();
    if (s.ticks() == 0) continue;
    const PeriodStats p = s.period_stats(from_ns, to_ns);
    const double secs = static_cast<double>(to_ns - from_ns) * 1e-9;
    std::snprintf(line, sizeof line,
                  "haptic loop: %llu updates, period p50 %.3f ms, p99 %.3f ms, max %.3f ms (mean %.3f ms, %.0f Hz over "
                  "%.2f s; %s, %s scheduling)\n",
                  static_cast<unsigned long long>(p.updates), p.p50, p.p99, p.max, p.mean,
                  secs > 0 ? static_cast<double>(p.updates) / secs : 0.0, secs, d->name.value().c_str(),
                  s.realtime() ? "real-time" : "normal");
    out += line;
    if (auto* lcp = dynamic_cast<LCPForceFeedback*>(d->force_feedback.get())) {
      std::snprintf(line, sizeof line,
                    "  %s: %llu haptic solves (%llu stopped by solverTimeout %.3g ms), %llu snapshots, last problem "
                    "%d rows\n",
                    lcp->name.value().c_str(), static_cast<unsigned long long>(lcp->solves()),
                    static_cast<unsigned long long>(lcp->timeouts()), lcp->solver_timeout.value() * 1e3,
                    static_cast<unsigned long long>(lcp->snapshots()), lcp->last_rows());
      out += line;
    }
  }
  if (out.empty()) out = "haptic loop: no device served (no driver with a trajectory, emulator or device)\n";
  return out;
}

}  // namespace sinew::haptics
