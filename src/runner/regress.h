// Regression runs against SOFA's references (spec/regression-protocol.md).
#pragma once

#include <string>
#include <vector>

#include "regression/scene_list.h"

namespace sinew::runner {

enum class TestKind { state, topology };

struct RegressResult {
  std::string scene;
  bool passed = false;
  double value = 0;    // state: weighted mean error; topology: total mismatch count
  double epsilon = 0;
  int files = 0;       // reference files compared
  double seconds = 0;  // wall time of load + run
  std::string reason;  // why it failed (first error), empty when passed
};

struct RegressOptions {
  std::string data_root;                // SOFA data (share/, examples/)
  std::vector<std::string> extra_paths;
  bool isolate = true;                  // run each scene in a child process
  double time_limit = 600;              // seconds per scene (isolated runs only)
};

// Runs one scene of a list and compares it with its references.
RegressResult regress_scene(const regression::SceneList& list, const regression::SceneEntry& entry, TestKind kind,
                            const RegressOptions& options);

// Same, in a child process when options.isolate: a crash or a hang fails that scene only.
RegressResult regress_scene_isolated(const regression::SceneList& list, const regression::SceneEntry& entry,
                                     TestKind kind, const RegressOptions& options);

// A whole list run as `sinew regress` does: each scene of `list_file` whose path matches
// `filter` (a regex; empty: all), a PASS/FAIL line each and a summary on stdout.
// Returns 0 when all passed, 1 when one failed, 2 when the list or the filter is
// unreadable (message on stderr). The list's kind (state or topology) comes from its
// name, as SOFA's lists are named.
struct RegressListArgs {
  std::string list_file;
  std::string filter;
  RegressOptions options;  // data_root required
};
int regress_list(const RegressListArgs& args);

}  // namespace sinew::runner
