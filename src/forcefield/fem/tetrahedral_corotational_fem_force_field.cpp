#include "forcefield/fem/tetrahedral_corotational_fem_force_field.h"

#include <algorithm>

#include "core/assert.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/fem/tetra_fem_setup.h"

namespace sinew {

TetrahedralCorotationalFEMForceField::TetrahedralCorotationalFEMForceField() { assembling.add_alias("assembling"); }

void TetrahedralCorotationalFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  bool known = true;
  TetraFEMSetup in = read_tetra_fem_fields(*this, false, known);
  if (!known) msg_warning("unknown method '" + method.get() + "' (expected small, large or polar): large is used");

  if (in.topology && in.topology->tetrahedra().empty() && in.topology->hexahedra().empty() && mstate.get() &&
      mstate->state_type() == StateType::vec3) {
    // SOFA warns and computes nothing; tetrahedra added later are picked up by follow_topology.
    msg_warning("no tetrahedra found in the topology " + in.topology->describe());
    fem_ = fem::TetraFEM{};
    tetra_version_ = in.topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
    return;
  }
  fem_.update_stiffness_matrix = update_stiffness_matrix.get();
  fem_.assembling = assembling.get();
  fem_.symmetric_update = true;
  in.von_mises = compute_von_mises_stress.get();
  if (!setup_tetra_fem(*this, in, fem_)) {
    set_state(ComponentState::invalid);
    return;
  }
  if (topology) tetra_version_ = topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
  per_element_ = topology && young_modulus.get().size() <= 1 && poisson_ratio.get().size() <= 1 &&
                 local_stiffness_factor.get().empty() && !compute_von_mises_stress.get() &&
                 fem_.size() == topology->tetrahedra().size();
  needs_init_ = false;
  changed_ = false;
  follower_.attach(per_element_ ? topology.get() : nullptr);
  if (!fem_.forces_supported())
    msg_error("computeGlobalMatrix is not supported with method " + method.get() +
              ": this force field adds no force (as SOFA)");
}

void TetrahedralCorotationalFEMForceField::on_change(const TopologyChange& c) {
  using T = TopologyChangeType;
  if (needs_init_) return;
  switch (c.type) {
    case T::tetrahedra_removed:
      fem_.remove_elements(c.indices);
      changed_ = true;
      break;
    case T::points_removed:
      fem_.remove_points(c.indices);
      changed_ = true;
      break;
    case T::tetrahedra_added:
    case T::points_added:
      needs_init_ = true;
      break;
    case T::ending:
      if (changed_) fem_.end_change();
      changed_ = false;
      break;
    default:
      break;
  }
}

void TetrahedralCorotationalFEMForceField::follow_topology() {
  if (!topology || topology->elements_version(MeshTopologyBase::Elements::tetrahedra) == tetra_version_) return;
  if (per_element_ && !needs_init_ && !changed_ && fem_.size() == topology->tetrahedra().size() &&
      fem_.X0.size() == mstate->size()) {
    // The follower kept the element data in step with the container.
    SINEW_ASSERT(std::equal(fem_.tetra.begin(), fem_.tetra.end(), topology->tetrahedra().begin(),
                            [](const std::array<int, 4>& a, const Tetra& b) {
                              return std::equal(a.begin(), a.end(), b.begin(),
                                                [](int x, unsigned y) { return static_cast<unsigned>(x) == y; });
                            }),
                 "the followed elements equal the container's");
    tetra_version_ = topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
    return;
  }
  if (topology->tetrahedra().empty()) {
    // Every element was removed: no force, no error.
    fem_ = fem::TetraFEM{};
    tetra_version_ = topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
    return;
  }
  init();
}

void TetrahedralCorotationalFEMForceField::add_force(const MechParams& p) {
  follow_topology();
  MechanicalState& s = *mstate;
  add_tetra_fem_force(fem_, s, p);
  // SOFA computes it after each addForce, from the state's current positions.
  if (compute_von_mises_stress.value() && state() == ComponentState::valid)
    fem_.von_mises(as_vec3(s.read(kPosition)), 3, von_mises_per_element.edit(), von_mises_per_node.edit());
}

void TetrahedralCorotationalFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  add_tetra_fem_dforce(fem_, *mstate, p, kfactor);
}

bool TetrahedralCorotationalFEMForceField::build_stiffness(MatrixSink& K) {
  follow_topology();
  add_tetra_fem_stiffness(fem_, mstate.get(), K);
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
