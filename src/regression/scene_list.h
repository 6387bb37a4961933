// `.regression-tests` list files: which scenes to run, for how many steps,
// with which threshold, and where their references live
// (regression-protocol.md §1).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sinew::regression {

// One scene line of a list file.
struct SceneEntry {
  std::string scene;       // token 1, relative to the list folder, verbatim
  int steps = 0;           // token 2: number of animation steps
  double epsilon = 0.0;    // token 3: state threshold (unused by topology tests)
  bool mapped = false;     // token 4: also test states/topologies under a mapping
  bool last_only = false;  // token 5: write only the first and last state
  int period = 0;          // token 6: write every `period` steps (0 = every step)
  int line = 0;            // 1-based line number in the list file
};

struct SceneList {
  std::string list_dir;       // folder holding the list file ("" = current folder)
  std::string reference_dir;  // resolved reference folder (see parse_scene_list)
  std::vector<SceneEntry> scenes;
  std::vector<std::string> problems;  // "line N: ..." messages; never fatal by themselves
};

// Values of the environment variables the list rules use, passed explicitly
// so that tests and tools can inject them.
struct ListEnvironment {
  std::optional<std::string> regression_dir;   // REGRESSION_DIR
  std::optional<std::string> references_dir;   // REGRESSION_REFERENCES_DIR
  // Reads both variables from the process environment.
  static ListEnvironment from_process();
};

// Parses the text of a list file whose folder is `list_dir`.
// Rules: a line is skipped iff it is empty or its first character is '#'
// (no trimming: "  # x" is not a comment). The first other line is the
// reference folder, verbatim: a leading "$REGRESSION_DIR" is replaced by
// env.regression_dir, otherwise the folder is relative to `list_dir`
// (an absolute path is kept as is). If that folder does not exist,
// env.references_dir is tried (absolute or relative to `list_dir`); if no
// folder exists the list is unusable: `scenes` stays empty and a problem is
// recorded (reference_dir keeps the first candidate, for messages).
// Every later line is a scene: whitespace-separated tokens
// "scene steps epsilon [mapped [lastonly [period]]]", extra tokens ignored;
// a line with fewer than 3 tokens, or whose numbers do not convert, is
// recorded in `problems` and ignored. Conversions follow std::stoi (leading
// integer) and std::stod (leading floating value).
// Touches the file system only to test whether folders exist.
SceneList parse_scene_list(std::string_view text, const std::string& list_dir,
                           const ListEnvironment& env);

// Reads and parses the list file at `path` (list_dir = its parent folder).
// Returns nullopt and sets *error (if non-null) when the file cannot be read.
std::optional<SceneList> read_scene_list(const std::string& path, const ListEnvironment& env,
                                         std::string* error = nullptr);

// `<list_dir>/<scene>`: the scene file of an entry.
std::string scene_path(const SceneList& list, const SceneEntry& entry);

// `<reference_dir>/<scene>.reference`: the reference base of an entry. The
// reference files are `<base>_<N>_<NAME>_mstate.txt.gz` /
// `<base>_<N>_<NAME>_topology.txt.gz`; the base itself is an empty marker file
// whose presence selects compare mode.
std::string reference_base(const SceneList& list, const SceneEntry& entry);

}  // namespace sinew::regression
