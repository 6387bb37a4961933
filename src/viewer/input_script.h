// Scripted input for `sinew view --script FILE`: tests and demos drive the viewer through
// the same handlers as the mouse and keyboard, frame by frame.
//
// One event per line, `<frame> <command> [arguments]`, frames counted from 0 (the first
// picture); `#` starts a comment. Commands:
//   play | pause | step | reset
//   shift down|up                     the picking modifier (left Shift)
//   move X Y                          cursor to pixel (X, Y) from the top-left corner
//   press left|right|middle, release left|right|middle
//   scroll DY                         wheel (positive: zoom in)
//   key C                             Ctrl+Shift+C: a key event sent to the scene
//   screenshot FILE | window-shot FILE   picture of the 3D view | of the window with its panels
//   select NAME                       show the node or component named NAME in the properties
//   report | quit                     print the grab state; stop
#pragma once

#include <string>
#include <vector>

namespace sinew::viewer {

struct ScriptEvent {
  long frame = 0;
  std::string command;
  std::vector<std::string> args;
  int line = 0;
};

// Events of `path` sorted by frame (stable); false with "file:line: reason" in *error.
bool read_input_script(const std::string& path, std::vector<ScriptEvent>& out, std::string* error);

}  // namespace sinew::viewer
