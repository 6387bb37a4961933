// Python handles on the scene graph.
//
// A Python object never owns a graph object that is in a graph: the graph
// does (unique_ptr children and objects). A handle points at its Node or
// Component and learns through the core's destroyed hook when it goes away,
// after which using it raises instead of touching freed memory. There is at
// most one handle per live object, so `a is b` holds as in SofaPython3.
// Objects made from Python and not inserted yet (a `Sofa.Core.Node("root")`,
// a controller before addObject) are owned by their handle until inserted.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "core/component.h"
#include "core/node.h"

namespace sinew::python {

namespace py = pybind11;

struct BaseHandle {
  Base* ptr = nullptr;          // nullptr once the object was destroyed
  std::unique_ptr<Base> owned;  // set while Python owns the object (not in a graph)
  virtual ~BaseHandle();
  // The object; raises Python's ReferenceError when it was destroyed.
  Base& get() const;
};
struct NodeHandle : BaseHandle {
  Node& node() const { return static_cast<Node&>(get()); }
};
struct ObjectHandle : BaseHandle {
  Component& component() const { return static_cast<Component&>(get()); }
};

// Raises Python's ReferenceError (a handle whose object was destroyed).
[[noreturn]] void throw_reference_error(const std::string& what);

// The Python object for a graph object (its existing handle, or a new one);
// None for nullptr.
py::object wrap(Base* b);
// Per-class Python types (SofaPython3's SpringForceField, linear system and
// constraint solver bindings): a maker returns a new handle of its own
// ObjectHandle subclass for the components it knows, else nullptr. wrap()
// asks the makers in registration order; the first answer wins.
using HandleMaker = ObjectHandle* (*)(Component&);
void register_handle_maker(HandleMaker maker);
// Registers `h` as the handle of `b` (its Python object is found from `h` by pybind11).
void adopt(BaseHandle& h, Base* b);
// Installs the destroyed hook (once).
void install_handle_hooks();

// Where Python code is running now (file and line of the innermost frame), for messages.
SourceLocation python_location();
// "Traceback ...\nValueError: ..." of the Python error being handled (and clears it).
std::string python_error_text(py::error_already_set& e);

// Messages of a graph are printed when Python drives it directly (python3 scene.py);
// `sinew run` prints them itself.
void set_print_messages(bool on);
void flush_messages(Node& root);
// Python's Sofa.Helper.MessageHandler objects in use (`with handler:`): each
// message is also given to their process(dict).
py::list& message_sinks();
// A message from Python code (Sofa.Helper.msg_info, ...): printed and given to the sinks.
void emit_python_message(Severity sev, const SourceLocation& where, const std::string& who, const std::string& text);

}  // namespace sinew::python
