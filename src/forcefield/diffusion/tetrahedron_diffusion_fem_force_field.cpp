#include "forcefield/diffusion/tetrahedron_diffusion_fem_force_field.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/fem/sofa_mat3.h"
#include "topology/mesh_topology.h"

namespace sinew {

// SOFA's context get with a tag, SearchUp: this node's objects, then each parent's, upwards.
MechanicalState* TetrahedronDiffusionFEMForceField::find_geometry() const {
  const std::string& tag = tag_mechanics.value();
  auto tagged = [&](const Component& c) {
    const auto& t = c.tags.value();
    return std::find(t.begin(), t.end(), tag) != t.end();
  };
  std::vector<const Node*> todo{node()};
  for (std::size_t k = 0; k < todo.size(); ++k) {
    for (const auto& o : todo[k]->objects())
      if (auto* s = dynamic_cast<MechanicalState*>(o.get()); s && tagged(*s)) return s;
    for (const Node* p : todo[k]->parents())
      if (std::find(todo.begin(), todo.end(), p) == todo.end()) todo.push_back(p);
  }
  return nullptr;
}

void TetrahedronDiffusionFEMForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  const StateType st = mstate->state_type();
  if (st != StateType::vec1 && st != StateType::vec2 && st != StateType::vec3) {
    msg_error(std::string("needs a Vec1d, Vec2d or Vec3d state (got ") + mstate->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  width_ = mstate->info().deriv_width;
  if (!bind_node_topology(*this, topology, "a tetrahedral mesh is required")) return;
  const MeshTopologyBase& t = *topology;
  const std::size_t nt = t.tetrahedra().size();
  if (nt == 0) msg_warning("no tetrahedra found in the topology " + t.describe());
  auto coef = tetra_diffusion_coefficient.value();
  if (coef.empty()) {
    coef.assign(nt, constant_diffusion_coefficient.value());
    tetra_diffusion_coefficient.set(coef);
  } else if (coef.size() != nt) {
    msg_error("tetraDiffusionCoefficient has " + std::to_string(coef.size()) + " values for " + std::to_string(nt) +
              " tetrahedra");
    set_state(ComponentState::invalid);
    return;
  }
  const MechanicalState* geometry = find_geometry();
  if (!geometry) {
    msg_error("no state tagged '" + tag_mechanics.value() + "' (tagMechanics) in this node or above: it gives the "
              "geometry of the mesh");
    set_state(ComponentState::invalid);
    return;
  }
  if (geometry->state_type() != StateType::vec3) {
    msg_error("the state tagged '" + tag_mechanics.value() + "' (" + geometry->describe() + ") is not Vec3d");
    set_state(ComponentState::invalid);
    return;
  }
  const std::size_t np = std::min(mstate->size(), geometry->size());
  if (!element_points_in_state(*this, t.tetrahedra(), "tetrahedron", np) ||
      !element_points_in_state(*this, t.edges(), "edge", np)) {
    set_state(ComponentState::invalid);
    return;
  }
  if (t.edges_in_tetrahedron().size() != nt) {
    msg_error("the topology " + t.describe() + " gives no edges of its tetrahedra");
    set_state(ComponentState::invalid);
    return;
  }
  const double r = anisotropy_ratio.value();
  const bool isotropic = r == 1.0;
  if (!isotropic && anisotropy_direction.value().size() < nt) {
    msg_error("anisotropyRatio " + std::to_string(r) + " needs one transverseAnisotropyArray direction per "
              "tetrahedron (" + std::to_string(anisotropy_direction.value().size()) + " for " + std::to_string(nt) +
              ")");
    set_state(ComponentState::invalid);
    return;
  }
  // SOFA's computeEdgeDiffusionCoefficient, from the geometry's positions at init.
  const double* x = geometry->read(kPosition).data();
  edge_coef_.assign(t.edges().size(), 0.0);
  for (std::size_t i = 0; i < nt; ++i) {
    const auto& te = t.edges_in_tetrahedron()[i];
    const Tetra& tet = t.tetrahedra()[i];
    Vec3 p[4], shape[4];
    for (int j = 0; j < 4; ++j) p[j] = fem::at3(x, tet[j]);
    const double volume = fem::dot3(fem::cross3(p[1] - p[0], p[2] - p[0]), p[0] - p[3]);
    if (!(volume != 0) || !std::isfinite(volume)) {
      msg_error("tetrahedron " + std::to_string(i) + " (" + std::to_string(tet[0]) + " " + std::to_string(tet[1]) +
                " " + std::to_string(tet[2]) + " " + std::to_string(tet[3]) + ") is degenerate: its volume is 0");
      set_state(ComponentState::invalid);
      return;
    }
    for (int j = 0; j < 4; ++j) {
      const Vec3 c = fem::cross3(p[(j + 2) % 4] - p[(j + 1) % 4], p[(j + 3) % 4] - p[(j + 1) % 4]);
      const Vec3 s = j % 2 == 0 ? Vec3(-c) : c;
      shape[j] = Vec3(s[0] / volume, s[1] / volume, s[2] / volume);
    }
    const double diff = coef[i] * std::fabs(volume) / 6;
    for (int j = 0; j < 6; ++j) {
      const unsigned k = topo::kEdgesInTetra[j][0], l = topo::kEdgesInTetra[j][1];
      double val;
      if (isotropic) {
        val = fem::dot3(shape[k], shape[l]) * diff;
      } else {
        const Vec3& a = anisotropy_direction.value()[i];
        const double along = (r - 1) * fem::dot3(a, shape[l]);
        val = fem::dot3(shape[k], shape[l] + Vec3(a[0] * along, a[1] * along, a[2] * along)) * diff;
      }
      edge_coef_[te[j]] += val;
    }
  }
}

// Per edge (v0, v1): f[v1] += (u[v1] − u[v0])·c·factor, f[v0] −= the same (factor 1 for the
// force: a product by 1 changes no bit).
void TetrahedronDiffusionFEMForceField::add_fluxes(const double* u, double* f, double factor) const {
  const auto& edges = topology->edges();
  const std::size_t ne = std::min(edges.size(), edge_coef_.size());
  const std::size_t w = static_cast<std::size_t>(width_);
  for (std::size_t i = 0; i < ne; ++i) {
    const std::size_t a = w * edges[i][0], b = w * edges[i][1];
    for (std::size_t c = 0; c < w; ++c) {
      const double dp = (u[b + c] - u[a + c]) * edge_coef_[i] * factor;
      f[b + c] += dp;
      f[a + c] -= dp;
    }
  }
}

void TetrahedronDiffusionFEMForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  add_fluxes(mstate->read(p.x).data(), mstate->write(p.f).data(), 1.0);
}

void TetrahedronDiffusionFEMForceField::add_dforce(const MechParams& p, double) {
  if (state() != ComponentState::valid) return;
  // SOFA's mparams->kFactor(), without rayleighStiffness.
  add_fluxes(mstate->read(p.dx).data(), mstate->write(p.df).data(), p.k);
}

// Every component, as add_dforce applies it. SOFA's buildStiffnessMatrix fills only the
// first component of each point (indices N·v) for Vec2d and Vec3d: a deliberate difference.
bool TetrahedronDiffusionFEMForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  const auto& edges = topology->edges();
  const std::size_t ne = std::min(edges.size(), edge_coef_.size());
  const std::size_t w = static_cast<std::size_t>(width_);
  for (std::size_t i = 0; i < ne; ++i) {
    const std::size_t a = w * edges[i][0], b = w * edges[i][1];
    for (std::size_t c = 0; c < w; ++c) {
      K.add(s, b + c, s, a + c, -edge_coef_[i]);
      K.add(s, a + c, s, b + c, -edge_coef_[i]);
      K.add(s, a + c, s, a + c, edge_coef_[i]);
      K.add(s, b + c, s, b + c, edge_coef_[i]);
    }
  }
  return true;
}

void register_tetrahedron_diffusion_fem_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronDiffusionFEMForceField";
  info.category = "ForceField/Diffusion";
  info.description = "linear diffusion of a field on a tetrahedral mesh (heat, potential)";
  info.templates = {"Vec1d", "Vec2d", "Vec3d"};
  info.default_template = "Vec2d";
  info.requirement = Requirement::state;
  info.create = creator<TetrahedronDiffusionFEMForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
