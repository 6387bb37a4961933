// Initialisation shared by TetrahedronFEMForceField and
// TetrahedralCorotationalFEMForceField: element list, per-element material
// (SOFA's broadcast and validation rules, spec/mechanics.md §0.4), kernel
// init, messages attributed to the component.
#pragma once

#include <vector>

#include "core/roles.h"
#include "forcefield/tetra_fem.h"

namespace sinew {

struct TetraFEMSetup {
  MeshTopologyBase* topology = nullptr;
  bool allow_hexa_split = false;  // TetrahedronFEMForceField: split hexahedra when there are no tetrahedra
  std::vector<double> young, poisson, local_stiffness_factor;
  fem::TetraMethod method = fem::TetraMethod::large;
  bool von_mises = false;  // prepare the von Mises output data
};

// Fills `fem` from the component's state rest positions; reports problems
// through `c` and returns false when the component cannot run.
bool setup_tetra_fem(ForceField& c, const TetraFEMSetup& in, fem::TetraFEM& fem);

// Parses SOFA's method names; `allow_svd` for TetrahedronFEMForceField.
// Unknown names give large (SOFA), `known` tells the caller.
fem::TetraMethod parse_tetra_method(const std::string& name, bool allow_svd, bool& known);

}  // namespace sinew
