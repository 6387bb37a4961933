#include <pybind11/embed.h>

#include <filesystem>

#include "components/register_all.h"
#include "data.h"
#include "graph.h"
#include "handles.h"
#include "module.h"
#include "scene/builder.h"

#ifndef SINEW_PYTHON_DIR
#define SINEW_PYTHON_DIR ""
#endif

namespace sinew::python {

void define_module(py::module_& m) {
  m.doc() = "Sinew's native Python module; use the packages Sofa, SofaRuntime and sinew";
  register_all_components();
  install_handle_hooks();
  define_data(m);
  define_graph(m);
  define_simulation(m);
  define_gui(m);
}

namespace {

std::string executable_dir() {
  std::error_code ec;
  auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : p.parent_path().string();
}

}  // namespace

void ensure_interpreter() {
  if (Py_IsInitialized()) return;
  // UTF-8 mode (PEP 540), as python3 itself runs under a C or C.UTF-8 locale:
  // an embedding program does not set its locale, and Python would otherwise
  // print through ASCII (SofaPython3's examples print emoji).
  PyPreConfig pre;
  PyPreConfig_InitPythonConfig(&pre);
  pre.utf8_mode = 1;
  if (PyStatus st = Py_PreInitialize(&pre); PyStatus_Exception(st)) Py_ExitStatusException(st);
  py::initialize_interpreter();
  {
    py::module_ sys = py::module_::import("sys");
    py::list path = sys.attr("path");
    // The packages next to the command (build/bin/../python), else where the build put them.
    for (const std::string& dir : {executable_dir() + "/../python", std::string(SINEW_PYTHON_DIR)}) {
      if (dir.empty() || dir == "/../python" || !std::filesystem::exists(dir + "/Sofa")) continue;
      path.insert(0, std::filesystem::weakly_canonical(dir).string());
      break;
    }
  }
  PyEval_SaveThread();  // the GIL is taken by whoever calls Python from now on
}

namespace {

// Line of the innermost frame of `file` in the traceback of `e` (0 when none).
int line_in(py::error_already_set& e, const std::string& file) {
  int line = 0;
  try {
    py::list frames = py::module_::import("traceback").attr("extract_tb")(e.trace());
    for (py::handle f : frames)
      if (py::cast<std::string>(f.attr("filename")) == file) line = py::cast<int>(f.attr("lineno"));
  } catch (...) {
  }
  return line;
}

scene::LoadedScene load_python_scene(const std::string& path, const scene::LoadOptions& options, Diagnostics& diag) {
  scene::LoadedScene out;
  out.file = path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    diag.error({path, 0}, "cannot read the scene file (not found)");
    return out;
  }
  ensure_interpreter();
  py::gil_scoped_acquire gil;
  const std::string abs = std::filesystem::absolute(path).lexically_normal().string();
  auto root = std::make_unique<Node>("root");
  root->name.set("root");
  root->where = {path, 0};
  data_paths() = options.data_paths;
  scene::ResourcePaths paths;
  for (const auto& d : options.data_paths) paths.add(d);
  if (options.use_sofa_data_path) paths.add_from_env();
  root->data_dirs = paths.dirs();
  Node* raw = root.get();
  out.root = std::move(root);
  try {
    py::module_::import("_sinew");  // registers the handle types before the root is wrapped
    py::module_ sys = py::module_::import("sys");
    const std::filesystem::path p(abs);
    py::list argv;
    argv.append(p.filename().string());
    for (const auto& a : options.script_args) argv.append(a);
    sys.attr("argv") = argv;
    py::list sys_path = sys.attr("path");
    const std::string dir = p.parent_path().string();
    if (!sys_path.contains(dir)) sys_path.insert(0, dir);
    py::module_ util = py::module_::import("importlib.util");
    const std::string name = p.stem().string();
    py::object spec = util.attr("spec_from_file_location")(name, abs);
    py::object module = util.attr("module_from_spec")(spec);
    sys.attr("modules")[py::str(name)] = module;
    spec.attr("loader").attr("exec_module")(module);
    if (!py::hasattr(module, "createScene")) {
      raw->diagnostics().error({path, 0}, "Missing createScene function (a Python scene defines createScene(rootNode))");
      return out;
    }
    module.attr("createScene")(wrap(raw));
  } catch (py::error_already_set& e) {
    const int line = line_in(e, abs);
    raw->diagnostics().error({path, line}, "Unable to completely load the scene:\n" + python_error_text(e));
  }
  return out;
}

}  // namespace

void register_python_scene_loader() {
  for (const char* ext : {".py", ".py3", ".pyscn", ".py3scn"}) scene::register_scene_loader(ext, &load_python_scene);
}

}  // namespace sinew::python
