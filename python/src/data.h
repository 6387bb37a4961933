// Python views of fields (SofaPython3's Data) and of state vectors.
//
// `.value` of a number, string or flag is the Python value; of a vector,
// matrix or list of them it is a read-only numpy view on the field's own
// memory (no copy), valid while the field keeps its size: copy it
// (`numpy.array(d.value)`) to keep it across steps. `writeableArray()` gives
// a writable view and marks the field changed when the block ends.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/field.h"
#include "core/roles.h"

namespace sinew::python {

namespace py = pybind11;

// A field of a graph object. Holds the owner's handle so that the owner's
// destruction is seen (using the field afterwards raises).
struct DataHandle {
  BaseField* field = nullptr;
  py::object owner;  // the owner's Python handle
  BaseField& get() const;
};

// A state vector (force, dx, ... of a solver) passed to a Python force field:
// the same interface as a Data for addForce/addDForce.
struct StateVecHandle {
  MechanicalState* state = nullptr;
  int id = 0;
};

// SofaPython3's LinkPath (`obj.linkpath`, `data.linkpath`): names an object or
// a Data as "@/path" or "@/path.data"; given as a Data or link value it makes
// a link. `target` is the object's or the Data's Python handle.
struct LinkPath {
  py::object target;
  std::string text() const;
};

py::object wrap_field(BaseField* f, py::object owner);
py::object state_vector(MechanicalState& s, int id);

// Value of a field as Python (scalars, strings, read-only numpy views, lists of strings).
py::object field_value(BaseField& f, py::handle base);
// Writes a Python value (text, number, sequence, numpy array, Data) into a field; raises on bad input.
void set_field_value(BaseField& f, py::handle value);
// SOFA's text for a Python value (SofaPython3's toSofaParsableString): lists joined by spaces,
// numbers by repr (round-trip exact), Data by their text, objects and Data links by their link path.
std::string to_sofa_text(py::handle value);

void define_data(py::module_& m);

}  // namespace sinew::python
