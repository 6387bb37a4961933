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

}  // namespace sinew::runner
