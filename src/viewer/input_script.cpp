#include "viewer/input_script.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sinew::viewer {

namespace {

// Number of arguments each command takes.
int arity(const std::string& c) {
  if (c == "play" || c == "pause" || c == "step" || c == "reset" || c == "report" || c == "quit") return 0;
  if (c == "shift" || c == "press" || c == "release" || c == "scroll" || c == "key" || c == "screenshot" ||
      c == "window-shot" || c == "select")
    return 1;
  if (c == "move") return 2;
  return -1;
}

bool is_number(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == 0;
}

}  // namespace

bool read_input_script(const std::string& path, std::vector<ScriptEvent>& out, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    if (error) *error = "cannot open the input script " + path;
    return false;
  }
  std::string line;
  int number = 0;
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ":" + std::to_string(number) + ": " + why;
    return false;
  };
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string frame;
    if (!(words >> frame)) continue;  // blank
    ScriptEvent e;
    e.line = number;
    char* end = nullptr;
    e.frame = std::strtol(frame.c_str(), &end, 10);
    if (!end || *end || e.frame < 0) return fail("a line starts with its frame number (>= 0), not '" + frame + "'");
    if (!(words >> e.command)) return fail("a command follows the frame number");
    const int n = arity(e.command);
    if (n < 0) return fail("unknown command '" + e.command + "'");
    for (std::string w; words >> w;) e.args.push_back(w);
    if (static_cast<int>(e.args.size()) != n)
      return fail("'" + e.command + "' takes " + std::to_string(n) + " argument(s)");
    const std::string a0 = n > 0 ? e.args[0] : "";
    if (e.command == "shift" && a0 != "down" && a0 != "up") return fail("shift down|up");
    if ((e.command == "press" || e.command == "release") && a0 != "left" && a0 != "right" && a0 != "middle")
      return fail(e.command + " left|right|middle");
    if (e.command == "move" && (!is_number(e.args[0]) || !is_number(e.args[1]))) return fail("move X Y (pixels)");
    if (e.command == "scroll" && !is_number(a0)) return fail("scroll DY (a number)");
    if (e.command == "key" && a0.size() != 1) return fail("key takes one character");
    out.push_back(std::move(e));
  }
  std::stable_sort(out.begin(), out.end(), [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
  return true;
}

}  // namespace sinew::viewer
