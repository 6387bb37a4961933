#include "forcefield/hexahedron_fem_force_field.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void HexahedronFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (a hexahedral mesh is required)");
    state_ = ComponentState::invalid;
    return;
  }
  const auto& hexas = topology->hexahedra();
  if (hexas.empty()) {
    msg_error("the topology " + topology->describe() + " has no hexahedra");
    state_ = ComponentState::invalid;
    return;
  }
  fem::HexaMethod m;
  if (method.value() == "large") m = fem::HexaMethod::large;
  else if (method.value() == "polar") m = fem::HexaMethod::polar;
  else if (method.value() == "small") m = fem::HexaMethod::small;
  else {
    msg_error("unknown method '" + method.value() + "' (expected large, polar or small)");
    state_ = ComponentState::invalid;
    return;
  }
  const std::size_t ne = hexas.size();
  // Per-element material: value i if given, else value 0 (SOFA's broadcast);
  // out-of-range values are replaced by SOFA's defaults with a message.
  std::vector<double> E(ne), nu(ne);
  const auto& ey = young_modulus.get();
  const auto& pr = poisson_ratio.get();
  for (std::size_t i = 0; i < ne; ++i) {
    double e = ey.empty() ? 5000.0 : (i < ey.size() ? ey[i] : ey[0]);
    double v = pr.empty() ? 0.45 : (i < pr.size() ? pr[i] : pr[0]);
    if (!(e > 0)) {
      if (i < ey.size() || i == 0)
        msg_warning("youngModulus of element " + std::to_string(i) + " is " + parse::format_double(e) +
                    (e < 0 ? ": replaced by 5000" : ": the element has no stiffness"));
      if (e < 0) e = 5000.0;
    }
    if (v < 0 || v >= 0.5) {
      if (i < pr.size() || i == 0)
        msg_warning("poissonRatio of element " + std::to_string(i) + " is " + parse::format_double(v) +
                    " (must be in [0, 0.5)): replaced by 0.45");
      v = 0.45;
    }
    E[i] = e;
    nu[i] = v;
  }
  MechanicalState& s = *mstate;
  if (s.state_type() != StateType::vec3) {
    msg_error("only Vec3d states are supported");
    state_ = ComponentState::invalid;
    return;
  }
  const std::vector<double>& x0 = s.vec(kRestPosition);
  std::vector<std::array<int, 8>> h(ne);
  for (std::size_t i = 0; i < ne; ++i)
    for (int k = 0; k < 8; ++k) h[i][k] = static_cast<int>(hexas[i][k]);
  fem_.update_stiffness = update_stiffness_matrix.value();
  const auto issues = fem_.init(as_vec3(x0), h, E, nu, m);
  bool fatal = false;
  for (const auto& is : issues) {
    const std::string where = is.element >= 0 ? "element " + std::to_string(is.element) + ": " : "";
    if (is.fatal) {
      msg_error(where + is.message);
      fatal = true;
    } else {
      msg_warning(where + is.message);
    }
  }
  if (fatal) state_ = ComponentState::invalid;
}

void HexahedronFEMForceField::add_force(const MechParams& p) {
  MechanicalState& s = *mstate;
  const std::vector<double>& x = s.vec(p.x);
  std::vector<double>& f = s.vec(p.f);
  fem_.add_force(as_vec3(x), as_vec3(f));
}

void HexahedronFEMForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const std::vector<double>& dx = s.vec(p.dx);
  std::vector<double>& df = s.vec(p.df);
  fem_.add_dforce(as_vec3(dx), as_vec3(df), kfactor);
}

bool HexahedronFEMForceField::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  // ∂f/∂x blocks −Rᵀ·K_ij·R (kfactor 1); the assembler applies its factor.
  fem_.add_stiffness_blocks(1.0, [&](int i, int j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
  return true;
}

void register_hexahedron_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronFEMForceField";
  info.category = "ForceField/FEM";
  info.description = "hexahedral finite elements, corotational (large, polar) or linear (small)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<HexahedronFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
