// Components that only a viewer application uses and Sinew's pictures do not draw: window and
// GUI settings, the corner frame (drawn: see render), the visual loop, a matrix image. Each has
// SOFA's Data (unknown attributes are reported as for any component) and does nothing in batch
// runs; `sinew view` reads ViewerSetting's resolution.
#include "core/registry.h"
#include "core/roles.h"
#include "visual/choice.h"
#include "visual/color.h"
#include "visual/drawing/ogl_scene_frame.h"

namespace sinew {

namespace {

// SOFA's DefaultVisualManagerLoop: runs the visual passes; Sinew's viewer and pictures do.
class DefaultVisualManagerLoop final : public VisualComponent {};

// ViewerSetting (Sofa.Component.Setting): the viewer window.
class ViewerSetting final : public VisualComponent {
 public:
  Field<std::vector<int>> resolution{this, "resolution", {800, 600}, "window size (width height)", "Viewer"};
  Field<bool> fullscreen{this, "fullscreen", false, "full-screen window", "Viewer"};
  Field<std::string> camera_mode{this, "cameraMode", "Perspective", "Perspective or Orthographic", "Viewer"};
  Field<std::string> object_picking_method{this, "objectPickingMethod", "Ray casting",
                                           "Ray casting or Selection buffer", "Viewer"};
  Field<bool> show_selected_node_bbox{this, "showSelectedNodeBoundingBox", true,
                                      "show the bounding box of selected nodes", "Viewer"};
  Field<bool> show_selected_object_bbox{this, "showSelectedObjectBoundingBox", true,
                                        "show the bounding box of selected components", "Viewer"};
  Field<bool> show_selected_object_positions{this, "showSelectedObjectPositions", true,
                                             "show the positions of selected components", "Viewer"};
  Field<bool> show_selected_object_surfaces{this, "showSelectedObjectSurfaces", true,
                                            "show the surfaces of selected components", "Viewer"};
  Field<bool> show_selected_object_volumes{this, "showSelectedObjectVolumes", true,
                                           "show the volumes of selected components", "Viewer"};
  Field<bool> show_selected_object_indices{this, "showSelectedObjectIndices", true,
                                           "show the indices of selected components' positions", "Viewer"};
  Field<double> selected_visual_scaling{this, "showSelectedVisualScaling", 0.02,
                                        "scale of the drawing of selected components", "Viewer"};
  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    Component::parse(attrs, diag);
    check_choice(*this, camera_mode, {"Perspective", "Orthographic"}, diag);
    check_choice(*this, object_picking_method, {"Ray casting", "Selection buffer"}, diag);
    const std::vector<int>& r = resolution.value();
    if (r.size() != 2 || r[0] <= 0 || r[1] <= 0)
      diag.error(where, describe() + ": resolution must be two positive integers (width height)");
  }
};

// StatsSetting (Sofa.Component.Setting): what runSofa prints or exports about a run.
class StatsSetting final : public VisualComponent {
 public:
  Field<bool> dump_state{this, "dumpState", false, "dump the state vectors at each step (runSofa)", "Stats"};
  Field<bool> log_time{this, "logTime", false, "print the time of the simulation's stages (runSofa)", "Stats"};
  Field<bool> export_state{this, "exportState", false, "gnuplot files of the states (runSofa)", "Stats"};
  Field<bool> trace_visitors{this, "traceVisitors", false, "trace the visitors' times (runSofa)", "Stats"};
};

// SofaDefaultPathSetting (Sofa.Component.Setting): where runSofa saves its files.
class SofaDefaultPathSetting final : public VisualComponent {
 public:
  Field<std::string> gnuplot_path{this, "gnuplotPath", "", "folder of the gnuplot files", "Stats"};
};

// GlobalSystemMatrixImage (SofaMatrix plugin): an image of a linear system's matrix in the GUI.
class GlobalSystemMatrixImage final : public VisualComponent {
 public:
  Link<Component> linear_system{this, "linearSystem", "the linear system whose matrix is shown"};
};

template <class T>
void add_viewer_component(Registry& r, const char* name, const char* what) {
  ComponentInfo info;
  info.name = name;
  info.category = "Visual";
  info.description = std::string(what) + " (viewer only; no effect in batch runs)";
  info.create = creator<T>();
  r.add(std::move(info));
}

}  // namespace

void register_viewer_only(Registry& r) {
  add_viewer_component<DefaultVisualManagerLoop>(r, "DefaultVisualManagerLoop", "visual update loop of the viewer");
  add_viewer_component<OglSceneFrame>(r, "OglSceneFrame", "axes drawn in a corner of the viewer");
  add_viewer_component<ViewerSetting>(r, "ViewerSetting", "viewer window settings (resolution, fullscreen, picking method)");
  add_viewer_component<GlobalSystemMatrixImage>(r, "GlobalSystemMatrixImage", "image of a linear system's matrix (SofaMatrix plugin)");
  add_viewer_component<StatsSetting>(r, "StatsSetting", "statistics the GUI application prints or exports");
  add_viewer_component<SofaDefaultPathSetting>(r, "SofaDefaultPathSetting", "folders where the GUI application saves records and plots");
}

}  // namespace sinew
