// The `_sinew` Python module: defined once, built twice (an extension module
// for `python3`, and a module built into the `sinew` command, which embeds
// Python to run `.py` scenes).
#pragma once

#include <pybind11/pybind11.h>

namespace sinew::python {

void define_module(pybind11::module_& m);

// Starts the embedded interpreter when none runs yet (the `sinew` command),
// with the folder of the Python packages on sys.path; the GIL is then free.
void ensure_interpreter();

// Lets scene::load_scene read SofaPython3 scenes (.py, .py3, .pyscn, .py3scn):
// the file's createScene(rootNode) builds the graph.
void register_python_scene_loader();

}  // namespace sinew::python
