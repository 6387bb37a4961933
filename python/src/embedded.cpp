// The `_sinew` module built into the `sinew` command: `.py` scenes run in the
// command's own interpreter and `import Sofa` finds this module first (built-in
// modules come before sys.path), never a second copy of Sinew.
#include <pybind11/embed.h>

#include "module.h"

PYBIND11_EMBEDDED_MODULE(_sinew, m) { sinew::python::define_module(m); }
