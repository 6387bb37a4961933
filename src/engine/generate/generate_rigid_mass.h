// GenerateRigidMass: mass, volume, centre of mass and inertia of a closed
// surface mesh of uniform density (SOFA's Engine/Generate, Rigid3d). The
// volume integrals of 1, x, y, z, x², y², z², xy, yz, zx are accumulated over
// the triangles (quads and polygons fanned from their first vertex) by the
// divergence theorem (Eberly's polyhedral mass properties, as SOFA); the
// inertia is taken about the centre of mass and per unit mass.
// Outputs: rigidMass "mass volume I00 … I22" (SOFA's Rigid3Mass text, the
// value UniformMass's vertexMass takes), mass = density·volume, volume,
// inertiaMatrix (per unit mass), massCenter, centerToOrigin = −massCenter.
// A zero volume leaves the outputs as they were, with a warning.
#pragma once

#include <array>

#include "core/engine.h"
#include "core/roles.h"
#include "io/loader_fields.h"

namespace sinew {

class GenerateRigidMass final : public Engine {
 public:
  GenerateRigidMass();

  Field<double> density{this, "density", 1000.0, "density of the object", "Inputs", "mass/length³"};
  Field<std::vector<Vec3>> position{this, "position", {}, "vertices of the mesh", "Inputs", "length"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the mesh", "Inputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the mesh", "Inputs"};
  io::ValueField<std::vector<std::vector<unsigned>>> polygons{this, "polygons", "polygons of the mesh", "Inputs"};
  Field<std::vector<double>> rigid_mass{this, "rigidMass", {1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1},
                                        "mass volume I00 I01 … I22 (SOFA's Rigid3Mass)", "Outputs"};
  Field<double> mass{this, "mass", 0.0, "mass of the mesh", "Outputs", "mass"};
  Field<double> volume{this, "volume", 0.0, "volume of the mesh", "Outputs", "length³"};
  Field<Mat3> inertia_matrix{this, "inertiaMatrix", Mat3::Zero(), "inertia per unit mass about the centre of mass",
                             "Outputs", "length²"};
  Field<Vec3> mass_center{this, "massCenter", Vec3::Zero(), "centre of mass", "Outputs", "length"};
  Field<Vec3> center_to_origin{this, "centerToOrigin", Vec3::Zero(), "−massCenter", "Outputs", "length"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

// The ten volume integrals of a closed triangulated surface (1, x, y, z, x²,
// y², z², xy, yz, zx), SOFA's integrateMesh before its final divisions.
void accumulate_volume_integrals(const Vec3& a, const Vec3& b, const Vec3& c, std::array<double, 10>& acc);

}  // namespace sinew
