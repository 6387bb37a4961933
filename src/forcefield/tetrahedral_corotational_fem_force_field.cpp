#include "forcefield/tetrahedral_corotational_fem_force_field.h"

#include "core/node.h"
#include "core/registry.h"
#include "forcefield/tetra_fem_setup.h"

namespace sinew {

TetrahedralCorotationalFEMForceField::TetrahedralCorotationalFEMForceField() { assembling.add_alias("assembling"); }

void TetrahedralCorotationalFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!topology) topology.set(node()->get_mesh_topology_link());

  bool known = true;
  TetraFEMSetup in;
  in.topology = topology.get();
  in.allow_hexa_split = false;
  in.young = young_modulus.get();
  in.poisson = poisson_ratio.get();
  in.local_stiffness_factor = local_stiffness_factor.get();
  in.method = parse_tetra_method(method.get(), false, known);
  if (!known) msg_warning("unknown method '" + method.get() + "' (expected small, large or polar): large is used");

  fem_.update_stiffness_matrix = update_stiffness_matrix.get();
  fem_.assembling = assembling.get();
  fem_.symmetric_update = true;
  in.von_mises = compute_von_mises_stress.get();
  if (!setup_tetra_fem(*this, in, fem_)) {
    state_ = ComponentState::invalid;
    return;
  }
  if (!fem_.forces_supported())
    msg_error("computeGlobalMatrix is not supported with method " + method.get() +
              ": this force field adds no force (as SOFA)");
}

void TetrahedralCorotationalFEMForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.vec(p.x);
  std::vector<double>& f = s.vec(p.f);
  fem_.add_force(as_vec3(x), as_vec3(f));
  // SOFA computes it after each addForce, from the state's current positions.
  if (compute_von_mises_stress.value() && state() == ComponentState::valid)
    fem_.von_mises(as_vec3(s.vec(kPosition)), 3, von_mises_per_element.edit(), von_mises_per_node.edit());
}

void TetrahedralCorotationalFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const std::vector<double>& dx = s.vec(p.dx);
  std::vector<double>& df = s.vec(p.df);
  fem_.add_dforce(as_vec3(dx), as_vec3(df), kfactor);
}

bool TetrahedralCorotationalFEMForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  fem_.add_stiffness_blocks([&](int i, int j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
  return true;
}

void register_tetrahedral_corotational_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedralCorotationalFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "tetrahedral corotational finite elements (large, polar) or linear (small)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TetrahedralCorotationalFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
