#include "data.h"

#include <algorithm>
#include <cstring>

#include "core/constraint_matrix_field.h"
#include "core/node.h"
#include "core/path.h"
#include "graph.h"
#include "handles.h"

namespace sinew::python {

namespace {

py::dtype dtype_of(FieldLayout::Scalar s) {
  switch (s) {
    case FieldLayout::Scalar::f64: return py::dtype::of<double>();
    case FieldLayout::Scalar::f32: return py::dtype::of<float>();
    case FieldLayout::Scalar::i32: return py::dtype::of<std::int32_t>();
    case FieldLayout::Scalar::u32: return py::dtype::of<std::uint32_t>();
    case FieldLayout::Scalar::boolean: return py::dtype::of<bool>();
    case FieldLayout::Scalar::none: break;
  }
  return py::dtype::of<double>();
}

std::size_t item_size(FieldLayout::Scalar s) {
  switch (s) {
    case FieldLayout::Scalar::f64: return 8;
    case FieldLayout::Scalar::boolean: return 1;
    default: return 4;
  }
}

void make_read_only(py::array& a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
}

// A numpy array on the layout's memory; `base` keeps the owner's handle alive.
py::array view(const FieldLayout& L, py::handle base, bool writable) {
  const std::size_t item = item_size(L.scalar);
  std::vector<py::ssize_t> shape, strides;
  if (L.dims == 2) {
    shape = {static_cast<py::ssize_t>(L.rows), L.cols};
    if (L.column_major) strides = {static_cast<py::ssize_t>(item), static_cast<py::ssize_t>(item * L.rows)};
    else strides = {static_cast<py::ssize_t>(item * L.cols), static_cast<py::ssize_t>(item)};
  } else if (L.dims == 1) {
    shape = {static_cast<py::ssize_t>(L.rows * L.cols)};
    strides = {static_cast<py::ssize_t>(item)};
  }
  if (!L.data) {  // an empty list: a fresh empty array of the right shape
    py::array a(dtype_of(L.scalar), shape, strides);
    if (!writable) make_read_only(a);
    return a;
  }
  py::array a(dtype_of(L.scalar), shape, strides, L.data, base);
  if (!writable) make_read_only(a);
  return a;
}

py::object scalar_value(const FieldLayout& L) {
  switch (L.scalar) {
    case FieldLayout::Scalar::f64: return py::float_(*static_cast<const double*>(L.data));
    case FieldLayout::Scalar::f32: return py::float_(*static_cast<const float*>(L.data));
    case FieldLayout::Scalar::i32: return py::int_(*static_cast<const std::int32_t*>(L.data));
    case FieldLayout::Scalar::u32: return py::int_(*static_cast<const std::uint32_t*>(L.data));
    case FieldLayout::Scalar::boolean: return py::bool_(*static_cast<const bool*>(L.data));
    case FieldLayout::Scalar::none: break;
  }
  return py::none();
}

std::string field_path(const BaseField& f) {
  std::string owner;
  if (auto* n = dynamic_cast<const Node*>(f.owner())) owner = n->path();
  else if (auto* c = dynamic_cast<const Component*>(f.owner()))
    owner = (c->node() ? (c->node()->path() == "/" ? std::string("/") : c->node()->path() + "/") : std::string()) +
            c->name.value();
  return owner + "." + f.name();
}

int vec_width(const MechanicalState& s, int id) {
  const StateTypeInfo& info = s.info();
  if (id < kFirstDynamicVec) return is_coord_vec(id) ? info.coord_width : info.deriv_width;
  const std::size_t n = s.size();
  return n ? static_cast<int>(s.read(id).size() / n) : info.deriv_width;
}

py::array state_view(MechanicalState& s, int id, bool writable, py::handle base) {
  const int w = vec_width(s, id);
  std::vector<double>& v = writable ? s.write(id) : const_cast<std::vector<double>&>(s.read(id));
  FieldLayout L{FieldLayout::Scalar::f64, v.empty() ? nullptr : v.data(), s.size(), w, 2, false, true};
  return view(L, base, writable);
}

// `with data.writeableArray() as a:` — a writable view; the field is marked changed at the end.
struct WriteAccess {
  py::object target;  // DataHandle or StateVecHandle
  py::array array;
};

}  // namespace

BaseField& DataHandle::get() const {
  if (!field || !owner || !py::cast<BaseHandle&>(owner).ptr)
    throw_reference_error("this Data belongs to an object that was destroyed");
  return *field;
}

std::string LinkPath::text() const {
  if (py::isinstance<DataHandle>(target)) return "@" + field_path(py::cast<DataHandle&>(target).get());
  return to_sofa_text(target);
}

py::object wrap_field(BaseField* f, py::object owner) {
  if (!f) return py::none();
  return py::cast(DataHandle{f, std::move(owner)});
}

py::object state_vector(MechanicalState& s, int id) { return py::cast(StateVecHandle{&s, id}); }

namespace {

// SofaPython3 gives a MatrixDeriv Data as a scipy.sparse CSR matrix of
// (highest row id + 1) rows and (highest DoF + 1)·width columns: one row per
// constraint row of the state, every scalar of the blocks it stores. Sinew's
// projective constraints zero the blocks of fixed DoFs where SOFA's erase
// them (clearColBlock): all-zero blocks are left out, as in SOFA.
py::object constraint_matrix_value(ConstraintMatrixField& f) {
  ConstraintMatrix& J = f.state().constraint_jacobian();
  J.compress();
  const int w = J.width();
  auto zero = [&](int e) { return std::all_of(J.value(e), J.value(e) + w, [](double v) { return v == 0.0; }); };
  int rows = 0, dofs = 0;
  for (const ConstraintMatrix::Row& r : J.rows()) {
    rows = std::max(rows, r.id + 1);
    for (int e = r.begin; e < r.end; ++e)
      if (!zero(e)) dofs = std::max(dofs, J.entries()[e].dof + 1);
  }
  std::vector<std::int32_t> row_begin(static_cast<std::size_t>(rows) + 1, 0), cols;
  std::vector<double> values;
  for (const ConstraintMatrix::Row& r : J.rows()) {  // ascending ids, entries by DoF
    for (int e = r.begin; e < r.end; ++e) {
      if (zero(e)) continue;
      for (int c = 0; c < w; ++c) {
        cols.push_back(J.entries()[e].dof * w + c);
        values.push_back(J.value(e)[c]);
      }
      row_begin[static_cast<std::size_t>(r.id) + 1] += w;
    }
  }
  for (std::size_t i = 0; i + 1 < row_begin.size(); ++i) row_begin[i + 1] += row_begin[i];
  return scipy_csr(values, cols, row_begin, static_cast<std::size_t>(rows), static_cast<std::size_t>(dofs) * w);
}

}  // namespace

py::object field_value(BaseField& f, py::handle base) {
  f.update();
  if (auto* c = dynamic_cast<ConstraintMatrixField*>(&f)) return constraint_matrix_value(*c);
  const FieldLayout L = f.layout();
  if (L.scalar != FieldLayout::Scalar::none) {
    if (L.dims == 0) return scalar_value(L);
    return view(L, base, false);
  }
  if (auto* s = dynamic_cast<Field<std::string>*>(&f)) return py::str(s->value());
  if (auto* l = dynamic_cast<Field<std::vector<std::string>>*>(&f)) return py::cast(l->value());
  return py::str(f.text());
}

std::string to_sofa_text(py::handle value) {
  if (py::isinstance<py::str>(value)) return py::cast<std::string>(value);
  if (py::isinstance<LinkPath>(value)) return py::cast<LinkPath&>(value).text();
  if (py::isinstance<py::bool_>(value)) return py::cast<bool>(value) ? "1" : "0";
  if (py::isinstance<DataHandle>(value)) return py::cast<DataHandle&>(value).get().text();
  if (py::isinstance<BaseHandle>(value)) {
    Base& b = py::cast<BaseHandle&>(value).get();
    if (auto* n = dynamic_cast<Node*>(&b)) return "@" + n->path();
    auto& c = static_cast<Component&>(b);
    if (!c.node()) throw py::value_error(c.describe() + " is not in a graph: it has no link path yet");
    return "@" + (c.node()->path() == "/" ? std::string("/") : c.node()->path() + "/") + c.name.value();
  }
  if (py::isinstance<py::array>(value)) return to_sofa_text(value.attr("tolist")());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string out;
    for (py::handle item : value) {
      if (!out.empty()) out += ' ';
      out += to_sofa_text(item);
    }
    return out;
  }
  if (value.is_none()) return {};
  return py::cast<std::string>(py::repr(value));  // numbers: repr is exact (round trip)
}

void set_field_value(BaseField& f, py::handle value) {
  if (py::isinstance<py::str>(value) || py::isinstance<DataHandle>(value) || py::isinstance<BaseHandle>(value) ||
      py::isinstance<LinkPath>(value)) {
    const std::string text = to_sofa_text(value);
    if (!text.empty() && text[0] == '@' && !py::isinstance<DataHandle>(value)) {
      // A link given as text: made at once when its target exists, else at init.
      f.set_link_path(text);
      if (Component* c = dynamic_cast<Component*>(f.owner()); c && c->node())
        if (BaseField* parent = resolve_field_link(*c->node(), c, text); parent && parent != &f) {
          f.set_parent(parent);
          f.set_link_path({});
        }
      f.update();
      return;
    }
    if (!f.read(text)) throw py::value_error("cannot read '" + text + "' as a value of " + f.name() + " (" + f.type_name() + ")");
    return;
  }
  f.update();
  const FieldLayout L = f.layout();
  if (L.scalar == FieldLayout::Scalar::none) {
    const std::string text = to_sofa_text(value);
    if (!f.read(text)) throw py::value_error("cannot read " + text + " as a value of " + f.name() + " (" + f.type_name() + ")");
    return;
  }
  py::array a = py::array::ensure(value);
  if (!a) throw py::type_error("cannot convert this value for " + f.name() + " (" + f.type_name() + ")");
  a = py::reinterpret_steal<py::array>(
      py::detail::npy_api::get().PyArray_FromAny_(a.ptr(), dtype_of(L.scalar).release().ptr(), 0, 0,
                                                  py::detail::npy_api::NPY_ARRAY_C_CONTIGUOUS_ |
                                                      py::detail::npy_api::NPY_ARRAY_FORCECAST_,
                                                  nullptr));
  if (!a) throw py::error_already_set();
  const std::size_t count = static_cast<std::size_t>(a.size());
  const std::size_t item = item_size(L.scalar);
  const bool same_shape = count == L.rows * static_cast<std::size_t>(L.cols) &&
                          (L.dims != 2 || L.column_major || a.ndim() != 2 || a.shape(0) == static_cast<py::ssize_t>(L.rows));
  if (L.dims == 0 && count != 1) throw py::value_error(f.name() + " holds one value; got " + std::to_string(count));
  if (same_shape && L.data) {
    if (L.column_major) {  // a row-major numpy matrix into Eigen's column-major storage
      const char* src = static_cast<const char*>(a.data());
      char* dst = static_cast<char*>(L.data);
      for (std::size_t r = 0; r < L.rows; ++r)
        for (int c = 0; c < L.cols; ++c) std::memcpy(dst + (c * L.rows + r) * item, src + (r * L.cols + c) * item, item);
    } else {
      std::memcpy(L.data, a.data(), count * item);
    }
    f.mark_set();
    f.touch();
    return;
  }
  if (!L.list) throw py::value_error(f.name() + " holds " + std::to_string(L.rows * L.cols) + " values; got " + std::to_string(count));
  // Another length: through the text reader, which resizes as SOFA's does.
  if (!f.read(to_sofa_text(a))) throw py::value_error("cannot read this value as " + f.name() + " (" + f.type_name() + ")");
}

void define_data(py::module_& m) {
  py::class_<DataHandle>(m, "Data", "A field of a node or component (SofaPython3's Data)")
      .def_property(
          "value", [](py::object self) { return field_value(py::cast<DataHandle&>(self).get(), self); },
          [](DataHandle& d, py::handle v) { set_field_value(d.get(), v); })
      .def("array", [](py::object self) {
        BaseField& f = py::cast<DataHandle&>(self).get();
        f.update();
        const FieldLayout L = f.layout();
        if (L.scalar == FieldLayout::Scalar::none) throw py::type_error(f.name() + " (" + f.type_name() + ") is not an array");
        return view(L, self, false);
      })
      .def("writeableArray", [](py::object self) { return WriteAccess{self, {}}; })
      .def("writeable", [](py::object self) { return WriteAccess{self, {}}; })
      .def("getName", [](DataHandle& d) { return d.get().name(); })
      .def("getHelp", [](DataHandle& d) { return d.get().help(); })
      .def("getGroup", [](DataHandle& d) { return d.get().group(); })
      .def("getValueTypeString", [](DataHandle& d) { return d.get().type_name(); })
      .def("getValueString", [](DataHandle& d) { return d.get().text(); })
      .def("getDefaultValueString", [](DataHandle& d) { return d.get().default_text(); })
      .def("getOwner", [](DataHandle& d) { d.get(); return d.owner; })
      .def("getPathName", [](DataHandle& d) { return field_path(d.get()); })
      .def("getLinkPath", [](DataHandle& d) { return "@" + field_path(d.get()); })
      .def_property_readonly("linkpath", [](py::object self) {
        py::cast<DataHandle&>(self).get();
        return LinkPath{self};
      })
      .def("isSet", [](DataHandle& d) { return d.get().is_set(); })
      .def("unset", [](DataHandle& d) { d.get().unset(); })
      .def("read", [](DataHandle& d, const std::string& t) { return d.get().read(t); })
      .def("hasParent", [](DataHandle& d) { return d.get().parent() != nullptr; })
      .def("getParent", [](DataHandle& d) -> py::object {
        BaseField* p = d.get().parent();
        return p ? wrap_field(p, wrap(p->owner())) : py::none();
      })
      .def("setParent", [](DataHandle& d, py::handle parent) {
        BaseField& f = d.get();
        if (py::isinstance<DataHandle>(parent)) {
          BaseField& p = py::cast<DataHandle&>(parent).get();
          if (&p == &f) throw py::value_error("a Data cannot be its own parent");
          f.set_parent(&p);
          f.set_link_path({});
          f.update();
          return;
        }
        std::string path = py::cast<std::string>(py::str(parent));
        if (path.empty() || path[0] != '@') path = "@" + path;
        set_field_value(f, py::str(path));
      })
      .def("getCounter", [](DataHandle& d) { return d.get().version(); })
      .def("__len__", [](py::object self) {
        BaseField& f = py::cast<DataHandle&>(self).get();
        f.update();
        const FieldLayout L = f.layout();
        if (L.scalar == FieldLayout::Scalar::none || L.dims == 0) throw py::type_error(f.name() + " has no length");
        return L.dims == 2 ? L.rows : L.rows * L.cols;
      })
      .def("__getitem__", [](py::object self, py::handle key) {
        return field_value(py::cast<DataHandle&>(self).get(), self).attr("__getitem__")(key);
      })
      .def("__setitem__", [](py::object self, py::handle key, py::handle v) {
        BaseField& f = py::cast<DataHandle&>(self).get();
        f.update();
        const FieldLayout L = f.layout();
        if (L.scalar == FieldLayout::Scalar::none || L.dims == 0) throw py::type_error(f.name() + " is not an array");
        view(L, self, true).attr("__setitem__")(key, v);
        f.mark_set();
        f.touch();
      })
      .def("__array__", [](py::object self, py::args) {
        return field_value(py::cast<DataHandle&>(self).get(), self);
      })
      .def_property_readonly("shape", [](py::object self) { return py::array(field_value(py::cast<DataHandle&>(self).get(), self)).attr("shape"); })
      .def_property_readonly("ndim", [](py::object self) { return py::array(field_value(py::cast<DataHandle&>(self).get(), self)).ndim(); })
      .def_property_readonly("size", [](py::object self) { return py::array(field_value(py::cast<DataHandle&>(self).get(), self)).size(); })
      .def("tolist", [](py::object self) {
        py::object v = field_value(py::cast<DataHandle&>(self).get(), self);
        return py::isinstance<py::array>(v) ? v.attr("tolist")() : v;
      })
      .def("__str__", [](py::object self) { return py::str(field_value(py::cast<DataHandle&>(self).get(), self)); })
      .def("__repr__", [](DataHandle& d) { return "<Data " + field_path(d.get()) + " = " + d.get().text().substr(0, 60) + ">"; });

  py::class_<LinkPath>(m, "LinkPath", "A link to an object or a Data (\"@/path\", \"@/path.data\")")
      .def("__str__", &LinkPath::text)
      .def("__repr__", [](const LinkPath& l) { return "LinkPath(\"" + l.text() + "\")"; })
      .def("target", [](const LinkPath& l) { return l.target; });

  py::class_<StateVecHandle>(m, "StateVector", "A state vector handed to a Python force field (as a Data)")
      .def_property_readonly("value", [](py::object self) {
        auto& h = py::cast<StateVecHandle&>(self);
        return state_view(*h.state, h.id, false, self);
      })
      .def("array", [](py::object self) {
        auto& h = py::cast<StateVecHandle&>(self);
        return state_view(*h.state, h.id, false, self);
      })
      .def("writeableArray", [](py::object self) { return WriteAccess{self, {}}; })
      .def("writeable", [](py::object self) { return WriteAccess{self, {}}; })
      .def("__len__", [](StateVecHandle& h) { return h.state->size(); })
      .def("__array__", [](py::object self, py::args) {
        auto& h = py::cast<StateVecHandle&>(self);
        return state_view(*h.state, h.id, false, self);
      });

  py::class_<WriteAccess>(m, "WriteAccess", "Context giving a writable numpy view on a Data")
      .def("__enter__", [](WriteAccess& w) -> py::array {
        if (py::isinstance<StateVecHandle>(w.target)) {
          auto& h = py::cast<StateVecHandle&>(w.target);
          w.array = state_view(*h.state, h.id, true, w.target);
          return w.array;
        }
        BaseField& f = py::cast<DataHandle&>(w.target).get();
        f.update();
        FieldLayout L = f.layout();
        if (L.scalar == FieldLayout::Scalar::none) throw py::type_error(f.name() + " (" + f.type_name() + ") is not an array");
        if (L.dims == 0) L.dims = 1;  // a single number: a one-element array
        w.array = view(L, w.target, true);
        return w.array;
      })
      .def("__exit__", [](WriteAccess& w, py::args) {
        if (py::isinstance<DataHandle>(w.target)) {
          BaseField& f = py::cast<DataHandle&>(w.target).get();
          f.mark_set();
          f.touch();
        }
        w.array = py::array();
        return false;
      });
}

}  // namespace sinew::python
