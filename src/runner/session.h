// Session: load a scene file, initialise it, step it. Shared by the command
// line (run, check, regress), the benchmarks and the tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/builder.h"

namespace sinew::runner {

struct SessionOptions {
  std::vector<std::string> data_paths;  // extra data folders (after the scene's folder)
  std::vector<std::string> script_args; // a Python scene's sys.argv[1:]
};

class Session {
 public:
  // Loads and initialises `path`; check ok() and diagnostics() afterwards.
  Session(const std::string& path, const SessionOptions& options);
  ~Session();

  bool loaded() const { return scene_.root != nullptr; }
  // True when loading and init reported no error.
  bool ok() const { return loaded() && !diagnostics().has_errors(); }
  Node& root() { return *scene_.root; }
  const Diagnostics& diagnostics() const { return scene_.root ? scene_.root->diagnostics() : load_diag_; }
  const std::vector<scene::MissingComponent>& missing() const { return scene_.missing; }

  // One step of the root's dt; false once an error was reported.
  bool step();
  // Closes the simulation (cleanup_root: exportAtEnd files are written). The destructor
  // does it too; calling it first lets the caller print the messages it raises.
  void close();
  long steps_done() const { return steps_; }

 private:
  scene::LoadedScene scene_;
  Diagnostics load_diag_;
  long steps_ = 0;
};

// Data folders for SOFA's layout under `data_root`: share/ then examples/.
std::vector<std::string> sofa_data_paths(const std::string& data_root);

// A data file (`name` relative to a data folder, e.g. SOFA's font texture) found as the scene
// builder finds resources: in `data_paths`, then in those of SOFA_DATA_PATH. Empty when absent.
std::string find_data_file(const std::vector<std::string>& data_paths, const std::string& name);

}  // namespace sinew::runner
