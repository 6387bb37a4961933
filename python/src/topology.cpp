// Topology modifiers from Python (SofaPython3's PointSetTopologyModifier binding):
// addPoints and removePoints on any dynamic modifier.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "graph.h"
#include "handles.h"
#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew::python {

namespace {

PointSetTopologyModifier& modifier(ObjectHandle& h) {
  auto* m = dynamic_cast<PointSetTopologyModifier*>(&h.component());
  if (!m) throw py::type_error(h.component().describe() + " is not a topology modifier");
  return *m;
}

}  // namespace

void define_topology(py::module_& m) {
  auto object = py::reinterpret_borrow<py::object>(m.attr("Object"));
  object.attr("addPoints") = py::cpp_function(
      [](ObjectHandle& h, unsigned n, bool add_dof) {
        PointSetTopologyModifier& mod = modifier(h);
        mod.add_points(n, {}, {}, add_dof);
        flush_messages(*mod.node()->root());
      },
      py::is_method(object), py::name("addPoints"), py::arg("nPoints"), py::arg("addDOF") = true,
      py::doc("Add n points to the modifier's container (and DoFs to the states using it)"));
  object.attr("removePoints") = py::cpp_function(
      [](ObjectHandle& h, std::vector<unsigned> indices, bool remove_dof) {
        PointSetTopologyModifier& mod = modifier(h);
        mod.remove_points(std::move(indices), remove_dof);
        flush_messages(*mod.node()->root());
      },
      py::is_method(object), py::name("removePoints"), py::arg("indices"), py::arg("removeDOF") = true,
      py::doc("Remove points (SOFA's swap-with-last order; the states using the container follow)"));
  object.attr("removeItems") = py::cpp_function(
      [](ObjectHandle& h, std::vector<unsigned> indices) {
        PointSetTopologyModifier& mod = modifier(h);
        std::string why;
        if (!mod.remove_items(indices, &why)) throw py::value_error(why);
        flush_messages(*mod.node()->root());
      },
      py::is_method(object), py::name("removeItems"), py::arg("indices"),
      py::doc("Remove elements of the modifier's kind (points, edges, triangles, ... ) and what they leave isolated"));
}

}  // namespace sinew::python
