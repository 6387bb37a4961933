// Helpers of the bad-input audit (badinput_*_test.cpp): run a scene given as
// an XML string through the same path as `sinew run` (runner::Session: load,
// refuse on errors, init, step) and collect what happened.
#pragma once

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/roles.h"
#include "runner/session.h"
#include "test_scene.h"
#include "test_paths.h"

namespace sinew::test {

struct Outcome {
  bool loaded = false;
  bool init_ok = false;   // loading and init reported no error
  long steps = 0;         // steps done without error
  bool finite = true;     // every state vector (x, v) finite at the end
  std::vector<std::string> errors, warnings;
  std::string all() const {
    std::string s;
    for (const auto& e : errors) s += "  " + e + "\n";
    for (const auto& w : warnings) s += "  " + w + "\n";
    return s;
  }
  // Every error and warning.
  std::vector<std::string> problems() const {
    std::vector<std::string> v = errors;
    v.insert(v.end(), warnings.begin(), warnings.end());
    return v;
  }
};

// Whether some message contains every needle.
inline bool any_contains_all(const std::vector<std::string>& v, std::initializer_list<std::string_view> needles) {
  for (const auto& s : v) {
    bool all = true;
    for (auto n : needles) all = all && s.find(n) != std::string::npos;
    if (all) return true;
  }
  return false;
}

inline bool all_finite(Node& root) {
  std::vector<MechanicalState*> states;
  root.collect_down(states);
  for (MechanicalState* s : states)
    for (int id : {kPosition, kVelocity})
      for (double x : s->read(id))
        if (!std::isfinite(x)) return false;
  return true;
}

// Runs the scene file `path` for up to `steps` steps (resources also searched in
// `data_paths`); `after` may inspect the session once the steps are done.
inline Outcome run_scene_file(const std::string& path, long steps, const std::vector<std::string>& data_paths = {},
                              const std::function<void(runner::Session&)>& after = {}) {
  Outcome o;
  runner::SessionOptions opts;
  opts.data_paths = data_paths;
  runner::Session session(path, opts);
  o.loaded = session.loaded();
  o.init_ok = session.ok();
  if (o.init_ok) {
    for (long i = 0; i < steps; ++i)
      if (!session.step()) break;
    o.steps = session.steps_done();
    o.finite = all_finite(session.root());
    if (after) after(session);
  }
  o.errors = messages(session.diagnostics(), Severity::error);
  o.warnings = messages(session.diagnostics(), Severity::warning);
  return o;
}

// SOFA's example scene `rel` (under SINEW_DATA_DIR/examples, with SOFA's data paths) run
// for `steps` steps; not loaded (o.loaded false) when the data is absent.
inline Outcome run_sofa_example(const std::string& rel, long steps,
                                const std::function<void(runner::Session&)>& after = {}) {
  const std::filesystem::path data = SINEW_DATA_DIR;
  if (!std::filesystem::exists(data / "examples" / rel)) return {};
  return run_scene_file((data / "examples" / rel).string(), steps,
                        {(data / "share").string(), (data / "examples").string()}, after);
}

inline Outcome run_xml(const TempDir& dir, const std::string& xml, long steps = 5,
                       const std::string& name = "scene.scn") {
  return run_scene_file(dir.write(name, xml), steps);
}

// The product rule for a scene given bad input: either it is refused / stops
// with an error, or it runs with finite states; never NaNs without an error.
inline void expect_no_silent_garbage(const Outcome& o) {
  EXPECT_TRUE(o.loaded);
  if (o.errors.empty()) {
    EXPECT_TRUE(o.finite) << "non-finite states without any error:\n" << o.all();
  }
}

}  // namespace sinew::test
