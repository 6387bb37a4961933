// Initialisation shared by TetrahedronFEMForceField and
// TetrahedralCorotationalFEMForceField: element list, per-element material
// (SOFA's broadcast and validation rules, spec/mechanics.md §0.4), kernel
// init, messages attributed to the component.
#pragma once

#include <vector>

#include "core/node.h"
#include "core/roles.h"
#include "forcefield/fem/tetra_fem.h"

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

// Both tetrahedral components declare the material fields under SOFA's same
// names (topology, youngModulus, poissonRatio, localStiffnessFactor, method),
// so one template reads them. `tetrahedron_fem` turns on what only
// TetrahedronFEMForceField accepts: the svd method and the hexahedron split.
// Binds the node's topology when none is linked. The caller reports an
// unknown method (`method_known` false): the two components word it differently.
template <class TetraComponent>
TetraFEMSetup read_tetra_fem_fields(TetraComponent& c, bool tetrahedron_fem, bool& method_known) {
  if (!c.topology) c.topology.set(c.node()->get_mesh_topology_link());
  TetraFEMSetup in;
  in.topology = c.topology.get();
  in.allow_hexa_split = tetrahedron_fem;
  in.young = c.young_modulus.get();
  in.poisson = c.poisson_ratio.get();
  in.local_stiffness_factor = c.local_stiffness_factor.get();
  in.method = parse_tetra_method(c.method.get(), tetrahedron_fem, method_known);
  return in;
}

// add_force, add_dforce and build_stiffness of both components: the kernel on
// the component's Vec3d state.
void add_tetra_fem_force(fem::TetraFEM& fem, MechanicalState& s, const MechParams& p);
void add_tetra_fem_dforce(const fem::TetraFEM& fem, MechanicalState& s, const MechParams& p, double kfactor);
void add_tetra_fem_stiffness(const fem::TetraFEM& fem, const MechanicalState* s, MatrixSink& K);

}  // namespace sinew
