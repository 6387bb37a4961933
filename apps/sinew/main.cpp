// sinew: run, check and regression-test SOFA scenes.
#include <CLI/CLI.hpp>

#include "commands.h"
#include "module.h"

int main(int argc, char** argv) {
  using namespace sinew::cli;
  // SofaPython3 scenes (.py) run in the command's own embedded interpreter, started on first use.
  sinew::python::register_python_scene_loader();
  CLI::App app{"Sinew: real-time physics for medical simulation; runs SOFA .scn and SofaPython3 .py scenes"};
  app.require_subcommand(1);

  RunArgs run_args;
  std::string gui;
  auto* run_cmd = app.add_subcommand("run", "run a scene in batch mode and print timing (runSofa -g batch)");
  run_cmd->add_option("scene", run_args.scene, "scene file (.scn, .xml or SofaPython3 .py)")->required();
  run_cmd->add_option("-n,--nbIter", run_args.steps, "number of steps (default 1000)");
  run_cmd->add_option("-g,--gui", gui, "accepted for runSofa compatibility: only 'batch' is supported");
  run_cmd->add_option("--data-path", run_args.data_paths, "extra folder searched for meshes and includes");
  run_cmd->add_option("--dump-states", run_args.dump_states,
                      "write SOFA-format state files (<scene>.reference_<k>_<name>_mstate.txt) to this folder");
  run_cmd->add_flag("--dump-mapped", run_args.dump_mapped, "also dump states under mappings");
  run_cmd->add_flag("--dump-topology", run_args.dump_topology,
                    "write SOFA-format topology files (_topology.txt) instead of states");
  run_cmd->add_option("--vtk", run_args.vtk,
                      "write the final state of the first simulated body to this legacy VTK file (ParaView)");
  run_cmd->add_option("--threads", run_args.threads, "worker threads (default: all cores)");
  run_cmd->add_flag("--timing", run_args.timing, "print the time spent in each stage of the steps");
  run_cmd->add_flag("--haptics-report", run_args.haptics_report,
                    "print the haptic servo loop's period distribution (p50, p99, max) over the run");
  run_cmd->add_option("--argv", run_args.script_args, "arguments given to a Python scene (its sys.argv[1:])");
  bool hide_progress = false;
  run_cmd->add_flag("--hideProgressBar", hide_progress, "no progress bar");

  ViewArgs view_args;
  auto* view_cmd = app.add_subcommand("view", "open a scene in the interactive viewer (OpenGL window, Dear ImGui)");
  view_cmd->add_option("scene", view_args.scene, "scene file (.scn, .xml or SofaPython3 .py)")->required();
  view_cmd->add_flag("--play", view_args.play, "start animating at once (else press Space)");
  view_cmd->add_option("--quit-after", view_args.quit_after, "close after this many frames (scripted use)");
  view_cmd->add_option("--screenshot", view_args.screenshot, "PNG of the 3D view written when the viewer closes");
  view_cmd->add_option("--script", view_args.script,
                       "input events to replay, one per line: FRAME COMMAND [ARGS] (docs/viewer.md)");
  view_cmd->add_option("--size", view_args.size, "window size WxH (default: the scene's ViewerSetting, else 1024x768)");
  view_cmd->add_option("--samples", view_args.samples,
                       "multisampling (default 4, none with Mesa's software renderer)");
  view_cmd->add_flag("--stats", view_args.stats, "print frames per second and step times when closing");
  view_cmd->add_option("--data-path", view_args.data_paths, "extra folder searched for meshes and includes");
  view_cmd->add_option("--argv", view_args.script_args, "arguments given to a Python scene (its sys.argv[1:])");

  RenderArgs render_args;
  auto* render_cmd = app.add_subcommand("render", "run a scene and write a picture of it (off-screen OpenGL, no window)");
  render_cmd->add_option("scene", render_args.scene, "scene file (.scn, .xml or SofaPython3 .py)")->required();
  render_cmd->add_option("-n,--nbIter", render_args.steps, "steps before the picture (default 0: the initial state)");
  render_cmd->add_option("-o,--output", render_args.output, "PNG file of the final state (default render.png)");
  render_cmd->add_option("--frames", render_args.frames,
                         "also write one PNG per step to this folder (frame_00000.png is the initial state)");
  render_cmd->add_option("--size", render_args.size, "picture size WxH (default 800x600)");
  render_cmd->add_option("--data-path", render_args.data_paths, "extra folder searched for meshes and includes");
  render_cmd->add_option("--argv", render_args.script_args, "arguments given to a Python scene (its sys.argv[1:])");

  CheckArgs check_args;
  auto* check_cmd = app.add_subcommand("check", "load and initialise scenes; print every problem");
  check_cmd->add_option("scenes", check_args.scenes, "scene files")->required();
  check_cmd->add_option("--data-path", check_args.data_paths, "extra folder searched for meshes and includes");
  check_cmd->add_flag("--tsv", check_args.tsv, "one line per scene: scene, status, missing components");

  std::string component_name;
  auto* comp_cmd = app.add_subcommand("components", "list components with templates, aliases and fields");
  comp_cmd->add_option("name", component_name, "one component (shows its fields)");

  RegressArgs regress_args;
  auto* reg_cmd = app.add_subcommand("regress", "run SOFA regression scenes against their references");
  reg_cmd->add_option("--data", regress_args.data, "SOFA data folder (default ../shared/sofa-data)");
  reg_cmd->add_option("--list", regress_args.list,
                      "a .regression-tests list (default <data>/examples/RegressionStateScenes.regression-tests)");
  reg_cmd->add_option("--filter", regress_args.filter, "only scenes whose path matches this regular expression");
  bool no_isolate = false;
  reg_cmd->add_flag("--no-isolate", no_isolate, "run scenes in this process (no crash isolation)");
  reg_cmd->add_option("--time-limit", regress_args.time_limit, "seconds per scene (default 600)");

  CLI11_PARSE(app, argc, argv);

  if (*run_cmd) {
    if (!gui.empty() && gui != "batch") {
      std::fprintf(stderr, "sinew: GUI '%s' is not available here; use -g batch (or the viewer)\n", gui.c_str());
      return 1;
    }
    run_args.progress = !hide_progress;
    return run(run_args);
  }
  if (*render_cmd) return render(render_args);
  if (*view_cmd) return view(view_args);
  if (*check_cmd) return check(check_args);
  if (*comp_cmd) return components(component_name);
  if (*reg_cmd) {
    regress_args.isolate = !no_isolate;
    return regress(regress_args);
  }
  return 1;
}
