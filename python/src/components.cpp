#include "components.h"

#include "data.h"
#include "handles.h"

namespace sinew::python {

PythonHost::~PythonHost() {
  if (!Py_IsInitialized()) return;  // the interpreter is gone (process exit): nothing to release
  py::gil_scoped_acquire gil;
  cache_.clear();
  if (held_) Py_DECREF(held_);
  held_ = nullptr;
}

py::object PythonHost::self() const {
  if (!handle_) return py::none();
  return py::cast(handle_, py::return_value_policy::reference);
}

void PythonHost::hold_self(bool strong) {
  if (strong == (held_ != nullptr) || !handle_) return;
  if (strong) {
    held_ = self().release().ptr();
  } else {
    PyObject* h = held_;
    held_ = nullptr;
    Py_DECREF(h);
  }
}

py::object PythonHost::override_of(const char* name) const {
  py::object me = self();
  if (me.is_none()) return py::none();
  // The first class of the MRO that defines `name` decides: a Python class
  // (the user's subclass) overrides; a binding class (module _sinew) does not.
  py::handle type = reinterpret_cast<PyObject*>(Py_TYPE(me.ptr()));
  for (py::handle cls : type.attr("__mro__")) {
    if (py::cast<std::string>(py::str(cls.attr("__module__"))) == "_sinew") return py::none();
    if (py::cast<py::dict>(cls.attr("__dict__")).contains(name)) return me.attr(name);
  }
  return py::none();
}

py::object PythonHost::cached_method(const std::string& name) {
  if (auto it = cache_.find(name); it != cache_.end()) return it->second;
  py::object m = py::none();
  py::object me = self();
  if (!me.is_none() && py::hasattr(me, name.c_str())) {
    py::object f = me.attr(name.c_str());
    if (PyCallable_Check(f.ptr())) m = f;
  }
  cache_[name] = m;
  return m;
}

void PythonHost::report(const Component& owner, const char* what, py::error_already_set& e) {
  owner.msg_error(std::string("Python error in ") + what + ":\n" + python_error_text(e));
}

void PythonHost::call_override(const Component& owner, const char* name) {
  call(owner, name, [&] {
    py::object m = override_of(name);
    if (!m.is_none()) m();
  });
}

const char* event_class_name(const Event& e) {
  switch (e.kind) {
    case Event::Kind::animate_begin: return "AnimateBeginEvent";
    case Event::Kind::animate_end: return "AnimateEndEvent";
    case Event::Kind::simulation_init_done: return "SimulationInitDoneEvent";
    case Event::Kind::key_pressed: return "KeypressedEvent";
    case Event::Kind::key_released: return "KeyreleasedEvent";
    case Event::Kind::script: return "PythonScriptEvent";
    case Event::Kind::build_constraint_system_end: return "BuildConstraintSystemEndEvent";
    case Event::Kind::solve_constraint_system_end: return "SolveConstraintSystemEndEvent";
  }
  return "Event";
}

py::dict event_dict(const Event& e) {
  py::dict d;
  d["type"] = event_class_name(e);
  d["isHandled"] = e.handled;
  switch (e.kind) {
    case Event::Kind::animate_begin:
    case Event::Kind::animate_end: d["dt"] = e.dt; break;
    case Event::Kind::key_pressed:
    case Event::Kind::key_released: d["key"] = std::string(1, e.key); break;
    case Event::Kind::script:
      d["sender"] = wrap(const_cast<Node*>(e.sender));
      d["event_name"] = e.name;
      d["userData"] = e.payload ? py::reinterpret_borrow<py::object>(static_cast<PyObject*>(e.payload)) : py::none();
      break;
    default: break;
  }
  return d;
}

PythonController::PythonController() { listening.set(true); }

void PythonController::handle_event(Event& e) {
  call(*this, event_class_name(e), [&] {
    py::object m = cached_method(std::string("on") + event_class_name(e));
    if (m.is_none()) m = cached_method("onEvent");
    if (m.is_none()) return;
    py::object r = m(event_dict(e));
    if (!r.is_none() && py::cast<bool>(r)) e.handled = true;
  });
}

void PythonForceField::init() {
  ForceField::init();
  if (!mstate) {
    msg_error("no mechanical state in this node or above: a Python force field needs one");
    set_state(ComponentState::invalid);
    return;
  }
  if (mstate->state_type() != type_) {
    msg_error(std::string("its mechanical state is ") + mstate->info().name + ", not " + state_type_info(type_).name);
    set_state(ComponentState::invalid);
    return;
  }
  call_override(*this, "init");
}

py::dict PythonForceField::params(const MechParams& p, double kfactor) const {
  py::dict d;
  d["time"] = node() ? node()->time.value() : 0.0;
  d["mFactor"] = p.m;
  d["bFactor"] = p.b;
  d["kFactor"] = kfactor;
  d["isImplicit"] = p.implicit;
  return d;
}

void PythonForceField::add_force(const MechParams& p) {
  MechanicalState* s = mstate.get();
  call(*this, "addForce", [&] {
    self().attr("addForce")(params(p, p.k), state_vector(*s, p.f), state_vector(*s, p.x), state_vector(*s, p.v));
  });
}

void PythonForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState* s = mstate.get();
  call(*this, "addDForce", [&] {
    py::dict d = params(p, kfactor);
    d["nFactor"] = p.m;  // SofaPython3 names the mass factor so in addDForce
    self().attr("addDForce")(d, state_vector(*s, p.df), state_vector(*s, p.dx));
  });
}

// SofaPython3's addKToMatrix returns either a dense (n·d)×(n·d)(×1) matrix or
// (i, j, value) rows; entries are scalar indices of this force field's state.
bool PythonForceField::build_stiffness(MatrixSink& K) {
  MechanicalState* s = mstate.get();
  bool ok = false;
  call(*this, "addKToMatrix", [&] {
    py::object m = override_of("addKToMatrix");
    if (m.is_none()) {
      msg_error("addKToMatrix is not defined: an assembled linear solver needs it");
      return;
    }
    MechParams p;
    p.k = 1;
    const int width = s->info().deriv_width;
    py::object ret = m(params(p, 1.0), static_cast<int>(s->size()), width);
    if (!py::isinstance<py::array>(ret)) {
      msg_error("addKToMatrix must return a numpy array (a dense matrix or (i, j, value) rows)");
      return;
    }
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(ret);
    const std::size_t n = s->size() * static_cast<std::size_t>(width);
    // SofaPython3's forms: (n, n, 1) dense, or (m, 3) rows; an (n, n) matrix is taken as
    // dense when it cannot be read as rows (n != 3).
    if ((a.ndim() == 3 && a.shape(2) == 1) || (a.ndim() == 2 && a.shape(1) != 3)) {
      if (static_cast<std::size_t>(a.shape(0)) != n || static_cast<std::size_t>(a.shape(1)) != n) {
        msg_error("addKToMatrix returned a " + std::to_string(a.shape(0)) + "×" + std::to_string(a.shape(1)) +
                  " matrix; expected " + std::to_string(n) + "×" + std::to_string(n));
        return;
      }
      const double* v = a.data();
      for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c)
          if (const double x = v[r * n + c]; x != 0) K.add(s, r, s, c, x);
      ok = true;
    } else if (a.ndim() == 2 && a.shape(1) == 3) {
      const double* v = a.data();
      for (py::ssize_t k = 0; k < a.shape(0); ++k) {
        const double r = v[k * 3], c = v[k * 3 + 1];
        if (!(r >= 0 && c >= 0 && r < double(n) && c < double(n))) {
          msg_error("addKToMatrix: entry (" + std::to_string(r) + ", " + std::to_string(c) + ") is outside the " +
                    std::to_string(n) + "×" + std::to_string(n) + " matrix");
          return;
        }
        K.add(s, static_cast<std::size_t>(r), s, static_cast<std::size_t>(c), v[k * 3 + 2]);
      }
      ok = true;
    } else {
      msg_error("addKToMatrix must return a plain 2D matrix or (i, j, value) rows");
    }
  });
  return ok;
}

py::dict PythonMapping::params() const {
  // SofaPython3 passes the mechanical parameters of the call; the mapping's own
  // calls in Sinew carry none, so they are the defaults (SOFA's defaultInstance).
  py::dict d;
  d["time"] = node() ? node()->time.value() : 0.0;
  d["mFactor"] = 0.0;
  d["bFactor"] = 0.0;
  d["kFactor"] = 0.0;
  d["isImplicit"] = false;
  d["energy"] = false;
  return d;
}

// `a` and `b` make the two vector arguments (under the GIL).
template <class A, class B>
void PythonMapping::call_python(const char* method, A&& a, B&& b) {
  call(*this, method, [&] {
    py::object m = override_of(method);
    if (m.is_none()) {
      // SofaPython3 declares these methods pure: a mapping without one cannot run.
      msg_error(std::string("defines no ") + method + "(): a Python mapping must define apply, applyJ and applyJT");
      set_state(ComponentState::invalid);
      return;
    }
    m(params(), a(), b());
  });
}

void PythonMapping::apply(int x) {
  if (!out_) return;  // a visual output: SofaPython3's mappings write mechanical states only
  call_python("apply", [&] { return state_vector(*out_, vec_for(*out_, x, kPosition)); },
              [&] { return state_vector(*in_[0], vec_for(*in_[0], x, kPosition)); });
}

void PythonMapping::apply_j(int v, int role) {
  if (!out_) return;
  call_python("applyJ", [&] { return state_vector(*out_, vec_for(*out_, v, role)); },
              [&] { return state_vector(*in_[0], vec_for(*in_[0], v, role)); });
}

void PythonMapping::apply_jt(int f, int role) {
  if (!out_) return;
  call_python("applyJT", [&] { return state_vector(*in_[0], vec_for(*in_[0], f, role)); },
              [&] { return state_vector(*out_, vec_for(*out_, f, role)); });
}

bool PythonMapping::apply_jt_constraints() {
  if (!out_) return true;
  // The states' constraint matrices, as SofaPython3 gives a MatrixDeriv Data (scipy.sparse).
  BaseField* in_c = in_[0]->find_field("constraint");
  BaseField* out_c = out_->find_field("constraint");
  if (!in_c || !out_c) return false;
  bool ok = true;
  call(*this, "applyConstraintsJT", [&] {
    py::object m = override_of("applyConstraintsJT");
    if (m.is_none()) {
      ok = false;
      return;
    }
    py::dict d;
    d["time"] = node() ? node()->time.value() : 0.0;
    m(d, wrap_field(in_c, wrap(in_[0])), wrap_field(out_c, wrap(out_)));
  });
  return ok;
}

void PythonDataEngine::do_update() {
  call(*this, "update", [&] {
    py::object me = self();
    if (!py::hasattr(me, "update")) {
      msg_error("has no update() method");
      return;
    }
    me.attr("update")();
  });
}

}  // namespace sinew::python
