// Sofa.Gui (SofaPython3's GUIManager) on Sinew's viewer: a Python script that builds its
// graph and calls Sofa.Gui.GUIManager.MainLoop(root) gets `sinew view`'s window on it.
#include <cstdlib>
#include <string>

#include "graph.h"
#include "handles.h"
#include "viewer/viewer.h"

namespace sinew::python {

namespace {

// Scripted runs of a Python GUI (tests, demos): the viewer's command-line options from the
// environment, as `sinew view` takes them.
void options_from_environment(viewer::ViewerOptions& o) {
  if (const char* v = std::getenv("SINEW_VIEW_QUIT_AFTER")) o.quit_after = std::atol(v);
  if (const char* v = std::getenv("SINEW_VIEW_SCREENSHOT")) o.screenshot = v;
  if (const char* v = std::getenv("SINEW_VIEW_SCRIPT")) o.input_script = v;
  if (const char* v = std::getenv("SINEW_VIEW_PLAY")) o.play = std::string(v) == "1";
}

}  // namespace

void define_gui(py::module_& m) {
  m.def(
      "gui_main_loop",
      [](NodeHandle& h, const std::string& name, int width, int height) {
        Node& root = *h.node().root();
        viewer::ViewerOptions o;
        o.scene = name;
        o.width = width, o.height = height;
        options_from_environment(o);
        if (o.quit_after < 0) throw py::value_error("SINEW_VIEW_QUIT_AFTER must be >= 0");
        py::gil_scoped_release release;  // Python components take it back when called
        return viewer::run_viewer_on(root, o);
      },
      py::arg("root"), py::arg("name"), py::arg("width") = 0, py::arg("height") = 0,
      "Runs the viewer on an initialised graph until its window closes; the exit code (0: fine).");
  m.def("gui_save_screenshot", &viewer::request_screenshot, py::arg("path"),
        "Asks the running viewer for a picture of its 3D view; False when no viewer runs.");
}

}  // namespace sinew::python
