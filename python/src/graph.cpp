// Sofa.Core.Base, Node and Object (SofaPython3's Binding_Base/Node/BaseObject).
#include <pybind11/stl.h>

#include <algorithm>

#include "components.h"
#include "core/mechanical_ops.h"
#include "core/path.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "data.h"
#include "dynamic_data.h"
#include "graph.h"
#include "handles.h"
#include "scene/builder.h"

namespace sinew::python {

namespace {

std::string object_path(const Component& c) {
  if (!c.node()) return c.name.value();
  const std::string p = c.node()->path();
  return (p == "/" ? p : p + "/") + c.name.value();
}

std::string path_of(Base& b) {
  if (auto* n = dynamic_cast<Node*>(&b)) return n->path();
  return object_path(static_cast<Component&>(b));
}

// Suggestions for an unknown attribute name, as SofaPython3's spelling hints.
std::string unknown_attribute(Base& b, const std::string& name) {
  std::vector<std::string> names;
  for (BaseField* f : b.fields()) names.push_back(f->name());
  for (BaseLink* l : b.links()) names.push_back(l->name());
  if (auto* n = dynamic_cast<Node*>(&b)) {
    for (auto& o : n->objects()) names.push_back(o->name.value());
    for (auto& c : n->children()) names.push_back(c->name.value());
  }
  std::string text = b.describe() + " has no attribute, Data, link, child or object named '" + name + "'";
  const auto close = closest_names(name, names);
  if (!close.empty()) {
    text += " (did you mean ";
    for (std::size_t i = 0; i < close.size(); ++i) text += (i ? ", '" : "'") + close[i] + "'";
    text += "?)";
  }
  return text;
}

py::object link_target(BaseLink& l) { return wrap(l.target()); }

// Data, then link (SofaPython3's BindingBase::GetAttr order); nullopt when neither.
std::optional<py::object> field_or_link(py::object self, Base& b, const std::string& name) {
  if (BaseField* f = b.find_field(name)) return wrap_field(f, self);
  if (BaseLink* l = b.find_link(name)) return link_target(*l);
  return std::nullopt;
}

bool set_field_or_link(Base& b, const std::string& name, py::handle value) {
  if (BaseField* f = b.find_field(name)) {
    set_field_value(*f, value);
    return true;
  }
  if (BaseLink* l = b.find_link(name)) {
    if (py::isinstance<LinkPath>(value)) {
      py::object t = py::cast<LinkPath&>(value).target;
      if (!py::isinstance<BaseHandle>(t))
        throw py::type_error(b.describe() + ": link '" + name + "' is given a Data (" +
                             py::cast<LinkPath&>(value).text() + "); a link points to an object");
      return set_field_or_link(b, name, t);
    }
    if (py::isinstance<BaseHandle>(value)) {
      Base& target = py::cast<BaseHandle&>(value).get();
      if (!l->accept(&target)) throw py::type_error(b.describe() + ": link '" + name + "' cannot point to " + target.describe());
      if (!l->is_multi()) l->set_path("@" + path_of(target));
      return true;
    }
    std::string path = to_sofa_text(value);
    l->set_path(path);
    if (auto* c = dynamic_cast<Component*>(&b); c && c->node() && !path.empty()) {
      std::string why;
      Base* t = resolve_object_path(*c->node(), c, path[0] == '@' ? path.substr(1) : path,
                                    [l](Base* x) { return l->accept(x); }, &why);
      if (t) l->accept(t);
    }
    return true;
  }
  return false;
}

void base_setattr(py::object self, const std::string& name, py::object value) {
  auto& h = py::cast<BaseHandle&>(self);
  if (h.ptr && set_field_or_link(*h.ptr, name, value)) return;
  if (h.ptr && name.rfind("on", 0) == 0 && PyCallable_Check(value.ptr()))
    if (auto* host = dynamic_cast<PythonHost*>(h.ptr)) host->forget_cached(name);
  py::module_::import("builtins").attr("object").attr("__setattr__")(self, name, value);
}

// Inserts an object made in Python (or moved out of another node) into `node`.
py::object insert_object(Node& node, py::object obj) {
  auto& h = py::cast<ObjectHandle&>(obj);
  if (!h.owned) {
    if (!h.ptr) throw_reference_error("this object was destroyed");
    throw py::value_error(h.ptr->describe() + " is already in a graph; remove it first (removeObject)");
  }
  auto* c = static_cast<Component*>(h.owned.get());
  if (dynamic_cast<PythonHost*>(c)) {
    c->set_type(py::cast<std::string>(py::type::of(obj).attr("__name__")), c->template_name());
    if (c->name.value().empty()) c->name.set(c->class_name());
  }
  if (c->where.file.empty()) c->where = python_location();
  std::unique_ptr<Component> owned(static_cast<Component*>(h.owned.release()));
  if (!node.add_object(std::move(owned))) {
    h.owned = std::move(owned);  // refused: Python keeps it
    flush_messages(*node.root());
    throw py::value_error("cannot add " + c->describe() + " now (the graph is locked during a step)");
  }
  if (auto* host = dynamic_cast<PythonHost*>(c)) host->hold_self(true);
  return obj;
}

py::object add_object_by_type(Node& node, const std::string& type, py::kwargs kwargs) {
  scene::ObjectSpec spec;
  spec.type = type;
  spec.where = python_location();
  spec.base_dir = spec.where.file.empty() ? std::string(".") : scene::parent_dir(spec.where.file);
  spec.names = scene::DefaultNames::python;
  spec.report_unused = false;
  for (auto [k, v] : kwargs) spec.attributes.set(py::cast<std::string>(k), to_sofa_text(v));
  Diagnostics local;
  Component* c = scene::add_object(node, spec, resource_paths(node), local);
  Diagnostics& diag = node.diagnostics();
  std::string errors;
  for (const Message& m : local.messages()) {
    if (m.severity == Severity::error) errors += (errors.empty() ? "" : "\n") + Diagnostics::format(m);
    else diag.add(m.severity, m.where, m.who, m.text);
  }
  flush_messages(*node.root());
  if (!errors.empty()) throw py::value_error(errors);
  if (!c) throw py::value_error("cannot create '" + type + "'");
  if (!spec.unused.empty()) {
    std::string text = c->describe() + ": unknown attribute(s):";
    for (const auto& u : spec.unused) text += "\n  - " + u;
    throw py::type_error(text);
  }
  return wrap(c);
}

py::object add_child(Node& parent, py::object child) {
  auto& h = py::cast<NodeHandle&>(child);
  if (!h.owned) {
    // A node of the graph already: it gains a further parent (SOFA's DAG).
    if (!parent.add_linked_child(&h.node())) {
      flush_messages(*parent.root());
      throw py::value_error("cannot add " + h.node().describe() + " as a child of " + parent.describe() +
                            " (see the error above)");
    }
    return child;
  }
  std::unique_ptr<Node> owned(static_cast<Node*>(h.owned.release()));
  if (!parent.add_child(std::move(owned))) {
    h.owned = std::move(owned);  // refused (a cycle, or the graph is locked): Python keeps it
    flush_messages(*parent.root());
    throw py::value_error("cannot add " + h.node().describe() + " as a child of " + parent.describe() +
                          " (see the error above)");
  }
  return child;
}

py::object add_child_named(Node& parent, const std::string& name, py::kwargs kwargs) {
  auto n = std::make_unique<Node>(name);
  n->where = python_location();
  Node* raw = parent.add_child(std::move(n));
  if (!raw) {
    flush_messages(*parent.root());
    throw py::value_error("cannot add a child now (the graph is locked during a step)");
  }
  raw->name.set(name);
  py::object o = wrap(raw);
  for (auto [k, v] : kwargs) {
    const std::string key = py::cast<std::string>(k);
    if (!set_field_or_link(*raw, key, v)) throw py::type_error(unknown_attribute(*raw, key));
  }
  return o;
}

void give_back(Base* b, std::unique_ptr<Base> owned) {
  if (!owned) return;
  py::object o = wrap(b);
  auto& h = py::cast<BaseHandle&>(o);
  h.owned = std::move(owned);
  if (auto* host = dynamic_cast<PythonHost*>(b)) host->hold_self(false);
}

py::object node_getattr(py::object self, const std::string& name) {
  Node& n = py::cast<NodeHandle&>(self).node();
  if (Component* c = n.find_object_named(name)) return wrap(c);
  if (Node* child = n.find_child_named(name)) return wrap(child);
  if (auto r = field_or_link(self, n, name)) return *r;
  throw py::attribute_error(unknown_attribute(n, name));
}

py::object object_getattr(py::object self, const std::string& name) {
  Component& c = py::cast<ObjectHandle&>(self).component();
  if (BaseField* f = c.find_field(name)) {
    // A component's fields never change: the Data object is kept in the instance's
    // dictionary, so the next `obj.name` is a plain attribute read (no search, no new
    // object). Writes still go through __setattr__, which sets the value.
    py::object d = wrap_field(f, self);
    py::object dict = py::getattr(self, "__dict__", py::none());
    if (py::isinstance<py::dict>(dict)) dict[py::str(name)] = d;
    return d;
  }
  if (auto r = field_or_link(self, c, name)) return *r;
  throw py::attribute_error(unknown_attribute(c, name));
}

// root["child.object.data"]: a dotted path that only descends.
py::object node_getitem(py::object self, const std::string& path) {
  std::vector<std::string> parts;
  std::string cur;
  for (char ch : path) {
    if (ch == '.') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
    } else {
      cur += ch;
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  if (parts.empty()) throw py::value_error("invalid path '" + path + "'");
  py::object at = self;
  for (const auto& p : parts) {
    if (py::isinstance<NodeHandle>(at)) {
      at = node_getattr(at, p);
    } else if (py::isinstance<ObjectHandle>(at)) {
      at = object_getattr(at, p);
    } else {
      throw py::key_error("'" + path + "': '" + p + "' is below a Data");
    }
  }
  return at;
}

void node_init(Node& n) {
  Node& root = *n.root();
  {
    py::gil_scoped_release release;  // as a step: components may call Python from worker threads
    if (!root.initialised) init_root(root);
    else init_added(root);
  }
  flush_messages(root);
}

py::list data_fields(py::object self) {
  py::list out;
  for (BaseField* f : py::cast<BaseHandle&>(self).get().fields()) out.append(wrap_field(f, self));
  return out;
}

// Python components: the instance is the handle. Keyword arguments that name a
// Data set it; the others belong to the subclass (SofaPython3 ignores them here).
template <class H, class C>
H* make_python_component(std::unique_ptr<C> c, py::args args, py::kwargs kwargs) {
  auto* h = new H{};
  C* raw = c.get();
  h->owned = std::move(c);
  adopt(*h, raw);
  raw->bind_handle(h);
  if (args.size() == 1 && py::isinstance<py::str>(args[0])) raw->name.set(py::cast<std::string>(args[0]));
  for (auto [k, v] : kwargs) set_field_or_link(*raw, py::cast<std::string>(k), v);
  return h;
}

struct ControllerHandle : ObjectHandle {};
struct DataEngineHandle : ObjectHandle {};
template <StateType T>
struct ForceFieldHandle : ObjectHandle {};

template <StateType In, StateType Out>
struct MappingHandle : ObjectHandle {};

// SofaPython3's Mapping_<In>_<Out> (e.g. Mapping_Vec3d_Vec1d).
template <StateType In, StateType Out>
void define_mapping(py::module_& m) {
  const std::string name = std::string("Mapping_") + state_type_info(In).name + "_" + state_type_info(Out).name;
  py::class_<MappingHandle<In, Out>, ObjectHandle>(m, name.c_str(), py::dynamic_attr(),
                                                   "A mapping written in Python: override apply, applyJ, applyJT "
                                                   "(and applyConstraintsJT for Lagrangian constraints)")
      .def(py::init([](py::args a, py::kwargs k) {
        return make_python_component<MappingHandle<In, Out>>(std::make_unique<PythonMapping>(In, Out), a, k);
      }));
}

template <StateType T>
void define_force_field(py::module_& m, const char* name) {
  py::class_<ForceFieldHandle<T>, ObjectHandle>(m, name, py::dynamic_attr(),
                                                "A force field written in Python: override addForce, addDForce "
                                                "(and addKToMatrix for assembled solvers)")
      .def(py::init([](py::args a, py::kwargs k) {
        return make_python_component<ForceFieldHandle<T>>(std::make_unique<PythonForceField>(T), a, k);
      }));
}

}  // namespace

void define_graph(py::module_& m) {
  py::class_<BaseHandle>(m, "Base", py::dynamic_attr(), "Anything with Data: a node or an object")
      .def("getName", [](BaseHandle& h) {
        Base& b = h.get();
        if (auto* n = dynamic_cast<Node*>(&b)) return n->name.value();
        return static_cast<Component&>(b).name.value();
      })
      .def("setName", [](BaseHandle& h, const std::string& name) {
        Base& b = h.get();
        if (auto* n = dynamic_cast<Node*>(&b)) n->name.set(name);
        else static_cast<Component&>(b).name.set(name);
      })
      .def("getData", [](py::object self, const std::string& name) -> py::object {
        BaseField* f = py::cast<BaseHandle&>(self).get().find_field(name);
        return f ? wrap_field(f, self) : py::none();
      })
      .def("findData", [](py::object self, const std::string& name) -> py::object {
        BaseField* f = py::cast<BaseHandle&>(self).get().find_field(name);
        return f ? wrap_field(f, self) : py::none();
      })
      .def("getDataFields", &data_fields)
      .def("getLinks", [](BaseHandle& h) {
        py::list out;
        for (BaseLink* l : h.get().links()) out.append(py::make_tuple(l->name(), link_target(*l)));
        return out;
      })
      .def("addData", [](py::object self, const std::string& name, py::object value, py::object default_value,
                         const std::string& help, const std::string& group, const std::string& type) {
             BaseField& f = add_dynamic_field(py::cast<BaseHandle&>(self).get(), name, type, value, default_value, help, group);
             return wrap_field(&f, self);
           },
           py::arg("name"), py::arg("value") = py::none(), py::arg("default") = py::none(), py::arg("help") = "",
           py::arg("group") = "", py::arg("type") = "")
      .def("getPathName", [](BaseHandle& h) { return path_of(h.get()); })
      .def("getLinkPath", [](BaseHandle& h) { return "@" + path_of(h.get()); })
      .def_property_readonly("linkpath", [](py::object self) {
        py::cast<BaseHandle&>(self).get();
        return LinkPath{self};
      })
      .def("__setattr__", &base_setattr)
      .def("__repr__", [](BaseHandle& h) {
        return h.ptr ? "<" + h.ptr->describe() + " at " + path_of(*h.ptr) + ">" : std::string("<destroyed object>");
      });

  py::class_<NodeHandle, BaseHandle>(m, "Node", py::dynamic_attr(), "A node of the scene graph (SofaPython3's Node)")
      .def(py::init([](const std::string& name, py::kwargs kwargs) {
             auto* h = new NodeHandle{};
             auto n = std::make_unique<Node>(name);
             n->name.set(name);
             n->where = python_location();
             Node* raw = n.get();
             h->owned = std::move(n);
             adopt(*h, raw);
             for (auto [k, v] : kwargs) {
               const std::string key = py::cast<std::string>(k);
               if (!set_field_or_link(*raw, key, v)) throw py::type_error(unknown_attribute(*raw, key));
             }
             return h;
           }),
           py::arg("name") = "unnamed")
      .def("addObject", [](NodeHandle& h, py::object what, py::kwargs kwargs) -> py::object {
        if (py::isinstance<py::str>(what)) return add_object_by_type(h.node(), py::cast<std::string>(what), kwargs);
        if (py::isinstance<ObjectHandle>(what)) return insert_object(h.node(), what);
        throw py::type_error("addObject takes a type name (with its Data as keyword arguments) or an object");
      })
      .def("createObject", [](NodeHandle& h, const std::string& type, py::kwargs kwargs) {
        return add_object_by_type(h.node(), type, kwargs);
      })
      .def("addChild", [](NodeHandle& h, py::object what, py::kwargs kwargs) -> py::object {
        if (py::isinstance<py::str>(what)) return add_child_named(h.node(), py::cast<std::string>(what), kwargs);
        if (py::isinstance<NodeHandle>(what)) return add_child(h.node(), what);
        throw py::type_error("addChild takes a name (with Data as keyword arguments) or a Node");
      })
      .def("createChild", [](NodeHandle& h, const std::string& name, py::kwargs kwargs) {
        return add_child_named(h.node(), name, kwargs);
      })
      .def("removeObject", [](NodeHandle& h, py::object obj) {
        Component* c = &py::cast<ObjectHandle&>(obj).component();
        auto owned = h.node().remove_object(c);
        if (!owned) throw py::value_error(c->describe() + " is not an object of " + h.node().describe());
        give_back(c, std::unique_ptr<Base>(owned.release()));
      })
      .def("removeChild", [](NodeHandle& h, py::object child) {
        Node* n = nullptr;
        if (py::isinstance<py::str>(child)) n = h.node().find_child_named(py::cast<std::string>(child));
        else n = &py::cast<NodeHandle&>(child).node();
        if (!n) throw py::value_error("no child named " + py::cast<std::string>(py::str(child)));
        const auto& kids = h.node().children();
        if (std::find(kids.begin(), kids.end(), n) == kids.end())
          throw py::value_error(n->describe() + " is not a child of " + h.node().describe());
        const bool last_parent = n->parents().size() == 1;
        auto owned = h.node().remove_child(n);
        if (last_parent && !owned) {
          flush_messages(*h.node().root());
          throw py::value_error("cannot remove a child now (the graph is locked during a step)");
        }
        give_back(n, std::unique_ptr<Base>(owned.release()));  // nothing when other parents keep it
      })
      .def("detachFromGraph", [](NodeHandle& h) {
        // Every parent lets go; the last one hands the node back to Python.
        Node& n = h.node();
        while (Node* p = n.parent()) {
          auto owned = p->remove_child(&n);
          if (owned) give_back(&n, std::unique_ptr<Base>(owned.release()));
          else if (n.parent() == p) break;  // refused (graph locked)
        }
      })
      .def("getChild", [](NodeHandle& h, const std::string& name) { return wrap(h.node().find_child_named(name)); })
      .def("getObject", [](NodeHandle& h, const std::string& name) { return wrap(h.node().find_object_named(name)); })
      .def("hasObject", [](NodeHandle& h, const std::string& name) { return h.node().find_object_named(name) != nullptr; })
      .def_property_readonly("children", [](NodeHandle& h) {
        py::list out;
        for (Node* c : h.node().children()) out.append(wrap(c));
        return out;
      })
      .def_property_readonly("objects", [](NodeHandle& h) {
        py::list out;
        for (auto& o : h.node().objects()) out.append(wrap(o.get()));
        return out;
      })
      .def_property_readonly("parents", [](NodeHandle& h) {
        py::list out;
        for (Node* p : h.node().parents()) out.append(wrap(p));
        return out;
      })
      .def("getRoot", [](NodeHandle& h) { return wrap(h.node().root()); })
      .def("getRootPath", [](NodeHandle& h) {
        std::string p;
        for (Node* n = h.node().parent(); n; n = n->parent()) p += p.empty() ? ".." : "/..";
        return p;
      })
      .def("getContext", [](py::object self) { return self; })
      .def("getTime", [](NodeHandle& h) { return h.node().time.get(); })
      .def("getDt", [](NodeHandle& h) { return h.node().dt.get(); })
      .def("getGravity", [](NodeHandle& h) { return std::vector<double>(h.node().gravity.get().data(), h.node().gravity.get().data() + 3); })
      .def("init", [](NodeHandle& h) { node_init(h.node()); })
      .def("isInitialized", [](NodeHandle& h) { return h.node().initialised; })
      .def("getMechanicalState", [](NodeHandle& h) { return wrap(h.node().mechanical_state); })
      .def("getMechanicalMapping", [](NodeHandle& h) { return wrap(h.node().mechanical_mapping); })
      .def("getMass", [](NodeHandle& h) { return wrap(h.node().mass); })
      .def("getForceField", [](NodeHandle& h, std::size_t i) -> py::object {
        auto& ff = h.node().force_fields;
        return i < ff.size() ? wrap(ff[i]) : py::none();
      })
      .def("hasODESolver", [](NodeHandle& h) { return !h.node().solvers.empty(); })
      .def("sendEvent", [](NodeHandle& h, py::object user_data, const std::string& name) {
        Event e{};
        e.kind = Event::Kind::script;
        e.sender = &h.node();
        e.name = name;
        e.payload = user_data.ptr();
        propagate_event(h.node(), e);
        flush_messages(*h.node().root());
      })
      .def("computeEnergy", [](NodeHandle& h) { return compute_energy(h.node()); })
      .def("__getattr__", &node_getattr)
      .def("__getitem__", &node_getitem)
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](py::object, py::args) { return false; });

  py::class_<ObjectHandle, BaseHandle>(m, "Object", py::dynamic_attr(), "A component (SofaPython3's BaseObject)")
      .def("getContext", [](ObjectHandle& h) { return wrap(h.component().node()); })
      .def("getClassName", [](ObjectHandle& h) { return h.component().class_name(); })
      .def("getTemplateName", [](ObjectHandle& h) { return h.component().template_name(); })
      .def("init", [](ObjectHandle& h) {
        Component& c = h.component();
        c.init();
        c.mark_initialised();
      })
      .def("bwdInit", [](ObjectHandle& h) { h.component().bwd_init(); })
      .def("reinit", [](ObjectHandle& h) { h.component().reinit(); })
      .def("reset", [](ObjectHandle& h) { h.component().reset(); })
      .def("isValid", [](ObjectHandle& h) { return h.component().state() == ComponentState::valid; })
      .def("__getattr__", &object_getattr);

  define_matrix_access(m);
  define_topology(m);
  define_deformable(m);
  define_linear_system(m);
  define_constraint_solver(m);

  // Python components: subclass these and call the base __init__.
  py::class_<ControllerHandle, ObjectHandle>(m, "Controller", py::dynamic_attr(),
                                             "A component written in Python that reacts to events (on<Event>)")
      .def(py::init([](py::args a, py::kwargs k) {
        return make_python_component<ControllerHandle>(std::make_unique<PythonController>(), a, k);
      }));
  py::class_<DataEngineHandle, ObjectHandle>(m, "DataEngine", py::dynamic_attr(),
                                             "An engine written in Python: update() computes the outputs")
      .def(py::init([](py::args a, py::kwargs k) {
        return make_python_component<DataEngineHandle>(std::make_unique<PythonDataEngine>(), a, k);
      }))
      .def("addInput", [](ObjectHandle& h, DataHandle& d) {
        static_cast<PythonDataEngine&>(h.component()).add_python_input(&d.get());
      })
      .def("addOutput", [](ObjectHandle& h, DataHandle& d) {
        static_cast<PythonDataEngine&>(h.component()).add_python_output(&d.get());
      });
  define_force_field<StateType::vec3>(m, "ForceFieldVec3d");
  define_force_field<StateType::vec2>(m, "ForceFieldVec2d");
  define_force_field<StateType::vec1>(m, "ForceFieldVec1d");
  define_force_field<StateType::vec6>(m, "ForceFieldVec6d");
  define_force_field<StateType::rigid3>(m, "ForceFieldRigid3d");
  define_force_field<StateType::rigid2>(m, "ForceFieldRigid2d");
  using S = StateType;  // SofaPython3's list of mapping pairs
  define_mapping<S::vec1, S::vec1>(m);
  define_mapping<S::vec1, S::vec2>(m);
  define_mapping<S::vec1, S::vec3>(m);
  define_mapping<S::vec2, S::vec2>(m);
  define_mapping<S::vec2, S::vec1>(m);
  define_mapping<S::vec3, S::vec3>(m);
  define_mapping<S::vec3, S::vec2>(m);
  define_mapping<S::vec3, S::vec1>(m);
  define_mapping<S::vec6, S::vec6>(m);
  define_mapping<S::vec6, S::vec3>(m);
  define_mapping<S::vec6, S::vec1>(m);
  define_mapping<S::rigid2, S::vec2>(m);
  define_mapping<S::rigid2, S::rigid2>(m);
  define_mapping<S::rigid3, S::vec6>(m);
  define_mapping<S::rigid3, S::vec3>(m);
  define_mapping<S::rigid3, S::vec1>(m);
  define_mapping<S::rigid3, S::rigid3>(m);
  define_mapping<S::vec3, S::rigid3>(m);
}

}  // namespace sinew::python
