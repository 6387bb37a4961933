#include "module.h"

#include "handles.h"

// The extension module imported by `python3` (build/python/_sinew*.so).
PYBIND11_MODULE(_sinew, m) {
  sinew::python::define_module(m);
  sinew::python::set_print_messages(true);  // nobody else prints them in a Python process
  sinew::python::register_python_scene_loader();
}
