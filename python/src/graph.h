// Bindings of the scene graph and of the simulation entry points.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <vector>

#include "core/node.h"
#include "scene/resource_paths.h"

namespace sinew::python {

namespace py = pybind11;

void define_graph(py::module_& m);       // Base, Node, Object, Python component bases
void define_matrix_access(py::module_& m);
void define_topology(py::module_& m);      // addPoints / removePoints / removeItems on modifiers
void define_deformable(py::module_& m);    // LinearSpring, SpringForceField (Sofa.SofaDeformable)
void define_linear_system(py::module_& m);  // linear systems and solvers' A, b, x (Sofa.SofaLinearSystem/Solver)
void define_constraint_solver(py::module_& m);  // W, lambda_force, dfree (Sofa.SofaConstraintSolver)

// A scipy.sparse CSR matrix from its three arrays (copied).
py::object scipy_csr(const std::vector<double>& values, const std::vector<std::int32_t>& cols,
                     const std::vector<std::int32_t>& row_begin, std::size_t n_rows, std::size_t n_cols);
void define_simulation(py::module_& m);  // init, animate, reset, load, messages, factory
void define_gui(py::module_& m);         // the viewer under Sofa.Gui.GUIManager

// (kinetic, potential) energy of the subtree (SOFA's MechanicalComputeEnergyVisitor).
py::tuple compute_energy(Node& node);
// Where resource files named by Python-made objects are searched: the data
// folders given to the run (`--data-path`, DataRepository) and $SOFA_DATA_PATH.
scene::ResourcePaths resource_paths(Node& node);
std::vector<std::string>& data_paths();

}  // namespace sinew::python
