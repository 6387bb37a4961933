// BeamFEMForceField: 3D beam elements (axial, two bendings, torsion) on the
// edges of a topology, between Rigid3d frames (spec/mechanics.md §2.9).
//
// Large displacements only, as SOFA: each beam is corotated with the current
// orientation of its first node; the local displacement of the second node
// (translation and rotation vector relative to the rest configuration) times
// the local 12×12 stiffness gives the forces. The beam frame set by add_force
// is the one add_dforce and build_stiffness use. Kernel: forcefield/beam_fem.h.
#pragma once

#include <vector>

#include "core/roles.h"
#include "forcefield/fem/beam_fem.h"

namespace sinew {

class BeamFEMForceField final : public ForceField {
 public:
  Field<double> poisson_ratio{this, "poissonRatio", 0.49, "Poisson's ratio", "Material", "dimensionless"};
  Field<double> young_modulus{this, "youngModulus", 5000.0, "Young's modulus", "Material", "pressure (force/length²)"};
  Field<double> radius{this, "radius", 0.1, "radius of the (circular) section", "Material", "length"};
  Field<double> radius_inner{this, "radiusInner", 0.0, "inner radius of the section, for hollow beams",
                             "Material", "length"};
  Field<std::vector<unsigned>> list_segment{
      this, "listSegment", {}, "edges the force field applies to (default: all edges of the topology)", "Material"};
  Field<bool> use_symmetric_assembly{this, "useSymmetricAssembly", false,
                                     "assemble K from its upper block triangle, mirrored", "Material"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the edges (default: the node's)"};

  void init() override;
  void reinit() override { init(); }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  struct Beam {
    unsigned a, b;
    beam::BeamSection section;
    beam::Mat12 k;   // local stiffness
    beam::Quat q;    // beam frame: normalised orientation of node a at the last add_force
  };
  const std::vector<Beam>& beams() const { return beams_; }

 private:
  bool partial_ = false;      // listSegment in use (SOFA then ignores useSymmetricAssembly)
  std::vector<Beam> beams_;  // in the order SOFA visits them (listSegment order, or edge order)
};

}  // namespace sinew
