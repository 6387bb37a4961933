// The viewer's state and its parts (internal to src/viewer): viewer.cpp runs the window,
// the input handlers and the frame; panels.cpp draws the Dear ImGui panels.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "render/draw_list.h"
#include "render/gl_renderer.h"
#include "runner/session.h"
#include "viewer/camera_control.h"
#include "viewer/input_script.h"
#include "viewer/mouse_attach.h"
#include "viewer/step_thread.h"
#include "viewer/viewer.h"

struct GLFWwindow;

namespace sinew {
class Base;
}

namespace sinew::viewer {

struct Timings {
  static constexpr int kHistory = 120;
  std::array<float, kHistory> frame_ms{}, step_ms{};
  int cursor = 0;
  double step_total_ms = 0, draw_total_ms = 0;
  std::vector<float> all_step_ms;  // every step's duration, kept for --stats (its median)
  long steps = 0, frames = 0;
  double last_frame_ms = 0, last_step_ms = 0;
};

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& o) : options(o) {}
  // Shows a graph built elsewhere (initialised) instead of loading options.scene.
  void use_root(Node& root) { root_ = &root; }
  int run();
  Node& root() const { return *root_; }

  // ---- what the panels read and change
  ViewerOptions options;
  std::unique_ptr<runner::Session> session;  // null when showing a graph built elsewhere
  std::unique_ptr<render::GlRenderer> gl;
  render::DrawList list;
  render::View view;
  CameraControl camera;
  MouseAttach attach;
  double attach_stiffness = 1000;  // AttachBodyButtonSetting's stiffness when the scene has one
  bool animating = false;
  bool step_once = false;
  bool quit = false;
  int background = 0;  // 0: the scene's (BackgroundSetting, else black), 1 white, 2 black, 3 grey
  Base* selected = nullptr;  // component or node shown in the properties panel
  std::string status;        // one line at the bottom (picking messages, errors)
  Timings timings;
  int screenshot_counter = 0;
  bool log_levels[3] = {false, true, true};  // Log panel: info, warnings, errors
  std::string pending_shot;  // picture of the 3D view to write after this frame's drawing
  std::string window_shot;  // picture of the whole window (panels included) to write after this frame

  void reset_scene();
  bool reload_scene();
  void save_screenshot(const std::string& path);
  void save_camera();
  void save_window_shot(const std::string& path);
  void send_key(char c);
  void select_named(const std::string& name);
  void frame_camera(bool use_view_file);

  // ---- input (window callbacks and scripted events)
  void on_key(int key, int action, int mods);
  void on_button(int button, int action);
  void on_move(double x, double y);
  void on_scroll(double dy);
  void set_shift(bool down);

 private:
  bool open_window(std::string* error);
  bool step();
  bool load(std::string* error);
  void run_script_events(long frame);
  // A frame's picture in two halves: gathered from the scene (precondition: no step running),
  // then drawn from what was gathered (while a step may run).
  bool gather_frame();
  void draw_gathered();
  void draw_frame();  // both halves
  void finish_step();  // waits for the running step, then what follows a step
  void draw_panels();  // panels.cpp
  std::array<float, 4> background_color() const;
  int fb_width() const;
  int fb_height() const;

  Node* root_ = nullptr;
  GLFWwindow* window_ = nullptr;
  std::vector<ScriptEvent> script_;
  std::size_t script_next_ = 0;
  long frame_ = 0;
  // Mouse state: position, the button dragging the camera (-1: none), the picking modifier.
  double mx_ = 0, my_ = 0;
  int drag_button_ = -1;
  bool shift_ = false;
  double grab_depth_ = 0;  // distance along the ray of the grabbed point
  Vec3 bbox_min_ = Vec3::Zero(), bbox_max_ = Vec3::Zero();
  std::array<float, 4> background_{0.f, 0.f, 0.f, 1.f};  // gathered with the picture
  std::unique_ptr<StepThread> stepper_;  // while the window loop runs
  std::size_t printed_ = 0;  // diagnostics printed so far
  int exit_code_ = 0;
};

}  // namespace sinew::viewer
