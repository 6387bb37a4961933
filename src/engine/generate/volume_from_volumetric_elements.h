// VolumeFromVolumetricElements: total volume of tetrahedra and hexahedra
// (SOFA's Engine/Generate, alias VolumeFromTetrahedrons): Σ|tetra volume| +
// Σ hexahedron volumes (each the sum of the |volumes| of SOFA's six inner
// tetrahedra), absolute value of the sum. Positions default to the node's
// state's position, elements to the node's topology's (copied at init).
// Computed at init and reinit; with `update` it follows the state's
// positions whenever it is read, as SOFA.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class VolumeFromVolumetricElements final : public Engine {
 public:
  VolumeFromVolumetricElements();

  Link<MeshTopologyBase> topology{this, "topology", "topology giving the elements (default: the node's)"};
  Link<MechanicalState> mechanical{this, "mechanical", "state giving the positions (default: the node's)"};
  Field<std::vector<Vec3>> position{this, "position", {}, "points (default: the node's state's position)", "Inputs",
                                    "length"};
  Field<std::vector<Tetra>> tetras{this, "tetras", {}, "tetrahedra (default: the topology's)", "Inputs"};
  Field<std::vector<Hexa>> hexas{this, "hexas", {}, "hexahedra (default: the topology's)", "Inputs"};
  Field<double> volume{this, "volume", 0.0, "total volume", "Outputs", "length³"};
  Field<bool> do_update_field{this, "update", false, "follow the state's positions (recompute when read)",
                              "Inputs"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  void compute();
};

// SOFA's geometry::Tetrahedron::volume (|signed volume|) and Hexahedron::volume (six tetrahedra).
double tetra_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
double hexa_volume(const std::array<Vec3, 8>& n);

}  // namespace sinew
