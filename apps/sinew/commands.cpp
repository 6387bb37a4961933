#include "commands.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <set>

#include <oneapi/tbb/global_control.h>

#include "components/register_all.h"
#include "core/interrupt.h"
#include "core/node.h"
#include "core/registry.h"
#include "core/profile.h"
#include "haptics/haptics_report.h"
#include "haptics/servo_loop.h"
#include "io/vtk_writer.h"
#include "regression/gzip_text.h"
#include "render/draw_text.h"
#include "render/offscreen.h"
#include "render/png_io.h"
#include "runner/probes.h"
#include "runner/regress.h"
#include "runner/session.h"
#include "viewer/viewer.h"

namespace sinew::cli {

namespace {

bool is_dir(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string basename_of(const std::string& p) {
  const auto slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

// Prints the messages from index `from` on (those not printed yet).
void print_messages(const Diagnostics& d, bool include_info = false, std::size_t from = 0) {
  const auto& all = d.messages();
  for (std::size_t i = from; i < all.size(); ++i)
    if (include_info || all[i].severity != Severity::info)
      std::fprintf(stderr, "%s\n", Diagnostics::format(all[i]).c_str());
}

std::vector<std::string> data_paths_for(const std::vector<std::string>& extra) {
  std::vector<std::string> paths = extra;
  const std::string root = default_data_root();
  if (!root.empty())
    for (const auto& p : runner::sofa_data_paths(root)) paths.push_back(p);
  return paths;
}

class ProgressBar {
 public:
  ProgressBar(long total, bool enabled) : total_(total), enabled_(enabled && ::isatty(1)) {}
  void update(long done) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done != total_ && now - last_ < std::chrono::milliseconds(33)) return;
    last_ = now;
    const int width = 50;
    const int fill = total_ > 0 ? static_cast<int>(width * done / total_) : width;
    std::printf("\r[%s%s] %ld/%ld", std::string(fill, '#').c_str(), std::string(width - fill, ' ').c_str(), done,
                total_);
    if (done == total_) std::printf("\n");
    std::fflush(stdout);
  }

 private:
  long total_;
  bool enabled_;
  std::chrono::steady_clock::time_point last_{};
};

// Final state of the first simulated Vec3 body, with the cells of its topology.
bool export_vtk(Node& root, const std::string& path) {
  for (const auto& t : runner::select_states(root, false)) {
    if (t.state->state_type() != StateType::vec3) continue;
    io::VtkMesh mesh;
    const auto x = as_vec3(t.state->read(kPosition));
    const auto v = as_vec3(t.state->read(kVelocity));
    mesh.points.assign(x.begin(), x.end());
    mesh.point_vectors.emplace_back("velocity", std::vector<Vec3>(v.begin(), v.end()));
    if (MeshTopologyBase* topo = t.node->get_mesh_topology_link(); topo && topo->nb_points() == x.size()) {
      if (!topo->hexahedra().empty() || !topo->tetrahedra().empty()) {
        mesh.hexahedra = topo->hexahedra();
        mesh.tetrahedra = topo->tetrahedra();
      } else if (!topo->triangles().empty() || !topo->quads().empty()) {
        mesh.triangles = topo->triangles();
        mesh.quads = topo->quads();
      } else {
        mesh.edges = topo->edges();
      }
    }
    std::string err;
    if (!io::write_vtk(path, mesh, "sinew: " + t.state->describe(), &err)) {
      std::fprintf(stderr, "sinew: %s\n", err.c_str());
      return false;
    }
    std::printf("Final state of %s written to %s\n", t.state->describe().c_str(), path.c_str());
    return true;
  }
  std::fprintf(stderr, "sinew: no simulated Vec3d body to export\n");
  return false;
}

// Stage table, then the solvers' own scopes ("solve/forces", ...).
void print_profile(const StepProfile& p) {
  const long n = p.steps();
  if (n == 0) return;
  std::printf("%-40s %12s %10s %8s\n", "stage", "total (ms)", "ms/step", "calls");
  std::printf("%-40s %12.2f %10.3f %8ld\n", "step", 1000.0 * p.step_seconds(), 1000.0 * p.step_seconds() / n, n);
  for (int i = 0; i < kStageCount; ++i) {
    const Stage s = static_cast<Stage>(i);
    const std::string name = std::string("step/") + stage_name(s);
    std::printf("%-40s %12.2f %10.3f %8ld\n", name.c_str(), 1000.0 * p.stage_seconds(s), 1000.0 * p.stage_seconds(s) / n,
                n);
  }
  for (const auto& e : p.scopes())
    std::printf("%-40s %12.2f %10.3f %8ld\n", e.name.c_str(), 1000.0 * e.seconds, 1000.0 * e.seconds / n, e.count);
}

// Ctrl-C during `sinew run`: the current step finishes (long CG loops stop
// early), the run reports and exits non-zero. A second Ctrl-C kills as usual.
void on_interrupt(int) { request_interrupt(); }

class InterruptHandler {
 public:
  InterruptHandler() {
    clear_interrupt();
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    installed_ = ::sigaction(SIGINT, &sa, &previous_) == 0;
  }
  ~InterruptHandler() {
    if (installed_) ::sigaction(SIGINT, &previous_, nullptr);
  }

 private:
  struct sigaction previous_ {};
  bool installed_ = false;
};

// Steps `session` `steps` times under a Ctrl-C handler, calling after(k) once step k is done;
// after() returning false stops the loop. Shared by `run` and `render`.
enum class LoopEnd { done, step_failed, stopped, interrupted };
LoopEnd step_loop(runner::Session& session, long steps, const std::function<bool(long)>& after) {
  InterruptHandler on_sigint;
  for (long i = 0; i < steps; ++i) {
    if (!session.step()) return LoopEnd::step_failed;
    if (!after(i + 1)) return LoopEnd::stopped;
    if (interrupt_requested()) {
      std::fflush(stdout);
      std::fprintf(stderr, "sinew: interrupted after %ld of %ld steps\n", session.steps_done(), steps);
      return LoopEnd::interrupted;
    }
  }
  return LoopEnd::done;
}

}  // namespace

std::string default_data_root() {
  if (const char* env = std::getenv("SINEW_SOFA_DATA"); env && is_dir(env)) return env;
  if (is_dir("../shared/sofa-data")) return "../shared/sofa-data";
  return {};
}

int run(const RunArgs& a) {
  std::unique_ptr<tbb::global_control> threads;
  if (a.threads > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, a.threads);
  runner::SessionOptions so;
  so.data_paths = data_paths_for(a.data_paths);
  so.script_args = a.script_args;
  runner::Session session(a.scene, so);
  print_messages(session.diagnostics());
  const std::size_t printed = session.diagnostics().messages().size();
  if (!session.ok()) {
    std::fprintf(stderr, "sinew: the scene %s cannot run (see the errors above)\n", a.scene.c_str());
    return 1;
  }
  Node& root = session.root();

  // Probes writing SOFA-format files, attached after init as SOFA's harness does.
  std::vector<std::pair<std::string, const std::string*>> dumps;
  if (!a.dump_states.empty()) {
    if (!is_dir(a.dump_states)) {
      std::fprintf(stderr, "sinew: --dump-states folder %s does not exist\n", a.dump_states.c_str());
      return 1;
    }
    const std::string base = a.dump_states + "/" + basename_of(a.scene) + ".reference";
    if (a.dump_topology) {
      for (const auto& t : runner::select_topologies(root, a.dump_mapped)) {
        auto* p = static_cast<runner::TopologyWriterProbe*>(
            t.node->add_object(std::make_unique<runner::TopologyWriterProbe>(t.topology)));
        dumps.emplace_back(base + runner::topology_file_suffix(t), &p->text());
      }
    } else {
      for (const auto& t : runner::select_states(root, a.dump_mapped)) {
        auto* p = static_cast<runner::StateWriterProbe*>(
            t.node->add_object(std::make_unique<runner::StateWriterProbe>(t.state)));
        dumps.emplace_back(base + runner::state_file_suffix(t), &p->text());
      }
    }
  }

  StepProfile& profile = root.profile();
  profile.set_enabled(a.timing);
  std::printf("Computing %ld iterations.\n", a.steps);
  ProgressBar bar(a.steps, a.progress);
  const auto t0 = std::chrono::steady_clock::now();
  const std::int64_t haptics_from = haptics::ServoLoop::now_ns();
  const LoopEnd end = step_loop(session, a.steps, [&](long done) {
    bar.update(done);
    return true;
  });
  const std::int64_t haptics_to = haptics::ServoLoop::now_ns();
  bool ok = end == LoopEnd::done;
  const bool interrupted = end == LoopEnd::interrupted;
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long done = session.steps_done();
  std::printf("%ld iterations done in %g s ( %g FPS).\n", done, secs, secs > 0 ? done / secs : 0.0);
  if (done > 0) std::printf("%.3f ms/step\n", 1000.0 * secs / done);
  if (a.timing && done > 0) print_profile(profile);
  if (a.haptics_report) std::fputs(haptics::haptics_report(root, haptics_from, haptics_to).c_str(), stdout);
  for (const auto& [file, text] : dumps) {
    std::string err;
    if (!regression::write_text_file(file, *text, false, &err)) {
      std::fprintf(stderr, "sinew: cannot write %s: %s\n", file.c_str(), err.c_str());
      ok = false;
    }
  }
  if (!a.vtk.empty() && !export_vtk(root, a.vtk)) ok = false;
  // The scene is closed here (exporters with exportAtEnd write now) so that what it
  // reports is printed below.
  session.close();
  // Messages of the run (solver warnings, step errors), printed once.
  print_messages(session.diagnostics(), false, printed);
  if (interrupted) return 130;
  return ok ? 0 : 1;
}

int render(const RenderArgs& a) {
  int width = 0, height = 0;
  char tail = 0;
  if (std::sscanf(a.size.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width <= 0 || height <= 0) {
    std::fprintf(stderr, "sinew: --size must be WIDTHxHEIGHT (e.g. 800x600), not '%s'\n", a.size.c_str());
    return 1;
  }
  if (a.steps < 0) {
    std::fprintf(stderr, "sinew: the number of steps must be >= 0\n");
    return 1;
  }
  if (!a.frames.empty() && !is_dir(a.frames)) {
    std::fprintf(stderr, "sinew: --frames folder %s does not exist\n", a.frames.c_str());
    return 1;
  }
  // The GL context first: without one there is no point in loading the scene.
  render::RenderOptions ro;
  ro.width = width, ro.height = height;
  std::string err;
  auto renderer = render::OffscreenRenderer::create(ro, &err);
  if (!renderer) {
    std::fprintf(stderr, "sinew: %s\n", err.c_str());
    return 1;
  }
  runner::SessionOptions so;
  so.data_paths = data_paths_for(a.data_paths);
  so.script_args = a.script_args;
  renderer->set_font(runner::find_data_file(so.data_paths, render::kFontFile));
  runner::Session session(a.scene, so);
  print_messages(session.diagnostics());
  std::size_t printed = session.diagnostics().messages().size();
  if (!session.ok()) {
    std::fprintf(stderr, "sinew: the scene %s cannot run (see the errors above)\n", a.scene.c_str());
    return 1;
  }
  Node& root = session.root();
  // The view is framed on the loaded scene, as a viewer does: bodies move in the pictures.
  if (!renderer->frame(root, &err)) {
    std::fprintf(stderr, "sinew: %s\n", err.c_str());
    return 1;
  }
  render::Image image;
  auto picture = [&](const std::string& path) {
    if (!renderer->render(root, image, &err) || !render::write_png(path, image, &err)) {
      std::fprintf(stderr, "sinew: %s\n", err.c_str());
      return false;
    }
    return true;
  };
  auto frame_path = [&](long k) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%05ld.png", k);
    return a.frames + name;
  };
  if (!a.frames.empty() && !picture(frame_path(0))) return 1;
  const LoopEnd end =
      step_loop(session, a.steps, [&](long done) { return a.frames.empty() || picture(frame_path(done)); });
  if (end == LoopEnd::stopped) return 1;  // a frame could not be written (said above)
  const bool ok = end == LoopEnd::done;
  print_messages(session.diagnostics(), false, printed);
  if (!picture(a.output)) return 1;
  std::printf("%s: %ld steps, picture %dx%d written to %s (%s)\n", a.scene.c_str(), session.steps_done(), width,
              height, a.output.c_str(), renderer->gl_description().c_str());
  return ok ? 0 : 1;
}

int view(const ViewArgs& a) {
  viewer::ViewerOptions o;
  o.scene = a.scene;
  o.data_paths = data_paths_for(a.data_paths);
  o.script_args = a.script_args;
  o.play = a.play;
  o.screenshot = a.screenshot;
  o.input_script = a.script;
  o.stats = a.stats;
  if (a.samples != -1 && (a.samples < 0 || a.samples > 16)) {
    std::fprintf(stderr, "sinew: --samples takes 0 to 16\n");
    return 1;
  }
  o.samples = a.samples;
  if (a.quit_after < 0) {
    std::fprintf(stderr, "sinew: --quit-after must be >= 0\n");
    return 1;
  }
  o.quit_after = a.quit_after;
  if (!a.size.empty()) {
    char tail = 0;
    if (std::sscanf(a.size.c_str(), "%dx%d%c", &o.width, &o.height, &tail) != 2 || o.width <= 0 || o.height <= 0 ||
        o.width > 16384 || o.height > 16384) {
      std::fprintf(stderr, "sinew: --size must be WIDTHxHEIGHT (e.g. 1024x768), not '%s'\n", a.size.c_str());
      return 1;
    }
  }
  return viewer::run_viewer(o);
}

int check(const CheckArgs& a) {
  int failures = 0;
  for (const auto& scene : a.scenes) {
    runner::SessionOptions so;
    so.data_paths = data_paths_for(a.data_paths);
    runner::Session session(scene, so);
    const bool ok = session.ok();
    if (!ok) ++failures;
    if (a.tsv) {
      std::set<std::string> missing;
      for (const auto& m : session.missing()) missing.insert(m.type);
      std::string list;
      for (const auto& m : missing) list += (list.empty() ? "" : " ") + m;
      std::printf("%s\t%s\t%s\n", scene.c_str(), ok ? "ok" : "error", list.c_str());
    } else {
      std::fflush(stdout);
      print_messages(session.diagnostics());
      std::fflush(stderr);
      std::printf("%s: %s (%d errors, %d warnings)\n", scene.c_str(), ok ? "ok" : "FAILED",
                  session.diagnostics().error_count(), session.diagnostics().warning_count());
    }
  }
  return failures == 0 ? 0 : 1;
}

int components(const std::string& name) {
  register_all_components();
  const Registry& r = registry();
  if (name.empty()) {
    for (const auto& [n, info] : r.all()) {
      std::string line = n;
      if (!info.templates.empty()) {
        line += " <";
        for (std::size_t i = 0; i < info.templates.size(); ++i) line += (i ? "," : "") + info.templates[i];
        line += ">";
      }
      std::printf("%-40s %-22s %s\n", line.c_str(), info.category.c_str(), info.description.c_str());
    }
    return 0;
  }
  const ComponentInfo* info = r.find(renamed_component(name));
  if (!info) {
    std::string hint;
    for (const auto& s : closest_names(name, r.names())) hint += " " + s;
    std::fprintf(stderr, "sinew: unknown component '%s'%s%s\n", name.c_str(), hint.empty() ? "" : "; did you mean",
                 hint.c_str());
    return 1;
  }
  std::printf("%s  (%s)\n  %s\n", info->name.c_str(), info->category.c_str(), info->description.c_str());
  if (!info->templates.empty()) {
    std::printf("  templates:");
    for (const auto& t : info->templates) std::printf(" %s%s", t.c_str(), t == info->default_template ? "*" : "");
    std::printf("   (* default)\n");
  }
  if (!info->aliases.empty()) {
    std::printf("  aliases:");
    for (const auto& al : info->aliases) std::printf(" %s", al.c_str());
    std::printf("\n");
  }
  auto c = info->create(info->default_template);
  if (!c) return 0;
  std::map<std::string, std::vector<BaseField*>> groups;
  for (BaseField* f : c->fields()) groups[f->group()].push_back(f);
  for (const auto& [group, fields] : groups) {
    std::printf("  [%s]\n", group.empty() ? "General" : group.c_str());
    for (BaseField* f : fields) {
      const std::string unit = *f->unit() ? std::string(" [") + f->unit() + "]" : std::string();
      std::printf("    %-26s %-18s default \"%s\"%s  %s\n", f->name().c_str(), f->type_name().c_str(),
                  f->default_text().c_str(), unit.c_str(), f->help().c_str());
    }
  }
  if (!c->links().empty()) {
    std::printf("  [Links]\n");
    for (BaseLink* l : c->links()) std::printf("    %-26s %-18s %s\n", l->name().c_str(), "@path", l->help().c_str());
  }
  return 0;
}

int regress(const RegressArgs& a) {
  std::string data = a.data.empty() ? default_data_root() : a.data;
  if (data.empty() || !is_dir(data)) {
    std::printf("sinew regress: SOFA data folder not found (%s); skipped\n", data.empty() ? "../shared/sofa-data"
                                                                                          : data.c_str());
    return 77;
  }
  runner::RegressListArgs args;
  args.list_file = a.list.empty() ? data + "/examples/RegressionStateScenes.regression-tests" : a.list;
  args.filter = a.filter;
  args.options.data_root = data;
  args.options.isolate = a.isolate;
  args.options.time_limit = a.time_limit;
  return runner::regress_list(args);
}

}  // namespace sinew::cli
