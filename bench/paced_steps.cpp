// Steps taken at a frame's pace (issue 15, done-when 4): a scene stepped N times with a pause
// between steps, as the viewer's step thread runs them, but with no window and nothing drawn.
//
//   bench_paced SCENE [--steps N] [--pause MS] [--data ROOT]
//
// Prints the mean and median duration of a step (the pauses excluded). Against `sinew run` (steps back to
// back) it shows what pausing alone costs; against `sinew view --stats` at the same frame period,
// what drawing costs (bench/run_viewer prints the three). Why pausing costs anything: on this
// virtual machine an idle CPU loses its caches and predictors to whatever the host runs there.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "runner/session.h"

int main(int argc, char** argv) {
  using namespace sinew;
  const auto usage = [] {
    std::fprintf(stderr, "usage: bench_paced SCENE [--steps N] [--pause MS] [--data ROOT]\n");
    return 2;
  };
  if (argc < 2) return usage();
  const std::string scene = argv[1];
  long steps = 1000;
  double pause_ms = 16;
  std::string data = "../shared/sofa-data";
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage();
    if (a == "--steps") steps = std::strtol(argv[++i], nullptr, 10);
    else if (a == "--pause") pause_ms = std::strtod(argv[++i], nullptr);
    else if (a == "--data") data = argv[++i];
    else return usage();
  }
  if (steps < 1 || !(pause_ms >= 0 && pause_ms <= 1000)) return usage();

  runner::SessionOptions options;
  options.data_paths = runner::sofa_data_paths(data);
  runner::Session session(scene, options);
  if (!session.ok()) {
    for (const auto& m : session.diagnostics().messages()) std::fprintf(stderr, "%s\n", Diagnostics::format(m).c_str());
    std::fprintf(stderr, "bench_paced: %s does not load\n", scene.c_str());
    return 1;
  }
  using Clock = std::chrono::steady_clock;
  const auto pause = std::chrono::duration<double, std::milli>(pause_ms);
  double total_ms = 0;
  std::vector<double> each(static_cast<std::size_t>(steps));
  for (long s = 0; s < steps; ++s) {
    const auto t0 = Clock::now();
    if (!session.step()) {
      std::fprintf(stderr, "bench_paced: step %ld failed\n", s + 1);
      return 1;
    }
    each[static_cast<std::size_t>(s)] = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    total_ms += each[static_cast<std::size_t>(s)];
    if (pause_ms > 0) std::this_thread::sleep_for(pause);
  }
  const auto mid = each.begin() + steps / 2;
  std::nth_element(each.begin(), mid, each.end());
  std::printf("steps %ld, %.3f ms pause: %.3f ms/step (median %.3f)\n", steps, pause_ms, total_ms / steps, *mid);
  return 0;
}
