#include "forcefield/fem/fast_tetrahedral_corotational_force_field.h"

#include "core/matrix_sink.h"
#include "core/node.h"
#include "core/parse.h"
#include "core/registry.h"

namespace sinew {

void FastTetrahedralCorotationalForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!topology) topology.set(node()->get_mesh_topology_link());
  if (!topology) {
    msg_error("no topology found (a tetrahedral mesh is required)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!mstate || mstate->state_type() != StateType::vec3) {
    msg_error("only Vec3d states are supported");
    set_state(ComponentState::invalid);
    return;
  }
  if (!fem::parse_fast_tetra_method(method.get(), method_)) {
    // SOFA reports it and then runs with an undefined method.
    msg_error("unknown method '" + method.get() + "' (expected qr, large, polar, polar2, linear, none or small)");
    set_state(ComponentState::invalid);
    return;
  }
  // SOFA's checks on the material, once, values replaced in the fields.
  auto& ym = young_modulus.edit();
  bool warned_zero = false;
  for (double& e : ym)
    if (e < 0) {
      msg_warning("youngModulus " + parse::format_double(e) + " must be positive: replaced by 5000");
      e = 5000.0;
    } else if (e == 0 && !warned_zero) {
      // Accepted as in SOFA, but worth saying.
      msg_warning("youngModulus 0: the elements using it have no stiffness");
      warned_zero = true;
    }
  auto& pr = poisson_ratio.edit();
  for (double& v : pr)
    if (v < 0 || v >= 0.5) {
      msg_warning("poissonRatio " + parse::format_double(v) + " must be in [0, 0.5): replaced by 0.45");
      v = 0.45;
    }
  if (topology->tetrahedra().empty()) {
    msg_error("no tetrahedra found in the topology " + topology->describe());
    set_state(ComponentState::invalid);
    return;
  }
  if (!setup()) set_state(ComponentState::invalid);
}

bool FastTetrahedralCorotationalForceField::setup() {
  MeshTopologyBase& topo = *topology;
  const auto& tets = topo.tetrahedra();
  const std::size_t ne = tets.size();
  // SOFA's per-element lookup: value i when there is one, else the first.
  const auto& ym = young_modulus.get();
  const auto& pr = poisson_ratio.get();
  if (ym.empty()) msg_warning("youngModulus is empty: 5000 is used");
  if (pr.empty()) msg_warning("poissonRatio is empty: 0.45 is used");
  std::vector<double> E(ne), nu(ne);
  for (std::size_t i = 0; i < ne; ++i) {
    E[i] = ym.empty() ? 5000.0 : (i < ym.size() ? ym[i] : ym[0]);
    nu[i] = pr.empty() ? 0.45 : (i < pr.size() ? pr[i] : pr[0]);
  }
  const auto& edges = topo.edges();
  const auto& tetra_edges = topo.edges_in_tetrahedron();
  const std::string problem =
      fem_.init(as_vec3(mstate->read(kRestPosition)), tets, edges, tetra_edges, E, nu, method_);
  tetra_version_ = topo.elements_version(MeshTopologyBase::Elements::tetrahedra);
  edge_version_ = topo.elements_version(MeshTopologyBase::Elements::edges);
  if (!problem.empty()) {
    msg_error(problem);
    return false;
  }
  return true;
}

void FastTetrahedralCorotationalForceField::follow_topology() {
  if (!topology) return;
  if (topology->elements_version(MeshTopologyBase::Elements::tetrahedra) == tetra_version_ &&
      topology->elements_version(MeshTopologyBase::Elements::edges) == edge_version_ &&
      fem_.size() == topology->tetrahedra().size())
    return;
  if (topology->tetrahedra().empty()) {
    fem_ = fem::FastTetraCorotational{};  // every element removed: no force
    tetra_version_ = topology->elements_version(MeshTopologyBase::Elements::tetrahedra);
    edge_version_ = topology->elements_version(MeshTopologyBase::Elements::edges);
    return;
  }
  if (!setup()) set_state(ComponentState::invalid);
}

void FastTetrahedralCorotationalForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  follow_topology();
  if (state() != ComponentState::valid) return;
  const std::vector<double>& x = mstate->read(p.x);
  std::vector<double>& f = mstate->write(p.f);
  fem_.add_force(x.data(), f.data());
}

void FastTetrahedralCorotationalForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  const std::vector<double>& dx = mstate->read(p.dx);
  std::vector<double>& df = mstate->write(p.df);
  fem_.add_dforce(dx.data(), df.data(), kfactor);
}

bool FastTetrahedralCorotationalForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  follow_topology();
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  fem_.stiffness_blocks(
      [&](std::size_t i, std::size_t j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
  return true;
}

void register_fast_tetrahedral_corotational_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "FastTetrahedralCorotationalForceField";
  info.category = "ForceField/FEM";
  info.description =
      "corotational tetrahedral FEM with edge-stored stiffness (rotation by qr, polar, polar2, or linear)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<FastTetrahedralCorotationalForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
