// Soak run (issue 14): one scene stepped for a long time, its resident memory
// sampled as it goes. A simulation that allocates per step without freeing, or
// that keeps a message per step, shows as RSS growing between the checkpoints;
// a value that stops being finite stops the run (the check stage of every step
// reports it as an error, naming the step, state and point).
//
//   bench_soak SCENE [--steps N] [--data ROOT] [--max-growth-kb K]
//
// Prints one line per checkpoint (steps done, RSS in kB, wall seconds) and a
// summary. Exit 0 when every step ran without error, every position and velocity
// is finite at the end and RSS grew by at most K kB (default 1024) between the
// first checkpoint (after the warm-up: caches and pools filled) and the last.
// Not a CTest case: 10^6 steps take minutes (bench/run_soak).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "core/node.h"
#include "core/roles.h"
#include "runner/session.h"

namespace {

using namespace sinew;

// Resident set size in kB (VmRSS of /proc/self/status), or -1 off Linux.
long rss_kb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  }
  return -1;
}

// Number of non-finite position and velocity scalars over every state of the graph.
long count_non_finite(Node& root) {
  std::vector<MechanicalState*> states;
  root.collect_down(states);
  long bad = 0;
  for (MechanicalState* s : states) {
    for (int id : {kPosition, kVelocity}) {
      for (double v : s->read(id)) bad += std::isfinite(v) ? 0 : 1;
    }
  }
  return bad;
}

int usage() {
  std::fprintf(stderr, "usage: bench_soak SCENE [--steps N] [--data ROOT] [--max-growth-kb K]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  std::string scene = argv[1];
  long steps = 1000000;
  long max_growth_kb = 1024;
  std::string data = "../shared/sofa-data";
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    if (a == "--steps") steps = std::strtol(argv[++i], nullptr, 10);
    else if (a == "--data") data = argv[++i];
    else if (a == "--max-growth-kb") max_growth_kb = std::strtol(argv[++i], nullptr, 10);
    else return usage();
  }
  if (steps < 1) return usage();

  // One thread, as the other benchmarks compare with SOFA.
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  runner::SessionOptions options;
  options.data_paths = runner::sofa_data_paths(data);
  runner::Session session(scene, options);
  if (!session.ok()) {
    for (const auto& m : session.diagnostics().messages()) std::fprintf(stderr, "%s\n", Diagnostics::format(m).c_str());
    std::fprintf(stderr, "soak: %s does not load\n", scene.c_str());
    return 1;
  }

  // Checkpoints: the end of the warm-up (1,000 steps or a tenth of the run), then
  // each tenth of the run.
  const long warm = std::min(1000L, std::max(1L, steps / 10));
  std::vector<long> marks{warm};
  for (int k = 1; k <= 10; ++k) {
    const long m = steps * k / 10;
    if (m > marks.back()) marks.push_back(m);
  }

  std::printf("soak %s, %ld steps\n%12s %12s %10s\n", scene.c_str(), steps, "steps", "RSS (kB)", "seconds");
  std::printf("%12d %12ld %10.1f\n", 0, rss_kb(), 0.0);
  const auto t0 = std::chrono::steady_clock::now();
  long first_rss = -1, last_rss = -1;
  bool failed = false;
  size_t next = 0;
  for (long s = 1; s <= steps; ++s) {
    if (!session.step()) {
      failed = true;
      break;
    }
    if (s == marks[next]) {
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      last_rss = rss_kb();
      if (first_rss < 0) first_rss = last_rss;
      std::printf("%12ld %12ld %10.1f\n", s, last_rss, sec);
      std::fflush(stdout);
      ++next;
    }
  }
  const long bad = count_non_finite(session.root());
  for (const auto& m : session.diagnostics().messages()) {
    if (m.severity == Severity::error) std::fprintf(stderr, "%s\n", Diagnostics::format(m).c_str());
  }
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long growth = last_rss - first_rss;
  std::printf("steps run %ld, %.3f ms/step, RSS growth after warm-up %ld kB, non-finite values %ld\n",
              session.steps_done(), 1e3 * sec / std::max(1L, session.steps_done()), growth, bad);
  if (failed) std::printf("soak: FAILED: a step reported an error\n");
  if (bad > 0) std::printf("soak: FAILED: non-finite positions or velocities\n");
  if (growth > max_growth_kb) std::printf("soak: FAILED: RSS grew by more than %ld kB\n", max_growth_kb);
  return failed || bad > 0 || growth > max_growth_kb ? 1 : 0;
}
