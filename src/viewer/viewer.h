// `sinew view SCENE`: the interactive viewer (spec/user-interfaces.md §3), a GLFW window
// drawn by the same renderer as `sinew render`, with Dear ImGui panels.
//
// Controls as SOFA's GLFW/ImGui viewer: Space play/pause, Backspace reset (SOFA's reset),
// Ctrl+R reload the file, Esc quit, S screenshot (<scene>_NNNN.png), W save the camera
// (<scene>.view), B background; left-drag turns, right-drag pans, middle-drag and the
// wheel zoom; Shift + left-drag grabs a body with a spring (while playing);
// Ctrl+Shift+key sends a key event to the scene.
#pragma once

#include <string>
#include <vector>

namespace sinew {
class Node;
}

namespace sinew::viewer {

struct ViewerOptions {
  std::string scene;
  std::vector<std::string> data_paths;   // as `sinew run --data-path`
  std::vector<std::string> script_args;  // a Python scene's sys.argv[1:]
  int width = 0, height = 0;             // 0: ViewerSetting's resolution, else 1024×768
  bool play = false;                     // start animating
  long quit_after = 0;                   // frames, 0: run until the window closes
  std::string screenshot;                // picture of the 3D view written when quitting
  std::string input_script;              // scripted input (viewer/input_script.h)
  bool stats = false;                    // print frame and step timings when quitting
  int samples = -1;                      // multisampling; -1: 4, none on a software renderer
};

// Loads options.scene and runs until the window closes; the process exit code.
int run_viewer(const ViewerOptions& options);

// Shows `root`, a graph built and initialised elsewhere (SofaPython3's
// Sofa.Gui.GUIManager.MainLoop); options.scene only names it (title, `.view` file).
// Reload is not available. The exit code as run_viewer's.
int run_viewer_on(Node& root, const ViewerOptions& options);

// Asks the running viewer for a picture of its 3D view after its next frame
// (Sofa.Gui.GUIManager.SaveScreenshot, called by a controller); false when none runs.
bool request_screenshot(const std::string& path);

}  // namespace sinew::viewer
