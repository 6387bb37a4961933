#include "forcefield/fem/tetrahedron_fem_force_field.h"

#include "core/node.h"
#include "core/registry.h"
#include "forcefield/fem/tetra_fem_setup.h"

namespace sinew {

TetrahedronFEMForceField::TetrahedronFEMForceField() { assembling.add_alias("assembling"); }

void TetrahedronFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  bool known = true;
  TetraFEMSetup in = read_tetra_fem_fields(*this, true, known);
  if (!known) msg_error("unknown method '" + method.get() + "' (expected small, large, polar or svd): large is used");

  const int vm = compute_von_mises_stress.get();
  von_mises_mode_ = vm;
  if (vm < 0 || vm > 2) {
    msg_warning("computeVonMisesStress must be 0, 1 or 2: no von Mises stress is computed");
    von_mises_mode_ = 0;
  }
  if (vm == 1 && in.method == fem::TetraMethod::small) {
    msg_warning("VonMisesStress can only be computed with full Green strain when the method is SMALL");
    von_mises_mode_ = 0;
  }
  in.von_mises = von_mises_mode_ != 0;

  fem_.update_stiffness_matrix = update_stiffness_matrix.get();
  fem_.assembling = assembling.get();
  fem_.symmetric_update = false;
  fem_.plasticity.max_threshold = plastic_max_threshold.get();
  fem_.plasticity.yield_threshold = plastic_yield_threshold.get();
  fem_.plasticity.creep = plastic_creep.get();
  if (!setup_tetra_fem(*this, in, fem_)) {
    set_state(ComponentState::invalid);
    return;
  }
  if (!fem_.forces_supported())
    msg_error(std::string("computeGlobalMatrix is not supported with ") +
              (fem_.plasticity.max_threshold > 0 ? "plasticity" : "method " + method.get()) +
              ": this force field adds no force (as SOFA)");
  initial_points.set(std::vector<Vec3>(fem_.X0.begin(), fem_.X0.end()));
  update_von_mises();
}

void TetrahedronFEMForceField::update_von_mises() {
  if (von_mises_mode_ == 0 || state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  fem_.von_mises(as_vec3(s.read(kPosition)), von_mises_mode_, von_mises_per_element.edit(),
                 von_mises_per_node.edit());
}

void TetrahedronFEMForceField::handle_event(Event& ev) {
  if (ev.kind == Event::Kind::animate_end) update_von_mises();
}

void TetrahedronFEMForceField::reset() { fem_.reset_plasticity(); }

void TetrahedronFEMForceField::add_force(const MechParams& p) {
  add_tetra_fem_force(fem_, *mstate, p);
}

void TetrahedronFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  add_tetra_fem_dforce(fem_, *mstate, p, kfactor);
}

bool TetrahedronFEMForceField::build_stiffness(MatrixSink& K) {
  add_tetra_fem_stiffness(fem_, mstate.get(), K);
  return true;
}

std::optional<double> TetrahedronFEMForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  if (fem_.method != fem::TetraMethod::small) return std::nullopt;
  const std::span<const Vec3> x = as_vec3(mstate->read(kPosition));
  if (x.size() < fem_.X0.size()) return std::nullopt;
  // The blocks are those of ∂f/∂x = −K.
  double e = 0;
  fem_.add_stiffness_blocks(
      [&](int i, int j, const Mat3& b) { e -= 0.5 * (x[i] - fem_.X0[i]).dot(b * (x[j] - fem_.X0[j])); });
  return e;
}

void register_tetrahedron_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "tetrahedral finite elements, linear (small) or corotational (large, polar, svd), with plasticity";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TetrahedronFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
