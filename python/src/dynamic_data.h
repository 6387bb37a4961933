// Fields added at run time from Python (SofaPython3's addData): owned here,
// beside their owner, and destroyed with it.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "core/field.h"

namespace sinew::python {

namespace py = pybind11;

// A new field on `owner`; `type` is SOFA's type name ("double", "int", "bool",
// "string", "Vec3d", "vector<double>", "vector<Vec3d>", ...) or empty to infer
// it from `value`. Raises TypeError for an unknown type, ValueError for a name
// the owner already has.
BaseField& add_dynamic_field(Base& owner, const std::string& name, std::string type, py::handle value,
                             py::handle default_value, const std::string& help, const std::string& group);
void forget_dynamic_fields(const Base* owner);

}  // namespace sinew::python
