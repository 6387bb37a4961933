#include "handles.h"

#include <frameobject.h>

#include <cstdio>
#include <unordered_map>
#include <vector>

#include "dynamic_data.h"

namespace sinew::python {

namespace {

// The handle of each object that has one (the entry leaves with the handle).
std::unordered_map<const Base*, BaseHandle*>& live() {
  static std::unordered_map<const Base*, BaseHandle*> map;
  return map;
}

void on_destroyed(const Base* b) {
  forget_dynamic_fields(b);
  auto& map = live();
  auto it = map.find(b);
  if (it == map.end()) return;
  it->second->ptr = nullptr;
  map.erase(it);
}

std::vector<HandleMaker>& makers() {
  static std::vector<HandleMaker> v;
  return v;
}

bool g_print = false;
std::unordered_map<const Diagnostics*, std::size_t>& printed() {
  static std::unordered_map<const Diagnostics*, std::size_t> map;
  return map;
}

}  // namespace

BaseHandle::~BaseHandle() {
  if (ptr) {
    auto it = live().find(ptr);
    if (it != live().end() && it->second == this) live().erase(it);
  }
  if (owned) {
    // Python owned the object (never inserted): it goes with its handle. Its
    // destructor must not find this handle any more.
    ptr = nullptr;
    owned.reset();
  }
}

void throw_reference_error(const std::string& what) {
  PyErr_SetString(PyExc_ReferenceError, what.c_str());
  throw py::error_already_set();
}

Base& BaseHandle::get() const {
  if (!ptr) throw_reference_error("this object was destroyed (removed from its graph, or its graph was unloaded)");
  return *ptr;
}

void adopt(BaseHandle& h, Base* b) {
  h.ptr = b;
  live()[b] = &h;
}

py::object wrap(Base* b) {
  if (!b) return py::none();
  auto& map = live();
  // An existing handle: pybind11 finds its Python object (of the most derived
  // type, a Python subclass for Python components) from the handle's address.
  if (auto it = map.find(b); it != map.end()) return py::cast(it->second, py::return_value_policy::reference);
  BaseHandle* h = nullptr;
  if (dynamic_cast<Node*>(b)) {
    h = new NodeHandle{};
  } else {
    auto& c = static_cast<Component&>(*b);
    for (HandleMaker make : makers())
      if ((h = make(c))) break;
    if (!h) h = new ObjectHandle{};
  }
  adopt(*h, b);
  return py::cast(h, py::return_value_policy::take_ownership);
}

void register_handle_maker(HandleMaker maker) { makers().push_back(maker); }

void install_handle_hooks() { set_base_destroyed_hook(&on_destroyed); }

SourceLocation python_location() {
  SourceLocation where;
  PyFrameObject* frame = PyEval_GetFrame();  // borrowed
  if (!frame) return where;
  where.line = PyFrame_GetLineNumber(frame);
  PyCodeObject* code = PyFrame_GetCode(frame);  // new reference
  if (code) {
    py::object file = py::reinterpret_borrow<py::object>(code->co_filename);
    where.file = py::cast<std::string>(py::str(file));
    Py_DECREF(code);
  }
  return where;
}

std::string python_error_text(py::error_already_set& e) {
  try {
    py::module_ tb = py::module_::import("traceback");
    py::list lines = tb.attr("format_exception")(e.type(), e.value(), e.trace());
    std::string out;
    for (py::handle l : lines) out += py::cast<std::string>(l);
    while (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
  } catch (...) {
    return e.what();
  }
}

void set_print_messages(bool on) { g_print = on; }

py::list& message_sinks() {
  static py::list* sinks = new py::list();  // never destroyed: outlives the interpreter's teardown
  return *sinks;
}

namespace {
const char* severity_name(Severity s) {
  switch (s) {
    case Severity::info: return "Info";
    case Severity::warning: return "Warning";
    case Severity::error: return "Error";
  }
  return "Info";
}

void to_sinks(const Message& m) {
  if (message_sinks().empty()) return;
  py::dict d;
  d["type"] = severity_name(m.severity);
  d["sender"] = m.who;
  d["message"] = m.text;
  d["fileInfo"] = m.where.file.empty() ? std::string() : m.where.file + ":" + std::to_string(m.where.line);
  for (py::handle sink : message_sinks()) sink.attr("process")(d);
}
}  // namespace

void flush_messages(Node& root) {
  const Diagnostics& d = root.diagnostics();
  std::size_t& done = printed()[&d];
  const auto& msgs = d.messages();
  if (done > msgs.size()) done = 0;  // cleared since
  for (; done < msgs.size(); ++done) {
    if (g_print) std::fprintf(stderr, "%s\n", Diagnostics::format(msgs[done]).c_str());
    to_sinks(msgs[done]);
  }
  std::fflush(stderr);
}

void emit_python_message(Severity sev, const SourceLocation& where, const std::string& who, const std::string& text) {
  Message m{sev, where, who, text};
  std::fprintf(stderr, "%s\n", Diagnostics::format(m).c_str());
  std::fflush(stderr);
  to_sinks(m);
}

}  // namespace sinew::python
