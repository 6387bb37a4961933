// SofaPython3's SofaDeformable module: LinearSpring, and SpringForceField's
// spring list edited from Python (addSpring, removeSpring, clear, ...).
//
// Springs given to the force field are checked against its states (an end
// beyond a state raises IndexError) and used from the next force computation
// on; the force field also rewrites its per-spring Data from the new list.
#include <pybind11/stl.h>

#include <algorithm>
#include <sstream>

#include "forcefield/spring/spring_force_field.h"
#include "graph.h"
#include "handles.h"

namespace sinew::python {

namespace {

using springs::LinearSpring;

struct SpringForceFieldHandle : ObjectHandle {
  SpringForceField& ff() const { return static_cast<SpringForceField&>(component()); }
};

ObjectHandle* make_spring_handle(Component& c) {
  return dynamic_cast<SpringForceField*>(&c) ? new SpringForceFieldHandle{} : nullptr;
}

void replace(SpringForceFieldHandle& h, std::vector<LinearSpring> list) {
  SpringForceField& ff = h.ff();
  const std::string why = ff.set_springs(std::move(list));
  if (!why.empty()) throw py::index_error(ff.describe() + ": " + why);
}

void remove_spring(SpringForceFieldHandle& h, int index) {
  SpringForceField& ff = h.ff();
  std::vector<LinearSpring> list = ff.spring_list();
  // SOFA ignores an index past the end; a scene that removes one spring per key
  // press must keep running once none is left, so this warns instead of raising.
  if (index < 0 || static_cast<std::size_t>(index) >= list.size()) {
    ff.msg_warning("removeSpring(" + std::to_string(index) + "): there are " + std::to_string(list.size()) +
                   " springs; nothing removed");
    if (ff.node()) flush_messages(*ff.node()->root());
    return;
  }
  list.erase(list.begin() + index);
  replace(h, std::move(list));
}

}  // namespace

void define_deformable(py::module_& m) {
  py::class_<LinearSpring>(m, "LinearSpring", "A linear spring between point index1 of object1 and index2 of object2")
      .def(py::init([](unsigned i1, unsigned i2, double ks, double kd, double l0, bool elongation_only, bool enabled) {
             return LinearSpring{i1, i2, ks, kd, l0, elongation_only, enabled};
           }),
           py::arg("index1"), py::arg("index2"), py::arg("springStiffness") = 100.0, py::arg("dampingFactor") = 5.0,
           py::arg("restLength"), py::arg("elongationOnly") = false, py::arg("enabled") = true)
      .def_readwrite("index1", &LinearSpring::m1)
      .def_readwrite("index2", &LinearSpring::m2)
      .def_readwrite("springStiffness", &LinearSpring::ks)
      .def_readwrite("dampingFactor", &LinearSpring::kd)
      .def_readwrite("restLength", &LinearSpring::l0)
      .def_readwrite("elongationOnly", &LinearSpring::elongation_only)
      .def_readwrite("enabled", &LinearSpring::enabled)
      .def("__str__", [](const LinearSpring& s) {
        std::ostringstream o;
        o << "<Sofa.SofaDeformable.LinearSpring: [index1: " << s.m1 << "; index2: " << s.m2
          << "; springStiffness: " << s.ks << "; dampingFactor: " << s.kd << "; restLength: " << s.l0
          << "; elongationOnly: " << s.elongation_only << "; enabled: " << s.enabled << "] at " << &s << ">";
        return o.str();
      });

  py::class_<SpringForceFieldHandle, ObjectHandle>(m, "SpringForceField",
                                                   "SpringForceField (any template) with its spring list")
      .def("getSprings", [](SpringForceFieldHandle& h) { return h.ff().spring_list(); },
           "The springs in use (copies: change them through addSpring/removeSpring)")
      .def("clear", [](SpringForceFieldHandle& h, unsigned /*reserve*/) { replace(h, {}); }, py::arg("reserve") = 0,
           "Remove every spring")
      .def("removeSpring", &remove_spring, py::arg("index"), "Remove the spring at this index")
      .def(
          "removeSprings",
          [](SpringForceFieldHandle& h, std::vector<int> indices) {
            // Highest first, so the lower indices still name the springs the caller meant.
            std::sort(indices.begin(), indices.end(), std::greater<int>());
            for (int i : indices) remove_spring(h, i);
          },
          py::arg("indices"), "Remove the springs at these indices (of the list before the call)")
      .def(
          "addSpring",
          [](SpringForceFieldHandle& h, const LinearSpring& s) {
            auto list = h.ff().spring_list();
            list.push_back(s);
            replace(h, std::move(list));
          },
          py::arg("spring"), "Append a spring")
      .def(
          "addSpring",
          [](SpringForceFieldHandle& h, unsigned i1, unsigned i2, double ks, double kd, double l0) {
            auto list = h.ff().spring_list();
            list.push_back(LinearSpring{i1, i2, ks, kd, l0, false, true});
            replace(h, std::move(list));
          },
          py::arg("index1"), py::arg("index2"), py::arg("springStiffness"), py::arg("dampingFactor"),
          py::arg("restLength"), "Append a spring")
      .def(
          "addSprings",
          [](SpringForceFieldHandle& h, const std::vector<LinearSpring>& add) {
            auto list = h.ff().spring_list();
            list.insert(list.end(), add.begin(), add.end());
            replace(h, std::move(list));
          },
          py::arg("springs"), "Append springs");
  register_handle_maker(&make_spring_handle);
}

}  // namespace sinew::python
