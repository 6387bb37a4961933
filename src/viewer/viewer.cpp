#include "viewer/viewer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <utility>

#ifdef __linux__
#include <sys/resource.h>
#endif

#include "core/diagnostics.h"
#include "core/node.h"
#include "core/simulation.h"
#include "imgui.h"
#include "imgui_impl_glfw.h"
#include "imgui_impl_opengl3.h"
#include "render/draw_text.h"
#include "render/material.h"
#include "render/png_io.h"
#include "viewer/picking.h"
#include "viewer/view_file.h"
#include "viewer/viewer_app.h"
#include "visual/background_setting.h"
#include "visual/recorded_camera.h"

namespace sinew::viewer {

namespace {

std::string glfw_error;  // the last GLFW error, for the message when no window opens
ViewerApp* running = nullptr;  // the viewer in this process's window loop (one at a time)
// A picture asked for by the scene (request_screenshot), from the step's thread.
std::mutex requested_shot_mutex;
std::string requested_shot;

std::string take_requested_shot() {
  std::lock_guard lock(requested_shot_mutex);
  return std::exchange(requested_shot, {});
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

ViewerApp* app_of(GLFWwindow* w) { return static_cast<ViewerApp*>(glfwGetWindowUserPointer(w)); }

std::string basename_of(const std::string& p) {
  const auto slash = p.find_last_of('/');
  std::string b = slash == std::string::npos ? p : p.substr(slash + 1);
  if (const auto dot = b.find_last_of('.'); dot != std::string::npos && dot > 0) b.resize(dot);
  return b;
}

// Reads a field of the first component of class `cls` as text (the GUI settings components).
std::string setting_text(Node& root, const char* cls, const char* field) {
  std::string out;
  for_each_node(root, [&](Node& n) {
    if (!out.empty()) return;
    for (const auto& o : n.objects())
      if (o->class_name() == cls)
        if (const BaseField* f = o->find_field(field)) {
          out = f->text();
          return;
        }
  });
  return out;
}

// AttachBodyButtonSetting's stiffness, else SOFA's default 1000.
double stiffness_setting(Node& root) {
  const std::string k = setting_text(root, "AttachBodyButtonSetting", "stiffness");
  return k.empty() ? 1000.0 : std::atof(k.c_str());
}

// Mesa's software renderer rasterises on threads of its own ("llvmpipe-N"), and they run while
// the step thread steps (the previous state is drawn meanwhile). Lowered below the step, they
// leave it the CPU it needs: on two cores the step then runs as fast as with nothing drawn
// (docs/viewer.md). Mesa lowers its own shader-cache thread the same way. Raising a thread's
// nice value needs no privilege; nothing to do on a GPU or off Linux.
void yield_renderer_threads_to_the_step() {
#ifdef __linux__
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    if (!std::getline(comm, name) || name.rfind("llvmpipe-", 0) != 0) continue;
    const int tid = std::atoi(task.path().filename().c_str());
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(tid));
    if (errno == 0 && nice < 5) setpriority(PRIO_PROCESS, static_cast<id_t>(tid), 5);
  }
#endif
}

double median(std::vector<float> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

void print_new_messages(const Diagnostics& d, std::size_t& printed) {
  const auto& all = d.messages();
  for (; printed < all.size(); ++printed)
    if (all[printed].severity != Severity::info)
      std::fprintf(stderr, "%s\n", Diagnostics::format(all[printed]).c_str());
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
  ViewerApp app(options);
  return app.run();
}

bool request_screenshot(const std::string& path) {
  std::lock_guard lock(requested_shot_mutex);
  if (!running) return false;
  requested_shot = path;
  return true;
}

int run_viewer_on(Node& root, const ViewerOptions& options) {
  ViewerApp app(options);
  app.use_root(root);
  return app.run();
}

bool ViewerApp::open_window(std::string* error) {
  glfwSetErrorCallback([](int, const char* what) { glfw_error = what ? what : ""; });
  if (!glfwInit()) {
    *error = "cannot open a window (" + glfw_error + "); without a display, run it under xvfb-run, or use " +
             "`sinew render` for pictures";
    return false;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  // Not forward-compatible: such contexts refuse wide lines (glLineWidth above 1).
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);
  int w = options.width, h = options.height;
  if (w <= 0 || h <= 0) {  // ViewerSetting's resolution, else 1024×768
    w = 1024, h = 768;
    int rw = 0, rh = 0;
    if (std::sscanf(setting_text(root(), "ViewerSetting", "resolution").c_str(), "%d %d", &rw, &rh) == 2 &&
        rw > 0 && rh > 0 && rw <= 16384 && rh <= 16384)
      w = rw, h = rh;
  }
  window_ = glfwCreateWindow(w, h, ("Sinew - " + options.scene).c_str(), nullptr, nullptr);
  if (!window_) {
    *error = "cannot create an OpenGL 3.3 window (" + glfw_error + ")";
    return false;
  }
  glfwMakeContextCurrent(window_);
  yield_renderer_threads_to_the_step();
  // Scripted runs measure and finish as fast as they can; people get the display's rate.
  glfwSwapInterval(options.quit_after > 0 || !options.input_script.empty() ? 0 : 1);
  glfwSetWindowUserPointer(window_, this);
  // Sinew's handlers first: Dear ImGui installs its own and chains to these.
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (!ImGui::GetIO().WantCaptureKeyboard || key == GLFW_KEY_LEFT_SHIFT) app_of(w)->on_key(key, action, mods);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (action == GLFW_RELEASE || !ImGui::GetIO().WantCaptureMouse) app_of(w)->on_button(button, action);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) { app_of(w)->on_move(x, y); });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    if (!ImGui::GetIO().WantCaptureMouse) app_of(w)->on_scroll(dy);
  });

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written into the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  // Multisampling: 4× on a GPU; none on Mesa's software renderers, where 4× halves the frame rate.
  int samples = options.samples;
  if (samples < 0) {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string r = renderer ? renderer : "";
    const bool software = r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos;
    samples = software ? 0 : 4;
  }
  gl = render::GlRenderer::create(std::max(fb_width(), 1), std::max(fb_height(), 1), samples, error);
  if (gl) gl->set_font(runner::find_data_file(options.data_paths, render::kFontFile));
  return gl != nullptr;
}

int ViewerApp::fb_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int ViewerApp::fb_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

bool ViewerApp::load(std::string* error) {
  runner::SessionOptions so;
  so.data_paths = options.data_paths;
  so.script_args = options.script_args;
  auto s = std::make_unique<runner::Session>(options.scene, so);
  std::size_t printed = 0;
  print_new_messages(s->diagnostics(), printed);
  if (!s->ok()) {
    *error = "the scene " + options.scene + " cannot run (see the errors above)";
    return false;
  }
  attach.stop();
  selected = nullptr;
  session = std::move(s);
  root_ = &session->root();
  list = {};  // its batches name the old graph's components
  attach_stiffness = stiffness_setting(root());
  return true;
}

namespace {

// The scene's box: the root's `bbox` when set, else what is drawn (the unit box when nothing
// is; a point grows to a unit cube).
void scene_box(const Node& root, const render::DrawList& list, Vec3& min, Vec3& max) {
  min = list.has_bounds ? list.min : Vec3::Zero(), max = list.has_bounds ? list.max : Vec3::Ones();
  if (const auto& b = root.bbox.get(); b.size() == 6 && b[0] <= b[3] && b[1] <= b[4] && b[2] <= b[5])
    min = Vec3(b[0], b[1], b[2]), max = Vec3(b[3], b[4], b[5]);
  if (min == max) min -= Vec3::Constant(0.5), max += Vec3::Constant(0.5);
}

}  // namespace

void ViewerApp::frame_camera(bool use_view_file) {
  Node& root = this->root();
  render::gather(root, list);
  Vec3 min, max;
  scene_box(root, list, min, max);
  bbox_min_ = min, bbox_max_ = max;
  render::CameraFrame f = render::camera_frame(root, min, max);
  if (use_view_file)
    if (const std::string vf = view_file_for(options.scene); !vf.empty()) {
      std::string err;
      if (auto read = read_view_file(vf, &err)) f = *read;
      else std::fprintf(stderr, "sinew view: %s (camera file ignored)\n", err.c_str());
    }
  camera.reset(f, navigation_of(root));
  camera.set_scene_box(min, max);
}

bool ViewerApp::step() {
  if (session) return session->step();
  // A graph built by a script (Sofa.Gui.GUIManager.MainLoop): stepped as Sofa.Simulation.animate does.
  Node& r = root();
  if (r.diagnostics().has_errors()) return false;
  try {
    r.step_index = static_cast<long>(r.step_index + 1);
    animate(r);
  } catch (const std::exception& e) {
    r.diagnostics().error({}, std::string("step failed: ") + e.what());
    return false;
  }
  return !r.diagnostics().has_errors();
}

void ViewerApp::reset_scene() {
  attach.stop();
  reset_root(root());
  status = "reset to the initial state";
}

bool ViewerApp::reload_scene() {
  if (!session) {
    status = "this graph was built by a script: nothing to reload";
    return false;
  }
  std::string err;
  if (!load(&err)) {
    status = err;
    return false;
  }
  frame_camera(true);  // as when opened: the scene's camera, then its .view file
  status = "reloaded " + options.scene;
  return true;
}

void ViewerApp::save_screenshot(const std::string& path) {
  render::Image image;
  gl->read(image);
  std::string err;
  if (render::write_png(path, image, &err)) status = "screenshot written to " + path;
  else status = err;
  std::printf("sinew view: %s\n", status.c_str());
}

void ViewerApp::save_window_shot(const std::string& path) {
  render::Image image;
  image.width = fb_width(), image.height = fb_height();
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  std::vector<std::uint8_t> rows(row * image.height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  image.rgba.resize(rows.size());
  for (int y = 0; y < image.height; ++y)  // GL's first row is the bottom one
    std::copy_n(&rows[(image.height - 1 - y) * row], row, &image.rgba[y * row]);
  std::string err;
  status = render::write_png(path, image, &err) ? "window picture written to " + path : err;
  std::printf("sinew view: %s\n", status.c_str());
}

void ViewerApp::save_camera() {
  const std::string path = options.scene + ".view";
  std::string err;
  status = write_view_file(path, camera.frame(), &err) ? "camera saved to " + path : err;
}

void ViewerApp::select_named(const std::string& name) {
  selected = nullptr;
  for_each_node(root(), [&](Node& n) {
    if (selected) return;
    if (n.name.get() == name) selected = &n;
    else if (Component* c = n.find_object_named(name)) selected = c;
  });
  if (!selected) status = "nothing named " + name;
}

void ViewerApp::send_key(char c) {
  Event e{Event::Kind::key_pressed};
  e.key = c;
  propagate_event(root(), e);
  Event r{Event::Kind::key_released};
  r.key = c;
  propagate_event(root(), r);
}

// ------------------------------------------------------------------ input

void ViewerApp::set_shift(bool down) {
  shift_ = down;
  if (!down && attach.active()) attach.stop();  // releasing Shift first also ends picking
}

void ViewerApp::on_key(int key, int action, int mods) {
  if (key == GLFW_KEY_LEFT_SHIFT) {
    if (action == GLFW_PRESS) set_shift(true);
    if (action == GLFW_RELEASE) set_shift(false);
    return;
  }
  if (action != GLFW_PRESS) return;
  const bool ctrl = mods & GLFW_MOD_CONTROL, shift = mods & GLFW_MOD_SHIFT;
  if (ctrl && shift && key >= GLFW_KEY_A && key <= GLFW_KEY_Z) {
    send_key(static_cast<char>('a' + (key - GLFW_KEY_A)));
    return;
  }
  switch (key) {
    case GLFW_KEY_SPACE: animating = !animating; break;
    case GLFW_KEY_BACKSPACE: reset_scene(); break;
    case GLFW_KEY_ESCAPE: quit = true; break;
    case GLFW_KEY_R:
      if (ctrl) reload_scene();
      break;
    case GLFW_KEY_S: {
      char name[32];
      std::snprintf(name, sizeof name, "_%04d.png", screenshot_counter++);
      save_screenshot(basename_of(options.scene) + name);
      break;
    }
    case GLFW_KEY_W: save_camera(); break;
    case GLFW_KEY_B: background = (background + 1) % 4; break;
    default: break;
  }
}

void ViewerApp::on_button(int button, int action) {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  if (action == GLFW_RELEASE) {
    if (button == GLFW_MOUSE_BUTTON_LEFT && attach.active()) {
      const Vec3 a = attach.attached_point(), t = attach.target();
      std::printf("sinew view: released at (%.6g %.6g %.6g), mouse at (%.6g %.6g %.6g)\n", a[0], a[1], a[2], t[0],
                  t[1], t[2]);
      attach.stop();
    }
    if (button == drag_button_) {
      drag_button_ = -1;
      camera.release();
    }
    return;
  }
  if (shift_ && button == GLFW_MOUSE_BUTTON_LEFT) {
    if (!animating) {  // as SofaGLFW: nothing moves while paused
      status = "Animation is not running: press Space, then grab";
      return;
    }
    const Ray ray = ray_through(view, mx_, my_, w, h);
    const Pick p = pick(root(), list, ray, 0.02 * (bbox_max_ - bbox_min_).norm());
    std::string why;
    if (!p) {
      status = "nothing to grab under the cursor";
    } else if (attach.start(p, attach_stiffness, &why)) {
      grab_depth_ = p.distance;
      const Vec3 a = attach.attached_point();
      char text[96];
      std::snprintf(text, sizeof text, "grabbed: spring of stiffness %g", attach_stiffness);
      status = text;
      std::printf("sinew view: grabbed %s at (%.6g %.6g %.6g)\n",
                  p.on == Pick::On::collision_element ? "a collision element" : "a particle", a[0], a[1], a[2]);
    } else {
      status = why;
    }
    return;
  }
  drag_button_ = button;
  if (camera.navigation().law == Navigation::Law::none)
    status = "the scene's Camera does not follow the mouse (as SOFA's); InteractiveCamera does";
  using Mode = CameraControl::Mode;
  camera.press(button == GLFW_MOUSE_BUTTON_LEFT    ? Mode::trackball
               : button == GLFW_MOUSE_BUTTON_RIGHT ? Mode::pan
               : button == GLFW_MOUSE_BUTTON_MIDDLE ? Mode::zoom
                                                    : Mode::none,
               mx_, my_);
}

void ViewerApp::on_move(double x, double y) {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  mx_ = x, my_ = y;
  if (attach.active()) {
    const Ray ray = ray_through(view, x, y, w, h);
    attach.move(ray.origin + grab_depth_ * ray.dir);
    return;
  }
  if (drag_button_ >= 0) camera.move(x, y, w, h);
}

void ViewerApp::on_scroll(double dy) {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  camera.wheel(dy, h);
}

void ViewerApp::run_script_events(long frame) {
  static const auto button_of = [](const std::string& b) {
    return b == "left" ? GLFW_MOUSE_BUTTON_LEFT : b == "right" ? GLFW_MOUSE_BUTTON_RIGHT : GLFW_MOUSE_BUTTON_MIDDLE;
  };
  for (; script_next_ < script_.size() && script_[script_next_].frame <= frame; ++script_next_) {
    const ScriptEvent& e = script_[script_next_];
    const std::string a0 = e.args.empty() ? "" : e.args[0];
    if (e.command == "play") animating = true;
    else if (e.command == "pause") animating = false;
    else if (e.command == "step") step_once = true;
    else if (e.command == "reset") reset_scene();
    else if (e.command == "shift") set_shift(a0 == "down");
    else if (e.command == "move") on_move(std::atof(e.args[0].c_str()), std::atof(e.args[1].c_str()));
    else if (e.command == "press") on_button(button_of(a0), GLFW_PRESS);
    else if (e.command == "release") on_button(button_of(a0), GLFW_RELEASE);
    else if (e.command == "scroll") on_scroll(std::atof(a0.c_str()));
    else if (e.command == "key") send_key(a0[0]);
    else if (e.command == "screenshot") save_screenshot(a0);
    else if (e.command == "window-shot") window_shot = a0;
    else if (e.command == "select") select_named(a0);
    else if (e.command == "quit") quit = true;
    else if (e.command == "report") {
      if (attach.active()) {
        const Vec3 a = attach.attached_point(), t = attach.target();
        std::printf("sinew view: frame %ld: grabbed point at (%.6g %.6g %.6g), mouse at (%.6g %.6g %.6g)\n", frame,
                    a[0], a[1], a[2], t[0], t[1], t[2]);
      } else {
        std::printf("sinew view: frame %ld: nothing grabbed (%s)\n", frame, status.c_str());
      }
    }
  }
}

std::array<float, 4> ViewerApp::background_color() const {
  switch (background) {
    case 1: return {1.f, 1.f, 1.f, 1.f};
    case 2: return {0.f, 0.f, 0.f, 1.f};
    case 3: return {0.5f, 0.5f, 0.5f, 1.f};
    default: break;
  }
  if (const auto* bg = root().find_down<BackgroundSetting>())
    if (auto c = render::parse_color(bg->color.get())) return {(*c)[0], (*c)[1], (*c)[2], 1.f};
  return {0.f, 0.f, 0.f, 1.f};
}

bool ViewerApp::gather_frame() {
  const int w = fb_width(), h = fb_height();
  if (w <= 0 || h <= 0) return false;  // minimised
  std::string err;
  if (!gl->resize(w, h, &err)) {
    status = err;
    return false;
  }
  Node& root = this->root();
  render::gather(root, list);
  // The camera's scene box follows the scene, as SofaGLFW hands the root's box to the camera
  // every frame (the mouse's scene pivot and zoom and pan speeds).
  Vec3 box_min, box_max;
  scene_box(root, list, box_min, box_max);
  camera.set_scene_box(box_min, box_max);
  // Clip planes from what is drawn now and the box framed at loading.
  Vec3 min = bbox_min_, max = bbox_max_;
  if (list.has_bounds) min = min.cwiseMin(list.min), max = max.cwiseMax(list.max);
  view = render::view_of(camera.frame(), root, min, max, w, h);
  background_ = background_color();
  if (background != 0) list.background_image.clear();  // B chose a plain colour over the scene's image
  return true;
}

void ViewerApp::draw_gathered() {
  gl->draw(list, view, background_);
  gl->present(fb_width(), fb_height());
}

void ViewerApp::draw_frame() {
  if (gather_frame()) draw_gathered();
}

void ViewerApp::finish_step() {
  double ms = 0;
  bool ok = false;
  try {
    ok = stepper_->wait(&ms);
  } catch (const std::exception& e) {  // step() reports its own failures; this is a last resort
    root().diagnostics().error({}, std::string("step failed: ") + e.what());
  }
  timings.last_step_ms = ms;
  timings.step_total_ms += ms;
  ++timings.steps;
  timings.step_ms[timings.cursor] = static_cast<float>(ms);
  if (options.stats) timings.all_step_ms.push_back(static_cast<float>(ms));
  print_new_messages(root().diagnostics(), printed_);
  // A screenshot asked for by the scene during the step: the next picture shows its state.
  if (std::string shot = take_requested_shot(); !shot.empty()) pending_shot = std::move(shot);
  // A RecordedCamera moves with the simulation; SOFA's viewer draws through it.
  if (const auto* rc = root().find_down<RecordedCamera>();
      ok && rc && rc->activated.get() && (rc->rotation_mode.get() || rc->translation_mode.get() || rc->navigation_mode.get()))
    camera.reset(render::camera_frame(root(), bbox_min_, bbox_max_), navigation_of(root()));
  if (!ok) {
    animating = false;
    attach.stop();
    status = "the step failed: see the messages in the terminal";
    exit_code_ = 1;
  }
}

int ViewerApp::run() {
  std::string err;
  if (!options.input_script.empty() && !read_input_script(options.input_script, script_, &err)) {
    std::fprintf(stderr, "sinew: %s\n", err.c_str());
    return 1;
  }
  if (!root_ && !load(&err)) {
    std::fprintf(stderr, "sinew: %s\n", err.c_str());
    return 1;
  }
  if (root_ && !session) attach_stiffness = stiffness_setting(root());
  if (!open_window(&err)) {
    std::fprintf(stderr, "sinew: %s\n", err.c_str());
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
    return 1;
  }
  frame_camera(true);
  running = this;
  animating = options.play;
  printed_ = root().diagnostics().messages().size();
  stepper_ = std::make_unique<StepThread>([this] { return step(); });
  const auto start = Clock::now();
  // Each frame: input and panels (they may change the scene), the picture's data gathered from
  // the scene, then the step runs on its thread while that picture is drawn; the frame ends
  // once both are done, so nothing else ever touches the scene during a step.
  bool drawn_after_step = true;  // the last picture shows the current state
  while (!quit && !glfwWindowShouldClose(window_)) {
    const auto t_frame = Clock::now();
    glfwPollEvents();
    // The view the input sees is this frame's camera (the clip planes follow at gathering).
    view = render::view_of(camera.frame(), root(), bbox_min_, bbox_max_, std::max(fb_width(), 1),
                           std::max(fb_height(), 1));
    run_script_events(frame_);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    draw_panels();
    ImGui::Render();
    // A picture the scene asked for outside a step (a key handler): this frame's.
    if (std::string shot = take_requested_shot(); !shot.empty()) pending_shot = std::move(shot);
    const bool drawable = gather_frame();
    const bool stepping = animating || step_once;
    step_once = false;
    if (stepping) stepper_->start();
    const auto t_draw = Clock::now();
    if (drawable) {
      draw_gathered();
      if (!pending_shot.empty()) {
        save_screenshot(pending_shot);
        pending_shot.clear();
      }
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!window_shot.empty()) {
      save_window_shot(window_shot);
      window_shot.clear();
    }
    glfwSwapBuffers(window_);
    // Mesa's software renderer draws on its own threads: the frame's picture is finished
    // before the next frame's input and gathering.
    glFinish();
    timings.draw_total_ms += ms_since(t_draw);
    if (stepping) finish_step();
    drawn_after_step = drawable && !stepping;
    timings.last_frame_ms = ms_since(t_frame);
    timings.frame_ms[timings.cursor] = static_cast<float>(timings.last_frame_ms);
    timings.cursor = (timings.cursor + 1) % Timings::kHistory;
    ++timings.frames;
    ++frame_;
    if (options.quit_after > 0 && frame_ >= options.quit_after) quit = true;
  }
  const double wall = ms_since(start) / 1000.0;
  stepper_.reset();
  // The last step ran while the state before it was drawn: pictures taken now show its state.
  if (!drawn_after_step && (!options.screenshot.empty() || !pending_shot.empty())) draw_frame();
  if (!pending_shot.empty()) save_screenshot(pending_shot);
  if (!options.screenshot.empty()) save_screenshot(options.screenshot);
  if (options.stats) {
    std::printf("frames %ld in %.3f s: %.1f frames/s\n", timings.frames, wall, wall > 0 ? timings.frames / wall : 0);
    std::printf("steps %ld: %.3f ms/step (median %.3f)\n", timings.steps,
                timings.steps ? timings.step_total_ms / timings.steps : 0.0, median(timings.all_step_ms));
    std::printf("drawing: %.3f ms/frame\n", timings.frames ? timings.draw_total_ms / timings.frames : 0.0);
  }
  running = nullptr;
  attach.stop();
  gl.reset();  // GL objects go while the context exists
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
  return exit_code_;
}

}  // namespace sinew::viewer
