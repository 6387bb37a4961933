// The sinew command line: one function per sub-command.
#pragma once

#include <string>
#include <vector>

namespace sinew::cli {

struct RunArgs {
  std::string scene;
  long steps = 1000;
  std::vector<std::string> data_paths;
  std::string dump_states;
  bool dump_mapped = false;
  bool dump_topology = false;
  std::string vtk;  // write the final state of the first simulated body as legacy VTK
  bool progress = true;
  int threads = 0;
  bool timing = false;  // print where the steps spent their time
  bool haptics_report = false;  // print the haptic loop's period distribution over the run
  std::vector<std::string> script_args;  // a Python scene's sys.argv[1:]
};
int run(const RunArgs& a);

struct RenderArgs {
  std::string scene;
  long steps = 0;
  std::string output = "render.png";
  std::string frames;        // folder for one picture per step (frame_00000.png = initial state)
  std::string size = "800x600";
  std::vector<std::string> data_paths;
  std::vector<std::string> script_args;
};
// Steps a scene and writes off-screen pictures of its visual models (src/render).
int render(const RenderArgs& a);

struct ViewArgs {
  std::string scene;
  bool play = false;
  long quit_after = 0;
  std::string screenshot;
  std::string script;
  std::string size;  // WxH; empty: the scene's ViewerSetting, else 1024x768
  bool stats = false;
  int samples = -1;
  std::vector<std::string> data_paths;
  std::vector<std::string> script_args;
};
// Opens a scene in the interactive viewer (src/viewer).
int view(const ViewArgs& a);

struct CheckArgs {
  std::vector<std::string> scenes;
  std::vector<std::string> data_paths;
  bool tsv = false;  // one line per scene: scene, status, missing components
};
int check(const CheckArgs& a);

int components(const std::string& name);

struct RegressArgs {
  std::string data;
  std::string list;
  std::string filter;
  bool isolate = true;
  double time_limit = 600;
};
int regress(const RegressArgs& a);

// Data folders used when none are given: $SINEW_SOFA_DATA, else ../shared/sofa-data if present.
std::string default_data_root();

}  // namespace sinew::cli
