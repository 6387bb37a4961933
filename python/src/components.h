// The C++ side of components written in Python (SofaPython3's Controller,
// ForceFieldVec3d/Rigid3d, DataEngine, Mapping_Vec3d_Vec3d...).
//
// The Python instance is the component's handle. Its methods are called
// with the GIL held; an exception becomes an error of the component, with
// the Python traceback, and the step stops as for any other error.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <unordered_map>

#include "core/engine.h"
#include "core/roles.h"
#include "handles.h"
#include "mapping/mapping_base.h"

namespace sinew::python {

namespace py = pybind11;

class PythonHost {
 public:
  virtual ~PythonHost();
  // The Python instance is the handle `h` (a subclass of Controller, ...).
  // While it owns this component (before addObject) nothing holds it from
  // here; once a graph owns the component, this holds a strong reference.
  void bind_handle(BaseHandle* h) { handle_ = h; }
  void hold_self(bool strong);
  py::object self() const;
  // The method `name` when the Python class defines it (not the binding's own), else None.
  py::object override_of(const char* name) const;
  // Bound method `name` of the instance (cached; SofaPython3 looks event handlers up once).
  py::object cached_method(const std::string& name);
  void forget_cached(const std::string& name) { cache_.erase(name); }
  // Calls `f` with the GIL held; a Python exception is reported as an error of `owner`.
  template <class F>
  bool call(const Component& owner, const char* what, F&& f) {
    py::gil_scoped_acquire gil;
    try {
      f();
      return true;
    } catch (py::error_already_set& e) {
      report(owner, what, e);
      return false;
    }
  }
  // Calls the Python override of `name` with no argument when there is one.
  void call_override(const Component& owner, const char* name);

 private:
  void report(const Component& owner, const char* what, py::error_already_set& e);
  BaseHandle* handle_ = nullptr;
  PyObject* held_ = nullptr;  // strong reference while a graph owns the component
  std::unordered_map<std::string, py::object> cache_;
};

// Python class name of an event (SofaPython3's dispatch calls on<Name>, else onEvent).
const char* event_class_name(const Event& e);
// The event as SofaPython3 gives it to Python: a dict with type, isHandled and the event's fields.
py::dict event_dict(const Event& e);

class PythonController final : public Component, public PythonHost {
 public:
  PythonController();
  // SofaPython3 calls a controller's init and reinit (and draw, in a viewer), not
  // bwdInit or reset: its own examples define those without `self`.
  void init() override { call_override(*this, "init"); }
  void reinit() override { call_override(*this, "reinit"); }
  void handle_event(Event& e) override;
};

class PythonForceField final : public ForceField, public PythonHost {
 public:
  explicit PythonForceField(StateType type) : type_(type) { listening.set(true); }
  StateType type() const { return type_; }
  void init() override;
  void reinit() override { call_override(*this, "reinit"); }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

 private:
  py::dict params(const MechParams& p, double kfactor) const;
  StateType type_;
};

class PythonDataEngine final : public Engine, public PythonHost {
 public:
  PythonDataEngine() { listening.set(true); }
  void init() override { call_override(*this, "init"); }
  void reinit() override { call_override(*this, "reinit"); }
  void add_python_input(BaseField* f) { add_input(f); }
  void add_python_output(BaseField* f) { add_output(f); }

 protected:
  void do_update() override;
};

// SofaPython3's Mapping_<In>_<Out>: apply, applyJ, applyJT and
// applyConstraintsJT are Python methods, called as SofaPython3 calls them:
// (params dict, output vector, input vector) for apply and applyJ, (params,
// input vector, output vector) for the transposed ones; the vectors behave as
// Data (`.value`, `writeableArray()`). The output is not resized: the Python
// code gives it its size (SofaPython3 does not either). SofaPython3 defines
// no Jacobian matrix for these mappings, so assembled solvers cannot go
// through them (an error says so).
class PythonMapping final : public MappingBase, public PythonHost {
 public:
  PythonMapping(StateType in, StateType out) : MappingBase(in, out) { listening.set(true); }
  void apply(int x) override;
  void apply_j(int v, int role) override;
  void apply_jt(int f, int role) override;
  bool apply_jt_constraints() override;

 protected:
  bool init_mapping() override { return true; }

 private:
  py::dict params() const;
  template <class A, class B>
  void call_python(const char* method, A&& a, B&& b);
};

}  // namespace sinew::python
