// Sofa.Simulation entry points, messages (Sofa.Helper), the component factory
// and data folders, as SofaPython3 gives them.
#include <pybind11/stl.h>

#include <tbb/global_control.h>

#include <cstdio>
#include <memory>
#include <thread>

#include "components/register_all.h"
#include "core/mechanical_ops.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "data.h"
#include "graph.h"
#include "handles.h"
#include "scene/builder.h"

namespace sinew::python {

std::vector<std::string>& data_paths() {
  static std::vector<std::string> paths;
  return paths;
}

scene::ResourcePaths resource_paths(Node& node) {
  scene::ResourcePaths p;
  for (const auto& d : node.root()->data_dirs) p.add(d);
  for (const auto& d : data_paths()) p.add(d);
  p.add_from_env();
  return p;
}

py::tuple compute_energy(Node& node) {
  MechanicalOps ops(node);
  static const int tmp = MechanicalOps::alloc_vec();
  double kinetic = 0, potential = 0;
  for (Mass* m : ops.masses()) {
    MechanicalState* s = m->single_state();
    if (!s) continue;
    std::vector<double>& mv = s->write(tmp);
    std::fill(mv.begin(), mv.end(), 0.0);
    m->add_mdx(MechParams{}, tmp, kVelocity, 1.0);
    const std::vector<double>& v = s->read(kVelocity);
    const std::vector<double>& r = s->read(tmp);
    double e = 0;
    for (std::size_t i = 0; i < v.size() && i < r.size(); ++i) e += v[i] * r[i];
    kinetic += 0.5 * e;
  }
  for (ForceField* ff : ops.force_fields()) potential += ff->potential_energy().value_or(0.0);
  return py::make_tuple(kinetic, potential);
}

namespace {

Node& root_of(NodeHandle& h) { return *h.node().root(); }

void init_graph(Node& root) {
  if (root.data_dirs.empty()) root.data_dirs = resource_paths(root).dirs();
  {
    // Without the GIL, as a step: a component may call Python from a worker thread.
    py::gil_scoped_release release;
    if (!root.initialised) init_root(root);
    else init_added(root);
  }
  flush_messages(root);
}

void step(Node& root, double dt) {
  root.step_index = static_cast<long>(root.step_index + 1);
  {
    py::gil_scoped_release release;  // Python components take it back when called
    animate(root, dt);
  }
  flush_messages(root);
}

py::object load_file(const std::string& path) {
  scene::LoadOptions lo;
  lo.data_paths = data_paths();
  Diagnostics diag;
  scene::LoadedScene s = scene::load_scene(path, lo, diag);
  if (!s.root) {
    std::string text;
    for (const Message& m : diag.messages()) text += Diagnostics::format(m) + "\n";
    throw py::value_error("cannot load " + path + ":\n" + text);
  }
  Node* raw = s.root.get();
  flush_messages(*raw);
  py::object o = wrap(raw);
  py::cast<BaseHandle&>(o).owned = std::move(s.root);
  return o;
}

void message(Severity sev, py::args args) {
  // msg_info(text) or msg_info(emitter, text): the emitter is a name or an object.
  std::string who, text;
  if (args.size() >= 2) {
    who = py::isinstance<BaseHandle>(args[0]) ? py::cast<BaseHandle&>(args[0]).get().describe()
                                               : py::cast<std::string>(py::str(args[0]));
    text = py::cast<std::string>(py::str(args[1]));
  } else if (args.size() == 1) {
    text = py::cast<std::string>(py::str(args[0]));
  }
  const SourceLocation where = python_location();
  emit_python_message(sev, where, who, text);
}

}  // namespace

void define_simulation(py::module_& m) {
  m.def("init", [](NodeHandle& h) { init_graph(root_of(h)); }, "Initialise the graph (SOFA's init)");
  m.def("initRoot", [](NodeHandle& h) { init_graph(root_of(h)); }, "Initialise the graph (SOFA's initRoot)");
  m.def("animate", [](NodeHandle& h, double dt) { step(root_of(h), dt); }, py::arg("node"), py::arg("dt") = 0.0,
        "One step of dt (0: the root's dt)");
  m.def("animateNSteps", [](NodeHandle& h, int n, double dt) {
        for (int i = 0; i < n; ++i) step(root_of(h), dt);
      }, py::arg("node"), py::arg("n_steps") = 1, py::arg("dt") = 0.0);
  m.def("reset", [](NodeHandle& h) {
    {
      py::gil_scoped_release release;
      reset_root(root_of(h));
    }
    flush_messages(root_of(h));
  });
  m.def("unload", [](NodeHandle& h) {
    Node& n = h.node();
    // SOFA's unload cleans the simulation up first: exporters write their exportAtEnd files.
    if (n.initialised && !n.parent()) {
      cleanup_root(n);
      flush_messages(n);
    }
    // The graph's contents go; the (root) node itself stays, empty, as in SOFA.
    while (!n.children().empty()) n.remove_child(n.children().back());
    while (!n.objects().empty()) n.remove_object(n.objects().back().get());
    n.cleaned_up = false;  // a graph built again in this root is cleaned up again
  });
  m.def("load", &load_file, "Load a scene file (XML or Python) and return its root");
  m.def("print", [](NodeHandle& h) {
    std::function<void(Node&, int)> show = [&](Node& n, int depth) {
      std::printf("%*s%s\n", depth * 2, "", n.name.value().c_str());
      for (auto& o : n.objects())
        std::printf("%*s  %s (%s)\n", depth * 2, "", o->name.value().c_str(), o->class_name().c_str());
      for (auto& c : n.children()) show(*c, depth + 1);
    };
    show(h.node(), 0);
  });
  m.def("sendKey", [](NodeHandle& h, const std::string& key, bool pressed) {
    if (key.size() != 1) throw py::value_error("a key is one character");
    Event e{};
    e.kind = pressed ? Event::Kind::key_pressed : Event::Kind::key_released;
    e.key = key[0];
    propagate_event(root_of(h), e);
    flush_messages(root_of(h));
  }, py::arg("node"), py::arg("key"), py::arg("pressed") = true,
  "Send a key event to the graph, as a viewer does (Ctrl held)");

  // SofaPython3's Sofa.Core.TaskScheduler: how many worker threads parallel components use.
  struct TaskScheduler {};
  static std::unique_ptr<tbb::global_control> threads;
  static unsigned thread_count = 0;
  py::class_<TaskScheduler>(m, "TaskScheduler", "Worker threads of the parallel components (oneTBB)")
      .def_static("GetHardwareThreadsCount", []() { return std::max(1u, std::thread::hardware_concurrency()); })
      .def_static("init", [](unsigned n) {
        if (n == 0) n = std::max(1u, std::thread::hardware_concurrency());
        threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
        thread_count = n;
      }, py::arg("nbThreads") = 0)
      .def_static("getThreadCount", []() {
        return thread_count ? thread_count : std::max(1u, std::thread::hardware_concurrency());
      })
      .def_static("stop", []() {
        threads.reset();
        thread_count = 0;
      });

  m.def("msg_info", [](py::args a) { message(Severity::info, a); });
  m.def("msg_warning", [](py::args a) { message(Severity::warning, a); });
  m.def("msg_error", [](py::args a) { message(Severity::error, a); });
  m.def("msg_deprecated", [](py::args a) { message(Severity::warning, a); });
  m.def("msg_fatal", [](py::args a) { message(Severity::error, a); });
  m.def("_set_message_sinks", [](py::list sinks) { message_sinks() = sinks; });

  m.def("data_paths", []() { return data_paths(); }, "Folders resource files are searched in (after the scene's)");
  m.def("add_data_path", [](const std::string& p, bool first) {
    auto& d = data_paths();
    if (first) d.insert(d.begin(), p);
    else d.push_back(p);
  }, py::arg("path"), py::arg("first") = false);
  m.def("remove_data_path", [](const std::string& p) { std::erase(data_paths(), p); });

  m.def("components", []() {
    register_all_components();
    py::list out;
    for (const auto& [name, info] : registry().all()) {
      py::dict d;
      d["className"] = name;
      d["description"] = info.description;
      d["category"] = info.category;
      d["templates"] = info.templates;
      d["defaultTemplate"] = info.default_template;
      d["aliases"] = info.aliases;
      out.append(d);
    }
    return out;
  }, "Every component class: name, description, category, templates, aliases");
  m.def("has_component", [](const std::string& name) {
    register_all_components();
    return registry().find(renamed_component(name)) != nullptr;
  });
  m.def("component_fields", [](const std::string& name, const std::string& tmpl) {
    register_all_components();
    const ComponentInfo* info = registry().find(renamed_component(name));
    if (!info) throw py::value_error("unknown component '" + name + "'");
    auto c = info->create(tmpl.empty() ? info->default_template : tmpl);
    py::list out;
    if (!c) return out;
    for (BaseField* f : c->fields()) {
      py::dict d;
      d["name"] = f->name();
      d["type"] = f->type_name();
      d["default"] = f->default_text();
      d["help"] = f->help();
      d["group"] = f->group();
      d["layout"] = static_cast<int>(f->layout().scalar) == 0 ? "text" : (f->layout().dims == 0 ? "scalar" : "array");
      out.append(d);
    }
    for (BaseLink* l : c->links()) {
      py::dict d;
      d["name"] = l->name();
      d["type"] = "link";
      d["default"] = "";
      d["help"] = l->help();
      d["group"] = "Links";
      d["layout"] = "link";
      out.append(d);
    }
    return out;
  }, py::arg("name"), py::arg("template") = "");
}

}  // namespace sinew::python
