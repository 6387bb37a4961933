#include "forcefield/hyperelastic/tetrahedron_hyperelasticity_fem_force_field.h"

#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

void HyperelasticTetraForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  reported_inversion_ = false;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  MeshTopologyBase* topo = topology.get();
  if (!topo) {
    msg_error("no topology found (a tetrahedral mesh is required)");
    set_state(ComponentState::invalid);
    return;
  }
  MechanicalState* s = mstate.get();
  if (s->state_type() != StateType::vec3) {
    msg_error("only Vec3d states are supported");
    set_state(ComponentState::invalid);
    return;
  }

  const std::string& name = material_name.get();
  const hyper::MaterialName* m = hyper::find_material(name);
  // SOFA's StandardTetrahedralFEMForceField has no StableNeoHookean.
  if (m && form_ == hyper::Formulation::standard && m->material == hyper::Material::stable_neo_hookean) m = nullptr;
  if (!m || !m->supported) {
    std::string known;
    for (const auto& n : hyper::material_names())
      if (n.supported && !(form_ == hyper::Formulation::standard && n.material == hyper::Material::stable_neo_hookean))
        known += (known.empty() ? "" : ", ") + std::string(n.name);
    msg_error("materialName '" + name + "' is " + (m ? "not supported" : "unknown") + " (supported: " + known + ")");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& params = parameter_set.get();
  const std::size_t need = static_cast<std::size_t>(m->nb_params);
  if (params.size() != need) {
    msg_error("material " + name + " needs " + std::to_string(need) + " values in ParameterSet (" +
              std::string(m->params) + "), " + std::to_string(params.size()) + " given");
    set_state(ComponentState::invalid);
    return;
  }
  if (m->material == hyper::Material::ogden && params[1] == 0) {
    msg_error("Ogden: alpha1 (second value of ParameterSet) must not be 0");
    set_state(ComponentState::invalid);
    return;
  }

  const auto& tets = topo->tetrahedra();
  if (tets.empty()) {
    msg_error("the topology " + topo->describe() + " has no tetrahedra");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& x0 = s->read(kRestPosition);
  const auto issues =
      fem_.init(as_vec3(x0), tets, topo->edges(), topo->edges_in_tetrahedron(), m->material, params, form_);
  for (const auto& is : issues)
    msg_error((is.element >= 0 ? "tetrahedron " + std::to_string(is.element) + ": " : std::string()) + is.message);
  if (!issues.empty()) set_state(ComponentState::invalid);
}

std::optional<double> HyperelasticTetraForceField::potential_energy() const {
  if (state() != ComponentState::valid) return std::nullopt;
  return fem_.energy(as_vec3(mstate->read(kPosition)));
}

void HyperelasticTetraForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  fem_.add_force(as_vec3(s.read(p.x)), as_vec3(s.write(p.f)));
  if (fem_.bad_element() >= 0 && !reported_inversion_) {
    reported_inversion_ = true;
    msg_error("tetrahedron " + std::to_string(fem_.bad_element()) + " is inverted or flat (J = " +
              parse::format_double(fem_.bad_j()) + ") at time " + parse::format_double(node()->time.value()) +
              ": such elements add no force (reported once)");
  }
}

void HyperelasticTetraForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  fem_.add_dforce(as_vec3(s.read(p.dx)), as_vec3(s.write(p.df)), kfactor);
}

bool HyperelasticTetraForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  fem_.stiffness_blocks([&](unsigned i, unsigned j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
  return true;
}

void register_tetrahedron_hyperelasticity_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronHyperelasticityFEMForceField";
  info.category = "ForceField/FEM";
  info.description =
      "hyperelastic tetrahedral finite elements (ArrudaBoyce, StVenantKirchhoff, NeoHookean, MooneyRivlin, "
      "VerondaWestman, Costa, Ogden, StableNeoHookean)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TetrahedronHyperelasticityFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
